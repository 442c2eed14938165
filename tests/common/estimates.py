"""The Result block's statement of the error estimate, derived from
backbone.csv (verification/harmonics_estimate.cc prints it)."""


def estimate_statement(found, main):
    """'median M %, 90th percentile P % over N of K' for the main points'
    finite estimates `found` (any order) out of `main` main points, to the two
    significant digits printed."""
    found = sorted(found)
    median, p90 = found[len(found) // 2], found[min(len(found) - 1, int(0.9 * len(found)))]
    return f"median {100 * median:.2g} %, 90th percentile {100 * p90:.2g} % over {len(found)} of {main}"
