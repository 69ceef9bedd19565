#!/usr/bin/python3
"""Checks that every #include and every CMake link between the project's modules points down the
layering (docs/layout.md). Top to bottom:

  apps          apps/<executable>/: the mains and what only one executable uses
                (tests/ and bench/ sit beside them)
  case          the whole case.yaml, its options and schema
  physics       structure_solver, coupler, prescribed_flow, fluid_adapter, pump (never each other)
  foundations   participant, proto, geometry, hdf5, checkpoint, motion (participant may use
                proto and checkpoint, geometry motion)
  common        configuration framework, logging, types, exit codes

No file is exempt. A file's module is the first folder of its path, an executable's the folder
under apps/ (one executable never includes another's files); an include's module is the first
folder of the included path (a bare file name is the including file's own folder). A CMake
target belongs to the module whose folder defines it (add_library, add_executable); each
target_link_libraries line may name only targets of its own module or of the modules it may
include. Prints one line per offending include or link (file:line: what, and why) and exits 1
if there is any.

    /usr/bin/python3 scripts/check_layering.py [ROOT]
"""

import os
import re
import sys

PHYSICS = {"structure_solver", "coupler", "prescribed_flow", "fluid_adapter", "pump"}
FOUNDATIONS = {"participant", "proto", "geometry", "hdf5", "checkpoint", "motion"}
BELOW_APPS = {"case"} | PHYSICS | FOUNDATIONS | {"common"}
# What each module may include besides itself.
ALLOWED = {
    "apps": BELOW_APPS,
    "case": PHYSICS | FOUNDATIONS | {"common"},
    **{m: FOUNDATIONS | {"common"} for m in PHYSICS},
    "participant": {"proto", "checkpoint", "common"},
    "proto": {"common"},
    "geometry": {"motion", "common"},
    "hdf5": {"common"},
    "checkpoint": {"common"},
    "motion": {"common"},
    "common": set(),
}
MODULES = set(ALLOWED)
TOP = {"tests", "bench"}  # beside the apps: may include and link anything but an app's files
SOURCE = re.compile(r"\.(hpp|cpp|h|H|C)$")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
DEFINE = re.compile(r"\badd_(?:library|executable)\(\s*([A-Za-z0-9_.+-]+)")
LINK = re.compile(r"\btarget_link_libraries\(\s*([A-Za-z0-9_.+-]+)([^)]*)\)", re.S)


def module_of(path):
    """The module of a repository path: its first folder, or apps/<executable> for an app."""
    parts = path.split("/")
    if parts[0] == "apps" and len(parts) > 2:
        return "apps/" + parts[1]
    return parts[0]


def layer(module):
    return "apps" if module.startswith("apps/") else module


def layer_name(module):
    if module in PHYSICS:
        return "physics module " + module
    if module in FOUNDATIONS:
        return "foundation " + module
    if module.startswith("apps/"):
        return "executable " + module
    return module


def allows(module, target):
    """May `module` include or link `target` (both modules)?"""
    if target == module:
        return True
    if layer(module) in TOP:
        return not target.startswith("apps/")
    if layer(target) not in MODULES:
        return True  # not one of ours (a system header, a third-party target)
    if target.startswith("apps/"):
        return False  # an executable's files are its own
    return target in ALLOWED[layer(module)]


def allowed_list(module):
    allowed = ", ".join(sorted(ALLOWED[layer(module)])) or "nothing but itself"
    return allowed


def checked_files(root, pattern):
    """(relative path, absolute path) of the files under the modules, tests and bench."""
    for folder, dirs, files in os.walk(root):
        rel_folder = os.path.relpath(folder, root)
        if rel_folder == ".":
            dirs[:] = [d for d in dirs if d in MODULES or d in TOP]
            continue
        for name in sorted(files):
            if pattern(name):
                path = os.path.join(rel_folder, name).replace(os.sep, "/")
                yield path, os.path.join(root, path)


def include_violations(root):
    found = []
    for path, full in checked_files(root, lambda name: SOURCE.search(name)):
        module = module_of(path)
        if layer(module) in TOP:
            continue  # tests and benchmarks include what they test (never an app's files: they link none)
        with open(full, errors="replace") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m or "/" not in m.group(1):
                    continue
                target = module_of(m.group(1))
                if allows(module, target):
                    continue
                found.append(f"{path}:{number}: #include \"{m.group(1)}\": the {layer_name(module)} may not "
                             f"include {layer_name(target)} (it may include: {allowed_list(module)})")
    return found


def strip_comments(text):
    return "\n".join(line.split("#", 1)[0] for line in text.splitlines())


def cmake_texts(root):
    """(texts by CMakeLists path, module by target) of the modules, tests and bench."""
    owner = {}  # target -> module that defines it
    texts = {}
    for path, full in checked_files(root, lambda name: name == "CMakeLists.txt"):
        with open(full, errors="replace") as f:
            texts[path] = strip_comments(f.read())
        for m in DEFINE.finditer(texts[path]):
            owner[m.group(1)] = module_of(path)
    return texts, owner


def link_closure(root, target):
    """The project's targets `target` links, directly or through others."""
    texts, owner = cmake_texts(root)
    links = {}
    for text in texts.values():
        for m in LINK.finditer(text):
            links.setdefault(m.group(1), set()).update(n for n in m.group(2).split() if n in owner)
    seen, todo = set(), [target]
    while todo:
        for name in links.get(todo.pop(), ()):
            if name not in seen:
                seen.add(name)
                todo.append(name)
    return seen


def link_violations(root):
    texts, owner = cmake_texts(root)
    found = []
    for path, text in texts.items():
        for m in LINK.finditer(text):
            target, linked = m.group(1), m.group(2).split()
            module = owner.get(target, module_of(path))
            number = text.count("\n", 0, m.start()) + 1
            for name in linked:
                if name in ("PUBLIC", "PRIVATE", "INTERFACE") or name not in owner:
                    continue
                if allows(module, owner[name]):
                    continue
                found.append(f"{path}:{number}: {target} links {name}: the {layer_name(module)} may not link "
                             f"{layer_name(owner[name])} (it may link: {allowed_list(module)})")
    return found


def violations(root):
    return include_violations(root) + link_violations(root)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    found = violations(root)
    for line in found:
        print(line)
    if found:
        print(f"{len(found)} include(s) or link(s) point up or sideways; see docs/layout.md", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
