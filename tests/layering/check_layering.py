#!/usr/bin/env python3
"""No module includes a module above it. The build enforces this (each module
compiles against a view of include/nsm holding only itself and the modules
below it: CMakeLists.txt); this check says the same before a build, naming
each upward include.

usage: check_layering.py [ROOT]
The order of the modules is NSM_MODULES in ROOT/CMakeLists.txt, lowest first.
"""
import os
import re
import sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else \
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def module_order():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        match = re.search(r"set\(NSM_MODULES ([^)]*)\)", f.read())
    return match.group(1).split()


def files_of(module):
    for folder in (os.path.join(ROOT, "source", module), os.path.join(ROOT, "include", "nsm", module)):
        for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
            yield os.path.join(folder, name)


def main():
    order = module_order()
    rank = {m: i for i, m in enumerate(order)}
    upward, unknown = [], []
    for module in order:
        for path in files_of(module):
            with open(path) as f:
                for number, line in enumerate(f, 1):
                    included = re.match(r'\s*#\s*include\s*[<"]nsm/([a-z_]+)/', line)
                    if not included:
                        continue
                    target = included.group(1)
                    where = f"{os.path.relpath(path, ROOT)}:{number}"
                    if target not in rank:
                        unknown.append(f"{where} includes nsm/{target}/, which is no module")
                    elif rank[target] > rank[module]:
                        upward.append(f"{where}: {module} includes {target}, a module above it")
    for folder in ("source", os.path.join("include", "nsm")):
        stray = [n for n in os.listdir(os.path.join(ROOT, folder)) if n not in rank]
        unknown += [f"{folder}/{n} is in no module" for n in stray]
    for line in upward + unknown:
        print(line)
    if upward or unknown:
        sys.exit(f"{len(upward)} upward includes, {len(unknown)} files outside the modules "
                 f"(order, lowest first: {' '.join(order)})")
    print(f"every include runs downward through {' < '.join(order)}")


if __name__ == "__main__":
    main()
