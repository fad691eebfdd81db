#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Post-processing of PERIDEM runs (numpy; matplotlib for the plots).

Reads LAMMPS text dumps (``dump custom`` and ``dump local``) and
``fix ave/time`` files, and does what is naturally done after a run:

* ``crack_angle``: the path and angle of a crack from a damage field
  (e.g. ``c_dmg[1]`` of compute peridem/damage in a dump): the principal
  axis of the damaged nodes, weighted by their damage (Bhattacharya & Lipton 2023,
  §6.2 compares crack paths);
* ``plot_vs_volume_fraction``: bulk damage and wall force against the
  volume fraction (Bhattacharya & Lipton 2023, §7.4, Fig. 14), from a fix ave/time
  file of ``c_bed[6]``, ``c_dmg`` and a wall force;
* ``snapshot``: the nodes coloured by damage or by fragment ID;
* ``grain_contact_loads``: from a node dump and a ``dump local`` of node-pair
  contact forces (compute pair/local), the force summed over each pair of
  touching grains (the force-chain network) and each grain's contact load.

Command line::

    peridem_post.py crack DUMP [--column c_dmg[1]] [--threshold 0.5]
    peridem_post.py snapshot DUMP --color c_frag [-o snapshot.png]
    peridem_post.py phi AVE_TIME_FILE --phi N --damage N --force N [-o phi.png]

(columns of the fix ave/time file counted from 1 after the time step).
See doc/peridem_post.md.
"""
import argparse
import math
import sys

import numpy as np


# ---------------------------------------------------------------- reading


def read_dump(path):
    """All snapshots of a LAMMPS text dump (custom or local).

    Returns a list of dicts: ``step`` (int), ``box`` (array of bounds lines),
    ``columns`` (names), ``data`` (2d float array, one row per atom/entry).
    ``column(snapshot, name)`` picks one column.
    """
    snaps = []
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        line = lines[k]
        if line.startswith("ITEM: TIMESTEP"):
            snaps.append({"step": int(lines[k + 1]), "box": [], "columns": [], "data": None})
            k += 2
        elif line.startswith("ITEM: NUMBER OF"):
            snaps[-1]["n"] = int(lines[k + 1])
            k += 2
        elif line.startswith("ITEM: BOX BOUNDS"):
            snaps[-1]["box"] = np.array([[float(v) for v in lines[k + d].split()]
                                         for d in (1, 2, 3)])
            k += 4
        elif line.startswith("ITEM: ATOMS") or line.startswith("ITEM: ENTRIES"):
            snap = snaps[-1]
            snap["columns"] = line.split()[2:]
            n = snap.get("n", 0)
            rows = [r.split() for r in lines[k + 1:k + 1 + n]]
            snap["data"] = np.array(rows, dtype=float).reshape(n, len(snap["columns"]))
            k += 1 + n
        else:
            k += 1
    return snaps


def column(snapshot, name):
    """One column of a dump snapshot by its name (e.g. 'x', 'c_dmg[1]')."""
    return snapshot["data"][:, snapshot["columns"].index(name)]


def read_ave_time(path):
    """A fix ave/time file.

    Scalar mode (one line per time step) returns (steps, values) with
    values[:, j] the j-th quantity. Vector mode (a "step rows" line and
    that many rows) returns a list of (step, 2d array of the rows).
    """
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    if not rows:
        return np.zeros(0), np.zeros((0, 0))
    # vector mode: a 2-value header whose second value counts the rows after it
    if len(rows[0]) == 2 and len(rows) > 1 and len(rows[1]) != 2 and \
            float(rows[0][1]) == int(float(rows[0][1])):
        blocks, k = [], 0
        while k < len(rows):
            step, n = int(rows[k][0]), int(rows[k][1])
            blocks.append((step, np.array(rows[k + 1:k + 1 + n], dtype=float)))
            k += 1 + n
        return blocks
    data = np.array(rows, dtype=float)
    return data[:, 0], data[:, 1:]


def read_thermo(path, first=("Step", "Time")):
    """The thermo output of a LAMMPS log: one dict per time step (column name -> value),
    each step once (a run's first line repeats the previous run's last). The header is the
    line starting with the words *first*; lines of another length or not numeric are skipped
    (echoed commands, warnings)."""
    rows, names, seen = [], None, set()
    for line in open(path):
        w = line.split()
        if tuple(w[:len(first)]) == tuple(first):
            names = w
            continue
        if names and len(w) == len(names) and w[0].isdigit():
            try:
                r = dict(zip(names, (float(v) for v in w)))
            except ValueError:
                continue
            if r[names[0]] not in seen:
                seen.add(r[names[0]])
                rows.append(r)
    return rows


def grain_contact_loads(node_ids, node_grains, pair_rows):
    """Contact forces between grains from node-pair forces.

    node_ids, node_grains: the node IDs and their grain (molecule) IDs;
    pair_rows: rows (id_i, id_j, ..., f) of a ``dump local`` of compute
    pair/local, the force in the last column (None, as read_dump gives for a
    snapshot without entries: no contact). Pairs within one grain are
    skipped (self contact). Returns (pairs, load): pairs maps each sorted
    (grain a, grain b) to the sum of |f| over their node pairs; load maps
    every grain to the sum of |f| over its node pairs with other grains.
    """
    grain_of = dict(zip((int(i) for i in node_ids), (int(g) for g in node_grains)))
    pairs = {}
    load = dict.fromkeys(grain_of.values(), 0.0)
    for row in pair_rows if pair_rows is not None else ():
        ga, gb = grain_of[int(row[0])], grain_of[int(row[1])]
        if ga == gb:
            continue
        f = abs(float(row[-1]))
        key = (min(ga, gb), max(ga, gb))
        pairs[key] = pairs.get(key, 0.0) + f
        load[ga] += f
        load[gb] += f
    return pairs, load


def verdict(fails, passed=""):
    """Print PERIDEM-FAIL with the failures, or PERIDEM-PASS; the exit code of a check."""
    if fails:
        print("PERIDEM-FAIL " + "; ".join(fails))
        return 1
    print("PERIDEM-PASS" + (" " + passed if passed else ""))
    return 0


# ------------------------------------------------------------------ crack


def crack_angle(x, y, damage, threshold=0.5):
    """Angle (degrees, in (-90, 90]), centre and length of a crack.

    The crack is the set of nodes with damage >= threshold; its path is the
    principal axis of their damage-weighted covariance, its length the
    spread of the nodes along that axis. Returns (angle, (cx, cy), length,
    mask of the crack nodes). A straight band of damaged nodes gives the
    band's direction (tested to 0.5 degree in unittest/scripts/test_post.py).
    """
    x, y, w = (np.asarray(a, dtype=float) for a in (x, y, damage))
    mask = w >= threshold
    if mask.sum() < 2:
        raise ValueError(f"fewer than 2 nodes with damage >= {threshold}")
    xs, ys, ws = x[mask], y[mask], w[mask]
    cx, cy = np.average(xs, weights=ws), np.average(ys, weights=ws)
    dx, dy = xs - cx, ys - cy
    cov = np.array([[np.average(dx * dx, weights=ws), np.average(dx * dy, weights=ws)],
                    [np.average(dx * dy, weights=ws), np.average(dy * dy, weights=ws)]])
    vals, vecs = np.linalg.eigh(cov)
    ax = vecs[:, np.argmax(vals)]
    angle = math.degrees(math.atan2(ax[1], ax[0]))
    if angle > 90.0:
        angle -= 180.0
    if angle <= -90.0:
        angle += 180.0
    proj = dx * ax[0] + dy * ax[1]
    return angle, (cx, cy), float(proj.max() - proj.min()), mask


# ------------------------------------------------------------------ plots


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def plot_vs_volume_fraction(phi, damage, force, path, labels=("bulk damage", "wall force")):
    """Bulk damage and wall force against the volume fraction (two panels)."""
    plt = _pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.5))
    for ax, values, label in zip(axes, (damage, force), labels):
        ax.plot(phi, values, "-")
        ax.set_xlabel("volume fraction")
        ax.set_ylabel(label)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def snapshot(x, y, values, path, fragments=False, title=None, size=4):
    """The nodes coloured by a value (damage) or, with fragments=True, by
    fragment ID (a repeating qualitative palette)."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6, 6))
    values = np.asarray(values)
    if fragments:
        _, codes = np.unique(values, return_inverse=True)
        sc = ax.scatter(x, y, c=codes % 20, cmap="tab20", s=size, vmin=0, vmax=19)
    else:
        sc = ax.scatter(x, y, c=values, cmap="viridis", s=size, vmin=0.0,
                        vmax=max(1.0, float(np.max(values))))
        fig.colorbar(sc, ax=ax, shrink=0.8)
    ax.set_aspect("equal")
    if title:
        ax.set_title(title)
    fig.savefig(path, dpi=120)
    plt.close(fig)


