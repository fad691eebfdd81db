/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Bond visibility inside a nonconvex grain: is the straight segment between two
// nodes inside the grain? (Bhattacharya & Lipton 2023, §5: a bond whose segment leaves
// the domain D is a "non-bond" and is removed in the reference configuration.)
//
// Two independent implementations:
//  * segment_inside_exact(): the reference answer, a purely combinatorial test
//    with exact orientation predicates (closed set: boundary counts as inside,
//    so bonds along an edge or through a reflex corner are kept).
//  * ExtendedBoundaryPruner: the method of Bhattacharya & Lipton 2023, §5, built from the extended
//  boundary
//    (vertices pushed out by delta along the outer angle bisectors) and the
//    bisectors of the nonconvex cusps; a bond is a non-bond iff it meets them.
// The unit tests show both give the same bond set on every built-in shape.
#ifndef PERIDEM_GEOMETRY_VISIBILITY_H
#define PERIDEM_GEOMETRY_VISIBILITY_H

#include "peridem_geometry_polygon.h"

#include <utility>
#include <vector>

namespace peridem {

// True iff every point of the closed segment [p, q] lies in the closed shape
// (p and q included). Exact for double input.
bool segment_inside_exact(const Polygon &shape, const Vec2 &p, const Vec2 &q);

// Bhattacharya & Lipton 2023, §5 non-bond detector for one (fixed) polygon.
class ExtendedBoundaryPruner {
 public:
  struct Segment {
    Vec2 a, b;
  };
  // delta: offset of the extended boundary; <= 0 selects the default
  // 0.01 * (local feature size: the shortest edge or vertex-to-edge gap), which
  // keeps the extended boundary strictly outside D.
  explicit ExtendedBoundaryPruner(const Polygon &shape, double delta = -1.0);

  // True if the bond x-y (x, y nodes of the shape) is kept, i.e. it meets
  // neither an extended boundary edge nor an open cusp bisector.
  bool keeps(const Vec2 &x, const Vec2 &y) const;

  double delta() const { return delta_; }
  // Extended boundary edges pbar^i pbar^{i+1} of every ring.
  const std::vector<Segment> &extended_boundary() const { return extended_; }
  // Cusp bisectors p^i q^i at the nonconvex (reflex) vertices.
  const std::vector<Segment> &cusp_bisectors() const { return cusps_; }
  // True if the shape has no reflex vertex and no hole (then every bond of
  // nodes inside it is kept and keeps() returns true without any test).
  bool convex() const { return cusps_.empty(); }

 private:
  struct Box {
    double x0, y0, x1, y1;
  };
  double delta_ = 0.0;
  std::vector<Segment> extended_, cusps_;
  std::vector<Box> extBox_, cuspBox_;
};

// Shortest edge length or distance between a vertex and a non-incident edge,
// over all rings (the scale below which the shape has no features).
double local_feature_size(const Polygon &shape);

} // namespace peridem

#endif
