#!/usr/bin/env python3
"""doc/parameters.md's tables are the declarations' own: fails unless the part
below its marker line is exactly what `nsm-bar --print-parameters=markdown`
prints (defaults, ranges in words, documentation).

usage: check_parameters_doc.py NSM_BAR [--write]
--write replaces that part with the program's listing.
"""
import os
import subprocess
import sys

DOC = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                   "doc", "parameters.md")
MARKER = "<!-- Generated: nsm-bar --print-parameters=markdown."


def main():
    if len(sys.argv) not in (2, 3) or sys.argv[2:] not in ([], ["--write"]):
        sys.exit(__doc__)
    listing = subprocess.run([sys.argv[1], "--print-parameters=markdown"], capture_output=True, text=True,
                             check=True).stdout
    with open(DOC) as f:
        text = f.read()
    start = text.index(MARKER)
    prose, generated = text[:start], text[start:]
    marker = generated[:generated.index("-->") + 4]
    if sys.argv[2:] == ["--write"]:
        with open(DOC, "w") as f:
            f.write(prose + marker + listing)
        return print(f"wrote {DOC}")
    if generated[len(marker):] != listing:
        have = generated[len(marker):].splitlines()
        want = listing.splitlines()
        first = next((i for i, (a, b) in enumerate(zip(have, want)) if a != b), min(len(have), len(want)))
        sys.exit(f"doc/parameters.md differs from the declarations at its generated line {first + 1}:\n"
                 f"  doc:      {have[first] if first < len(have) else '(end)'}\n"
                 f"  declared: {want[first] if first < len(want) else '(end)'}\n"
                 "run tests/docs/check_parameters_doc.py NSM_BAR --write")
    print("doc/parameters.md lists every declared parameter as declared")


if __name__ == "__main__":
    main()
