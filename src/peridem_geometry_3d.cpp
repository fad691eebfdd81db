/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// 3D grain shapes, lattice and bonds (projection argument for extrusions).
#include "peridem_geometry_3d.h"
#include "peridem_math.h"
#include "peridem_geometry_discretize.h"
#include "peridem_geometry_visibility.h"

#include <algorithm>
#include <cmath>

namespace peridem {

namespace {

void require_positive_parameter(double v, const char *what)
{
  if (!(v > 0.0) || !std::isfinite(v)) throw GeometryError(std::string(what) + " must be positive");
}

Vec2 xy(const Vec3 &p)
{
  return {p.x, p.y};
}

} // namespace

Shape3D Shape3D::sphere(double radius)
{
  require_positive_parameter(radius, "sphere radius");
  Shape3D s;
  s.kind_ = Kind::Sphere;
  s.a_ = radius;
  return s;
}

Shape3D Shape3D::box(double lx, double ly, double lz)
{
  require_positive_parameter(lx, "box x size");
  require_positive_parameter(ly, "box y size");
  require_positive_parameter(lz, "box z size");
  Shape3D s;
  s.kind_ = Kind::Box;
  s.a_ = 0.5 * lx, s.b_ = 0.5 * ly, s.c_ = 0.5 * lz;
  return s;
}

Shape3D Shape3D::cylinder(double radius, double height)
{
  require_positive_parameter(radius, "cylinder radius");
  require_positive_parameter(height, "cylinder height");
  Shape3D s;
  s.kind_ = Kind::Cylinder;
  s.a_ = radius, s.c_ = 0.5 * height;
  return s;
}

Shape3D Shape3D::extrusion(const Polygon &section, double height)
{
  require_positive_parameter(height, "extrusion height");
  section.validate();
  Shape3D s;
  s.kind_ = Kind::Extrusion;
  s.c_ = 0.5 * height;
  s.section_ = section;
  s.convexSection_ = ExtendedBoundaryPruner(section).convex();
  return s;
}

double Shape3D::volume() const
{
  switch (kind_) {
  case Kind::Sphere:
    return 4.0 / 3.0 * kPi * a_ * a_ * a_;
  case Kind::Box:
    return 8.0 * a_ * b_ * c_;
  case Kind::Cylinder:
    return kPi * a_ * a_ * 2.0 * c_;
  case Kind::Extrusion:
    return section_.area() * 2.0 * c_;
  }
  return 0.0;
}

std::array<Vec3, 2> Shape3D::bounding_box() const
{
  switch (kind_) {
  case Kind::Sphere:
    return {Vec3(-a_, -a_, -a_), Vec3(a_, a_, a_)};
  case Kind::Box:
    return {Vec3(-a_, -b_, -c_), Vec3(a_, b_, c_)};
  case Kind::Cylinder:
    return {Vec3(-a_, -a_, -c_), Vec3(a_, a_, c_)};
  case Kind::Extrusion: {
    const BoundingBox b = section_.bounding_box();
    return {Vec3(b.lo.x, b.lo.y, -c_), Vec3(b.hi.x, b.hi.y, c_)};
  }
  }
  return {};
}

bool Shape3D::contains(const Vec3 &p, double tol) const
{
  if (tol < 0.0) {
    const auto bb = bounding_box();
    tol = 1e-12 * std::sqrt((bb[1] - bb[0]).norm2());
  }
  const double az = std::fabs(p.z);
  switch (kind_) {
  case Kind::Sphere:
    return p.norm2() <= (a_ + tol) * (a_ + tol);
  case Kind::Box:
    return std::fabs(p.x) <= a_ + tol && std::fabs(p.y) <= b_ + tol && az <= c_ + tol;
  case Kind::Cylinder:
    return p.x * p.x + p.y * p.y <= (a_ + tol) * (a_ + tol) && az <= c_ + tol;
  case Kind::Extrusion:
    return az <= c_ + tol && section_.contains(xy(p), tol);
  }
  return false;
}

bool Shape3D::convex() const
{
  return kind_ != Kind::Extrusion || convexSection_;
}

Nodes3D lattice_nodes_3d(const Shape3D &s, double h, const Vec3 &off)
{
  require_positive_parameter(h, "lattice spacing");
  const auto bb = s.bounding_box();
  auto range = [&](double lo, double hi, double o, long &i0, long &i1) {
    i0 = static_cast<long>(std::floor((lo - o) / h));
    i1 = static_cast<long>(std::ceil((hi - o) / h));
  };
  long i0, i1, j0, j1, k0, k1;
  range(bb[0].x, bb[1].x, off.x, i0, i1);
  range(bb[0].y, bb[1].y, off.y, j0, j1);
  range(bb[0].z, bb[1].z, off.z, k0, k1);
  if (double(i1 - i0 + 1) * double(j1 - j0 + 1) * double(k1 - k0 + 1) > 1e8)
    throw GeometryError("lattice spacing too small for the grain size (more than 1e8 cells)");
  Nodes3D n;
  const double tol = 1e-9 * h;
  if (s.kind() == Shape3D::Kind::Extrusion) {
    // Reuse the 2D lattice of the section, whose nodes are snapped to be
    // exactly inside the polygon (needed by the exact bond test), and stack it.
    LatticeOptions lo;
    lo.offset = Vec2(off.x, off.y);
    const Nodes2D layer = lattice_nodes(s.section(), h, lo);
    for (long k = k0; k <= k1; ++k) {
      const double z = off.z + k * h;
      if (std::fabs(z) > bb[1].z + tol) continue;
      for (const Vec2 &q : layer.x) {
        n.x.emplace_back(q.x, q.y, std::clamp(z, bb[0].z, bb[1].z));
        n.volume.push_back(h * h * h);
      }
    }
    return n;
  }
  for (long k = k0; k <= k1; ++k)
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i) {
        const Vec3 p = off + Vec3(i * h, j * h, k * h);
        if (!s.contains(p, tol)) continue;
        n.x.push_back(p);
        n.volume.push_back(h * h * h);
      }
  return n;
}

