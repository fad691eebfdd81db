#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""thermo_compare.py LOG LOG [LOG...]: the thermo tables of every log must equal
those of the first log, value by value, to a relative tolerance (default
1e-9, --rtol) with an absolute floor (--atol, default 1e-12). Exits 1 with
the first difference otherwise. Used to check that a run on N MPI ranks
gives the thermo output of the run on one rank."""
import argparse
import sys


def thermo_tables(path):
    """All thermo tables of a LAMMPS log: a list of (header, rows)."""
    tables, header, rows = [], None, []
    with open(path) as f:
        for line in f:
            words = line.split()
            if words[:1] == ["Step"]:
                header, rows = words, []
            elif header is not None and words[:2] == ["Loop", "time"]:
                tables.append((header, rows))
                header = None
            elif header is not None and len(words) == len(header):
                try:
                    rows.append([float(w) for w in words])
                except ValueError:
                    pass  # a warning printed between thermo lines
    return tables


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("logs", nargs="+")
    ap.add_argument("--rtol", type=float, default=1e-9)
    ap.add_argument("--atol", type=float, default=1e-12)
    a = ap.parse_args()
    if len(a.logs) < 2:  # a log compared with itself would pass whatever it holds
        sys.exit(f"FAIL: {len(a.logs)} log given: compare two or more")
    ref = thermo_tables(a.logs[0])
    if not ref or not any(rows for _, rows in ref):
        sys.exit(f"FAIL: no thermo output in {a.logs[0]}")
    worst = 0.0
    for log in a.logs[1:]:
        other = thermo_tables(log)
        if len(other) != len(ref):
            sys.exit(f"FAIL: {log} has {len(other)} thermo tables, {a.logs[0]} has {len(ref)}")
        for (h1, r1), (h2, r2) in zip(ref, other):
            if h1 != h2 or len(r1) != len(r2):
                sys.exit(f"FAIL: thermo tables differ in shape: {h1} x {len(r1)} vs {h2} x {len(r2)}")
            for row1, row2 in zip(r1, r2):
                for name, x, y in zip(h1, row1, row2):
                    diff = abs(x - y)
                    scale = max(abs(x), abs(y))
                    if diff > a.atol + a.rtol * scale:
                        sys.exit(f"FAIL: {name} at step {row1[0]:g}: {x!r} ({a.logs[0]}) vs {y!r} ({log})")
                    if scale > 0:
                        worst = max(worst, diff / scale)
    nrows = sum(len(r) for _, r in ref)
    print(f"OK: {len(a.logs)} logs, {nrows} thermo rows each, largest relative difference {worst:.3g}")


if __name__ == "__main__":
    main()
