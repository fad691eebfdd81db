/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the order in which a rank keeps its nodes in memory: grain by
   grain, and within a grain by atom ID.

   create_peridem_grains numbers the nodes of a grain one after the other,
   in the order of its mesh, so this is the order of creation. The bond
   loop then reads the partners of a node from a few kilobytes around it,
   in the same pattern from node to node. LAMMPS's own sort (spatial bins
   of half the neighbour cutoff) interleaves the grains of a bed row by row
   instead, and the bond loop of a large bed is a third slower in that order
   (bench/compaction-bed; the figures in bench/README.md).
------------------------------------------------------------------------- */

#ifndef PERIDEM_ATOM_ORDER_H
#define PERIDEM_ATOM_ORDER_H

#include <algorithm>
#include <numeric>
#include <vector>

namespace peridem {

// The permutation that puts the n atoms with grain IDs grain[] and atom IDs id[] in
// grain-major order (ascending grain, then ascending ID): entry k names the atom to put at
// position k. Empty when the atoms are in that order already (the usual case on one rank:
// nothing moves them between two orderings). ID is LAMMPS's tagint (32 or 64 bits).
template <typename ID>
std::vector<int> grain_major_permutation(const ID *grain, const ID *id, int n)
{
  auto before = [&](int a, int b) {
    return grain[a] < grain[b] || (grain[a] == grain[b] && id[a] < id[b]);
  };
  bool ordered = true;
  for (int i = 1; i < n && ordered; i++) ordered = !before(i, i - 1);
  if (ordered) return {};
  std::vector<int> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  std::sort(perm.begin(), perm.end(), before);
  return perm;
}

} // namespace peridem

#endif
