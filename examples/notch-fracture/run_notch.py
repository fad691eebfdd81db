#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Runs in.notch_fracture for several G_c, resolutions and notch kinds and
tabulates the fragments of grain A (examples/notch-fracture/README.md).

    run_notch.py --lmp LMP [--potentials DIR] [--out DIR] [--m 5 10]
                 [--Gc 135 13.5] [--notch slot] [--time 5e-5] [--check]

--check (the ctest variant, m = 5, 20 us): A must break at both G_c of the
paper (at least 2 fragments) and into more pieces (fragments and debris) at
G_c = 13.5 than at 135 (the paper: 2 and 3 child particles; lower toughness,
more fracture surface). Prints PERIDEM-PASS or PERIDEM-FAIL.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
LINE = re.compile(r"PERIDEM-NOTCH Gc (\S+) m (\S+) notch (\S+): fragments of A (\d+) .*"
                  r"debris (\d+), all pieces (\d+)")


def run(lmp, potentials, out, Gc, m, notch, t, extra):
    tag = f"{Gc}_m{m}_{notch}"
    cmd = [lmp, "-in", "in.notch_fracture", "-log", f"log.{tag}", "-screen", "none",
           "-var", "potentials", potentials, "-var", "Gc", str(Gc), "-var", "m", str(m),
           "-var", "notch", notch, "-var", "time", str(t)] + extra
    t0 = time.time()
    subprocess.run(cmd, cwd=out, check=True)
    wall = time.time() - t0
    with open(os.path.join(out, f"log.{tag}")) as f:
        hit = LINE.search(f.read())
    if not hit:
        raise RuntimeError(f"no PERIDEM-NOTCH line in {out}/log.{tag}")
    return int(hit.group(4)), int(hit.group(5)), int(hit.group(6)), wall


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--lmp", required=True)
    p.add_argument("--potentials", default=os.path.join(HERE, "..", "..", "potentials"))
    p.add_argument("--out", default=".")
    p.add_argument("--m", nargs="+", default=["5"])
    p.add_argument("--Gc", nargs="+", default=["135", "13.5"])
    p.add_argument("--notch", nargs="+", default=["slot"])
    p.add_argument("--time", type=float, default=5e-5)
    p.add_argument("--check", action="store_true")
    p.add_argument("extra", nargs="*", help="more lmp arguments after --")
    a = p.parse_args()
    if a.check:
        a.m, a.Gc, a.notch, a.time = ["5"], ["135", "13.5"], ["slot"], 2e-5
    os.makedirs(a.out, exist_ok=True)
    shutil.copy(os.path.join(HERE, "in.notch_fracture"), a.out)
    lmp = os.path.abspath(a.lmp)
    potentials = os.path.abspath(a.potentials)
    rows = {}
    print("| notch | h = eps/m | G_c (J/m^2) | fragments (>= 1 % of A) | debris pieces | wall time (s) |")
    print("|---|---|---|---|---|---|")
    for notch in a.notch:
        for m in a.m:
            for Gc in a.Gc:
                n, debris, allp, wall = run(lmp, potentials, a.out, Gc, m, notch, a.time, a.extra)
                rows[(notch, m, Gc)] = (n, allp)
                print(f"| {notch} | eps/{m} | {Gc} | {n} | {debris} | {wall:.0f} |", flush=True)
    if a.check:
        (n135, all135), (n13, all13) = rows[("slot", "5", "135")], rows[("slot", "5", "13.5")]
        ok = n135 >= 2 and n13 >= 2 and all13 > all135
        print(("PERIDEM-PASS" if ok else "PERIDEM-FAIL") +
              f": A in {n135} fragments ({all135} pieces with debris) at G_c = 135 and {n13} "
              f"({all13}) at 13.5 (expected: >= 2 fragments at both, more pieces at the lower "
              "G_c; the paper: 2 and 3)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
