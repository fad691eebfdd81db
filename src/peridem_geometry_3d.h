/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// 3D grains: spheres, boxes, cylinders and extruded polygons (with holes).
//
// Same pipeline as in 2D: point-in-shape, volume, a simple-cubic lattice of
// spacing h clipped to the shape (nodal volume h^3), cell-list bonds within
// the horizon, and bond visibility for nonconvex extrusions: a prism
// P x [z0, z1] is convex in z, so a straight segment stays inside iff both
// ends have z in [z0, z1] and its projection stays in P (Bhattacharya & Lipton 2023, §5 in the
// plane).
#ifndef PERIDEM_GEOMETRY_3D_H
#define PERIDEM_GEOMETRY_3D_H

#include "peridem_geometry_bonds.h"
#include "peridem_geometry_polygon.h"

#include <array>
#include <vector>

namespace peridem {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
  Vec3() = default;
  Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  Vec3 operator+(const Vec3 &o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vec3 operator-(const Vec3 &o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  double norm2() const { return x * x + y * y + z * z; }
};

// Shapes are centred at the origin (extrusions: polygon frame, z symmetric),
// axis along z for cylinders and extrusions.
class Shape3D {
 public:
  enum class Kind { Sphere, Box, Cylinder, Extrusion };
  static Shape3D sphere(double radius);
  static Shape3D box(double lx, double ly, double lz);
  static Shape3D cylinder(double radius, double height);
  // Polygon (validated) extruded over z in [-height/2, height/2].
  static Shape3D extrusion(const Polygon &section, double height);

  Kind kind() const { return kind_; }
  double volume() const;
  // Closed point-in-shape with tolerance tol (< 0: 1e-12 * size).
  bool contains(const Vec3 &p, double tol = -1.0) const;
  // Axis-aligned bounding box.
  std::array<Vec3, 2> bounding_box() const;
  // Cross-section polygon of an extrusion (empty polygon otherwise).
  const Polygon &section() const { return section_; }
  // True if the shape is convex (sphere, box, cylinder, convex extrusion).
  bool convex() const;

 private:
  Kind kind_ = Kind::Sphere;
  double a_ = 0, b_ = 0, c_ = 0; // radius / half sizes / half height
  Polygon section_;
  bool convexSection_ = true;
};

struct Nodes3D {
  std::vector<Vec3> x;
  std::vector<double> volume;
  std::size_t size() const { return x.size(); }
};

// Simple-cubic lattice offset + (i, j, k) h clipped to the shape, volume h^3.
Nodes3D lattice_nodes_3d(const Shape3D &s, double h, const Vec3 &offset = Vec3());

// Exact visibility of a bond inside an extrusion (closed set); true for convex
// shapes when both ends are inside.
bool segment_inside_exact_3d(const Shape3D &s, const Vec3 &p, const Vec3 &q);

// Bonds within the horizon (cell list), pruned for nonconvex extrusions with
// the method of Bhattacharya & Lipton 2023, §5, on the projection (ExtendedBoundary) or the exact
// test (Exact).
std::vector<Bond> create_bonds_3d(const Shape3D &s, const std::vector<Vec3> &x, double eps,
                                  Pruning pruning = Pruning::ExtendedBoundary);

} // namespace peridem

#endif
