#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""The reduced compressive test (ctest compression_reduced): in.compression's two
stages on a 12 mm x 10 mm container (19 grains, h = 0.25 mm, eps = 3h, 863 nodes),
then checks of the physics Jha et al. (2021, §4.4) describe for the full bed.

    check_reduced.py --lmp LMP [--potentials DIR] [--out DIR] [--np N]

Reductions (README.md): the dashpot between grain centres acts while two nodes are
closer than R_c (-var onset node, eq. 27 as written: the full example takes the onset of
the authors' code, with which the 1-rank reduced bed broke 4 bonds in 15 ms); the bed settles under g = 1000 m/s^2 with a viscous drag
(stage settle only) so that it is at rest after 15 ms, and is compressed under the
same gravity (it stays at rest); the top wall starts 0.1 mm above the highest node
and moves at 0.1 m/s (the paper's 0.06 m/s) for 15 ms. Checks, from the wall loads
averaged over 1000 steps (fix ave/time file), the node dumps and the contact-force
dumps (compute pair/local):
  1. nothing is lost: nodes, bonds and grains are the same at the end of settling
     and at the start of compression;
  2. until damage spreads (10 broken bonds), the top wall's load rises linearly
     with its penetration (least-squares line over the loading branch: back from
     there while the load stays above 10 % and the preceding load is not above 1.5
     times the next (a frictionless bed rearranges and a new branch starts); R^2 >=
     0.9, slope > 0), and the floor carries the same load plus the bed's weight
     (quasi-static: within 10 % over that window);
  3. damage starts in the grains on force chains: at the first node dump with 3
     damaged grains, their contact load (sum of |f| over their contacts with other
     grains, averaged over the 8 contact-force dumps up to it) is at least 1.5 times
     the intact grains' mean;
  4. damage then grows: the broken-bond count never decreases and reaches 10.
A bed of 19 frictionless grains rearranges: trajectories differ between 1 and 2
ranks (round-off), so the thresholds hold with margin on both (README.md).
Prints PERIDEM-PASS or PERIDEM-FAIL.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from peridem_post import column, grain_contact_loads, read_dump  # noqa: E402

COMMON = ["-var", "W", "12e-3", "-var", "H", "10e-3", "-var", "h", "0.25e-3",
          "-var", "horizon", "0.75e-3", "-var", "every", "0", "-var", "tag", "red",
          "-var", "t_settle", "0.015", "-var", "onset", "node"]
SETTLE = ["-var", "stage", "settle", "-var", "g", "1000", "-var", "drag", "0.05",
          "-var", "thermo", "10000"]
EVERY = 1000  # steps between node and contact-force dumps
ONSET = 10  # broken bonds that end the elastic rise (0.13 % of the bed's 7904)
DAMAGED, WINDOW = 3, 8  # check 3: at the first dump with 3 damaged grains, 8 dumps back
COMPRESS = ["-var", "stage", "compress", "-var", "g", "1000", "-var", "top_gap", "1e-4",
            "-var", "v0", "0.1",
            "-var", "t_end", "0.03", "-var", "thermo", "1000", "-var", "dump", str(EVERY),
            "-var", "chains", str(EVERY)]
SETUP = re.compile(r"PERIDEM-SETUP stage (\w+) (\d+) nodes (\d+) bonds .* mass (\S+) kg/m g (\S+) ")
DONE = re.compile(r"PERIDEM-DONE stage (\w+) step (\d+) .* bulk damage (\S+) broken (\d+)")


def run(cmd, out, log):
    res = subprocess.run(cmd + ["-log", log, "-screen", "none"], cwd=out)
    if res.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited with {res.returncode} (see {out}/{log})")
    with open(os.path.join(out, log)) as f:
        return f.read()


def grains_of(path):
    snap = read_dump(path)[0]
    ids, mol = column(snap, "id").astype(int), column(snap, "mol").astype(int)
    return dict(zip(ids, mol))


def contact_loads(path, grain_of):
    """Sum of |f| over the contact pairs of different grains, per grain."""
    rows = read_dump(path)[0]["data"]
    return grain_contact_loads(list(grain_of), list(grain_of.values()), rows)[1]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--lmp", required=True)
    p.add_argument("--potentials", default=os.path.join(HERE, "..", "..", "potentials"))
    p.add_argument("--out", default="compression_reduced")
    p.add_argument("--np", type=int, default=1)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    shutil.copy(os.path.join(HERE, "in.compression"), a.out)
    lmp = [os.path.abspath(a.lmp)]
    if a.np > 1:
        # the test suite's launcher (root, oversubscription and the MPI environment)
        lmp = [os.path.join(HERE, "..", "..", "unittest", "scripts", "mpirun.sh"), str(a.np)] + lmp
    base = lmp + ["-in", "in.compression", "-var", "potentials",
                  os.path.abspath(a.potentials)] + COMMON
    fails = []

    log_s = run(base + SETTLE, a.out, "log.settle")
    log_c = run(base + COMPRESS, a.out, "log.compress")
    done_s, setup_c = DONE.search(log_s), SETUP.search(log_c)
    setup_s, done_c = SETUP.search(log_s), DONE.search(log_c)
    if not (done_s and setup_c and setup_s and done_c):
        print("PERIDEM-FAIL: a PERIDEM-SETUP or PERIDEM-DONE line is missing")
        return 1
    # 1. nothing lost between the stages (and no bond broken while settling)
    n_s, b_s = int(setup_s.group(2)), int(setup_s.group(3))
    n_c, b_c = int(setup_c.group(2)), int(setup_c.group(3))
    step0 = int(done_s.group(2))
    grain_of = grains_of(os.path.join(a.out, f"red_nodes.{step0}.dump"))
    n_grains = len(set(grain_of.values()))
    print(f"settle: {n_s} nodes, {b_s} bonds, {done_s.group(4)} broken; compress starts with "
          f"{n_c} nodes, {b_c} bonds, {n_grains} grains")
    if (n_s, b_s) != (n_c, b_c) or int(done_s.group(4)) != 0 or n_grains < 10:
        fails.append("nodes, bonds or grains changed between the stages")

    # 2. linear rise until damage spreads; the floor carries the same load
    d = np.loadtxt(os.path.join(a.out, f"red_compress_load.{step0}.txt"))
    top, floor, ywall, broken = d[:, 1], d[:, 2], d[:, 3], d[:, 5]
    # the elastic rise lasts until damage spreads: ONSET broken bonds (a single bond at a
    # contact can break well before, while the load keeps rising)
    k_break = int(np.argmax(broken >= ONSET))
    if broken[k_break] < ONSET:
        fails.append("no bond broke")
        k_break = len(d) - 1
    p_break = top[k_break - 1]
    # the loading branch up to there: back from it while the load is above 10 % of the
    # load at the onset and not above 1.5 x the load after it (a frictionless bed
    # rearranges: the load drops when a chain gives way, and a new branch starts)
    k0 = k_break - 1
    while k0 > 0 and 0.1 * p_break <= top[k0 - 1] <= 1.5 * top[k0]:
        k0 -= 1
    pen = ywall[0] - ywall[k0:k_break]
    slope, icpt = np.polyfit(pen, top[k0:k_break], 1)
    fit = slope * pen + icpt
    r2 = 1 - np.sum((top[k0:k_break] - fit) ** 2) / np.sum((top[k0:k_break] - top[k0:k_break].mean()) ** 2)
    # the floor carries the top wall's load and the bed's weight
    weight = float(setup_c.group(4)) * float(setup_c.group(5))
    balance = abs((floor[k0:k_break] - weight).sum() / top[k0:k_break].sum() - 1)
    print(f"before {ONSET} bonds broke (wall at {ywall[k_break]:.5g} m, load {p_break:.4g} N/m): "
          f"{k_break - k0} averages, slope {slope:.4g} N/m^2, R^2 = {r2:.4f}; (floor - weight)/top - 1 = "
          f"{balance:.3f} (weight {weight:.4g} N/m subtracted)")
    if k_break - k0 < 4 or r2 < 0.9 or slope <= 0:
        fails.append(f"the load before {ONSET} bonds broke does not rise linearly")
    if balance > 0.1:
        fails.append("the floor and the top wall carry different loads")

    # 3. the first damaged grains are on force chains
    steps = sorted(int(f.split(".")[1]) for f in os.listdir(a.out)
                   if f.startswith("red_nodes.") and f.endswith(".dump"))
    first_damaged, damaged = None, []
    for s in steps:
        snap = read_dump(os.path.join(a.out, f"red_nodes.{s}.dump"))[0]
        mol, dmg = column(snap, "mol").astype(int), column(snap, "c_dmg[1]")
        damaged = sorted(set(mol[dmg > 0]))
        if len(damaged) >= DAMAGED:
            first_damaged = s
            break
    if first_damaged is None:
        fails.append(f"fewer than {DAMAGED} damaged grains in the dumps")
    else:
        window = [s for s in steps if s <= first_damaged][-WINDOW:]
        mean_load = {g: 0.0 for g in set(grain_of.values())}
        for s in window:
            for g, v in contact_loads(os.path.join(a.out, f"red_chains.{s}.dump"),
                                      grain_of).items():
                mean_load[g] += v / len(window)
        on_damaged = np.array([mean_load[g] for g in damaged])
        on_intact = np.array([v for g, v in mean_load.items() if g not in damaged])
        ratio = on_damaged.mean() / on_intact.mean() if on_intact.mean() > 0 else 0
        print(f"step {first_damaged}: grains {damaged} damaged; their contact load (mean over "
              f"steps {window[0]}-{window[-1]}) {on_damaged.mean():.4g} N/m, {ratio:.2f} x the "
              f"{len(on_intact)} intact grains' {on_intact.mean():.4g} N/m")
        if ratio < 1.5:
            fails.append("the first damaged grains do not carry the larger contact loads")

    # 4. damage grows
    damage_end = float(done_c.group(3))
    print(f"end: bulk damage {damage_end:.4g}, {done_c.group(4)} broken bonds")
    if np.any(np.diff(broken) < 0) or int(done_c.group(4)) < 10:
        fails.append("damage did not grow")

    if fails:
        print("PERIDEM-FAIL: " + "; ".join(fails))
        return 1
    print("PERIDEM-PASS: nothing lost between the stages, linear elastic rise before the "
          "damage spreads, damage starts on the force chains and grows")
    return 0


if __name__ == "__main__":
    sys.exit(main())
