"""Reading the CSV files nsm-bar writes, checked: the plotting script and
compare_backbones.py read their inputs through it.

A file must be UTF-8 (a leading byte order mark is skipped) CSV with one
named column per field of every row; a number a finite decimal (no nan, inf,
hexadecimal float, '_' or spaces); each column as its Column rule says. Bad
input raises BadInput, whose message names the file, the line and the column:
the scripts print it as one line and exit 2.
"""
import csv
import io
import math
import re
import sys

BRANCHES = ("main", "tongue", "other")


class BadInput(Exception):
    """Bad input: main prints its message as one line and exits 2."""


def fail(program, message, code=2):
    """PROGRAM: error: MESSAGE as one line on stderr (control characters
    escaped), then exit CODE."""
    line = "".join(c if c.isprintable() else c.encode("unicode_escape", "backslashreplace").decode()
                   for c in message)
    print(f"{program}: error: {line}", file=sys.stderr, flush=True)
    sys.exit(code)


# A finite decimal number: no nan, inf, hexadecimal float, '_' or spaces.
DECIMAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


def decimal(text):
    """TEXT's value if it is a finite decimal number, else None."""
    if not DECIMAL.fullmatch(text) or not math.isfinite(float(text)):
        return None
    return float(text)


def shown(cell):
    return repr(cell if len(cell) <= 40 else cell[:37] + "...")


class Column:
    """What a column's cells hold: a finite decimal number (> 0 with
    positive, a whole number >= 0 with whole), with words one of them, with
    text any text; an empty cell only with empty. required: the file must
    have the column."""

    def __init__(self, required=False, empty=False, positive=False, whole=False, words=None, text=False):
        self.required, self.empty, self.positive, self.whole = required, empty, positive, whole
        self.words, self.text = words, text

    def value(self, cell):
        """The cell's value; a ValueError says what is wrong with it."""
        if self.text:
            return cell
        if cell == "" and self.empty:
            return "" if self.words else math.nan
        if self.words:
            if cell not in self.words:
                raise ValueError(f"{shown(cell)} is not one of {', '.join(self.words)}")
            return cell
        value = decimal(cell)
        if value is None:
            raise ValueError(f"{shown(cell)} is not a finite decimal number" if cell else "empty, a number is needed")
        if self.positive and value <= 0:
            raise ValueError(f"{cell} is not > 0")
        if self.whole and (value < 0 or not value.is_integer()):
            raise ValueError(f"{cell} is not a whole number >= 0")
        return value


def csv_lines(path):
    """[(line, fields)] of a CSV file (blank lines left out): UTF-8, a leading BOM skipped."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as error:
        raise BadInput(f"{path}: cannot be read: {error.strerror}")
    data = data[3:] if data.startswith(b"\xef\xbb\xbf") else data
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data[:error.start].count(b"\n") + 1
        raise BadInput(f"{path}: line {line}: byte 0x{data[error.start]:02x} is not UTF-8")
    reader = csv.reader(io.StringIO(text, newline=""), strict=True)
    rows, end = [], 0
    try:
        for fields in reader:
            if fields:
                rows.append((end + 1, fields))
            end = reader.line_num
    except csv.Error as error:
        raise BadInput(f"{path}: line {end + 1}: {error}")
    return rows


def read_table(path, columns):
    """(header, [(line, row)]) of a CSV file, each row a dict of its cells by
    column name, those of COLUMNS as their rules read them."""
    lines = csv_lines(path)
    if not lines:
        raise BadInput(f"{path}: empty file: no header line")
    (header_line, header), lines = lines[0], lines[1:]
    for i, name in enumerate(header):
        if name == "" or name in header[:i]:
            what = f"column {i + 1} has no name" if name == "" else f"column {name} appears twice"
            raise BadInput(f"{path}: line {header_line}: {what}")
    missing = [name for name, column in columns.items() if column.required and name not in header]
    if missing:
        raise BadInput(f"{path}: line {header_line}: no column {', '.join(missing)}")
    rows = []
    for line, fields in lines:
        if len(fields) != len(header):
            raise BadInput(f"{path}: line {line}: {len(fields)} fields, the header has {len(header)}")
        rows.append((line, checked(path, line, dict(zip(header, fields)), columns)))
    return header, rows


def checked(path, line, row, columns):
    """ROW (of PATH's LINE) with its cells of COLUMNS read by their rules."""
    for name, column in columns.items():
        if name in row:
            try:
                row[name] = column.value(row[name])
            except ValueError as error:
                raise BadInput(f"{path}: line {line}, column {name}: {error}")
    return row


# frc.csv's columns (doc/output.md): the forced response's curves.
FRC = {"forcing": Column(required=True, positive=True), "segment": Column(required=True, whole=True),
       "Omega": Column(required=True), "energy": Column(required=True, positive=True),
       "tip_amplitude": Column(required=True), "phase": Column(required=True), "stable": Column(whole=True),
       **{name: Column() for name in ("contact_fraction", "max_contact_force", "input_power", "dissipated_power",
                                      "residual")},
       # Filled at the points verified whose shooting converged (Forcing/Floquet).
       **{name: Column(empty=True) for name in ("floquet_largest", "floquet_real", "floquet_imag")}}

# backbone.csv's columns (doc/output.md): segment, Omega, energy and branch
# required, the others checked where present, empty only where a run leaves
# them empty (no estimate; a point not verified, not refined in time).
BACKBONE = {"segment": Column(required=True, whole=True), "Omega": Column(required=True),
            "energy": Column(required=True, positive=True), "branch": Column(required=True, words=BRANCHES),
            **{name: Column() for name in ("energy_spread", "max_contact_force", "max_contact_displacement",
                                           "contact_fraction", "residual", "max_displacement")},
            **{name: Column(whole=True) for name in ("newton_iterations", "resonance_mode",
                                                     "resonance_harmonic", "leading_harmonic")},
            **{name: Column(empty=True) for name in (
                "energy_error_estimate", "periodicity_defect", "periodicity_defect_end", "energy_drift",
                "impulse_ratio", "verified_contact_fraction", "verified_energy", "orbit_energy", "hb_energy_error",
                "orbit_contact_fraction", "floquet_max", "isolation")},
            "verified": Column(empty=True, words=("true", "false")),
            "stable": Column(empty=True, words=("true", "false"))}
