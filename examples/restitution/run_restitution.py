#!/usr/bin/env python3
"""Coefficient of restitution vs the damping parameter eps_n (PeriDEM seed §4.1, Table 2).

Runs in.restitution for eps_n = 1, 0.95, 0.9, 0.85, 0.8 (damping centroid, C = 100),
writes restitution.dat (eps_n, seed C_R, ours) and restitution.png (if matplotlib is
installed), and checks the trend when --check is given (exit 1 on failure):
  C_R(1) within 1% of 1, C_R strictly decreasing with eps_n, and each C_R within
  --tol of the reference values recorded below (this code, h = 0.1423 mm, dt = 5e-8 s).

usage: run_restitution.py [--lmp PATH] [--np N] [--potentials DIR] [--check] [--tol T]
                          [-- extra lmp arguments, e.g. -var dt 2.5e-8]
"""
import argparse
import os
import re
import subprocess
import sys

EPS = [1.0, 0.95, 0.9, 0.85, 0.8]
SEED = [1.0, 0.946, 0.893, 0.845, 0.796]      # Table 2 of the seed
OURS_REF = [0.9979, 0.9760, 0.9630, 0.9423, 0.9278]  # recorded, see README.md

here = os.path.dirname(os.path.abspath(__file__))
ap = argparse.ArgumentParser()
ap.add_argument("--lmp", default=os.path.join(here, "../../build/lmp_peridem"))
ap.add_argument("--np", type=int, default=1)
ap.add_argument("--potentials", default=os.path.join(here, "../../potentials"))
ap.add_argument("--out", default=".")
ap.add_argument("--check", action="store_true")
ap.add_argument("--tol", type=float, default=0.01)
ap.add_argument("extra", nargs="*")
a = ap.parse_args()

os.makedirs(a.out, exist_ok=True)
ours = []
for e in EPS:
    cmd = ([] if a.np == 1 else ["mpirun", "-np", str(a.np)]) + [
        a.lmp, "-in", os.path.join(here, "in.restitution"), "-echo", "none", "-screen", "none",
        "-log", os.path.join(a.out, "log.eps_%g" % e), "-var", "eps_n", str(e),
        "-var", "potentials", a.potentials] + a.extra
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    subprocess.run(cmd, check=True, env=env, cwd=here if a.out == "." else a.out)
    text = open(os.path.join(a.out, "log.eps_%g" % e)).read()
    m = re.search(r"PERIDEM-RESTITUTION eps_n \S+ H1 (\S+) CR (\S+) steps (\d+)", text)
    if not m:
        sys.exit("no result in log.eps_%g" % e)
    ours.append(float(m.group(2)))
    print("eps_n %-5g seed C_R %.3f  ours %.4f" % (e, SEED[len(ours) - 1], ours[-1]), flush=True)

with open(os.path.join(a.out, "restitution.dat"), "w") as f:
    f.write("# eps_n  C_R(seed Table 2)  C_R(PERIDEM, damping centroid C=100)\n")
    for e, s, o in zip(EPS, SEED, ours):
        f.write("%-6g %8.3f %10.4f\n" % (e, s, o))

PLOT = r"""
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = [list(map(float, l.split())) for l in open(sys.argv[1]) if l.strip() and l[0] != "#"]
eps, seed, ours = zip(*rows)
fig, ax = plt.subplots(figsize=(5, 4))
ax.plot(eps, seed, "s--", label="PeriDEM seed, Table 2")
ax.plot(eps, ours, "o-", label="PERIDEM, damping centroid (C = 100)")
ax.plot(eps, eps, ":", color="gray", label="C_R = eps_n")
ax.set_xlabel("damping parameter eps_n")
ax.set_ylabel("coefficient of restitution C_R")
ax.invert_xaxis()
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
"""
# matplotlib of this python, else Debian's (python3-matplotlib)
dat, png = os.path.join(a.out, "restitution.dat"), os.path.join(a.out, "restitution.png")
for py in [sys.executable, "/usr/bin/python3"]:
    if os.path.exists(py) and subprocess.run([py, "-c", PLOT, dat, png],
                                             stderr=subprocess.DEVNULL).returncode == 0:
        print("wrote " + png)
        break
else:
    print("matplotlib not installed: no restitution.png")

if a.check:
    bad = []
    if abs(ours[0] - 1.0) > 0.01:
        bad.append("C_R(1) = %g not within 1%% of 1" % ours[0])
    for k in range(1, len(EPS)):
        if not ours[k] < ours[k - 1]:
            bad.append("C_R does not decrease from eps_n %g to %g" % (EPS[k - 1], EPS[k]))
    for e, o, r in zip(EPS, ours, OURS_REF):
        if abs(o - r) > a.tol:
            bad.append("C_R(%g) = %g differs from the recorded %g by more than %g" % (e, o, r, a.tol))
    for e, o, s in zip(EPS, ours, SEED):
        if o < s - a.tol:
            bad.append("C_R(%g) = %g damps more than the seed's %g" % (e, o, s))
    if bad:
        print("PERIDEM-FAIL " + "; ".join(bad))
        sys.exit(1)
    print("PERIDEM-PASS restitution trend")
