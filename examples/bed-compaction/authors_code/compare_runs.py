#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Bulk damage and top-wall load against phi, the columns of RESULTS.md, for
runs of in.authors_bed (its -var out file: step time top phi bulk_damage
broken_bonds load ke; or any file whose '#' header names the columns phi,
bulk_damage, broken_bonds, top_wall_load..., as ../shapes_reduced/*.txt) and of the authors' simulate2d (parse_output.py --csv).

usage: compare_runs.py LABEL=FILE[@SCALE] ... [--phi=0.5,0.55,...] [--first-break]
                       [--scaled] [--plot=OUT.png] [--ranges]

@SCALE: envelope.py's envelope/node areas ratio of the run's bed; with
--scaled the table's phi is phi_env = phi x SCALE.  --plot draws bulk damage
and top-wall load against phi and bulk damage against phi x SCALE (needs
matplotlib; LABELs starting with 'theirs' dashed); LABELs that share the text before a '~' share a colour (one
legend entry: perturbed repeats of one run); with --ranges such runs make one
table row whose cells give the smallest and largest value of the group.

Each cell is 'bulk damage / load in kN/m' at the saved row whose phi is
nearest to the column's phi (no interpolation; rows every 1000 steps = 0.05 mm
of wall travel, phi steps of 0.002-0.013), as RESULTS.md's table; '-' where
no row is within 0.01.
--first-break adds the phi of the first row with a broken bond.
"""
import sys
import numpy as np

phis = [0.50, 0.55, 0.60, 0.62, 0.65, 0.70, 0.76, 0.85, 0.90, 0.95, 0.974]
runs = []
first_break = False
scaled = False
plot = None
ranges = False
for arg in sys.argv[1:]:
    if arg == '--ranges':
        ranges = True
    elif arg == '--scaled':
        scaled = True
    elif arg.startswith('--plot='):
        plot = arg[7:]
    elif arg.startswith('--phi='):
        phis = [float(x) for x in arg[6:].split(',')]
    elif arg == '--first-break':
        first_break = True
    else:
        label, path = arg.split('=', 1)
        scale = 1.0
        if '@' in path:
            path, scale = path.rsplit('@', 1)
            scale = float(scale)
        runs.append((label, path, scale))


def read_run(path):
    """(phi, damage, broken fraction or count, load N/m) rows, one per step."""
    if path.endswith('.csv'):   # parse_output.py
        d = np.genfromtxt(path, delimiter=',', names=True)
        return d['phi'], d['bulk_damage'], d['broken_bond_frac'], d[d.dtype.names[7]]
    rows = {}
    names = None
    for line in open(path):
        if line.startswith('#') and names is None:
            names = line[1:].split()
            continue
        if line.startswith('#') or not line.strip():
            continue
        v = line.split()
        rows[int(float(v[0]))] = [float(x) for x in v]
    a = np.array([rows[k] for k in sorted(rows)])
    # our load is the force of the nodes on the wall (+ upward on the top wall's outward
    # normal: compressive load > 0); theirs (reaction, y) is the same sign convention
    col = {n: k for k, n in enumerate(names)}
    load_col = [k for k, n in enumerate(names) if n.startswith('top_wall_load')][0]
    return a[:, col['phi']], a[:, col['bulk_damage']], a[:, col['broken_bonds']], a[:, load_col]


hdr = '| run | ' + ' | '.join('%g' % p for p in phis) + ' |' + (' first broken bond at phi |' if first_break else '')
print(hdr)
print('|' + '---|' * (len(phis) + 1 + first_break))
curves = []
rows = {}          # base label -> list of (cells, first break); cell = (damage, load) or None
order = []
for label, path, scale in runs:
    phi, dmg, brk, load = read_run(path)
    curves.append((label, phi, dmg, load, scale))
    if scaled:
        phi = phi * scale
    cells = []
    for p in phis:
        k = int(np.argmin(np.abs(phi - p)))
        cells.append(None if abs(phi[k] - p) > 0.01 else (dmg[k], load[k] / 1e3))
    k = np.nonzero(brk > 0)[0]
    fb = phi[k[0]] if len(k) else None
    base = label.split('~')[0] if ranges else label
    if base not in rows:
        rows[base] = []
        order.append(base)
    rows[base].append((cells, fb))


def span(values, fmt):
    lo, hi = min(values), max(values)
    return fmt % lo if fmt % lo == fmt % hi else (fmt + '-' + fmt) % (lo, hi)


for base in order:
    group = rows[base]
    out = []
    for c in range(len(phis)):
        vals = [g[0][c] for g in group if g[0][c] is not None]
        out.append('-' if len(vals) < len(group) else
                   '%s / %s' % (span([v[0] for v in vals], '%.3f'), span([v[1] for v in vals], '%.1f')))
    line = '| %s | %s |' % (base + (' (%d runs)' % len(group) if len(group) > 1 else ''), ' | '.join(out))
    if first_break:
        fbs = [g[1] for g in group if g[1] is not None]
        line += ' %s |' % (span(fbs, '%.3f') if len(fbs) == len(group) else '-')
    print(line)

if plot:
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    colours = {}
    for label, phi, dmg, load, scale in curves:
        base = label.split('~')[0]
        first = base not in colours
        if first:
            colours[base] = 'C%d' % (len(colours) % 10)
        kw = dict(color=colours[base], lw=2.0 if base.startswith('theirs') else 1.0,
                  ls='--' if base.startswith('theirs') else '-', label=base if first else None)
        ax[0].plot(phi, dmg, **kw)
        ax[1].plot(phi, load / 1e3, **kw)
        ax[2].plot(phi * scale, dmg, **kw)
    ax[0].set_xlabel('phi = node areas / container'); ax[0].set_ylabel('bulk damage')
    ax[1].set_xlabel('phi = node areas / container'); ax[1].set_ylabel('top wall load (kN/m)')
    ax[2].set_xlabel('phi_env = contact envelopes / container'); ax[2].set_ylabel('bulk damage')
    for a in ax:
        a.grid(alpha=.3)
    ax[0].set_xlim(0.45, 1.0); ax[1].set_xlim(0.45, 1.0)
    ax[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(plot, dpi=100)
