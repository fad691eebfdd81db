#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Draws doc/img/fix_peridem_wall_segment.png: the wall segment S of a node's contact
disk (left) and the corner regions combined by inclusion-exclusion (right).
Run: python3 doc/img/fix_peridem_wall_segment.py  (needs matplotlib)."""
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import Circle, Polygon

R = 1.0


def disk_points(cx, cy, n=2000):
    """The contact disk as a fine polygon (regions are clipped from it, for drawing only)."""
    return [(cx + R * math.cos(2 * math.pi * i / n), cy + R * math.sin(2 * math.pi * i / n))
            for i in range(n)]


def clip(poly, a, b, c):
    """Sutherland-Hodgman clip of poly by a x + b y <= c."""
    out = []
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        fp, fq = a * p[0] + b * p[1] - c, a * q[0] + b * q[1] - c
        if fp <= 0:
            out.append(p)
        if fp * fq < 0:
            t = fp / (fp - fq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def centroid(poly):
    a = cx = cy = 0.0
    for i, p in enumerate(poly):
        q = poly[(i + 1) % len(poly)]
        w = p[0] * q[1] - q[0] * p[1]
        a += w
        cx += (p[0] + q[0]) * w
        cy += (p[1] + q[1]) * w
    return cx / (3 * a), cy / (3 * a)


def finish(ax, title, xlim, ylim, legend_loc):
    ax.set_title(title)
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.legend(loc=legend_loc, fontsize=8)


fig, axes = plt.subplots(1, 2, figsize=(10, 4.6))

# --- single wall: floor y = 0, node at height d ----------------------------------------
ax = axes[0]
d = 0.45
p = (0.0, d)
circle = disk_points(*p)
seg = clip(circle, 0.0, 1.0, 0.0)  # y <= 0: beyond the wall
ax.add_patch(Circle(p, R, fill=False, ls="--", color="0.4"))
ax.add_patch(Polygon(seg, color="tab:orange", alpha=0.6, label=r"segment $S$ (area $|S|$)"))
ax.fill_between([-1.6, 1.6], -1.0, 0.0, color="0.85", zorder=0)
ax.axhline(0.0, color="k", lw=2)
c = centroid(seg)
ax.plot(*p, "ko")
ax.annotate(r"node $p$", p, (0.25, d + 0.35), arrowprops=dict(arrowstyle="-"))
ax.plot(*c, "x", color="tab:red", ms=9, mew=2)
ax.annotate(r"centroid $c$", c, (0.55, -0.45), arrowprops=dict(arrowstyle="-"))
ax.annotate("", (p[0] - 0.05, 0.0), (p[0] - 0.05, d), arrowprops=dict(arrowstyle="<->"))
ax.text(-0.32, d / 2, r"$d$")
ax.annotate("", (p[0] + R * math.cos(2.3), p[1] + R * math.sin(2.3)), p,
            arrowprops=dict(arrowstyle="<-", color="0.3"))
ax.text(-0.75, 0.85, r"$R_c$", color="0.3")
ax.annotate("", (0.0, d + 0.6), (0.0, d + 0.05),
            arrowprops=dict(arrowstyle="->", color="tab:blue", lw=2))
ax.text(0.05, d + 0.45, r"$F = -K_n (R_c - |c-p|) V |S| e$", color="tab:blue")
ax.text(-1.5, -0.85, "wall (outside the container)")
finish(ax, "one wall: circular segment", (-1.6, 1.6), (-1.0, 1.7), "upper left")

# --- corner: walls x = 0 and y = 0 ----------------------------------------------------------
ax = axes[1]
p = (0.5, 0.4)
circle = disk_points(*p)
sx = clip(circle, 1.0, 0.0, 0.0)  # x <= 0
sy = clip(circle, 0.0, 1.0, 0.0)  # y <= 0
sxy = clip(sx, 0.0, 1.0, 0.0)
ax.fill_between([-0.9, 1.7], -0.8, 0.0, color="0.85", zorder=0)
ax.fill_between([-0.9, 0.0], -0.8, 1.5, color="0.85", zorder=0)
ax.axhline(0.0, color="k", lw=2)
ax.axvline(0.0, color="k", lw=2)
ax.add_patch(Circle(p, R, fill=False, ls="--", color="0.4"))
ax.add_patch(Polygon(sx, color="tab:orange", alpha=0.5, label=r"$S_x$ (wall $x$)"))
ax.add_patch(Polygon(sy, color="tab:green", alpha=0.5, label=r"$S_y$ (wall $y$)"))
ax.add_patch(Polygon(sxy, fill=False, hatch="///", color="tab:purple",
                     label=r"$S_x \cap S_y$ (subtracted)"))
ax.plot(*p, "ko")
ax.text(p[0] + 0.05, p[1] + 0.07, r"$p$")
ax.text(-0.85, 1.3, r"$F = F_{S_x} + F_{S_y} - F_{S_x\cap S_y}$", color="tab:blue")
finish(ax, "corner: inclusion-exclusion (Bhattacharya & Lipton 2023, eq. 4.8)", (-0.9, 1.7), (-0.8, 1.5), "lower right")

fig.tight_layout()
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fix_peridem_wall_segment.png")
fig.savefig(out, dpi=110)
print(out)
