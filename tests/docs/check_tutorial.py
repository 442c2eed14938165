#!/usr/bin/env python3
"""The tutorial's commands, run in order, print what the tutorial says.

usage: check_tutorial.py BUILD_DIR SOURCE_DIR [WORK_DIR]
doc/tutorial.md shows each command in a ```console block as a line "$ COMMAND"
(a line ending in a backslash goes on on the next), followed by lines of what
it prints. This runs every command with bash, in order, in WORK_DIR (made
anew; default ./tutorial) where build/, prm/ and scripts/ are links to the
build and source folders, as the README's folder looks from a fresh clone.
Each command must exit 0 (or the code its block names in a line
"(exit N)"), and the lines shown after it must appear in what it printed
(standard output and error together), in that order, each whole; a line
"..." stands for lines left out. Standard library only.
"""
import os
import re
import shutil
import signal
import subprocess
import sys


# A command that waits for a line that never comes fails instead of hanging
# (every command of the tutorial takes seconds).
COMMAND_TIMEOUT = 300


def blocks(text):
    """The ```console blocks of a Markdown text, each a list of lines."""
    return [block.splitlines() for block in re.findall(r"```console\n(.*?)```", text, re.S)]


def steps(block):
    """(command, expected lines, exit code) for each "$ " line of a block."""
    found, command, expected, code = [], None, [], 0
    lines = iter(block)
    for line in lines:
        if line.startswith("$ "):
            if command is not None:
                found.append((command, expected, code))
            command, expected, code = line[2:], [], 0
            while command.endswith("\\"):
                command += "\n" + next(lines)
        elif re.fullmatch(r"\(exit (\d+)\)", line.strip()):
            code = int(re.fullmatch(r"\(exit (\d+)\)", line.strip())[1])
        elif line.strip() != "...":
            expected.append(line.rstrip())
    if command is not None:
        found.append((command, expected, code))
    return found


def missing_lines(expected, printed):
    """The first expected line not found (in order) among the printed ones."""
    printed = [line.rstrip() for line in printed.splitlines()]
    at = 0
    for line in expected:
        while at < len(printed) and printed[at] != line:
            at += 1
        if at == len(printed):
            return line
        at += 1
    return None


def run(command, work):
    """(exit code, standard output and error) of a command run by bash in
    `work`, in a session of its own: past COMMAND_TIMEOUT its whole group is
    killed (exit -9)."""
    process = subprocess.Popen(["bash", "-c", command], cwd=work, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, errors="replace", start_new_session=True)
    try:
        stdout, stderr = process.communicate(timeout=COMMAND_TIMEOUT)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        stdout, stderr = process.communicate()
        return -9, stdout + stderr + f"\n(killed after {COMMAND_TIMEOUT} s)"
    return process.returncode, stdout + stderr


def main():
    build, source = (os.path.abspath(a) for a in sys.argv[1:3])
    work = os.path.abspath(sys.argv[3] if len(sys.argv) > 3 else "tutorial")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for name, target in (("build", build), ("prm", os.path.join(source, "prm")),
                         ("scripts", os.path.join(source, "scripts"))):
        os.symlink(target, os.path.join(work, name))
    with open(os.path.join(source, "doc", "tutorial.md"), encoding="utf-8") as f:
        text = f.read()
    failures, count = [], 0
    for block in blocks(text):
        for command, expected, code in steps(block):
            count += 1
            returncode, printed = run(command, work)
            if returncode != code:
                failures.append(f"$ {command}\n  exit {returncode}, expected {code}:\n{printed[-2000:]}")
                continue
            line = missing_lines(expected, printed)
            if line is not None:
                failures.append(f"$ {command}\n  does not print (in order): {line}\n  it printed:\n{printed[-4000:]}")
                continue
            print(f"ok   $ {command.splitlines()[0]}")
    for failure in failures:
        print("FAIL " + failure)
    print(f"{count - len(failures)} passed, {len(failures)} failed")
    sys.exit(1 if failures or count == 0 else 0)


if __name__ == "__main__":
    main()
