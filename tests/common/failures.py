"""The end of a scene check: each failure on a line, then a count."""


def report(failures, summary=""):
    """Prints the failures and `summary`; returns the exit code (1 if any)."""
    for f in failures:
        print("FAIL: " + f)
    print((summary + "; " if summary else "") + f"{len(failures)} failures")
    return 1 if failures else 0
