#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Checks compute peridem/fragments against a brute-force union-find.

fragments_union_find.py DIR: DIR holds bonds.dump (dump local: the two atom
IDs of every intact bond), nodes.dump (dump custom: id mol c_frag) and
sizes.dump (dump local: fragment ID, grain, nodes) of the same step, as
written by unittest/lammps/inputs/fragments/pulverise.in. Independently of
the compute, the connected components of the bond graph are found here;
each node's fragment ID must be the smallest atom ID of its component and
the fragment rows must list every component once with its grain and size.
Prints the number of fragments; exit status 1 on any mismatch.
"""
import sys
from collections import Counter


def read_dump(path):
    """Rows (lists of strings) of the last snapshot of a LAMMPS dump."""
    rows, reading = [], False
    with open(path) as f:
        for line in f:
            if line.startswith("ITEM: TIMESTEP"):
                rows, reading = [], False
            elif line.startswith("ITEM: ATOMS") or line.startswith("ITEM: ENTRIES"):
                reading = True
            elif line.startswith("ITEM:"):
                reading = False
            elif reading:
                rows.append(line.split())
    return rows


def main(d):
    nodes = {int(r[0]): (int(r[1]), int(float(r[2]))) for r in read_dump(f"{d}/nodes.dump")}
    parent = {i: i for i in nodes}

    def find(i):
        while parent[i] != i:
            i = parent[i]
        return i

    for a, b in read_dump(f"{d}/bonds.dump"):
        ra, rb = find(int(a)), find(int(b))
        if ra != rb:
            parent[max(ra, rb)] = min(ra, rb)
    root = {i: find(i) for i in nodes}
    # the root is the smallest ID of each component (union keeps the smaller)
    members = Counter(root.values())
    errors = [f"atom {i}: compute says fragment {nodes[i][1]}, union-find {root[i]}"
              for i in nodes if nodes[i][1] != root[i]]
    rows = {int(float(r[0])): (int(float(r[1])), int(float(r[2])))
            for r in read_dump(f"{d}/sizes.dump")}
    if set(rows) != set(members):
        errors.append(f"fragment IDs differ: {len(rows)} rows, {len(members)} components")
    for fid, (grain, n) in rows.items():
        if fid in members and (n != members[fid] or grain != nodes[fid][0]):
            errors.append(f"fragment {fid}: compute {n} nodes of grain {grain}, "
                          f"union-find {members[fid]} of grain {nodes[fid][0]}")
    print(f"{len(members)} fragments from {len(nodes)} nodes; {len(errors)} mismatches")
    for e in errors[:20]:
        print(e)
    return 1 if errors or len(members) < 50 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
