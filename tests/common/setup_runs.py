"""Setup runs shared between table rows: a row's setup often runs nsm-bar to
make an earlier output (a complete run, a study, a run stopped with its
checkpoint) before the row attacks it. Many rows need the same earlier
output; `once` makes it once per table and copies it to the rows after.

A copy is the run's own result: the program is deterministic for a scene,
and an output holds no absolute path, so the output made in one row's
folder is the one it would make in another's. The key is the setup's own
(which run, with which arguments) together with the whole state of the
working directory before it: names, kinds, bytes and link targets.
"""
import atexit
import hashlib
import os
import shutil
import tempfile

_home = os.getcwd()  # the test's working directory, where the store is made
_store = None        # a folder of this process's own there, removed at exit
_runs = {}           # key -> folder holding the working directory after the run


def _state(directory):
    """A digest of every path under directory, or None if one is neither a
    file, a folder nor a link (a FIFO, a socket: not copied)."""
    digest = hashlib.sha256()
    for base, dirs, files in sorted(os.walk(directory)):
        dirs.sort()
        for name in sorted(dirs + files):
            path = os.path.join(base, name)
            digest.update(os.path.relpath(path, directory).encode(errors="surrogateescape") + b"\0")
            if os.path.islink(path):
                digest.update(b"L" + os.readlink(path).encode(errors="surrogateescape"))
            elif os.path.isdir(path):
                digest.update(b"D")
            elif os.path.isfile(path):
                with open(path, "rb") as f:
                    digest.update(b"F" + f.read())
            else:
                return None
            digest.update(b"\0")
    return digest.hexdigest()


def _copy_entries(source, target):
    for name in os.listdir(source):
        path = os.path.join(source, name)
        if os.path.isdir(path) and not os.path.islink(path):
            shutil.copytree(path, os.path.join(target, name), symlinks=True)
        else:
            shutil.copy2(path, os.path.join(target, name), follow_symlinks=False)


def _clear(directory):
    for name in os.listdir(directory):
        path = os.path.join(directory, name)
        if os.path.isdir(path) and not os.path.islink(path):
            shutil.rmtree(path)
        else:
            os.remove(path)


def once(key, run):
    """run() in the working directory, or, if a run of the same key started
    from the same directory state before, the directory that run left."""
    global _store
    before = _state(".")
    if before is None:
        run()
        return
    full_key = (key, before)
    if full_key in _runs:
        _clear(".")
        _copy_entries(_runs[full_key], ".")
        return
    run()
    if _state(".") is None:
        return
    if _store is None:
        _store = tempfile.mkdtemp(prefix="setup-runs-", dir=_home)
        atexit.register(shutil.rmtree, _store, ignore_errors=True)
    kept = tempfile.mkdtemp(dir=_store)
    _copy_entries(".", kept)
    _runs[full_key] = kept
