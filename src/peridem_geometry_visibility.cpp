/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Exact segment-in-shape test and the non-bond detector of Bhattacharya & Lipton 2023, §5.
#include "peridem_geometry_visibility.h"
#include "peridem_geometry_predicates.h"

#include <algorithm>
#include <limits>

namespace peridem {

namespace {

// Is the direction from vertex v towards w (w != v) inside the closed interior
// wedge at v, whose incident edges are a->v and v->c (material on the left)?
bool in_wedge(const Vec2 &a, const Vec2 &v, const Vec2 &c, const Vec2 &w)
{
  const int turn = orient2d(a, v, c);
  const bool left_of_in = orient2d(a, v, w) >= 0;
  const bool left_of_out = orient2d(v, c, w) >= 0;
  if (turn > 0) return left_of_in && left_of_out; // convex corner: intersection
  if (turn < 0) return left_of_in || left_of_out; // reflex corner: union
  return left_of_in;                              // straight vertex: half plane
}

} // namespace

bool segment_inside_exact(const Polygon &D, const Vec2 &p, const Vec2 &q)
{
  if (!D.contains_exact(p) || !D.contains_exact(q)) return false;
  if (p == q) return true;
  // The segment leaves D iff, at the first point z where it enters the open
  // exterior, one of these local events happens (z is on the boundary):
  //  (1) it crosses an edge at a point interior to both (proper crossing);
  //  (2) z is a vertex and the segment continues outside the interior wedge;
  //  (3) z = p or q lies inside an edge and the segment points outward.
  // Each event also proves the segment leaves D, so the test is exact.
  for (std::size_t k = 0; k < D.num_rings(); ++k) {
    const Ring &r = D.ring(k);
    const std::size_t n = r.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 &a = r[(i + n - 1) % n], &v = r[i], &c = r[(i + 1) % n];
      if (segments_cross_properly(p, q, v, c)) return false; // (1)
      if (on_segment(p, q, v)) {                             // (2)
        if (v != q && !in_wedge(a, v, c, q)) return false;
        if (v != p && !in_wedge(a, v, c, p)) return false;
      }
      // (3): endpoint strictly inside edge v->c; the other end must be on the
      // material side (left) or on the edge line.
      if (p != v && p != c && on_segment(v, c, p) && orient2d(v, c, q) < 0) return false;
      if (q != v && q != c && on_segment(v, c, q) && orient2d(v, c, p) < 0) return false;
    }
  }
  return true;
}

double local_feature_size(const Polygon &D)
{
  double lfs = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < D.num_rings(); ++k) {
    const Ring &r = D.ring(k);
    const std::size_t n = r.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 &a = r[i], &b = r[(i + 1) % n];
      lfs = std::min(lfs, (b - a).norm());
      for (std::size_t m = 0; m < D.num_rings(); ++m) {
        const Ring &s = D.ring(m);
        for (std::size_t j = 0; j < s.size(); ++j) {
          if (m == k && (j == i || j == (i + 1) % n)) continue; // incident vertex
          lfs = std::min(lfs, point_segment_distance(s[j], a, b));
        }
      }
    }
  }
  return lfs;
}

