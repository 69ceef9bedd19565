#!/usr/bin/python3
"""The length of every function defined at namespace level in C++ sources (the project's
clang-format style puts such definitions at column 0 and closes them with a '}' at column 0),
from the first line of its signature to its closing brace. Functions defined inside a class
body are not counted (they are one-liners by the project's style).

    /usr/bin/python3 scripts/function_lengths.py [--max N] FOLDER_OR_FILE...

prints the functions longer than N lines (all, without --max), longest first, as
file:line: name (n lines), and exits 1 if --max is given and any is longer.
"""

import argparse
import os
import re
import sys

SOURCE = re.compile(r"\.(cpp|C)$")
NOT_A_FUNCTION = re.compile(r"^(namespace|class|struct|enum|union|using|typedef|template\s*<[^>]*>\s*$|#|//|/\*|\}|extern)")
NAME = re.compile(r"([A-Za-z_][A-Za-z0-9_:~]*(?:operator\S+)?)\s*\(")


def function_lengths(path):
    """[(name, first line (1-based), number of lines)] of the functions defined in one file."""
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().split("\n")
    found, start = [], None
    for i, line in enumerate(lines):
        if start is None:
            if line and not line[0].isspace() and not NOT_A_FUNCTION.match(line) and "(" in line:
                start, depth, opened = i, 0, False
        if start is not None:
            code = re.sub(r'"(\\.|[^"\\])*"|\'(\\.|[^\'\\])*\'|//.*', "", line)
            if depth == 0 and code.rstrip().endswith(";"):  # a declaration, not a definition
                start = None
                continue
            depth += code.count("{") - code.count("}")
            opened = opened or "{" in code
            if opened and depth <= 0:
                name = NAME.search(lines[start])
                found.append((name.group(1) if name else lines[start].strip(), start + 1, i - start + 1))
                start = None
    return found


def sources(targets):
    for target in targets:
        if os.path.isfile(target):
            yield target
            continue
        for folder, _, files in os.walk(target):
            for name in sorted(files):
                if SOURCE.search(name):
                    yield os.path.join(folder, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--max", type=int, default=None, help="longest allowed function (lines)")
    parser.add_argument("targets", nargs="+")
    args = parser.parse_args()
    rows = [(n, path, line, name) for path in sources(args.targets) for name, line, n in function_lengths(path)]
    rows.sort(reverse=True)
    over = [r for r in rows if args.max is None or r[0] > args.max]
    for n, path, line, name in over:
        print("%s:%d: %s (%d lines)" % (path, line, name, n))
    return 1 if args.max is not None and over else 0


if __name__ == "__main__":
    sys.exit(main())
