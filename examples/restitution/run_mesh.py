#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Mesh study of the two-particle test (Jha, Desai, Bhattacharya & Lipton 2021, §4.1.1, Table 4).

Test 2 of Table 2 (two M1 disks of radius 1 mm, eps_n = 0.95, C = 100) at the four meshes of
Table 4: (h, horizon) = (0.1423, 0.6), (0.0805, 0.375), (0.062, 0.3), (0.0379, 0.2) mm, R_c =
0.95 h, with in.restitution, elastic (eps_n = 1) and damped (eps_n = 0.95).
Our choices, not the paper's: the dashpot onset centroid_range 1.006 R_c at every mesh (the
calibration of README.md, fitted to Table 2 at h = 0.1423 mm only, and scaled with R_c as the
paper scales R_c with h: at the finer meshes it is a prediction); the time step 50 ns
(h / 0.1423 mm)^1.5 (the contact's stiffness per node mass, K_n V^2 / m ~ eps^-5 h^2, scales
as h^-3 when eps is proportional to h), which is 0.28, 0.22, 0.20 and 0.16 of the package's
estimate (176, 96.4, 71.7, 42.6 ns: Table 4's horizons are not exactly proportional to h); the
falling disk starts 3 h above the contact with the speed of the 1 mm fall (ballistic; --gap G
starts it G h above: the free fall leaves the disk undeformed, so any start above the dashpot onset
gives the same impact up to the phase of the time steps, and a smaller gap saves steps).
--concurrent runs the elastic and the damped run of a test at the same time (two processes).
--grains lps: state-based grains (bond_style peridem/lps plane 3d) with the onset of Jha et al.'s
code, 1.01 R_c (README.md, (c)).

Writes mesh.dat and mesh.png.
usage: run_mesh.py [--lmp PATH] [--cases 1,2,3,4] [--out DIR] [--gap G] [--concurrent]
                   [--grains bond|lps]
"""
import argparse
import os
import re
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
# test: (h mm, horizon mm, paper dt us, paper C_R(1), paper C_R(0.95))
PAPER = {1: (0.1423, 0.6, 0.2, 1.0, 0.946), 2: (0.0805, 0.375, 0.1, 1.0, 0.962),
         3: (0.062, 0.3, 0.1, 1.0, 0.968), 4: (0.0379, 0.2, 0.05, 1.0, 0.977)}
ONSET = 1.006

ap = argparse.ArgumentParser()
ap.add_argument("--lmp", default=os.path.join(here, "../../build/lmp_peridem"))
ap.add_argument("--potentials", default=os.path.join(here, "../../potentials"))
ap.add_argument("--cases", default="1,2,3,4")
ap.add_argument("--out", default="mesh_run")
ap.add_argument("--gap", type=float, default=3.0, help="starting gap in units of h (default 3)")
ap.add_argument("--concurrent", action="store_true", help="run eps_n = 1 and 0.95 at once")
ap.add_argument("--grains", choices=["bond", "lps"], default="bond",
                help="bond-based (default, onset 1.006 R_c) or state-based grains (onset 1.01 R_c)")
a = ap.parse_args()
a.lmp, a.potentials, a.out = map(os.path.abspath, (a.lmp, a.potentials, a.out))
os.makedirs(a.out, exist_ok=True)
if a.grains == "lps":
    ONSET = 1.01  # Jha et al.'s code: centres closer than R + R' + 1.01 R_c


def start(case, eps):
    h, hor = PAPER[case][0] * 1e-3, PAPER[case][1] * 1e-3
    dt = 5e-8 * (h / 0.1423e-3) ** 1.5
    log = os.path.join(a.out, "log.mesh%d_eps_%g" % (case, eps))
    cmd = [a.lmp, "-in", os.path.join(here, "in.restitution"), "-echo", "none", "-screen", "none",
           "-log", log, "-var", "eps_n", str(eps), "-var", "onset", str(ONSET), "-var", "grains", a.grains,
           "-var", "potentials", a.potentials, "-var", "h", "%.6g" % h, "-var", "horizon",
           "%.6g" % hor, "-var", "dt", "%.4g" % dt, "-var", "g0", "%.6g" % (a.gap * h)]
    return subprocess.Popen(cmd, cwd=a.out), log, dt


def result(job):
    proc, log, dt = job
    if proc.wait() != 0:
        sys.exit("lmp failed, see " + log)
    text = open(log).read()
    m = re.search(r"PERIDEM-RESTITUTION eps_n \S+ H1 (\S+) CR (\S+) steps (\d+)", text)
    if not m:
        sys.exit("no result in " + log)
    rec = re.search(r"recommended time step (\S+)", text)
    loop = re.findall(r"Loop time of (\S+) on \d+ procs for \d+ steps with (\d+) atoms", text)
    cpu = sum(float(t) for t, _ in loop)
    return float(m.group(2)), int(m.group(3)), dt, float(rec.group(1)), int(loop[-1][1]), cpu


dat = os.path.join(a.out, "mesh.dat")
with open(dat, "w") as f:
    f.write("# test h_mm horizon_mm dt_ns dt_recommended_ns atoms CR1_paper CR1_ours CR095_paper"
            " CR095_ours loop_s\n")
for case in [int(c) for c in a.cases.split(",")]:
    h, hor, pdt, p1, p95 = PAPER[case]
    if a.concurrent:
        jobs = [start(case, 1.0), start(case, 0.95)]
        (c1, n1, dt, rec, atoms, t1), (c95, n95, _, _, _, t95) = map(result, jobs)
    else:
        c1, n1, dt, rec, atoms, t1 = result(start(case, 1.0))
        c95, n95, _, _, _, t95 = result(start(case, 0.95))
    line = "%d %g %g %.3g %.3g %d %.3f %.4f %.3f %.4f %.0f" % (case, h, hor, dt * 1e9, rec * 1e9,
                                                               atoms, p1, c1, p95, c95, t1 + t95)
    print(line, flush=True)
    with open(dat, "a") as f:
        f.write(line + "\n")

PLOT = r"""
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = [list(map(float, l.split())) for l in open(sys.argv[1]) if l.strip() and l[0] != "#"]
fig, ax = plt.subplots(figsize=(5.5, 4))
ax.plot([r[1] for r in rows], [r[8] for r in rows], "s--", label="Jha et al. 2021, Table 4")
ax.plot([r[1] for r in rows], [r[9] for r in rows], "o-", label="PERIDEM (%s)" % sys.argv[3])
ax.set_xlabel("mesh size h (mm), horizon as Table 4")
ax.set_ylabel("C_R at eps_n = 0.95")
ax.invert_xaxis()
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
"""
sys.path.insert(0, here)
from plot_png import plot  # noqa: E402
plot(PLOT, dat, os.path.join(a.out, "mesh.png"), "%s, onset %g R_c" % (a.grains, ONSET))
