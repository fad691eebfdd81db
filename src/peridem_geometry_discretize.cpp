/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Lattice discretization of a 2D grain with h^2 or exactly clipped nodal
// volumes (Bhattacharya & Lipton 2023, §6-7: uniform mesh size h).
#include "peridem_geometry_discretize.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace peridem {

namespace {

// Keeps the part of ring r on the side of an axis-aligned line where
// sign * (coord - c) >= 0 (one Sutherland-Hodgman stage). The cut point gets
// the line coordinate exactly so cells tile without gaps.
Ring clip_axis(const Ring &r, bool use_x, double c, double sign)
{
  Ring out;
  const std::size_t n = r.size();
  auto coord = [&](const Vec2 &p) { return use_x ? p.x : p.y; };
  auto inside = [&](const Vec2 &p) { return sign * (coord(p) - c) >= 0.0; };
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = r[i], &b = r[(i + 1) % n];
    const bool ia = inside(a), ib = inside(b);
    if (ia) out.push_back(a);
    if (ia != ib) {
      const double t = (c - coord(a)) / (coord(b) - coord(a));
      Vec2 p = a + (b - a) * t;
      (use_x ? p.x : p.y) = c;
      out.push_back(p);
    }
  }
  return out;
}

// Moves a point that is within round-off outside D onto the boundary and, if
// needed, a few ulps inward, so that D.contains_exact() holds. Returns false if
// that fails (the point is then dropped).
bool snap_inside(const Polygon &D, Vec2 &p)
{
  double best = std::numeric_limits<double>::infinity();
  Vec2 a, b;
  for (std::size_t k = 0; k < D.num_rings(); ++k) {
    const Ring &r = D.ring(k);
    for (std::size_t i = 0; i < r.size(); ++i) {
      const double d = point_segment_distance(p, r[i], r[(i + 1) % r.size()]);
      if (d < best) best = d, a = r[i], b = r[(i + 1) % r.size()];
    }
  }
  const Vec2 e = b - a;
  const double t = std::clamp(dot(p - a, e) / e.norm2(), 0.0, 1.0);
  const Vec2 proj = a + e * t;
  const Vec2 inward = Vec2(-e.y, e.x) / e.norm(); // material is left of a->b
  double step = 0.0;
  const double ulp =
      std::numeric_limits<double>::epsilon() * (std::fabs(proj.x) + std::fabs(proj.y));
  for (int it = 0; it < 40; ++it) {
    const Vec2 c = proj + inward * step;
    if (D.locate(c) >= 0) {
      p = c;
      return true;
    }
    step = (step == 0.0) ? ulp : 2.0 * step;
  }
  return false;
}

} // namespace

double clipped_box_area(const Polygon &D, const Vec2 &lo, const Vec2 &hi)
{
  double area = 0.0;
  for (std::size_t k = 0; k < D.num_rings(); ++k) {
    Ring r = D.ring(k);
    r = clip_axis(r, true, lo.x, 1.0);
    if (!r.empty()) r = clip_axis(r, true, hi.x, -1.0);
    if (!r.empty()) r = clip_axis(r, false, lo.y, 1.0);
    if (!r.empty()) r = clip_axis(r, false, hi.y, -1.0);
    if (r.size() >= 3) area += ring_signed_area(r); // CW holes: negative
  }
  return area;
}

Nodes2D lattice_nodes(const Polygon &D, double h, const LatticeOptions &opt)
{
  if (!(h > 0.0) || !std::isfinite(h)) throw GeometryError("lattice spacing must be positive");
  const BoundingBox bb = D.bounding_box();
  // One extra cell of margin so that ExactClip sees every cell touching D.
  const long i0 = static_cast<long>(std::floor((bb.lo.x - opt.offset.x) / h)) - 1;
  const long i1 = static_cast<long>(std::ceil((bb.hi.x - opt.offset.x) / h)) + 1;
  const long j0 = static_cast<long>(std::floor((bb.lo.y - opt.offset.y) / h)) - 1;
  const long j1 = static_cast<long>(std::ceil((bb.hi.y - opt.offset.y) / h)) + 1;
  if ((i1 - i0) * (j1 - j0) > 100000000L)
    throw GeometryError("lattice spacing too small for the grain size (more than 1e8 cells)");

  const double tol = 1e-9 * h;
  const bool exact = opt.volume == NodalVolume::ExactClip;
  const double half = 0.5 * h, reach = 0.7072 * h; // > h / sqrt(2)
  Nodes2D nodes;
  std::vector<std::pair<Vec2, double>> orphans; // cells without a node
  for (long j = j0; j <= j1; ++j) {
    for (long i = i0; i <= i1; ++i) {
      const Vec2 c = opt.offset + Vec2(i * h, j * h);
      const int loc = D.locate(c);
      const double dist = (loc == 1 && !exact) ? h : D.boundary_distance(c);
      Vec2 p = c;
      const bool keep = loc >= 0 || (dist <= tol && snap_inside(D, p));
      double vol = h * h;
      if (exact) {
        if (dist > reach)
          vol = (loc == 1) ? h * h : 0.0; // cell fully in/out
        else
          vol = clipped_box_area(D, c - Vec2(half, half), c + Vec2(half, half));
      }
      if (keep) {
        nodes.x.push_back(p);
        nodes.volume.push_back(vol);
      } else if (exact && vol > 0.0) {
        orphans.emplace_back(c, vol);
      }
    }
  }
  // The part of D in a cell whose centre lies outside D goes to the nearest
  // node, so that sum V_i = |D| (mass conservation of the discretization).
  for (const auto &o : orphans) {
    std::size_t best = 0;
    double bestD = std::numeric_limits<double>::infinity();
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      const double d = (nodes.x[n] - o.first).norm2();
      if (d < bestD) bestD = d, best = n;
    }
    if (!nodes.x.empty()) nodes.volume[best] += o.second;
  }
  return nodes;
}

} // namespace peridem
