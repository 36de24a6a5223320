#!/usr/bin/env bash
# The C++ files follow .clang-format: clang-format 14 (Debian's clang-format,
# which scripts/bootstrap.sh installs) in --dry-run -Werror mode over every
# C++ file git tracks (outside a git checkout: every C++ file under the root
# except build folders). Exits 0 when every file is formatted, 1 with the
# offending lines otherwise, and 77 (the CTest test `format` reports it as
# skipped) when no clang-format 14 is installed: another major version formats
# some constructs differently, so its verdict would not be the house style's.
# Fix: `clang-format -i FILE` (docs/testing.md, "Formatting").
# Usage: bash scripts/check-format.sh [CLANG_FORMAT]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
tool="${1:-}"
if [ -z "$tool" ]; then
  for t in clang-format-14 clang-format; do
    if command -v "$t" >/dev/null 2>&1; then tool="$t"; break; fi
  done
fi
if [ -z "$tool" ] || ! command -v "$tool" >/dev/null 2>&1; then
  echo "check-format: skipped: no clang-format (Debian: apt-get install clang-format)"
  exit 77
fi
version="$("$tool" --version)"
if ! [[ "$version" =~ version\ 14\. ]]; then
  echo "check-format: skipped: $tool is not clang-format 14 ($version)"
  exit 77
fi
files=()
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  while IFS= read -r -d '' f; do
    [ -f "$f" ] && files+=("$f")
  done < <(git ls-files -z -- '*.cpp' '*.hpp' '*.h' '*.cc')
else
  while IFS= read -r -d '' f; do
    files+=("$f")
  done < <(find . \( -path './build*' -o -path './.git' \) -prune -o -type f \
             \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cc' \) -print0)
fi
if [ "${#files[@]}" -eq 0 ]; then
  echo "check-format: no C++ files found under $root" >&2
  exit 1
fi
if "$tool" --dry-run -Werror "${files[@]}"; then
  echo "check-format: ${#files[@]} C++ files formatted as .clang-format says ($version)"
else
  echo "check-format: the files above are not formatted; run: clang-format -i FILE" >&2
  exit 1
fi
