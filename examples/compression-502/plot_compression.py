#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Figures and the table of README.md from a full run of in.compression.

    plot_compression.py [--dir RUN] [--tag c502] [--W 68.5e-3] [--dt 1e-7]
                        [--out .] [--match time|penetration] [--dump 20000]

Reads RUN/TAG_compress_load.*.txt (fix avg of in.compression: one file per leg,
averages over 5000 steps) and the node dumps RUN/TAG_nodes.STEP.dump, and writes
  compression_force.png   force per unit area on the top wall against its
                          penetration, beside Jha et al.'s (2021) Fig. 23a;
  compression_damage.png  nodes coloured by damage at the paper's four times;
(--match penetration: at the paper's penetrations at those times instead, for a run whose
wall started elsewhere, e.g. -var top_gap; the node dump nearest to each, every --dump steps)
and prints the table of README.md (penetration, force, bulk damage, damaged grains
at the four times) and, for each TAG_state.STEP.dump / TAG_contacts.STEP.dump pair
that in.fragments wrote from a restart file, the contact load (sum of |f| over a
grain's contacts with other grains) of the damaged grains against the intact ones. Penetration is counted from the first wall position at which
the averaged load exceeds ONSET (1 kPa, about 1 % of the paper's plateau), as the
paper's curve starts where the wall meets the bed.
"""
import argparse
import glob
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from peridem_post import column, grain_contact_loads, read_dump  # noqa: E402

ONSET = 1e3  # Pa
TIMES = (0.102, 0.118, 0.126, 0.134)  # s: the paper's t1-t4 (§4.4, Fig. 23)
# Jha et al. 2021, Fig. 23a (the authors' assets/compressive_test_reaction_force_n500.jpg,
# 900 us interval), read by eye: penetration (mm), force per unit area (kPa)
PAPER = np.array([[0.0, 0.0], [0.3, 0.3], [0.5, 2.0], [0.6, 5.0], [0.7, 10.0], [0.8, 17.0],
                  [0.85, 20.5], [0.9, 20.0], [1.0, 27.0], [1.1, 32.0], [1.2, 37.0],
                  [1.3, 42.0], [1.45, 55.0], [1.55, 60.0], [1.65, 68.0], [1.8, 78.0],
                  [1.9, 77.0], [1.95, 75.0], [2.1, 80.0], [2.25, 85.0], [2.4, 87.0],
                  [2.6, 87.0], [2.8, 90.0], [3.0, 92.0], [3.1, 85.0], [3.4, 86.0]])
PAPER_TIMES = np.array([[0.53, 3.0], [1.45, 57.0], [1.95, 76.0], [2.43, 87.0]])


def load_curve(run, tag):
    rows = []
    for path in glob.glob(os.path.join(run, f"{tag}_compress_load.*.txt")):
        rows.append(np.loadtxt(path, ndmin=2))
    if not rows:
        raise SystemExit(f"no {tag}_compress_load.*.txt in {run}")
    d = np.concatenate(rows)
    d = d[np.argsort(d[:, 0], kind="stable")]
    keep = np.concatenate([[True], np.diff(d[:, 0]) > 0])  # a resumed leg repeats no step
    return d[keep]


def force_chains(run, tag):
    """Per restart step: damaged grains' mean contact load against the intact grains'."""
    out = []
    for path in sorted(glob.glob(os.path.join(run, f"{tag}_state.*.dump"))):
        step = int(path.split(".")[-2])
        contacts = os.path.join(run, f"{tag}_contacts.{step}.dump")
        if not os.path.exists(contacts):
            continue
        snap = read_dump(path)[0]
        ids, mol = column(snap, "id").astype(int), column(snap, "mol").astype(int)
        dmg = column(snap, "c_dmg[1]")
        grains = np.unique(mol)
        c = read_dump(contacts)[0]
        _, load = grain_contact_loads(ids, mol, c["data"])
        damaged = set(mol[dmg > 0].tolist())
        on_d = [load[g] for g in grains if g in damaged]
        on_i = [load[g] for g in grains if g not in damaged]
        if on_d and on_i and np.mean(on_i) > 0:
            out.append((step, len(on_d), len(grains), np.mean(on_d), np.mean(on_i)))
    return out


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--dir", default=".")
    p.add_argument("--tag", default="c502")
    p.add_argument("--W", type=float, default=68.5e-3)
    p.add_argument("--dt", type=float, default=1e-7)
    p.add_argument("--out", default=".")
    p.add_argument("--match", choices=("time", "penetration"), default="time")
    p.add_argument("--dump", type=int, default=20000)
    a = p.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    d = load_curve(a.dir, a.tag)
    step, load, ywall, bulk = d[:, 0], d[:, 1], d[:, 3], d[:, 4]
    stress = load / a.W
    onset = bool(np.any(stress > ONSET))
    k_on = int(np.argmax(stress > ONSET)) if onset else 0
    y_on = ywall[k_on]  # without an onset: the wall's start
    pen = (y_on - ywall) * 1e3  # mm
    t = step * a.dt

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(pen, stress / 1e3, lw=1.2, label="PERIDEM (500 us averages)")
    ax.plot(PAPER[:, 0], PAPER[:, 1], "k--", lw=1.2, label="Jha et al. 2021, Fig. 23a (by eye)")
    ax.plot(PAPER_TIMES[:, 0], PAPER_TIMES[:, 1], "ko", mfc="none")
    rows = []
    for i, ti in enumerate(TIMES):
        if a.match == "time":
            k = int(np.argmin(abs(t - ti)))
            si = int(round(ti / a.dt))
        else:  # the paper's penetration at t_i, and the node dump nearest to it
            k = int(np.argmin(abs(pen - PAPER_TIMES[i][0]) + 1e9 * (np.arange(len(pen)) < k_on)))
            si = int(round(step[k] / a.dump)) * a.dump
            k = int(np.argmin(abs(step - si)))
            ti = si * a.dt
        ax.plot(pen[k], stress[k] / 1e3, "o", color="C3")
        ax.annotate(f"t{i + 1}", (pen[k], stress[k] / 1e3), textcoords="offset points",
                    xytext=(-14, 4))
        rows.append((ti, pen[k], stress[k], bulk[k], si))
    ax.set_xlim(left=-0.2)
    ax.set_xlabel("wall penetration (mm)" if onset else
                  f"wall displacement from its start at {y_on * 1e3:.2f} mm (no onset)")
    ax.set_ylabel("force per unit area on the top wall (kPa)")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "compression_force.png"), dpi=120)
    plt.close(fig)

    fig, axes = plt.subplots(2, 2, figsize=(10, 4.6))
    print("| time | penetration (mm) | force per unit area (kPa) | paper (mm, kPa) | bulk damage |"
          " grains with a broken bond | grains with damage > 0.1 |")
    print("|---|---|---|---|---|---|---|")
    for i, (ti, pk, sk, bk, si) in enumerate(rows):
        path = os.path.join(a.dir, f"{a.tag}_nodes.{si}.dump")
        ax = axes.flat[i]
        if not os.path.exists(path):
            ax.set_title(f"t{i + 1} = {ti:.4g} s: no dump")
            print(f"| t{i + 1} = {ti:.4g} s | {pk:.2f} | {sk / 1e3:.1f} | {PAPER_TIMES[i][0]}, "
                  f"{PAPER_TIMES[i][1]:.0f} | {bk:.4f} | (no dump) | |")
            continue
        snap = read_dump(path)[0]
        x, y, mol = column(snap, "x"), column(snap, "y"), column(snap, "mol").astype(int)
        dmg = column(snap, "c_dmg[1]")
        grains = np.unique(mol)
        gmean = np.array([dmg[mol == g].mean() for g in grains])
        gany = np.array([dmg[mol == g].max() > 0 for g in grains])
        ax.scatter(x * 1e3, y * 1e3, c=dmg, cmap="jet", vmin=0, vmax=0.5, s=0.8, lw=0)
        ax.set_aspect("equal")
        ax.set_title(f"t{i + 1} = {ti:.4g} s, penetration {pk:.2f} mm", fontsize=9)
        ax.set_xticks([])
        ax.set_yticks([])
        print(f"| t{i + 1} = {ti:.4g} s | {pk:.2f} | {sk / 1e3:.1f} | {PAPER_TIMES[i][0]}, "
              f"{PAPER_TIMES[i][1]:.0f} | {bk:.4f} | {int(gany.sum())} of {len(grains)} | "
              f"{int((gmean > 0.1).sum())} |")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "compression_damage.png"), dpi=80)
    plt.close(fig)
    kmax = int(np.argmax(stress))
    print((f"onset (averaged load > {ONSET / 1e3:.0f} kPa) at t = {t[k_on]:.4f} s, wall at "
           if onset else f"no onset (averaged load > {ONSET / 1e3:.0f} kPa): penetration "
           f"counted from the wall's start, t = {t[k_on]:.4f} s, at ") +
          f"{y_on * 1e3:.2f} mm; peak {stress[kmax] / 1e3:.1f} kPa at penetration "
          f"{pen[kmax]:.2f} mm; end: t = {t[-1]:.4f} s, penetration {pen[-1]:.2f} mm, "
          f"{stress[-1] / 1e3:.1f} kPa, bulk damage {bulk[-1]:.4f}")
    for step, nd, ng, ld, li in force_chains(a.dir, a.tag):
        print(f"step {step} (t = {step * a.dt:.3f} s): {nd} of {ng} grains damaged; their mean "
              f"contact load {ld:.4g} N/m, {ld / li:.2f} x the intact grains' {li:.4g} N/m")
    return 0


if __name__ == "__main__":
    sys.exit(main())
