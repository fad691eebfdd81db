#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Reduced in.fault (ctest sheared_fault_reduced): a 20 mm block with one jag, p = 0.1
sigma_c, sheared for 0.8 ms with contact friction on (mu 0.7, on NP ranks) and off (1 rank).
Checks:

1. the seam: the bond count equals an independent count of the node pairs within the
   horizon on the periodic lattice, in the same half by eq. 71 (so the bonds across the
   periodic boundary exist), and no node is lost by the end;
2. the pressure: the block's mean push on the driven edge over the shear equals p within 1 %
   (the thesis's eq. 22 holds on average; the edge's inertia makes each window differ);
3. mu (eq. 85) rises to a peak and falls: the peak, after the first window and before the
   last quarter of the run, is above 1.5 times the first window's mu, and the last quarter's
   mean is below 0.75 of it (friction on);
4. friction off gives a lower mean mu than friction on;
5. energy: the dissipated energy Q = W - dE (work of the driving force less the change of
   kinetic and potential energy) is positive and, with friction on and off, at least the
   contacts' dissipation (compute pair peridem/contact), since broken bonds take their
   stored energy with them (to 0.1 %: the contacts' share is counted to the integrator's
   accuracy). The power at v(n - 1/2) that the pair counted before gave more than Q with
   friction (823 against 802 J/m) by counting each flip of a stuck contact's force.

  check_fault.py --lmp LMP [--np N] [--out DIR]
"""
import argparse
import math
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
RUNS = {"on": "0.7", "off": "0"}
SMALL = {"L": 0.02, "H": 0.02, "h": 1e-3, "m": 3, "n_jag": 1, "jag": 2e-3}


def expected_bonds(L, H, h, m, n_jag, jag):
    """Pairs of lattice nodes within the horizon m h (1.0001 m h), periodic along x, on the
    same side of eq. 71's fault line, counted by brute force here."""
    nx, ny = round(L / h), round(H / h)
    eps = m * h * 1.0001
    xs = (np.arange(nx) + 0.5) * h
    ys = (np.arange(ny) + 0.5) * h
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    X, Y = X.ravel(), Y.ravel()
    upper = Y >= 0.5 * H + 0.5 * jag * np.sin(2 * math.pi * n_jag * X / L)
    n = 0
    for i in range(len(X)):
        dx = X[i + 1:] - X[i]
        dx -= L * np.round(dx / L)
        dy = Y[i + 1:] - Y[i]
        near = dx * dx + dy * dy <= eps * eps
        n += int(np.count_nonzero(near & (upper[i + 1:] == upper[i])))
    return len(X), n


def run(lmp, np_, mu, out, extra):
    tag = f"mu{mu}"
    cmd = ([os.path.join(HERE, "../../unittest/scripts/mpirun.sh"), str(np_)] if np_ > 1 else [])
    cmd += [lmp, "-in", os.path.join(HERE, "in.fault"), "-log", f"{tag}.log", "-screen", "none",
            "-var", "potentials", os.path.join(HERE, "../../potentials"), "-var", "tag", tag,
            "-var", "mu", mu, "-var", "ratio", "0.1", "-var", "t_load", "1e-4",
            "-var", "tau_load", "1e-5", "-var", "t_shear", "8e-4", "-var", "every", "200",
            "-var", "dt", "7e-8"]
    for k, v in SMALL.items():
        cmd += ["-var", k, str(v)]
    r = subprocess.run(cmd + extra, cwd=out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True)
    log = open(os.path.join(out, f"{tag}.log")).read() if os.path.exists(
        os.path.join(out, f"{tag}.log")) else ""
    if r.returncode != 0:
        print(r.stdout[-2000:], log[-2000:])
        raise SystemExit(f"PERIDEM-FAIL sheared fault: LAMMPS exit code {r.returncode} ({tag})")
    return np.loadtxt(os.path.join(out, f"{tag}.txt")), log


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--np", type=int, default=1, help="ranks of the friction-on run")
    ap.add_argument("--out", default="fault_check")
    ap.add_argument("extra", nargs="*", help="more LAMMPS arguments (after --)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    fails = []

    def check(ok, text):
        print(("ok   " if ok else "FAIL ") + text)
        if not ok:
            fails.append(text)

    data, logs = {}, {}
    for key, mu in RUNS.items():
        data[key], logs[key] = run(a.lmp, a.np if key == "on" else 1, mu, a.out, a.extra)
    nodes, bonds = expected_bonds(**SMALL)
    p = 0.1 * 280e6
    for key in RUNS:
        setup = re.search(r"PERIDEM-SETUP (\d+) nodes (\d+) bonds", logs[key])
        done = re.search(r"PERIDEM-DONE nodes (\d+)", logs[key])
        check(setup and int(setup.group(1)) == nodes and int(setup.group(2)) == bonds,
              f"friction {key}: {setup.group(1) if setup else '?'} nodes and "
              f"{setup.group(2) if setup else '?'} bonds = {nodes} and {bonds} counted "
              "independently (periodic seam bonded)")
        check(done and int(done.group(1)) == nodes,
              f"friction {key}: {done.group(1) if done else '?'} nodes at the end (none lost)")
        # the first row is the first output after the shear starts: its force averages cover
        # no complete window yet (0), so the checks start with the second
        d = data[key][1:]
        check(abs(np.mean(d[:, 4]) / p - 1) < 0.01,
              f"friction {key}: mean pressure on the driven edge {np.mean(d[:, 4]) / 1e6:.2f} MPa"
              f" = p {p / 1e6:.0f} MPa within 1 %")
    on, off = data["on"][1:], data["off"][1:]
    mu_on, mu_off = on[:, 2], off[:, 2]
    n = len(mu_on)
    peak = int(np.argmax(mu_on))
    late = np.mean(mu_on[3 * n // 4:])
    check(0 < peak < 3 * n // 4 and mu_on[peak] > 1.5 * mu_on[0] and late < 0.75 * mu_on[peak],
          f"friction on: mu rises from {mu_on[0]:.2f} to a peak of {mu_on[peak]:.2f} (t = "
          f"{on[peak, 1] * 1e3:.2f} ms, above 1.5x the start) and the last quarter's mean "
          f"{late:.2f} < 0.75 of it")
    check(np.mean(mu_off) < np.mean(mu_on),
          f"mean mu: friction off {np.mean(mu_off):.3f} < friction on {np.mean(mu_on):.3f}")
    for key in RUNS:
        q, qc = data[key][-1, 12], data[key][-1, 13]
        check(0 < qc <= 1.001 * q,
              f"friction {key}: dissipated Q = W - dE {q:.1f} J/m >= the contacts' share "
              f"{qc:.1f} J/m > 0 (the rest: energy of broken bonds)")
    if fails:
        print(f"PERIDEM-FAIL sheared fault: {len(fails)} check(s)")
        return 1
    print("PERIDEM-PASS sheared fault")
    return 0


if __name__ == "__main__":
    sys.exit(main())
