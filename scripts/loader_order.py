#!/usr/bin/env python3
"""Prints the shared libraries that the given ones load, most looked-up first,
separated by ';' (a CMake list), for the link line (CMakeLists.txt).

    loader_order.py /usr/lib/x86_64-linux-gnu/libdeal.ii.so ...

The dynamic loader resolves every symbol a library uses by searching the
loaded libraries in load order, and the first libraries loaded are the
program's own DT_NEEDED entries, in link order. deal.II brings about 200
libraries, most of which (gmsh, OpenCASCADE, PETSc) resolve thousands of their
own symbols at start-up: loaded late, each such lookup first walks past a
hundred others. Listing the libraries in the order of how many lookups end in
each makes those walks short. The counts come from loading the given libraries
here once with LD_DEBUG=bindings. Only the order of search changes: a symbol
defined in several libraries (C++ inline functions and templates, which the
one-definition rule makes identical) may bind to another of its copies.
"""
import collections
import os
import re
import subprocess
import sys

BINDING = re.compile(r"binding file \S+ \[\d+\] to (\S+) \[\d+\]")
LOAD = "import ctypes, sys\nfor p in sys.argv[1:]: ctypes.CDLL(p, mode=ctypes.RTLD_GLOBAL)"


def loaded_libraries(libraries):
    """The given libraries and every library they load, in load order."""
    found = []
    for library in libraries:
        out = subprocess.run(["ldd", library], capture_output=True, text=True, check=True).stdout
        for path in [library] + re.findall(r"=> (/\S+) \(", out):
            real = os.path.realpath(path)
            if real not in found and "ld-linux" not in real:
                found.append(real)
    return found


def lookups_per_library(libraries):
    env = dict(os.environ, LD_DEBUG="bindings")
    err = subprocess.run([sys.executable, "-c", LOAD] + libraries, capture_output=True, text=True, env=env,
                         check=True).stderr
    return collections.Counter(os.path.realpath(m.group(1)) for m in BINDING.finditer(err))


def main():
    libraries = [os.path.realpath(p) for p in sys.argv[1:]]
    order = loaded_libraries(libraries)
    counts = lookups_per_library(libraries)
    order.sort(key=lambda path: -counts[path])  # stable: unbound ones keep load order
    print(";".join(order), end="")


if __name__ == "__main__":
    main()
