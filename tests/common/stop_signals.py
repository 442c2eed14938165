"""Stopping nsm-bar at a known boundary without racing a timer: a full pipe
as its stderr makes it wait in its next progress line, and Linux's
/proc/PID/wchan tells when it waits there."""
import os


def blocked_writing_stderr(pid):
    """The process waits to write into a full pipe: its only pipe is stderr
    (Linux's /proc/PID/wchan names the kernel function it sleeps in)."""
    try:
        with open(f"/proc/{pid}/wchan") as f:
            return "pipe_write" in f.read()
    except OSError:
        return False


def full_pipe():
    """A pipe whose buffer is full: the first write to it waits for a read."""
    read_end, write_end = os.pipe()
    os.set_blocking(write_end, False)
    try:
        while True:
            os.write(write_end, b"x" * 4096)
    except BlockingIOError:
        pass
    os.set_blocking(write_end, True)  # the writer's writes must wait, not fail
    return read_end, write_end
