/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// 2D polygons with holes: the grain shapes of the PERIDEM geometry library.
//
// A 2D grain D is represented, as in Bhattacharya & Lipton 2023, §5, by a piecewise
// straight boundary: a closed outer polygon p^1 ... p^n oriented
// counter-clockwise plus optional holes (annular grains, §7.2) oriented
// clockwise. With this convention the material is always on the LEFT of every
// directed boundary edge, which is what Bhattacharya & Lipton's (2023) nonconvex-cusp criterion
// v_{i-1} x v_i < 0 assumes. The constructor normalizes the orientation, so
// callers can pass rings in either order.
#ifndef PERIDEM_GEOMETRY_POLYGON_H
#define PERIDEM_GEOMETRY_POLYGON_H

#include "peridem_geometry_error.h"

#include <cmath>
#include <string>
#include <vector>

namespace peridem {

// 2D point / vector.
struct Vec2 {
  double x = 0.0, y = 0.0;
  Vec2() = default;
  Vec2(double x_, double y_) : x(x_), y(y_) {}
  Vec2 operator+(const Vec2 &o) const { return {x + o.x, y + o.y}; }
  Vec2 operator-(const Vec2 &o) const { return {x - o.x, y - o.y}; }
  Vec2 operator*(double s) const { return {x * s, y * s}; }
  Vec2 operator/(double s) const { return {x / s, y / s}; }
  bool operator==(const Vec2 &o) const { return x == o.x && y == o.y; }
  bool operator!=(const Vec2 &o) const { return !(*this == o); }
  double norm() const { return std::hypot(x, y); }
  double norm2() const { return x * x + y * y; }
};
inline double dot(const Vec2 &a, const Vec2 &b)
{
  return a.x * b.x + a.y * b.y;
}
// z-component of the 2D cross product (Bhattacharya & Lipton 2023, §5 "v_{i-1} x v_i").
inline double cross(const Vec2 &a, const Vec2 &b)
{
  return a.x * b.y - a.y * b.x;
}

// Closed ring of vertices; the closing edge back[-1] -> front is implicit.
using Ring = std::vector<Vec2>;

struct BoundingBox {
  Vec2 lo, hi;
  double diagonal() const { return (hi - lo).norm(); }
};

// Signed area of a ring (shoelace formula): > 0 for counter-clockwise.
double ring_signed_area(const Ring &r);
// Euclidean distance from p to the closed segment [a, b].
double point_segment_distance(const Vec2 &p, const Vec2 &a, const Vec2 &b);

class Polygon {
 public:
  Polygon() = default;
  // Normalizes: drops a repeated closing vertex and consecutive duplicates,
  // makes the outer ring CCW and the holes CW. Does not validate (see
  // validate()), so that invalid input can still be inspected and reported.
  explicit Polygon(Ring outer, std::vector<Ring> holes = {});

  const Ring &outer() const { return outer_; }
  const std::vector<Ring> &holes() const { return holes_; }
  // Ring k: 0 is the outer ring, 1.. are the holes.
  std::size_t num_rings() const { return 1 + holes_.size(); }
  const Ring &ring(std::size_t k) const { return k == 0 ? outer_ : holes_[k - 1]; }
  std::size_t num_vertices() const;

  // Area of the material: outer area minus the hole areas.
  double area() const;
  // Area centroid of the material (holes subtracted).
  Vec2 centroid() const;
  BoundingBox bounding_box() const;
  // Largest |x| over the shape (Bhattacharya & Lipton 2023, §5 uses sup{|x| : x in D} for the
  // length of a cusp bisector that does not hit the boundary).
  double max_radius() const;

  // Closed point-in-shape: boundary points are inside. Points within distance
  // tol of the boundary also count as inside; tol < 0 selects the default
  // 1e-12 * (bounding box diagonal), which absorbs round-off in node positions.
  bool contains(const Vec2 &p, double tol = -1.0) const;
  // Exact closed point-in-shape (robust predicates, no tolerance).
  bool contains_exact(const Vec2 &p) const;
  // Exact point location: +1 interior, 0 on the boundary, -1 exterior.
  int locate(const Vec2 &p) const;
  // Distance from p to the boundary (all rings).
  double boundary_distance(const Vec2 &p) const;
  double default_tolerance() const;

  // Rigid motions and scaling (about a centre). scale() requires s > 0.
  Polygon &translate(const Vec2 &d);
  Polygon &rotate(double angle, const Vec2 &center = Vec2());
  Polygon &scale(double s, const Vec2 &center = Vec2());

  // Empty string if the polygon is a valid grain, otherwise a message naming
  // the problem: fewer than 3 vertices, zero area, self-intersecting ring,
  // hole not strictly inside the outer ring, holes overlapping.
  std::string validation_error() const;
  // Throws GeometryError with validation_error() if the polygon is invalid.
  void validate() const;

 private:
  Ring outer_;
  std::vector<Ring> holes_;
};

} // namespace peridem

#endif
