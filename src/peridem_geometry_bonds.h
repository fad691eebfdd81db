/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Peridynamic bonds inside one grain: all node pairs within the horizon
// (|xi| <= eps, i < j, each pair once), found with a cell list so the cost is
// linear in the number of nodes, optionally pruned to the bonds whose segment
// stays in the grain (Bhattacharya & Lipton 2023, §5), and removal of bonds that cross
// pre-notches / cracks (Bhattacharya & Lipton 2023, §6.2, §6.4: "bonds across the notch are removed
// in the reference configuration").
#ifndef PERIDEM_GEOMETRY_BONDS_H
#define PERIDEM_GEOMETRY_BONDS_H

#include "peridem_geometry_polygon.h"

#include <utility>
#include <vector>

namespace peridem {

// Bond between nodes i < j of one grain (local indices).
using Bond = std::pair<int, int>;

// |xi|^2 <= eps^2 up to a relative 1e-10, so that lattice pairs exactly at
// the horizon (e.g. eps = 3h along an axis) are kept despite round-off.
inline bool within_horizon(double dist2, double eps)
{
  return dist2 <= eps * eps * (1.0 + 1e-10);
}

// All pairs i < j with within_horizon(|x_i - x_j|^2, eps), sorted. `coords` is
// n points of `dim` (1..3) consecutive doubles. Cell list with cell size eps:
// O(n * neighbours), not O(n^2).
std::vector<Bond> pairs_within_horizon(const std::vector<double> &coords, int dim, double eps);
std::vector<Bond> pairs_within_horizon(const std::vector<Vec2> &x, double eps);

// Smallest distance between two of the n points of `coords` (as above), infinity
// for fewer than two. Searches pairs within r0 first (e.g. the node spacing) and
// doubles the radius until a pair is found.
double smallest_pair_distance(const std::vector<double> &coords, int dim, double r0);

enum class Pruning {
  None,             // keep every pair within the horizon (convex grains)
  ExtendedBoundary, // Bhattacharya & Lipton 2023, §5 (extended boundary + cusp bisectors)
  Exact,            // exact segment-in-shape reference test
};

// Bonds of one 2D grain D with nodes x (inside D) and horizon eps.
std::vector<Bond> create_bonds(const Polygon &D, const std::vector<Vec2> &x, double eps,
                               Pruning pruning = Pruning::ExtendedBoundary);

// A straight cut (pre-notch or crack) in reference coordinates.
struct CutSegment {
  Vec2 a, b;
};

// A bond crosses a cut if its end points lie on opposite sides of the cut's
// line and the crossing point lies on the closed cut. A node on the line
// belongs to the left side of a -> b, so a cut along a node row separates the
// row (kept with the left side) from the nodes right of it; bonds along the
// line, and bonds from the row to the left side, are kept.
bool bond_crosses_cut(const Vec2 &xi, const Vec2 &xj, const CutSegment &cut);

// Removes from `bonds` every bond crossing any cut; works on any bond list
// with reference positions x (e.g. bonds read from a LAMMPS data file).
// Returns the number of bonds removed.
std::size_t remove_bonds_crossing(std::vector<Bond> &bonds, const std::vector<Vec2> &x,
                                  const std::vector<CutSegment> &cuts);

} // namespace peridem

#endif
