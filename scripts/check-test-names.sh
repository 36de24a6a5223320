#!/usr/bin/env bash
# Every Catch2 test case must reach CTest under its own name: catch_discover_tests
# hands the names to CMake, which splits a name at ';' (the test then runs under
# two broken names and fails), and Catch reads a name that starts with '-' as an
# option. Fails, naming file and line, for any TEST_CASE whose name does either.
set -euo pipefail
cd "$(dirname "$0")/.."
bad=$(grep -rnE 'TEST_CASE(_METHOD|_TEMPLATE)?\((\w+, *)?"([^"]*;|-)' tests || true)
if [ -n "$bad" ]; then
  echo "test names CTest cannot run (a ';' splits a name, a leading '-' reads as an option):"
  echo "$bad"
  exit 1
fi
echo "test names: none has ';' or a leading '-'"
