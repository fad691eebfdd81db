#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Measured stability threshold of the time step against PERIDEM's estimate.

For each case the script reads the time-step estimate that pair_style peridem/contact prints
at setup ("recommended time step R (critical C: bonds B, contact K)"), then bisects the time
step dt of the run itself: a run is unstable when it stops with PERIDEM-UNSTABLE, a LAMMPS
error (lost or missing bond atoms) or, for the restitution drop, a coefficient of restitution
outside [0, 1.05].  It starts at `--start` (0.5) x the critical estimate, multiplies dt by
`--grow` (2) until the run is unstable, then halves the bracket `--steps` times.  Prints one table row per case.

Cases (at the papers' parameters):
  bed4, bed5  Bhattacharya & Lipton's (2023) Sec. 7.3 bed (examples/bed-settling/in.bed, reduced to
              4 grains of radius 0.2-0.25 mm) with K_n eps^4 (2D default) and eps^5, run for
              0.6 ms of physical time (fall, impacts and bounces)
  bed4lps     bed4 with state-based grains (bond_style peridem/lps, M2's K and E)
  bed24, bed24e5  the whole 24-grain bed of examples/bed-settling (radii 0.4-0.7 mm), eps^4
              and eps^5 (use --time 1.5e-3: the upper rows land after 1 ms)
  rest5, rest4  Jha et al.'s (2021) two-particle drop (examples/restitution/in.restitution,
              damping centroid 0.8 100) with eps^5 (its Table 2) and eps^4

usage: bisect_dt.py [--lmp build/lmp_peridem] [--cases bed4,bed5,rest5,rest4] [--steps 5]
"""
import argparse
import math
import os
import re
import subprocess
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "../.."))
ap = argparse.ArgumentParser()
ap.add_argument("--lmp", default=os.path.join(root, "build/lmp_peridem"))
ap.add_argument("--cases", default="bed4,bed5,rest5,rest4")
ap.add_argument("--steps", type=int, default=5)
ap.add_argument("--time", type=float, default=6e-4, help="physical time of a bed run (s)")
ap.add_argument("--start", type=float, default=0.5,
                help="first dt of the bracket search, as a multiple of the critical estimate")
ap.add_argument("--grow", type=float, default=2.0, help="factor between bracket trials")
ap.add_argument("--extra", default="", help="more LAMMPS command-line words for every run, "
                "e.g. '-var rd 0' (bed: damping ratio) or '-var mu 0' (bed: friction)")
ap.add_argument("--check", type=float, default=0.0,
                help="no bisection: require a stable run at the critical estimate and an "
                     "unstable one at CHECK x it; prints PERIDEM-PASS or PERIDEM-FAIL")
a = ap.parse_args()
pot = os.path.join(root, "potentials")


def bed_args(form, dt):
    steps = int(math.ceil(a.time / dt))
    return (os.path.join(root, "examples/bed-settling"), "in.bed",
            ["-var", "nx", "2", "-var", "ny", "2", "-var", "rmin", "2e-4", "-var", "rmax",
             "2.5e-4", "-var", "chunk", "500", "-var", "kn_form", form, "-var", "maxsteps",
             str(steps)])


def bed24_args(form, dt):
    steps = int(math.ceil(a.time / dt))
    return (os.path.join(root, "examples/bed-settling"), "in.bed",
            ["-var", "chunk", "500", "-var", "kn_form", form, "-var", "maxsteps", str(steps)])


def rest_args(form, dt):
    return (os.path.join(root, "examples/restitution"), "in.restitution",
            ["-var", "eps_n", "0.8", "-var", "kn_form", form])


CASES = {
    "bed4": lambda dt: bed_args("eps4", dt),
    "bed5": lambda dt: bed_args("eps5", dt),
    "bed4lps": lambda dt: bed_args("eps4", dt) + (["-var", "bond", "peridem/lps"],),
    "bed24": lambda dt: bed24_args("eps4", dt),
    "bed24e5": lambda dt: bed24_args("eps5", dt),
    "rest5": lambda dt: rest_args("eps5", dt),
    "rest4": lambda dt: rest_args("eps4", dt),
}


def run(case, dt):
    """(stable?, estimate (recommended, critical) or None, note)"""
    folder, inp, extra, *more = CASES[case](dt)
    for words in more:
        extra = extra + words
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "log.lammps")
        cmd = [a.lmp, "-in", inp, "-var", "potentials", pot, "-var", "dt", repr(dt), "-log", log,
               "-echo", "none", "-screen", "none"] + extra + a.extra.split()
        p = subprocess.run(cmd, cwd=folder, capture_output=True, text=True)
        text = open(log).read() if os.path.exists(log) else ""
    m = re.search(r"recommended time step ([0-9.eE+-]+) \(critical ([0-9.eE+-]+)", text)
    est = (float(m.group(1)), float(m.group(2))) if m else None
    if "PERIDEM-UNSTABLE" in text.replace("print 'PERIDEM-UNSTABLE", ""):
        return False, est, "PERIDEM-UNSTABLE"
    if p.returncode != 0 or "ERROR" in text:
        err = [l for l in (text + p.stdout).splitlines() if "ERROR" in l]
        return False, est, err[0] if err else "exit %d" % p.returncode
    if case.startswith("rest"):
        rows = [l.split() for l in text.splitlines() if re.match(r"^\s+\d+\s", l)]
        cr = float(rows[-1][-1]) if rows else float("nan")
        if not (0.0 <= cr <= 1.05):
            return False, est, "C_R = %g" % cr
        return True, est, "C_R = %.4f" % cr
    return True, est, "stable"


if a.check > 0.0:
    failed = False
    for case in a.cases.split(","):
        _, est, _ = run(case, a.time / 500) if case.startswith("bed") else run(case, 5e-8)
        crit = est[1]
        for factor, want in ((1.0, True), (a.check, False)):
            ok, _, note = run(case, factor * crit)
            print("%s: dt = %.4g (%.2f x critical estimate %.4g): %s (%s)" %
                  (case, factor * crit, factor, crit, "stable" if ok else "unstable", note))
            failed |= ok != want
    print("PERIDEM-FAIL" if failed else "PERIDEM-PASS")
    raise SystemExit(1 if failed else 0)

print("| case | estimate: recommended | critical | last stable dt | first unstable dt | "
      "threshold / critical |")
print("|---|---|---|---|---|---|")
for case in a.cases.split(","):
    # the estimate does not depend on dt: read it from a short first run
    _, est, _ = run(case, a.time / 500) if case.startswith("bed") else run(case, 5e-8)
    crit = est[1]
    lo, hi = None, None
    dt = a.start * crit
    while dt < 64 * crit:
        ok, _, note = run(case, dt)
        print("  %s dt = %.4g: %s (%s)" % (case, dt, "stable" if ok else "unstable", note),
              flush=True)
        if ok:
            lo = dt
            dt *= a.grow
        else:
            hi = dt
            break
    if lo is None or hi is None:
        print("| %s | %.4g | %.4g | %s | %s | bracket not found |" % (case, est[0], crit, lo, hi))
        continue
    for _ in range(a.steps):
        mid = 0.5 * (lo + hi)
        ok, _, note = run(case, mid)
        print("  %s dt = %.4g: %s (%s)" % (case, mid, "stable" if ok else "unstable", note),
              flush=True)
        if ok:
            lo = mid
        else:
            hi = mid
    print("| %s | %.4g | %.4g | %.4g | %.4g | %.2f-%.2f |" %
          (case, est[0], crit, lo, hi, lo / crit, hi / crit), flush=True)
