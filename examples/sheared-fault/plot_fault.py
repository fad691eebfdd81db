#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""The pressure sweep of run_sweep.sh, as Kiiskinen's thesis shows it (Sec. 5):

  mu(t) with the fit of eq. 100 (Fig. 12), D1 against p for friction on and off (Fig. 13),
  the debris layer's thickness against t, the dissipated energy Q(t)/p (Fig. 14), the final
  states (Fig. 11) and their classes F C L E B (Table 1), and a table (--csv, stdout).

  plot_fault.py DIR [--out PREFIX] [--h 1e-3] [--L 0.1] [--H 0.1] [--layer 3] [--v 2] [--csv]

Q is the dissipated energy from the balance W - dE (the series' Q_contact column is the part
of it that contact damping and friction took); Q / (p L v t) is the friction coefficient that
would dissipate it by sliding.
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np

SIGMA_C = 280e6


def eq100(t, tc, muc, d1, d2):
    """Kiiskinen's eq. 100: a linear rise to mu_crit at t_crit, then an exponential decay to D1."""
    t = np.asarray(t, dtype=float)
    return np.where(t <= tc, muc * t / tc, d1 + (muc - d1) * np.exp(-d2 * (t - tc)))


def fit_eq100(t, mu):
    from scipy.optimize import curve_fit

    k = int(np.argmax(mu))
    tail = mu[len(mu) * 2 // 3:]
    p0 = [max(t[k], t[1]), mu[k], float(np.mean(tail)), 5.0 / max(t[-1], 1e-12)]
    lo = [t[1] * 0.5, 0.0, -np.inf, 0.0]
    hi = [t[-1], np.inf, np.inf, np.inf]
    try:
        p, _ = curve_fit(eq100, t, mu, p0=p0, bounds=(lo, hi), maxfev=20000)
    except RuntimeError:
        p = np.array(p0)
    rms = float(np.sqrt(np.mean((eq100(t, *p) - mu) ** 2)))
    return p, rms


def read_dump(path):
    with open(path) as f:
        lines = f.read().splitlines()
    i = lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS")))
    cols = lines[i].split()[2:]
    d = np.array([l.split() for l in lines[i + 1:]], dtype=float)
    return {c: d[:, j] for j, c in enumerate(cols)}


def pieces(dump, debris_nodes):
    """Per node: in one of the two largest fragments (the blocks), in a debris fragment
    (fewer than debris_nodes nodes, as compute peridem/fragments min nodes counts them)."""
    frag = dump["c_frag"].astype(int)
    ids, inverse, counts = np.unique(frag, return_inverse=True, return_counts=True)
    in_block = np.isin(frag, ids[np.argsort(counts)[-2:]])
    return in_block, counts[inverse] < debris_nodes


def classify(dump, series, h, H, layer, debris_nodes):
    """Table 1's letters from the final state (our reading of them, README.md):
    F: 3 or more debris fragments; C: 10 or more nodes of the two blocks (the two largest
    fragments) with damage >= 0.3 more than 3 spacings from the debris; L: debris layer
    thicker than 3 spacings; E: a node with damage >= 0.3 in the `layer` rows next to a driven
    or held edge (the edges themselves are `layer` rows); B: a debris node there."""
    letters = ""
    in_block, debris = pieces(dump, debris_nodes)
    dmg = dump["c_dmg[1]"]
    y = dump["y"]
    if series[-1, 9] >= 3:
        letters += "F"
    if debris.any():
        yd_lo, yd_hi = y[debris].min() - 3 * h, y[debris].max() + 3 * h
    else:
        yd_lo = yd_hi = 0.5 * H
    cracked = in_block & (dmg >= 0.3) & ((y < yd_lo) | (y > yd_hi))
    if np.count_nonzero(cracked) >= 10:
        letters += "C"
    if series[-1, 10] > 3 * h:
        letters += "L"
    # the rows next to the driven and held edges, where they are now (the block compacts)
    edge = (y < y.min() + (2 * layer) * h) | (y > y.max() - (2 * layer) * h)
    if np.any(edge & (dmg >= 0.3)):
        letters += "E"
    if np.any(edge & debris):
        letters += "B"
    return letters


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir")
    ap.add_argument("--out", default="fault")
    ap.add_argument("--h", type=float, default=1e-3)
    ap.add_argument("--H", type=float, default=0.1)
    ap.add_argument("--L", type=float, default=0.1)
    ap.add_argument("--layer", type=int, default=3)
    ap.add_argument("--v", type=float, default=2.0)
    ap.add_argument("--debris", type=int, default=100, help="in.fault's debris (nodes)")
    ap.add_argument("--csv", action="store_true")
    a = ap.parse_args()
    runs = {}
    for f in glob.glob(os.path.join(a.dir, "p*_mu*.txt")):
        m = re.match(r"p([0-9.]+)_mu([0-9.]+)\.txt", os.path.basename(f))
        d = np.loadtxt(f)
        if d.ndim < 2 or len(d) < 5:
            continue
        runs[(float(m.group(1)), float(m.group(2)))] = (d, f[:-4])
    if not runs:
        sys.exit(f"no p*_mu*.txt in {a.dir}")
    ratios = sorted({k[0] for k in runs})
    mus = sorted({k[1] for k in runs}, reverse=True)
    rows, fits = [], {}
    for (r, mu), (d, stem) in sorted(runs.items()):
        t, m = d[1:, 1], d[1:, 2]
        fits[(r, mu)], rms = fit_eq100(t, m)
        tc, muc, d1, d2 = fits[(r, mu)]
        dump = stem + ".final.dump"
        cls = classify(read_dump(dump), d, a.h, a.H, a.layer, a.debris) if os.path.exists(dump) else "?"
        rows.append(dict(ratio=r, mu=mu, t_end=t[-1], mu_mean=float(np.mean(m)),
                         t_crit=tc, mu_crit=muc, D1=d1, D2=d2, rms=rms,
                         dilation=d[-1, 5], broken=d[-1, 7], debris=d[-1, 9],
                         thickness=d[-1, 10], Q=d[-1, 12],
                         Q_slip=d[-1, 12] / (r * SIGMA_C * a.L * a.v * t[-1]), cls=cls))
    keys = list(rows[0])
    if a.csv:
        print(",".join(keys))
        for r in rows:
            print(",".join(str(r[k]) for k in keys))
    else:
        print("| p/sigma_c | contact mu | t (ms) | mean mu | t_crit (ms) | mu_crit | D1 | D2 (1/ms) "
              "| fit rms | dilation (mm) | broken bonds | debris fragments | layer (mm) | Q (kJ/m) "
              "| Q / (p L v t) | Table 1 |")
        print("|" + "---|" * 16)
        for r in rows:
            print(f"| {r['ratio']:g} | {r['mu']:g} | {r['t_end'] * 1e3:.1f} | {r['mu_mean']:.3f} "
                  f"| {r['t_crit'] * 1e3:.2f} | {r['mu_crit']:.2f} | {r['D1']:.3f} "
                  f"| {r['D2'] / 1e3:.2f} | {r['rms']:.3f} | {r['dilation'] * 1e3:.2f} "
                  f"| {r['broken']:.0f} | {r['debris']:.0f} | {r['thickness'] * 1e3:.2f} "
                  f"| {r['Q'] / 1e3:.2f} | {r['Q_slip']:.3f} | {r['cls']} |")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    colors = plt.cm.viridis(np.linspace(0, 0.9, len(ratios)))
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    for (r, mu), (d, _) in sorted(runs.items()):
        c = colors[ratios.index(r)]
        ls = "-" if mu > 0 else "--"
        t = d[1:, 1] * 1e3
        if mu > 0:
            ax[0, 0].plot(t, d[1:, 2], ls, color=c, lw=0.8, label=f"p/σc = {r:g}")
            ax[0, 0].plot(t, eq100(d[1:, 1], *fits[(r, mu)]), ":", color=c, lw=1.5)
        ax[1, 0].plot(t, d[1:, 10] * 1e3, ls, color=c)
        ax[1, 1].plot(t, d[1:, 12] / (r * SIGMA_C), ls, color=c)
    ax[0, 0].set(xlabel="t (ms)", ylabel="μ = F_x / (p L)  (eq. 85)", ylim=(-0.5, 4),
                 title="friction on (μ_c = 0.7); dotted: fit of eq. 100 (peaks clipped)")
    ax[0, 0].legend(fontsize=7)
    for mu, mk in zip(mus, "os"):
        rr = [row for row in rows if row["mu"] == mu]
        ax[0, 1].plot([row["ratio"] for row in rr], [row["D1"] for row in rr], mk + "-",
                      label=f"D1, contact μ = {mu:g}")
        ax[0, 1].plot([row["ratio"] for row in rr], [row["mu_mean"] for row in rr], mk + ":",
                      alpha=0.5, label=f"mean μ, contact μ = {mu:g}")
    ax[0, 1].set(xscale="log", xlabel="p / σ_crit", ylabel="μ",
                 title="friction against pressure (thesis Fig. 13)")
    ax[0, 1].legend(fontsize=7)
    ax[1, 0].set(xlabel="t (ms)", ylabel="debris area / L (mm)",
                 title="fragment layer (solid: friction on, dashed: off)")
    ax[1, 1].set(xlabel="t (ms)", ylabel="Q / p  (m²)",
                 title="dissipated energy over pressure (thesis Fig. 14)")
    fig.tight_layout()
    fig.savefig(a.out + "_curves.png", dpi=90)

    shown = [r for r in ratios if os.path.exists(runs.get((r, mus[0]), (None, ""))[1] + ".final.dump")]
    if shown:
        fig, axs = plt.subplots(1, len(shown), figsize=(2.6 * len(shown), 3.2), squeeze=False)
        for k, r in enumerate(shown):
            dmp = read_dump(runs[(r, mus[0])][1] + ".final.dump")
            x, y = np.mod(dmp["x"], a.L) * 1e3, dmp["y"] * 1e3
            block, debris = pieces(dmp, a.debris)
            dmg = dmp["c_dmg[1]"]
            size = 40.0 / max(1.0, a.L / a.h / 25.0) ** 2
            whole = block & (dmg < 0.1)
            axs[0, k].scatter(x[whole], y[whole], s=size, linewidths=0,
                              c=np.where(dmp["mol"][whole] == 1, "lightsteelblue", "wheat"))
            piece = ~block & ~debris & (dmg < 0.1)
            axs[0, k].scatter(x[piece], y[piece], s=size, c="darkgrey", linewidths=0)
            hit = ~debris & (dmg >= 0.1)
            axs[0, k].scatter(x[hit], y[hit], s=size, c=dmg[hit], cmap="Reds", vmin=0, vmax=0.6,
                              linewidths=0)
            axs[0, k].scatter(x[debris], y[debris], s=size, c="k", linewidths=0)
            axs[0, k].set(aspect="equal", title=f"p/σc = {r:g}", xticks=[], yticks=[])
        fig.suptitle(f"final states, contact μ = {mus[0]:g}: the two blocks (blue, yellow), pieces "
                     f"of {a.debris} nodes or more broken off them (grey), damage >= 0.1 (red), "
                     "debris (black) (thesis Fig. 11)", fontsize=9)
        fig.tight_layout()
        fig.savefig(a.out + "_final.png", dpi=75)
    return 0


if __name__ == "__main__":
    sys.exit(main())