bool segment_inside_exact_3d(const Shape3D &s, const Vec3 &p, const Vec3 &q)
{
  if (s.kind() != Shape3D::Kind::Extrusion) return s.contains(p) && s.contains(q);
  const double hz = 0.5 * (s.bounding_box()[1].z - s.bounding_box()[0].z);
  if (std::fabs(p.z) > hz || std::fabs(q.z) > hz) return false;
  // Prism = polygon x interval: (x,y,z)(t) in prism iff (x,y)(t) in polygon
  // and z(t) in the interval; z(t) is linear, so only the ends matter.
  return segment_inside_exact(s.section(), xy(p), xy(q));
}

std::vector<Bond> create_bonds_3d(const Shape3D &s, const std::vector<Vec3> &x, double eps,
                                  Pruning pruning)
{
  std::vector<double> c;
  c.reserve(3 * x.size());
  for (const Vec3 &p : x) {
    c.push_back(p.x);
    c.push_back(p.y);
    c.push_back(p.z);
  }
  std::vector<Bond> bonds = pairs_within_horizon(c, 3, eps);
  if (pruning == Pruning::None || s.convex()) return bonds;
  const bool extended = pruning == Pruning::ExtendedBoundary;
  const ExtendedBoundaryPruner pruner(s.section());
  bonds.erase(std::remove_if(bonds.begin(), bonds.end(),
                             [&](const Bond &b) {
                               const Vec3 &p = x[b.first], &q = x[b.second];
                               return extended ? !pruner.keeps(xy(p), xy(q))
                                               : !segment_inside_exact_3d(s, p, q);
                             }),
              bonds.end());
  return bonds;
}

} // namespace peridem
