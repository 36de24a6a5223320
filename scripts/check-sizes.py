#!/usr/bin/env python3
"""Keeps the sources readable in one sitting: no source file over 800 lines
and no function over 100 lines, tests aside.

Sources are the files git tracks outside tests/: C++ (.cpp .hpp .h), Python
(.py), shell (.sh) and CMake (CMakeLists.txt, .cmake). A function is
  - C++: a brace-delimited body at namespace or class scope whose header has
    a parameter list (free functions, member functions, lambdas bound at
    namespace scope, macros such as PYBIND11_MODULE); its length runs from the
    first line of its header (template line included) to its closing brace;
  - Python: a def, from the def line to its last line (decorators excluded;
    a nested def counts towards its enclosing function too);
  - shell: `name() {` to the matching `}` at the same indentation;
  - CMake: function()/macro() to endfunction()/endmacro().
Prints each offender as file:line: what, and exits 1 if there is one.
Usage: python3 scripts/check-sizes.py [--max-file N] [--max-function N] [paths...]
(paths default to every tracked source outside tests/).
"""

import argparse
import ast
import os
import re
import subprocess
import sys

SOURCE = re.compile(r"(\.(cpp|hpp|h|cc|py|sh|cmake)|(^|/)CMakeLists\.txt)$")


def tracked_sources(root):
    out = subprocess.check_output(["git", "ls-files"], cwd=root, text=True)
    return [f for f in out.split() if SOURCE.search(f) and not f.startswith("tests/")]


def blank_cpp(text):
    """Returns text with comments, string and character literals replaced by
    spaces (newlines kept), so braces and parentheses in them do not count."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            k = text.find("(", i + 2)
            delim = ")" + text[i + 2 : k] + '"'
            j = text.find(delim, k)
            j = n if j < 0 else j + len(delim)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            # A digit separator (1'000) is not a character literal.
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def cpp_functions(text):
    """Yields (name, first line, last line) of each function body at namespace
    or class scope."""
    code = blank_cpp(text)
    # Preprocessor lines do not take part in the scope structure.
    code = re.sub(r"(?m)^[ \t]*#.*(\\\n.*)*$", lambda m: re.sub(r"[^\n]", " ", m.group(0)), code)
    line_of = []
    line = 1
    for ch in code:
        line_of.append(line)
        if ch == "\n":
            line += 1
    stack = []  # kinds of the open scopes: "ns", "class", "func", "block"
    header_start = 0  # offset where the current declaration's text begins
    opened = []  # (kind, name, start line) per open brace
    for i, ch in enumerate(code):
        if ch == "{":
            inside_function = any(k in ("func", "block") for k in stack)
            header = code[header_start:i]
            if inside_function:
                kind = "block"
            elif re.match(r"\s*(inline\s+)?namespace\b", header) or re.match(r'\s*extern\b[^(]*$', header):
                kind = "ns"
            elif re.search(r"\b(class|struct|union|enum)\b[^(]*$", header) and "(" not in header.split("=")[0]:
                kind = "class"
            elif "(" in header:
                kind = "func"
            else:
                kind = "block"
            name = ""
            if kind == "func":
                names = re.findall(r"([A-Za-z_]\w*(?:::~?[A-Za-z_]\w*)*)\s*\(", header)
                name = names[0] if names else "function"
            first = header_start + len(header) - len(header.lstrip())
            stack.append(kind)
            opened.append((kind, name, line_of[min(first, len(code) - 1)]))
            header_start = i + 1
        elif ch == "}":
            if stack:
                stack.pop()
                kind, name, start = opened.pop()
                if kind == "func":
                    yield name, start, line_of[i]
            header_start = i + 1
        elif ch == ";" and not any(k in ("func", "block") for k in stack):
            header_start = i + 1
        elif ch == ":" and stack and stack[-1] == "class":
            # An access specifier ends a declaration's header.
            before = code[header_start:i].strip()
            if before in ("public", "private", "protected"):
                header_start = i + 1


def python_functions(text, path):
    try:
        tree = ast.parse(text, filename=path)
    except SyntaxError as e:
        print(f"{path}:{e.lineno}: cannot parse: {e.msg}", file=sys.stderr)
        return
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield node.name, node.lineno, node.end_lineno


def shell_functions(text):
    lines = text.split("\n")
    for i, l in enumerate(lines):
        m = re.match(r"^(\s*)(?:function\s+)?([\w-]+)\s*\(\)\s*\{\s*$", l)
        if not m:
            continue
        indent = m.group(1)
        for j in range(i + 1, len(lines)):
            if re.match(r"^" + indent + r"\}", lines[j]):
                yield m.group(2), i + 1, j + 1
                break


def cmake_functions(text):
    lines = text.split("\n")
    start = None
    for i, l in enumerate(lines):
        m = re.match(r"^\s*(function|macro)\s*\(\s*(\w+)", l, re.I)
        if m:
            start, name = i, m.group(2)
        elif start is not None and re.match(r"^\s*end(function|macro)\s*\(", l, re.I):
            yield name, start + 1, i + 1
            start = None


def functions_of(path, text):
    if path.endswith(".py"):
        return python_functions(text, path)
    if path.endswith(".sh"):
        return shell_functions(text)
    if path.endswith((".cmake", "CMakeLists.txt")):
        return cmake_functions(text)
    return cpp_functions(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--max-file", type=int, default=800)
    ap.add_argument("--max-function", type=int, default=100)
    ap.add_argument("paths", nargs="*")
    args = ap.parse_args()
    root = subprocess.check_output(["git", "rev-parse", "--show-toplevel"], text=True).strip()
    paths = args.paths or tracked_sources(root)
    bad = 0
    for p in paths:
        full = p if os.path.isabs(p) else os.path.join(root, p)
        with open(full, encoding="utf-8", errors="replace") as f:
            text = f.read()
        nlines = text.count("\n") + (0 if text.endswith("\n") or not text else 1)
        if nlines > args.max_file:
            print(f"{p}:1: file has {nlines} lines (limit {args.max_file})")
            bad += 1
        for name, first, last in functions_of(p, text):
            if last - first + 1 > args.max_function:
                print(f"{p}:{first}: function {name} has {last - first + 1} lines (limit {args.max_function})")
                bad += 1
    if bad:
        print(f"{bad} offender(s): split files by concept, functions into named steps")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
