#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Fig. 14 of Bhattacharya & Lipton (2023) from in.compaction runs of several shapes: bulk
damage and top-wall load against the volume fraction phi, and a table per run of the phi at
the first broken bond (damage onset), the phi where the bulk damage reaches 0.01 and 0.2, the
damage rate d(bulk damage)/d(phi) between those, and the end of the run.

    plot_shapes.py LABEL=LOG [LABEL=LOG ...] [-o shapes.png] [--time] [--csv DIR]

--csv DIR writes DIR/LABEL.txt per run (step, time, phi, bulk damage, broken bonds, top-wall
load), the curves of the README's tables.
--time plots against time instead of phi (Fig. 15a, c). Reads the thermo columns of
in.compaction (Step Time v_lid c_bed v_phi_nodes c_dmg c_dmg[2] f_box[21] ...)."""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from peridem_post import read_thermo  # noqa: E402


def first_phi(rows, key, above):
    """phi of the first row where rows[key] > above (None if never)"""
    for r in rows:
        if r[key] > above:
            return r["c_bed"]
    return None


def summary(rows):
    onset = first_phi(rows, "c_dmg[2]", 0.5)
    d1, d20 = first_phi(rows, "c_dmg", 0.01), first_phi(rows, "c_dmg", 0.2)
    rate = 0.19 / (d20 - d1) if d1 is not None and d20 is not None and d20 > d1 else None
    end = rows[-1]
    return onset, d1, d20, rate, end


def fmt(v, spec=".3f"):
    return "-" if v is None else format(v, spec)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+", help="LABEL=LOG")
    ap.add_argument("-o", "--output", default=None)
    ap.add_argument("--time", action="store_true")
    ap.add_argument("--csv", default=None)
    a = ap.parse_args()
    runs = []
    for spec in a.runs:
        label, _, path = spec.partition("=")
        runs.append((label, read_thermo(path)))
    print("| run | phi at start | first broken bond at phi | bulk damage 0.01 at phi | 0.2 at phi "
          "| d(damage)/d(phi), 0.01 to 0.2 | end: phi, bulk damage, broken bonds, top-wall load "
          "(N/m) |")
    print("|---|---|---|---|---|---|---|")
    for label, rows in runs:
        onset, d1, d20, rate, end = summary(rows)
        print(f"| {label} | {rows[0]['c_bed']:.3f} | {fmt(onset)} | {fmt(d1)} | {fmt(d20)} | "
              f"{fmt(rate, '.2f')} | {end['c_bed']:.3f}, {end['c_dmg']:.3f}, "
              f"{int(end['c_dmg[2]'])}, {end['f_box[21]']:.4g} |")
    if a.csv:
        os.makedirs(a.csv, exist_ok=True)
        for label, rows in runs:
            with open(os.path.join(a.csv, label + ".txt"), "w") as out:
                out.write("# step time(s) phi bulk_damage broken_bonds top_wall_load(N/m)\n")
                for r in rows:
                    out.write(f"{int(r['Step'])} {r['Time']:.6g} {r['c_bed']:.6g} "
                              f"{r['c_dmg']:.6g} {int(r['c_dmg[2]'])} {r['f_box[21]']:.6g}\n")
    if not a.output:
        return 0
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    xkey, xlabel = ("Time", "time (ms)") if a.time else ("c_bed", "volume fraction phi")
    scale = 1e3 if a.time else 1.0
    shape_colours = {"perturbed_disk": "C0", "square": "C1", "plus": "C2", "ring": "C3"}
    named = [next((s for s in shape_colours if s in label), None) for label, _ in runs]
    by_shape = len(set(named)) == len(named) or None not in named and len(set(named)) > 1
    for k, (label, rows) in enumerate(runs):
        x = [r[xkey] * scale for r in rows]
        # one colour per shape named in the label, dashed for the authors' bond constants
        colour = next((c for s, c in shape_colours.items() if s in label), f"C{4 + k % 6}")
        style = dict(color=colour, linestyle="--" if label.startswith("authors") else "-")
        if not by_shape:  # a series of one shape (e.g. rings of several thinnesses)
            style = {"color": f"C{k % 10}"}
        ax1.plot(x, [r["c_dmg"] for r in rows], label=label, **style)
        ax2.plot(x, [r["f_box[21]"] for r in rows], label=label, **style)
    ax1.set_xlabel(xlabel)
    ax1.set_ylabel("bulk damage")
    ax2.set_xlabel(xlabel)
    ax2.set_ylabel("top wall load (N/m)")
    ax1.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)
    print(f"wrote {a.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
