#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""compare_thermo.py LOG_A LOG_B [--rtol R]: compares the thermo rows of two
LAMMPS logs of one input (e.g. 1 and 2 MPI ranks) over the steps both reached,
also when a run is still going (no "Loop time" line yet). Prints, per column,
the first step whose values differ by more than rtol (relative, default 1e-9)
and the largest relative difference; exits 1 when a column differs before
--window steps (default: never, the comparison is reported only).
--digits also prints, per common step, how many significant digits all columns
share (the fewest over the columns, from the relative difference: 1e-9 -> 9;
"all" when every printed digit agrees) and the column that has the fewest: for a
run continued from a restart file against the uninterrupted run."""
import argparse
import math
import sys


def rows(path):
    """{step: row} of the last thermo table of a log (complete or not)."""
    header, table = None, {}
    for line in open(path, errors="replace"):
        w = line.split()
        if w[:1] == ["Step"]:
            header, table = w, {}
        elif header and len(w) == len(header):
            try:
                v = [float(x) for x in w]
            except ValueError:
                continue
            table[int(v[0])] = v
    return header, table


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--rtol", type=float, default=1e-9)
    ap.add_argument("--window", type=int, default=-1)
    ap.add_argument("--digits", action="store_true")
    a = ap.parse_args()
    ha, ta = rows(a.a)
    hb, tb = rows(a.b)
    if not ta or not tb or ha != hb:
        sys.exit(f"compare_thermo: no common thermo table ({ha} / {hb})")
    steps = sorted(set(ta) & set(tb))
    print(f"compare_thermo: {len(steps)} common rows, steps {steps[0]}..{steps[-1]} "
          f"({a.a} reached {max(ta)}, {a.b} reached {max(tb)})")
    fail = False
    if a.digits:
        print("  step  digits shared by all columns (fewest in)")
        for s in steps:
            fewest, where = None, ""
            for j, name in enumerate(ha[1:], 1):
                x, y = ta[s][j], tb[s][j]
                if x == y:
                    continue
                d = -math.log10(abs(x - y) / max(abs(x), abs(y)))
                if fewest is None or d < fewest:
                    fewest, where = d, name
            shared = "all" if fewest is None else f"{fewest:.1f} ({where})"
            print(f"  {s:>6}  {shared}")
    for j, name in enumerate(ha[1:], 1):
        first, worst = None, 0.0
        for s in steps:
            x, y = ta[s][j], tb[s][j]
            scale = max(abs(x), abs(y))
            rel = abs(x - y) / scale if scale > 0 else 0.0
            worst = max(worst, rel)
            if first is None and rel > a.rtol:
                first = s
        print(f"  {name:>10}: largest relative difference {worst:.3g}; first step beyond "
              f"{a.rtol:g}: {first if first is not None else 'none'}")
        if a.window >= 0 and first is not None and first <= a.window:
            fail = True
    sys.exit(1 if fail else 0)


if __name__ == "__main__":
    main()
