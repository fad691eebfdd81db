#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Checks of the rigid-grain recipe (ctest rigid_grains_*; README.md says why each bound).

    check_rigid.py CASE --lmp LMP [--out DIR] [--np N]

CASE:
  drop   in.rigid_drop (rigid square on a rigid floor of nodes, no damping) at dt = 1e-3 and
         5e-4, and on a fix peridem/wall floor at 1e-3: the square lands (contact energy
         > 0.1 of the drop's 0.31) and bounces (its centre rises again by > 0.05); total
         energy (KE + gravity + contact) within TOL[dt] of its start, relative to the
         largest kinetic energy (1e-4 at 1e-3, 2.5e-5 at 5e-4), and the error at 5e-4 at
         most 1/3 of that at 1e-3 (the integrator's dt^2).
  crush  in.rigid_crush: the breakable disk is damaged (bulk damage > 0.1, broken bonds
         > 50 of 740), the rigid square slowed down, and its nodes' distances at the last
         step equal those at the first to 1e-12 relative (round-off).
  ranks  in.rigid_drop on 1 and --np ranks: the square's centre agrees at every output to
         1e-10 (the two differ by the order of sums only: measured 1.3e-14).
Prints PERIDEM-PASS or PERIDEM-FAIL.
"""
import argparse
import itertools
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MPIRUN = os.path.join(HERE, "..", "..", "unittest", "scripts", "mpirun.sh")


def run(args, lmp, out, np_, inp, extra, tag):
    os.makedirs(out, exist_ok=True)
    shutil.copy(os.path.join(HERE, inp), out)
    log = f"log.{tag}"
    cmd = [MPIRUN, str(np_), lmp, "-in", inp, "-log", log, "-screen", "none", "-echo", "none"] + extra
    res = subprocess.run(cmd, cwd=out)
    if res.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited with {res.returncode} (see {out}/{log})")
    return thermo(os.path.join(out, log))


def thermo(path):
    """The rows of the last thermo block of a log, as dicts by column name."""
    rows, names = [], None
    with open(path) as f:
        for line in f:
            p = line.split()
            if p and p[0] == "Step":
                names, rows = p, []
                continue
            if names:
                try:
                    vals = [float(x) for x in p]
                except ValueError:
                    names = None if rows else names
                    continue
                if len(vals) == len(names):
                    rows.append(dict(zip(names, vals)))
    return rows


def read_frames(path):
    """{step: {id: (x, y)}} of a dump custom with columns id x y."""
    frames, lines = {}, open(path).read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step, n = int(lines[i + 1]), int(lines[i + 3])
            rows = [lines[i + 9 + k].split() for k in range(n)]
            frames[step] = {int(r[0]): (float(r[1]), float(r[2])) for r in rows}
            i += 9 + n
        else:
            i += 1
    return frames


def fail(msgs):
    for m in msgs:
        print("PERIDEM-FAIL:", m)
    return 1


def case_drop(a):
    bad = []
    tol = {"1e-3": 1e-4, "5e-4": 2.5e-5}
    err = {}
    for dt, steps, floor in (("1e-3", 3000, "nodes"), ("5e-4", 6000, "nodes"), ("1e-3", 3000, "wall")):
        rows = run(a, a.lmp, a.out, 1, "in.rigid_drop",
                   ["-var", "dt", dt, "-var", "steps", str(steps), "-var", "every", str(int(10e-3 / float(dt))),
                    "-var", "floor", floor], f"drop_{floor}_{dt}")
        e = [r["v_etot"] for r in rows]
        ke = max(r["KinEng"] for r in rows)
        de = max(abs(x - e[0]) for x in e) / ke
        y = [r["c_com[2]"] for r in rows]
        k = next(i for i in range(1, len(y) - 1) if y[i] < y[i - 1] and y[i] <= y[i + 1])
        ylow = y[k]  # the first landing
        rise = max(y[k:]) - ylow
        # the contact energy: evdwl for the nodes' floor, the wall's energy (in pe) for the wall
        econt = max(r["E_vdwl"] for r in rows) if floor == "nodes" else None
        print(f"drop floor {floor} dt {dt}: {len(rows)} outputs, max |E - E0| / KE_max = {de:.3e} "
              f"(bound {tol[dt]:.1e}), KE_max {ke:.4f}, centre at the first landing {ylow:.4f}, rise after {rise:.4f}"
              + (f", contact energy max {econt:.4f}" if econt is not None else ""))
        if de > tol[dt]:
            bad.append(f"drop {floor} dt {dt}: energy error {de:.3e} > {tol[dt]:.1e}")
        if rise < 0.05:
            bad.append(f"drop {floor} dt {dt}: the square did not bounce (rise {rise:.4f})")
        if econt is not None and econt < 0.1:
            bad.append(f"drop {floor} dt {dt}: contact energy {econt:.4f} < 0.1: no landing")
        if floor == "nodes":
            err[dt] = de
    ratio = err["1e-3"] / err["5e-4"]
    print(f"drop: energy error ratio dt 1e-3 / 5e-4 = {ratio:.2f} (>= 3 required)")
    if ratio < 3:
        bad.append(f"energy error does not shrink with dt: ratio {ratio:.2f} < 3")
    return bad


def case_crush(a):
    bad = []
    rows = run(a, a.lmp, a.out, a.np, "in.rigid_crush", [], f"crush_np{a.np}")
    first, last = rows[0], rows[-1]
    print(f"crush np {a.np}: bulk damage {last['c_dmg']:.4f}, broken {last['c_dmg[2]']:.0f} of "
          f"{last['c_dmg[3]']:.0f} bonds, square centre {first['c_csq[2]']:.4f} -> {last['c_csq[2]']:.4f}")
    if last["c_dmg"] <= 0.1 or last["c_dmg[2]"] <= 50:
        bad.append(f"the breakable disk is not damaged (damage {last['c_dmg']}, broken {last['c_dmg[2]']})")
    frames = read_frames(os.path.join(a.out, "dump.square"))
    steps = sorted(frames)
    f0, f1 = frames[steps[0]], frames[steps[-1]]
    ids = sorted(f0)
    worst, size = 0.0, 0.0
    for i, j in itertools.combinations(ids, 2):
        d0 = ((f0[i][0] - f0[j][0]) ** 2 + (f0[i][1] - f0[j][1]) ** 2) ** 0.5
        d1 = ((f1[i][0] - f1[j][0]) ** 2 + (f1[i][1] - f1[j][1]) ** 2) ** 0.5
        worst, size = max(worst, abs(d1 - d0)), max(size, d0)
    moved = ((f1[ids[0]][0] - f0[ids[0]][0]) ** 2 + (f1[ids[0]][1] - f0[ids[0]][1]) ** 2) ** 0.5
    print(f"crush np {a.np}: {len(ids)} rigid nodes, steps {steps[0]} -> {steps[-1]}, node moved {moved:.4f}, "
          f"largest change of a node distance {worst:.3e} (size {size:.4f}; bound 1e-12 x size)")
    if len(steps) < 2 or moved < 0.1:
        bad.append("the rigid square did not move")
    if worst > 1e-12 * size:
        bad.append(f"the rigid square deformed: a node distance changed by {worst:.3e}")
    return bad


def case_ranks(a):
    bad = []
    runs = [run(a, a.lmp, os.path.join(a.out, f"np{n}"), n, "in.rigid_drop", ["-var", "every", "10"],
                f"drop_np{n}") for n in (1, a.np)]
    if len(runs[0]) != len(runs[1]) or len(runs[0]) < 2:
        return [f"different thermo output lengths {len(runs[0])} and {len(runs[1])}"]
    worst = max(max(abs(r1["c_com[1]"] - r2["c_com[1]"]), abs(r1["c_com[2]"] - r2["c_com[2]"]),
                    abs(r1["v_etot"] - r2["v_etot"])) for r1, r2 in zip(*runs))
    print(f"ranks 1 vs {a.np}: {len(runs[0])} outputs, largest difference of the centre or the "
          f"energy {worst:.3e} (bound 1e-10)")
    if worst > 1e-10:
        bad.append(f"1 and {a.np} ranks differ by {worst:.3e}")
    return bad


def main():
    p = argparse.ArgumentParser()
    p.add_argument("case", choices=["drop", "crush", "ranks"])
    p.add_argument("--lmp", required=True)
    p.add_argument("--out", default="rigid_check")
    p.add_argument("--np", type=int, default=1)
    a = p.parse_args()
    a.lmp, a.out = os.path.abspath(a.lmp), os.path.abspath(a.out)
    if a.case == "ranks" and a.np < 2:
        a.np = 2
    shutil.rmtree(a.out, ignore_errors=True)
    bad = {"drop": case_drop, "crush": case_crush, "ranks": case_ranks}[a.case](a)
    if bad:
        return fail(bad)
    print(f"PERIDEM-PASS rigid grains {a.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