ExtendedBoundaryPruner::ExtendedBoundaryPruner(const Polygon &D, double delta)
{
  delta_ = delta > 0.0 ? delta : 0.01 * local_feature_size(D);
  const double far_length = D.max_radius();
  for (std::size_t k = 0; k < D.num_rings(); ++k) {
    const Ring &r = D.ring(k);
    const std::size_t n = r.size();
    std::vector<Vec2> pbar(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 &prev = r[(i + n - 1) % n], &p = r[i], &next = r[(i + 1) % n];
      // Unit tangents v_{i-1}, v_i of the boundary (Bhattacharya & Lipton 2023, §5).
      const Vec2 vin = (p - prev) / (p - prev).norm();
      const Vec2 vout = (next - p) / (next - p).norm();
      // Bhattacharya & Lipton 2023, §5: p^i is a nonconvex cusp iff v_{i-1} x v_i < 0 (decided with
      // the exact predicate). n_i is the unit bisector of the OUTER angle. The
      // printed case formulas have sign/normalisation typos (the convex case
      // reads like a tangent, the straight case like the inward normal for a
      // CCW ring); we implement the stated intent, the outer-angle bisector.
      const int turn = orient2d(prev, p, next);
      Vec2 nrm;
      if (turn < 0)
        nrm = vout - vin; // reflex: into the exterior wedge
      else if (turn > 0)
        nrm = vin - vout; // convex: away from the corner
      else
        nrm = Vec2(vout.y, -vout.x); // straight: outward edge normal
      nrm = nrm / nrm.norm();
      pbar[i] = p + nrm * delta_; // pbar^i = p^i + delta n_i
      if (turn >= 0) continue;

      // Cusp bisector p^i q^i: q^i is the first hit of the ray p^i + t n_i
      // with the boundary; without a hit, t0 = |p^i| + sup{|x| : x in D}.
      double t0 = p.norm() + far_length;
      for (std::size_t m = 0; m < D.num_rings(); ++m) {
        const Ring &s = D.ring(m);
        for (std::size_t j = 0; j < s.size(); ++j) {
          if (m == k && (j == i || (j + 1) % n == i)) continue; // edges at p^i
          const Vec2 &a = s[j], &b = s[(j + 1) % s.size()];
          const Vec2 e = b - a;
          const double den = cross(nrm, e);
          if (den == 0.0) continue;
          const double t = cross(a - p, e) / den;
          const double u = cross(a - p, nrm) / den;
          if (t > 0.0 && u >= 0.0 && u <= 1.0) t0 = std::min(t0, t);
        }
      }
      // q^i is rounded; if it landed strictly inside D the open bisector would
      // poke into the material and cut good bonds, so pull it back to the
      // boundary/exterior (a few ulps).
      Vec2 q = p + nrm * t0;
      for (int it = 0; it < 64 && D.locate(q) > 0; ++it) {
        t0 *= 1.0 - 4.0 * std::numeric_limits<double>::epsilon() * (1 << std::min(it, 20));
        q = p + nrm * t0;
      }
      cusps_.push_back({p, q});
    }
    for (std::size_t i = 0; i < n; ++i) extended_.push_back({pbar[i], pbar[(i + 1) % n]});
  }
  auto box = [](const Segment &s) {
    return Box{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y), std::max(s.a.x, s.b.x),
               std::max(s.a.y, s.b.y)};
  };
  for (const auto &s : extended_) extBox_.push_back(box(s));
  for (const auto &s : cusps_) cuspBox_.push_back(box(s));
}

bool ExtendedBoundaryPruner::keeps(const Vec2 &x, const Vec2 &y) const
{
  if (convex()) return true; // Bhattacharya & Lipton 2023, §5: C_x is empty for convex D
  const double x0 = std::min(x.x, y.x), x1 = std::max(x.x, y.x);
  const double y0 = std::min(x.y, y.y), y1 = std::max(x.y, y.y);
  auto overlaps = [&](const Box &b) {
    return b.x0 <= x1 && x0 <= b.x1 && b.y0 <= y1 && y0 <= b.y1;
  };
  // Bhattacharya & Lipton 2023, §5: y in C_x iff segment xy meets a cusp bisector p^i q^i or an
  // extended boundary edge pbar^i pbar^{i+1}. The bisector is taken open (its
  // points strictly between p^i and q^i lie in the exterior, the ends lie on
  // the boundary), so bonds through a reflex corner that stay in D are kept.
  for (std::size_t i = 0; i < cusps_.size(); ++i)
    if (overlaps(cuspBox_[i]) && segment_hits_open_segment(x, y, cusps_[i].a, cusps_[i].b))
      return false;
  for (std::size_t i = 0; i < extended_.size(); ++i)
    if (overlaps(extBox_[i]) && segments_intersect_closed(x, y, extended_[i].a, extended_[i].b))
      return false;
  return true;
}

} // namespace peridem
