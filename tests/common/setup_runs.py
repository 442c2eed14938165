"""Setup runs shared between table rows: a row's setup often runs nsm-bar to
make an earlier output (a complete run, a study, a run stopped with its
checkpoint) before the row attacks it. Many rows need the same earlier
output; `once` makes it once per table and copies it to the rows after.

A copy is the run's own result: the program is deterministic for a scene
and reads nothing of an earlier output by its path, time or inode, so the
output made in one row's folder serves another's. (An absolute path is
written in plots.log alone, which a run removes before it draws again; the
manifest's date is the first run's.) The key is the setup's own (which run,
with which arguments) together with the whole state of the working directory
before it: names, kinds, permissions, bytes and link targets. A directory
holding a special file or a hard link is not cached.
"""
import atexit
import hashlib
import os
import shutil
import stat
import tempfile

_home = os.getcwd()  # the test's working directory, where the store is made
_store = None        # a folder of this process's own there, removed at exit
_runs = {}           # key -> folder holding the working directory after the run


def _raise(error):
    raise error


def _state(directory):
    """A digest of every path under directory, or None if one is neither a
    file, a folder nor a link, or is a hard link (a FIFO, a socket, a second
    name of a file: a copy would not be the same)."""
    digest = hashlib.sha256()
    for base, dirs, files in sorted(os.walk(directory, onerror=_raise)):
        for name in sorted(dirs + files):
            path = os.path.join(base, name)
            status = os.lstat(path)
            digest.update(os.path.relpath(path, directory).encode(errors="surrogateescape") + b"\0")
            digest.update(b"%o" % stat.S_IMODE(status.st_mode))
            if stat.S_ISLNK(status.st_mode):
                digest.update(b"L" + os.readlink(path).encode(errors="surrogateescape"))
            elif stat.S_ISDIR(status.st_mode):
                digest.update(b"D")
            elif stat.S_ISREG(status.st_mode) and status.st_nlink == 1:
                with open(path, "rb") as f:
                    digest.update(b"F" + f.read())
            else:
                return None
            digest.update(b"\0")
    return digest.hexdigest()


def _clear(directory):
    for name in os.listdir(directory):
        path = os.path.join(directory, name)
        if os.path.isdir(path) and not os.path.islink(path):
            shutil.rmtree(path)
        else:
            os.remove(path)


def _remove_stores_of_dead_processes():
    """The stores a killed table (a CTest timeout) left in _home."""
    for name in os.listdir(_home):
        parts = name.split("-")
        if name.startswith("setup-runs-") and len(parts) >= 4 and parts[2].isdigit():
            try:
                os.kill(int(parts[2]), 0)
            except ProcessLookupError:
                shutil.rmtree(os.path.join(_home, name), ignore_errors=True)
            except PermissionError:
                pass  # another user's live process


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
        shutil.copytree(_runs[full_key], ".", symlinks=True, dirs_exist_ok=True)
        return
    run()
    if _state(".") is None:
        return
    if _store is None:
        _remove_stores_of_dead_processes()
        _store = tempfile.mkdtemp(prefix=f"setup-runs-{os.getpid()}-", dir=_home)
        atexit.register(shutil.rmtree, _store, ignore_errors=True)
    kept = tempfile.mkdtemp(dir=_store)
    shutil.copytree(".", kept, symlinks=True, dirs_exist_ok=True)
    _runs[full_key] = kept
