"""Stopping nsm-bar at a known boundary without racing a timer: a full pipe
as its stderr makes it wait in its next progress line, and Linux's
/proc/PID/wchan tells when it waits there."""
import os
import subprocess
import tempfile
import time


def blocked_writing_stderr(pid):
    """The process waits to write into a full pipe: its only pipe is stderr
    (Linux's /proc/PID/wchan names the kernel function it sleeps in)."""
    try:
        with open(f"/proc/{pid}/wchan") as f:
            return "pipe_write" in f.read()
    except OSError:
        return False


PAGE = 4096  # a pipe's buffer is made of pages; a write that fits no free page waits


def full_pipe(room_pages=0):
    """A pipe whose buffer is full but for `room_pages` free pages: the
    writes that need more wait for a read."""
    read_end, write_end = os.pipe()
    os.set_blocking(write_end, False)
    try:
        while True:
            os.write(write_end, b"x" * 4096)
    except BlockingIOError:
        pass
    os.set_blocking(write_end, True)  # the writer's writes must wait, not fail
    if room_pages:
        os.read(read_end, room_pages * PAGE)
    return read_end, write_end


def signal_when_blocked(command, stop, what, cwd=None, room_pages=0):
    """Runs `command` with a full pipe as its stderr, sends it the signal
    `stop` once it waits to write a progress line (its first, or the first
    that finds no room in `room_pages` pages: a place set by the run's own
    output), and returns its exit code, stdout and stderr. `what` names the
    line, for a failure."""
    read_end, write_end = full_pipe(room_pages)
    with tempfile.TemporaryFile(mode="w+") as out:
        process = subprocess.Popen(command, cwd=cwd, stdout=out, stderr=write_end, text=True)
        os.close(write_end)
        deadline = time.time() + 300
        while not blocked_writing_stderr(process.pid):
            assert process.poll() is None and time.time() < deadline, f"the process never announced {what}"
            time.sleep(0.01)
        process.send_signal(stop)
        with os.fdopen(read_end, "rb") as pipe:
            stderr = pipe.read().decode(errors="replace").lstrip("x")
        process.wait()
        out.seek(0)
        return process.returncode, out.read(), stderr
