#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Coefficient of restitution vs the damping parameter eps_n (Jha et al. 2021, §4.1, Table 2).

Runs in.restitution for eps_n = 1, 0.95, 0.9, 0.85, 0.8 (damping centroid, C = 100) twice:
  (a) as Jha et al. 2021, eq. 27 is written: the centroid dashpot acts while two nodes of the disks are
      closer than R_c, i.e. from the moment the contact force starts;
  (b) with the dashpot switched on 0.6 % of R_c (0.8 micrometres) earlier (pair_coeff
      centroid_range 1.006 R_c); Jha et al.'s (2021) code also switches it on before the contact
      (centres closer than R_1 + R_2 + 1.01 R_c). 1.006 is a CALIBRATION: it was fitted to
      Jha et al.'s (2021) Table 2, so agreement with that table validates nothing.
Writes restitution.dat (eps_n, C_R of Jha et al. 2021, ours (a), ours (b)) and restitution.png (if
matplotlib is installed), and checks when --check is given (exit 1 on failure):
  independent bounds: C_R(1) within 1% of 1 (no damping: only the energy left as grain
  vibration is missing), C_R strictly decreasing with eps_n in both series, (b) <= (a)
  for every eps_n (the earlier dashpot acts over a longer time, so it dissipates more),
  (a) never below Jha et al.'s (2021) minus --tol (Jha et al.'s (2021) dashpot also starts earlier);
  calibration: (b) within --paper-tol of Jha et al.'s (2021) Table 2 (the table it was fitted to;
  this only guards the calibration against changes).
--grains lps: state-based grains (bond_style peridem/lps plane 3d, the model of Jha et al. 2021)
  and (b) with the onset of Jha et al.'s code, 1.01 R_c (its constant, not fitted here): the
  check of (b) against Table 2 is then a prediction.

usage: run_restitution.py [--lmp PATH] [--np N] [--potentials DIR] [--check] [--tol T]
                          [--grains bond|lps] [-- extra lmp arguments, e.g. -var dt 2.5e-8]
"""
import argparse
import os
import re
import subprocess
import sys

EPS = [1.0, 0.95, 0.9, 0.85, 0.8]
PAPER = [1.0, 0.946, 0.893, 0.845, 0.796]     # Jha et al. 2021, Table 2
ONSET = 1.006                                  # (b): centroid_range = ONSET x R_c (calibrated)

here = os.path.dirname(os.path.abspath(__file__))
ap = argparse.ArgumentParser()
ap.add_argument("--lmp", default=os.path.join(here, "../../build/lmp_peridem"))
ap.add_argument("--np", type=int, default=1)
ap.add_argument("--potentials", default=os.path.join(here, "../../potentials"))
ap.add_argument("--out", default=".")
ap.add_argument("--check", action="store_true")
ap.add_argument("--tol", type=float, default=0.01)
ap.add_argument("--paper-tol", type=float, default=0.005)
ap.add_argument("--grains", choices=["bond", "lps"], default="bond")
ap.add_argument("extra", nargs="*")
a = ap.parse_args()
if a.grains == "lps":
    ONSET = 1.01  # Jha et al.'s code: centres closer than R_1 + R_2 + 1.01 R_c

os.makedirs(a.out, exist_ok=True)


def restitution(eps, onset):
    log = os.path.join(a.out, "log.eps_%g_onset_%g" % (eps, onset))
    cmd = ([] if a.np == 1 else ["mpirun", "-np", str(a.np)]) + [
        a.lmp, "-in", os.path.join(here, "in.restitution"), "-echo", "none", "-screen", "none",
        "-log", log, "-var", "eps_n", str(eps), "-var", "onset", str(onset),
        "-var", "potentials", a.potentials, "-var", "grains", a.grains] + a.extra
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    subprocess.run(cmd, check=True, env=env, cwd=here if a.out == "." else a.out)
    m = re.search(r"PERIDEM-RESTITUTION eps_n \S+ H1 (\S+) CR (\S+) steps (\d+)", open(log).read())
    if not m:
        sys.exit("no result in " + log)
    return float(m.group(2))


ours, early = [], []
for k, e in enumerate(EPS):
    ours.append(restitution(e, 0))
    # without damping the onset plays no part: the same run
    early.append(ours[-1] if e == 1.0 else restitution(e, ONSET))
    print("eps_n %-5g paper C_R %.3f  ours (a) %.4f  (b) %.4f" % (e, PAPER[k], ours[-1], early[-1]),
          flush=True)

with open(os.path.join(a.out, "restitution.dat"), "w") as f:
    f.write("# eps_n  C_R(Jha et al. 2021, Table 2)  C_R(PERIDEM, %s grains, damping centroid "
            "C=100: (a) onset R_c, (b) onset %g R_c)\n" % (a.grains, ONSET))
    for e, s, o, b in zip(EPS, PAPER, ours, early):
        f.write("%-6g %8.3f %10.4f %10.4f\n" % (e, s, o, b))

PLOT = r"""
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = [list(map(float, l.split())) for l in open(sys.argv[1]) if l.strip() and l[0] != "#"]
eps, paper, ours, early = zip(*rows)
fig, ax = plt.subplots(figsize=(5, 4))
ax.plot(eps, paper, "s--", label="Jha et al. 2021, Table 2", markersize=9)
ax.plot(eps, ours, "o-", label="PERIDEM, dashpot on below R_c (eq. 27)")
ax.plot(eps, early, "^-", label="PERIDEM, dashpot on below %s R_c" % sys.argv[3])
ax.plot(eps, eps, ":", color="gray", label="C_R = eps_n")
ax.set_xlabel("damping parameter eps_n")
ax.set_ylabel("coefficient of restitution C_R")
ax.invert_xaxis()
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
"""
# matplotlib of this python, else Debian's (python3-matplotlib)
sys.path.insert(0, here)
from plot_png import plot  # noqa: E402
plot(PLOT, os.path.join(a.out, "restitution.dat"), os.path.join(a.out, "restitution.png"),
     "%g" % ONSET)

if a.check:
    bad = []
    if abs(ours[0] - 1.0) > 0.01:
        bad.append("C_R(1) = %g not within 1%% of 1" % ours[0])
    for series, name in ((ours, "(a)"), (early, "(b)")):
        for k in range(1, len(EPS)):
            if not series[k] < series[k - 1]:
                bad.append("%s C_R does not decrease from eps_n %g to %g" % (name, EPS[k - 1], EPS[k]))
    for e, o, b in zip(EPS, ours, early):
        if b > o + 1e-12 or (e < 1.0 and not b < o):
            bad.append("(b) C_R(%g) = %g is not below (a) %g: the earlier dashpot must dissipate "
                       "more" % (e, b, o))
    for e, o, s in zip(EPS, ours, PAPER):
        if o < s - a.tol:
            bad.append("(a) C_R(%g) = %g damps more than Jha et al.'s (2021) %g" % (e, o, s))
    for e, b, s in zip(EPS, early, PAPER):
        if abs(b - s) > a.paper_tol:
            bad.append("(b) C_R(%g) = %g differs from Jha et al.'s (2021) %g by more than %g (%s "
                       "grains, centroid_range %g)" % (e, b, s, a.paper_tol, a.grains, ONSET))
    if bad:
        print("PERIDEM-FAIL " + "; ".join(bad))
        sys.exit(1)
    print("PERIDEM-PASS restitution bounds (C_R(1) = 1, decreasing, (b) <= (a), (a) not below "
          "the paper); %s grains: Jha et al.'s (2021) Table 2 to %g with centroid_range %g R_c"
          % (a.grains, a.paper_tol, ONSET))
