#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""bed_lid_check.py LMP INPUT: runs INPUT (inputs/bed/bed_lid.in) and checks that each
PERIDEM-LID line's value equals the lid (yhi) of that bed file's "# bed" header, that the
two beds' lids differ (the variable is reset, not kept), and that every disk of each file
lies below its lid (y + r <= lid). Prints PERIDEM-PASS or PERIDEM-FAIL."""
import re
import subprocess
import sys


def main():
    lmp, inp = sys.argv[1], sys.argv[2]
    out = subprocess.run([lmp, "-in", inp, "-log", "none", "-echo", "none"],
                         capture_output=True, text=True)
    print(out.stdout, out.stderr)
    if out.returncode != 0:
        print("PERIDEM-FAIL: lmp exited with", out.returncode)
        return 1
    lids = re.findall(r"^PERIDEM-LID (\S+) (\S+)$", out.stdout, re.M)
    if len(lids) != 2:
        print("PERIDEM-FAIL: expected two PERIDEM-LID lines")
        return 1
    fails = []
    for path, value in lids:
        lines = open(path).read().splitlines()
        header = next(l for l in lines if l.startswith("# bed "))
        yhi = float(header.split()[5])
        tops = [float(l.split()[1]) + float(l.split()[3]) for l in lines if not l.startswith("#")]
        print(f"{path}: variable {value}, header lid {yhi!r}, highest disk top {max(tops)!r}")
        if float(value) != yhi or max(tops) > yhi:
            fails.append(path)
    if lids[0][1] == lids[1][1]:
        fails.append("the second bed did not reset the variable")
    if fails:
        print("PERIDEM-FAIL: " + ", ".join(fails))
        return 1
    print("PERIDEM-PASS: the lid variable equals each bed file's lid")
    return 0


if __name__ == "__main__":
    sys.exit(main())
