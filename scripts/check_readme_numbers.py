#!/usr/bin/python3
"""Checks that every marked number in an example README is the number the
example's run produces now.

Usage: check_readme_numbers.py README.md OUT_DIR

A README marks a result number with an HTML comment right after it (after
its unit, if any); the comment is invisible when the README is rendered:

    mp1 settles 4.45 mm<!-- check: loosened_zone.json final_uy_m.mp1 scale=-1000 -->

The marked number is the last number between the start of the line (or the
end of the previous marker on that line) and the marker. A number may have a
sign (+, -, or the typographic minus U+2212) and thousands separated by a
space, no-break space or thin space ("10 072").

Marker syntax (words split as by a POSIX shell, so quote a regular
expression that holds spaces, best in single quotes):

    <!-- check: FILE SELECTOR [scale=X] [offset=Y] [abs] [row=R | at=COLUMN:V] [match=N] -->

FILE is a path relative to OUT_DIR. What SELECTOR means depends on FILE:

  *.json  a key path: keys separated by dots, list items by their index
          (0-based); a key that holds a dot goes in brackets:
          "by_threshold_mm[0.5]", "segments.1.phi_deg".
  *.csv   a column name (the first row is the header); row= picks the value:
          last (default), first, a row index (0-based, negative from the
          end), or max, min, absmax, mean (of the whole column); or
          at=COLUMN:V picks the row whose COLUMN is nearest to V
          ("at=t:0.5": the sample nearest t = 0.5).
  other   a text file (what the run printed, saved by its run.sh): a regular
          expression whose first group is the number; match= picks the match
          (1-based, default 1; "last" for the last one).

scale=X multiplies the produced value (scale=1000 for m -> mm, scale=-1000
for a settlement from a downward displacement); offset=Y is then added
(offset=-30 for the error of an angle whose true value is 30); abs takes
the magnitude of the result.

Comparison: the produced value is compared with the printed one at the
precision the README prints it: a README number 4.45 must come from a value
in [4.445, 4.455], 82 from [81.5, 82.5]. Exit status 1, with one line per
problem (README path, line, printed number, produced number, source), if a
number differs, a marker has no number before it, or its source is missing
or unreadable; 0 otherwise.
"""
import csv
import json
import math
import os
import re
import shlex
import sys
from decimal import Decimal

MARKER = re.compile(r"<!--\s*check:(.*?)-->")
# A number: optional sign, digits with optional 3-digit groups after a space
# (plain, no-break or thin), optional decimals.
NUMBER = re.compile(r"([-+\u2212]?)(\d{1,3}(?:[ \u00a0\u2009\u202f]\d{3})+|\d+)(\.\d+)?(?![\d.]*\d)")


class SourceError(Exception):
    pass


def last_number(text):
    found = None
    for m in NUMBER.finditer(text):
        found = m
    if found is None:
        return None
    sign, whole, frac = found.groups()
    digits = re.sub(r"[ \u00a0\u2009\u202f]", "", whole) + (frac or "")
    value = Decimal(digits)
    if sign in ("-", "\u2212"):
        value = -value
    return found.group(0), value, len(frac) - 1 if frac else 0


def json_path(key):
    """Splits a.b[c.d].0 into ['a', 'b', 'c.d', '0']."""
    parts = []
    for m in re.finditer(r"\[([^\]]*)\]|([^.\[\]]+)", key):
        parts.append(m.group(1) if m.group(1) is not None else m.group(2))
    return parts


def from_json(path, key):
    with open(path) as f:
        value = json.load(f)
    for part in json_path(key):
        if isinstance(value, list):
            try:
                value = value[int(part)]
            except (ValueError, IndexError):
                raise SourceError(f"no item {part!r} in a list of {len(value)}")
        elif isinstance(value, dict):
            if part not in value:
                raise SourceError(f"no key {part!r}")
            value = value[part]
        else:
            raise SourceError(f"{part!r}: not inside a list or object")
    return value


