#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Force chains at the damage onset of in.compaction runs (Bhattacharya & Lipton 2023,
§7.4.1: grains form columns that carry the load, and damage starts in them).

    plot_chains_onset.py LABEL=DIR [LABEL=DIR ...] [--damage D] [-o chains_onset.png]

Each DIR holds one run made with -var dump yes -var chains yes: its log (log.*), the node
dumps nodes.STEP.dump and the contact dumps chains.STEP.dump. The moment is the first
broken bond (thermo c_dmg[2] > 0) or, with --damage D, the first thermo row with bulk damage
of at least D. For each run the last dump before it is drawn: grains as grey nodes, a line
between the centres of two touching grains as thick as their summed contact force
(python/peridem_post.grain_contact_loads), and in red the grains whose damage grew between
that dump and the first one at or after the moment. Printed per run: the moment, the grain
contacts, and the contact load of the grains that broke against the others' at the dump before.
"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from peridem_post import column, grain_contact_loads, read_dump, read_thermo  # noqa: E402


def dump_steps(run):
    return sorted(int(p.split(".")[-2]) for p in glob.glob(os.path.join(run, "nodes.*.dump")))


def moment(run, damage):
    """(step, phi) of the first thermo row with a broken bond (damage None) or with bulk
    damage >= damage, from the run's log."""
    logs = glob.glob(os.path.join(run, "log.*"))
    if len(logs) != 1:
        raise SystemExit(f"{run}: expected one log.* file, found {len(logs)}")
    for r in read_thermo(logs[0]):
        if (r["c_dmg[2]"] > 0) if damage is None else (r["c_dmg"] >= damage):
            return int(r["Step"]), r["c_bed"]
    raise SystemExit(f"{run}: the moment is not reached in {logs[0]}")


def grain_damage(snap):
    """Each grain's largest node damage."""
    mol, dmg = column(snap, "mol").astype(int), column(snap, "c_dmg[1]")
    return {int(g): float(dmg[mol == g].max()) for g in np.unique(mol)}


def analyse(run, damage):
    step_break, phi_break = moment(run, damage)
    steps = dump_steps(run)
    before = [s for s in steps if s < step_break]
    after = [s for s in steps if s >= step_break]
    if not before or not after:
        raise SystemExit(f"{run}: no node dump on both sides of the onset (step {step_break})")
    s0, s1 = before[-1], after[0]
    snap = read_dump(os.path.join(run, f"nodes.{s0}.dump"))[0]
    ids, mol = column(snap, "id").astype(int), column(snap, "mol").astype(int)
    x, y = column(snap, "x"), column(snap, "y")
    chains = read_dump(os.path.join(run, f"chains.{s0}.dump"))[0]
    pairs, load = grain_contact_loads(ids, mol, chains["data"])
    d0 = grain_damage(snap)
    d1 = grain_damage(read_dump(os.path.join(run, f"nodes.{s1}.dump"))[0])
    damaged = sorted(g for g in d1 if d1[g] > d0.get(g, 0.0))
    on_d = np.mean([load[g] for g in damaged])
    on_i = np.mean([v for g, v in load.items() if g not in damaged])
    # the damaged grains' rank among all grains by contact load (1 = most loaded)
    order = sorted(load, key=load.get, reverse=True)
    ranks = [order.index(g) + 1 for g in damaged]
    return dict(s0=s0, s1=s1, step_break=step_break, phi_break=phi_break, x=x, y=y, mol=mol,
                pairs=pairs, damaged=damaged, ratio=on_d / on_i if on_i > 0 else float("inf"),
                ranks=ranks, grains=len(load))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+", help="LABEL=DIR")
    ap.add_argument("--damage", type=float, default=None,
                    help="the moment: bulk damage D (default: the first broken bond)")
    ap.add_argument("-o", "--output", default="chains_onset.png")
    a = ap.parse_args()
    results = []
    for spec in a.runs:
        label, _, run = spec.partition("=")
        r = analyse(run, a.damage)
        results.append((label, r))
        print(f"{label}: the moment at step {r['step_break']} (phi {r['phi_break']:.3f}); "
              f"dump {r['s0']}: {len(r['pairs'])} grain contacts; {len(r['damaged'])} grains "
              f"broke by step {r['s1']}, their contact load {r['ratio']:.2f}x the others', "
              f"load ranks {sorted(r['ranks'])} of {r['grains']}")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(results), figsize=(3.2 * len(results), 4.6), squeeze=False)
    for ax, (label, r) in zip(axes[0], results):
        x, y, mol = r["x"] * 1e3, r["y"] * 1e3, r["mol"]
        hit = np.isin(mol, r["damaged"])
        ax.scatter(x[~hit], y[~hit], s=0.4, color="0.75", linewidths=0)
        ax.scatter(x[hit], y[hit], s=0.4, color="tab:red", linewidths=0)
        centre = {g: (x[mol == g].mean(), y[mol == g].mean()) for g in np.unique(mol)}
        fmean = np.mean(list(r["pairs"].values())) if r["pairs"] else 1.0
        for (g, h), f in r["pairs"].items():
            (x1, y1), (x2, y2) = centre[g], centre[h]
            ax.plot([x1, x2], [y1, y2], color="k", linewidth=1.2 * f / fmean,
                    solid_capstyle="round")
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        ax.set_title(f"{label}\nphi {r['phi_break']:.2f}, breaking grains in red", fontsize=8)
    axes[0][0].set_ylabel("y (mm)")
    fig.tight_layout()
    fig.savefig(a.output, dpi=130)
    print(f"wrote {a.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
