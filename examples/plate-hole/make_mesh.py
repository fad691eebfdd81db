#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Gmsh meshes of in.plate_hole's `geometry mesh`: the plate with nodes on its circular hole.

    make_mesh.py --n N [--W 0.1] [--aspect 1] [--r 0.1] [--dir .]

writes plate_hole_nN.msh (the plate with the hole), plate_ref_nN.msh (the same plate
without it) and plate_hole_nN_boundary.poly (the polygon that prunes the bonds).

A square lattice of spacing h = W/N (nodes on the plate's edges, N even: a node at the
centre) leaves a staircase at the hole whose top is flat over about 2 sqrt(r h), and the
hoop strain there converges like sqrt(h) only (README.md). Here rings of nodes at radii
r + j h, j = 0..J (J h ~ r), with a multiple of 4 nodes each (a node at the hole's top and
bottom), replace the lattice within 2 r of the centre; a Delaunay triangulation joins the
two, and create_peridem_grains takes the nodal volumes from its triangles.
"""
import argparse
import os

import numpy as np
from scipy.spatial import Delaunay


def nodes(n, W, aspect, r):
    """Ring nodes first, then lattice nodes; with the lattice indices (i, j) of the latter."""
    h = W / n
    nx = int(round(aspect * n))
    nx += nx % 2  # a lattice column at x = 0
    L = nx * h
    i, j = np.meshgrid(np.arange(nx + 1), np.arange(n + 1), indexing="ij")
    ij = np.column_stack((i.ravel(), j.ravel()))
    lat = np.column_stack((ij[:, 0] * h - L / 2, ij[:, 1] * h - W / 2))
    if r <= 0:
        return lat, ij, h, L, 0
    J = int(round(r / h))
    rings = []
    for k in range(J + 1):
        rho = r + k * h
        m = 4 * max(2, int(round(2 * np.pi * rho / (4 * h))))
        t = 2 * np.pi * np.arange(m) / m
        rings.append(np.column_stack((rho * np.cos(t), rho * np.sin(t))))
    # lattice nodes clear of the outer ring by 0.7 h
    keep = np.hypot(lat[:, 0], lat[:, 1]) > r + J * h + 0.7 * h
    rings = np.vstack(rings)
    ij = np.vstack((np.full((len(rings), 2), -10), ij[keep]))
    return np.vstack((rings, lat[keep])), ij, h, L, m_first(r, h)


def m_first(r, h):
    return 4 * max(2, int(round(2 * np.pi * r / (4 * h))))


def write_msh(path, xy, tri, quad):
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(xy))
        for k, (x, y) in enumerate(xy, 1):
            f.write("%d %.15g %.15g 0\n" % (k, x, y))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(tri) + len(quad)))
        for k, t in enumerate(tri, 1):
            f.write("%d 2 2 0 1 %d %d %d\n" % (k, t[0] + 1, t[1] + 1, t[2] + 1))
        for k, q in enumerate(quad, len(tri) + 1):
            f.write("%d 3 2 0 1 %d %d %d %d\n" % (k, q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1))
        f.write("$EndElements\n")


def mesh(xy, ij, r):
    """Quads on every lattice cell whose four corners are nodes (a Delaunay triangulation
    of a square lattice splits cells at random, and the nodal volumes, a third of the
    triangles' areas, would vary from 2/3 to 4/3 h^2), triangles elsewhere."""
    index = {tuple(v): k for k, v in enumerate(ij) if v[0] >= 0}
    quad, in_quad = [], set()
    for (i, j), k in index.items():
        c = [index.get(v) for v in ((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1))]
        if None not in c:
            quad.append(c)
            in_quad.add((i, j))
    tri = Delaunay(xy).simplices
    c = xy[tri].mean(axis=1)
    keep = np.hypot(c[:, 0], c[:, 1]) > r  # no triangle in the hole
    for t in range(len(tri)):
        v = ij[tri[t]]
        if keep[t] and (v[:, 0] >= 0).all():  # a triangle of lattice nodes in a quad's cell
            cell = (v[:, 0].min(), v[:, 1].min())
            if v[:, 0].max() - cell[0] <= 1 and v[:, 1].max() - cell[1] <= 1 and cell in in_quad:
                keep[t] = False
    tri = tri[keep]
    p = xy[tri]
    area = 0.5 * ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) -
                  (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1]))
    tri[area < 0] = tri[area < 0][:, [0, 2, 1]]  # counter-clockwise
    return tri, quad


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, required=True, help="lattice intervals across W (even)")
    ap.add_argument("--W", type=float, default=0.1)
    ap.add_argument("--aspect", type=float, default=1.0)
    ap.add_argument("--r", type=float, default=0.1, help="hole radius over W")
    ap.add_argument("--dir", default=".")
    a = ap.parse_args()
    if a.n % 2:
        raise SystemExit("make_mesh.py: --n must be even (a node at the centre)")
    r = a.r * a.W
    xy, ij, h, L, n0 = nodes(a.n, a.W, a.aspect, r)
    write_msh(os.path.join(a.dir, f"plate_hole_n{a.n}.msh"), xy, *mesh(xy, ij, r))
    ref, rij, _, _, _ = nodes(a.n, a.W, a.aspect, 0)
    write_msh(os.path.join(a.dir, f"plate_ref_n{a.n}.msh"), ref, *mesh(ref, rij, -1))
    # pruning polygon: the hole through the boundary nodes, shrunk by 1e-6 so that a bond
    # between two neighbours on the hole (an edge of the mesh) stays, a longer chord is cut;
    # the outer edges enlarged by as much
    g = 1 + 1e-6
    with open(os.path.join(a.dir, f"plate_hole_n{a.n}_boundary.poly"), "w") as f:
        f.write("# make_mesh.py: bond pruning of plate_hole_n%d.msh\nouter\n" % a.n)
        for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            f.write("%.15g %.15g\n" % (sx * g * L / 2, sy * g * a.W / 2))
        f.write("hole\n")
        for t in 2 * np.pi * np.arange(n0) / n0:
            f.write("%.15g %.15g\n" % (r / g * np.cos(t), r / g * np.sin(t)))
    print(f"make_mesh.py: n {a.n} h {h:.6g} L {L:.6g} nodes {len(xy)} (hole), {len(ref)} (ref), "
          f"{n0} on the hole")


if __name__ == "__main__":
    main()
