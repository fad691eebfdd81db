#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Reduced in.uniaxial (ctest bed_stress_uniaxial): runs LAMMPS and checks the physics of
the stress-strain record (stress_strain.txt):

1. before the lid touches the packing, it carries no stress (|sigma_zz| < 1e-6 of the final);
2. once loaded (the last 40 % of the strain), the packing's mean sigma_zz equals the mean of
   the lid's and the floor's loads over the section, -(N_lid + N_floor)/2A, within 10 %
   (the virial theorem up to the packing's inertia);
3. the stress grows with the strain: |sigma_zz| over the last 10 % of the strain is more
   than 3x its mean over the 40-60 % window;
4. the lateral stresses are compressive and smaller than the axial one, and the contact
   fabric leans along the load at the end (F_zz > 1/3 + 0.05);
5. the coordination number rises from 0 to at least 1.

  check_uniaxial.py --lmp LMP [--out DIR] [-- extra LAMMPS arguments]
"""
import argparse
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--out", default="uniaxial_check")
    ap.add_argument("extra", nargs="*", help="more LAMMPS arguments (after --)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cmd = [a.lmp, "-in", os.path.join(HERE, "in.uniaxial"), "-log", "log.lammps",
           "-var", "nx", "3", "-var", "layers", "3", "-var", "n", "3", "-var", "strain", "0.35",
           "-var", "picture", "no"] + a.extra
    run = subprocess.run(cmd, cwd=a.out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True)
    if run.returncode != 0:
        print(run.stdout[-3000:])
        print(f"PERIDEM-FAIL uniaxial: LAMMPS exit code {run.returncode}")
        return 1
    d = np.loadtxt(os.path.join(a.out, "stress_strain.txt"))
    e, sxx, syy, szz = d[:, 1], d[:, 2], d[:, 3], d[:, 4]
    lid, floor, Z, Fzz = d[:, 9], d[:, 10], d[:, 12], d[:, 15]
    emax = e[-1]
    fails = []

    def check(ok, text):
        print(("ok   " if ok else "FAIL ") + text)
        if not ok:
            fails.append(text)

    final = abs(np.mean(szz[e > 0.9 * emax]))
    free = np.abs(szz[(lid == 0) & (floor == 0) & (Z == 0)])
    check(len(free) > 1 and free.max() < 1e-6 * final,
          f"before the lid touches: max |szz| {free.max() if len(free) else float('nan'):.3g} "
          f"< 1e-6 of the final {final:.3g}")
    late = e > 0.6 * emax
    s_pack, s_walls = np.mean(szz[late]), np.mean(0.5 * (lid[late] + floor[late]))
    check(abs(s_pack / s_walls - 1) < 0.10,
          f"loaded: mean szz {s_pack:.4g} = -(lid + floor)/2A {s_walls:.4g} within 10 % "
          f"({s_pack / s_walls - 1:+.3f})")
    mid = np.abs(np.mean(szz[(e > 0.4 * emax) & (e < 0.6 * emax)]))
    check(final > 3 * mid, f"stress grows: |szz| {final:.3g} at the end > 3x {mid:.3g} at mid-strain")
    lateral = 0.5 * (np.mean(sxx[e > 0.9 * emax]) + np.mean(syy[e > 0.9 * emax]))
    check(lateral < 0 and abs(lateral) < final,
          f"lateral stress {lateral:.3g} compressive and below the axial {final:.3g}")
    check(Fzz[-1] > 1 / 3 + 0.05, f"fabric along the load: F_zz {Fzz[-1]:.3f} > 1/3 + 0.05")
    check(Z[0] == 0 and Z[-1] >= 1, f"coordination number 0 -> {Z[-1]:.3f} (>= 1)")
    if fails:
        print(f"PERIDEM-FAIL uniaxial: {len(fails)} check(s)")
        return 1
    print("PERIDEM-PASS uniaxial")
    return 0


if __name__ == "__main__":
    sys.exit(main())