def from_csv(path, column, row, at=None):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or column not in rows[0]:
        raise SourceError(f"no column {column!r}")
    header = rows[0]
    k = header.index(column)
    rows = [r for r in rows[1:] if len(r) > k and r[k].strip()]
    values = [float(r[k]) for r in rows]
    if not values:
        raise SourceError(f"column {column!r} is empty")
    if at is not None:
        key, _, target = at.partition(":")
        if key not in header or not target:
            raise SourceError(f"at={at}: not COLUMN:VALUE with a column of the file")
        j, target = header.index(key), float(target)
        return values[min(range(len(rows)), key=lambda i: abs(float(rows[i][j]) - target))]
    if row == "last":
        return values[-1]
    if row == "first":
        return values[0]
    if row == "max":
        return max(values)
    if row == "min":
        return min(values)
    if row == "absmax":
        return max(values, key=abs)
    if row == "mean":
        return sum(values) / len(values)
    try:
        return values[int(row)]
    except (ValueError, IndexError):
        raise SourceError(f"row={row}: not last, first, max, min, absmax, mean or a row index in range")


def from_text(path, pattern, match):
    with open(path) as f:
        text = f.read()
    hits = list(re.finditer(pattern, text))
    if not hits:
        raise SourceError(f"no match of {pattern!r}")
    try:
        hit = hits[-1] if match == "last" else hits[int(match) - 1]
    except (ValueError, IndexError):
        raise SourceError(f"match={match}: only {len(hits)} matches")
    return hit.group(1)


def produce(out, words):
    """The value a marker's words point to, as a float."""
    if len(words) < 2:
        raise SourceError("a marker needs a file and a selector")
    name, selector = words[0], words[1]
    opts, flags = {}, set()
    for w in words[2:]:
        if "=" in w:
            k, v = w.split("=", 1)
            opts[k] = v
        else:
            flags.add(w)
    unknown = (set(opts) - {"scale", "offset", "row", "at", "match"}) | (flags - {"abs"})
    if unknown:
        raise SourceError(f"unknown option(s) {sorted(unknown)}")
    path = os.path.join(out, name)
    if not os.path.isfile(path):
        raise SourceError(f"missing file {path}")
    if name.endswith(".json"):
        value = from_json(path, selector)
    elif name.endswith(".csv"):
        value = from_csv(path, selector, opts.get("row", "last"), opts.get("at"))
    else:
        value = from_text(path, selector, opts.get("match", "1"))
    try:
        value = float(value)
    except (TypeError, ValueError):
        raise SourceError(f"not a number: {value!r}")
    value = value * float(opts.get("scale", "1")) + float(opts.get("offset", "0"))
    if "abs" in flags:
        value = abs(value)
    return value


def agrees(printed, decimals, produced):
    """True if produced, rounded to the printed precision, is printed."""
    if not math.isfinite(produced):
        return False
    half = Decimal(5) * Decimal(10) ** (-decimals - 1)
    # A relative hair of slack so that a value printed by its own program
    # with the same rounding (e.g. 4.455 stored as 4.45499999...) passes.
    slack = Decimal(1e-9) * max(abs(printed), Decimal(1))
    return abs(Decimal(produced) - printed) <= half + slack


def check(readme, out):
    problems, count = [], 0
    with open(readme, encoding="utf-8") as f:
        lines = f.read().split("\n")
    for n, line in enumerate(lines, 1):
        start = 0
        for m in MARKER.finditer(line):
            count += 1
            body = m.group(1).strip()
            number = last_number(line[start:m.start()])
            start = m.end()
            where = f"{readme}:{n}"
            if number is None:
                problems.append(f"{where}: no number before the marker <!-- check: {body} -->")
                continue
            text, printed, decimals = number
            try:
                produced = produce(out, shlex.split(body))
            except (SourceError, OSError, ValueError, json.JSONDecodeError) as e:
                problems.append(f"{where}: printed {text}, source {body}: {e}")
                continue
            if not agrees(printed, decimals, produced):
                problems.append(f"{where}: printed {text}, produced {produced:.{decimals + 3}f} "
                                f"({produced:.{decimals}f} at the printed precision), source {body}")
    return problems, count


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__.split("\n\n")[1] if len(argv) < 2 else f"usage: {argv[0]} README.md OUT_DIR")
    problems, count = check(argv[1], argv[2])
    for p in problems:
        print("MISMATCH " + p if "produced" in p else "ERROR " + p)
    if count == 0:
        print(f"{argv[1]}: no check markers")
        return 1
    print(f"{argv[1]}: {count} marked numbers, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