# ------------------------------------------------------------ command line


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="what", required=True)
    c = sub.add_parser("crack", help="crack angle from the last snapshot of a dump")
    c.add_argument("dump")
    c.add_argument("--column", default="c_dmg[1]")
    c.add_argument("--threshold", type=float, default=0.5)
    s = sub.add_parser("snapshot", help="nodes of the last snapshot coloured by a column")
    s.add_argument("dump")
    s.add_argument("--color", required=True)
    s.add_argument("--fragments", action="store_true", help="colour by fragment ID")
    s.add_argument("-o", "--output", default="snapshot.png")
    f = sub.add_parser("phi", help="damage and wall force against volume fraction")
    f.add_argument("file")
    f.add_argument("--phi", type=int, required=True)
    f.add_argument("--damage", type=int, required=True)
    f.add_argument("--force", type=int, required=True)
    f.add_argument("-o", "--output", default="phi.png")
    a = p.parse_args(argv)

    if a.what == "crack":
        snap = read_dump(a.dump)[-1]
        angle, centre, length, mask = crack_angle(column(snap, "x"), column(snap, "y"),
                                                  column(snap, a.column), a.threshold)
        print(f"step {snap['step']}: crack angle {angle:.2f} deg, centre "
              f"({centre[0]:.6g}, {centre[1]:.6g}), length {length:.6g}, {mask.sum()} nodes")
    elif a.what == "snapshot":
        snap = read_dump(a.dump)[-1]
        snapshot(column(snap, "x"), column(snap, "y"), column(snap, a.color), a.output,
                 fragments=a.fragments or a.color.startswith("c_frag"),
                 title=f"step {snap['step']}: {a.color}")
        print(a.output)
    else:
        _, v = read_ave_time(a.file)
        plot_vs_volume_fraction(v[:, a.phi - 1], v[:, a.damage - 1], v[:, a.force - 1],
                                a.output)
        print(a.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
