#!/usr/bin/python3
"""Checks that every #include between the project's modules points down the layering
(docs/layout.md). Top to bottom:

  executables   */main.cpp, fluid_adapter/foam_smoke/, tests/, bench/   (may include anything)
  case          the whole case.yaml, its options and schema
  physics       structure_solver, coupler, prescribed_flow, fluid_adapter, pump (never each other)
  foundations   proto, geometry, hdf5, checkpoint, motion (geometry may use motion)
  common        configuration framework, logging, types, exit codes

A file's module is the first folder of its path; an include's module is the first folder of
the included path (a bare file name is the including file's own folder). Prints one line per
offending include (file:line: the include, and why) and exits 1 if there is any.

    /usr/bin/python3 scripts/check_layering.py [ROOT]
"""

import os
import re
import sys

PHYSICS = {"structure_solver", "coupler", "prescribed_flow", "fluid_adapter", "pump"}
FOUNDATIONS = {"proto", "geometry", "hdf5", "checkpoint", "motion"}
# What each module may include besides itself.
ALLOWED = {
    "case": PHYSICS | FOUNDATIONS | {"common"},
    **{m: FOUNDATIONS | {"common"} for m in PHYSICS},
    "proto": {"common"},
    "geometry": {"motion", "common"},
    "hdf5": {"common"},
    "checkpoint": {"common"},
    "motion": {"common"},
    "common": set(),
}
MODULES = set(ALLOWED)
TOP = {"tests", "bench"}
SOURCE = re.compile(r"\.(hpp|cpp|h|H|C)$")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def is_executable(path):
    parts = path.split("/")
    return parts[0] in TOP or parts[-1] == "main.cpp" or path.startswith("fluid_adapter/foam_smoke/")


def layer_name(module):
    if module in PHYSICS:
        return "physics module " + module
    if module in FOUNDATIONS:
        return "foundation " + module
    return module


def violations(root):
    found = []
    for folder, dirs, files in os.walk(root):
        rel_folder = os.path.relpath(folder, root)
        if rel_folder == ".":
            dirs[:] = [d for d in dirs if d in MODULES or d in TOP]
            continue
        for name in sorted(files):
            if not SOURCE.search(name):
                continue
            path = os.path.join(rel_folder, name).replace(os.sep, "/")
            module = path.split("/")[0]
            if is_executable(path) or module not in MODULES:
                continue
            with open(os.path.join(root, path), errors="replace") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if not m or "/" not in m.group(1):
                        continue
                    target = m.group(1).split("/")[0]
                    if target not in MODULES or target == module or target in ALLOWED[module]:
                        continue
                    allowed = ", ".join(sorted(ALLOWED[module])) or "nothing but itself"
                    found.append(f"{path}:{number}: #include \"{m.group(1)}\": the {layer_name(module)} may not "
                                 f"include {layer_name(target)} (it may include: {allowed})")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    found = violations(root)
    for line in found:
        print(line)
    if found:
        print(f"{len(found)} include(s) point up or sideways; see docs/layout.md", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
