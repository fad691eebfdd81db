/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Polygon-with-holes geometry: area, centroid, point location, transforms and
// validity checks for grain shapes (Bhattacharya & Lipton 2023, §5, §7.2).
#include "peridem_geometry_polygon.h"
#include "peridem_geometry_predicates.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace peridem {

namespace {

std::string fmt_point(const Vec2 &p)
{
  char buf[96];
  std::snprintf(buf, sizeof(buf), "(%.9g, %.9g)", p.x, p.y);
  return buf;
}

std::string ring_name(std::size_t k)
{
  return k == 0 ? std::string("outer ring") : "hole " + std::to_string(k);
}

// Drops a closing vertex equal to the first one and consecutive duplicates.
Ring clean_ring(Ring r)
{
  Ring out;
  for (const Vec2 &p : r)
    if (out.empty() || out.back() != p) out.push_back(p);
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

// Exact closed point-in-ring: +1 inside, 0 on the boundary, -1 outside.
// Crossing-number rule along +x, evaluated with the exact orient2d.
int locate_in_ring(const Ring &r, const Vec2 &p)
{
  bool inside = false;
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = r[i], &b = r[(i + 1) % n];
    if (on_segment(a, b, p)) return 0;
    if ((a.y <= p.y) != (b.y <= p.y)) {
      // Edge straddles the horizontal line through p: crossing to the right of
      // p iff p is left of the upward-directed edge.
      const int o = (b.y > a.y) ? orient2d(a, b, p) : orient2d(b, a, p);
      if (o > 0) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

// First self-intersection of ring r, as a message, or "".
std::string ring_self_intersection(const Ring &r, std::size_t k)
{
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = r[i], &b = r[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2 &c = r[j], &d = r[(j + 1) % n];
      const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
      bool bad;
      if (adjacent) {
        // Adjacent edges share one vertex; they are bad only if they fold
        // back onto each other (collinear overlap beyond the shared vertex).
        const Vec2 &shared = (j == i + 1) ? b : a;
        const Vec2 &e1 = (j == i + 1) ? a : b;
        const Vec2 &e2 = (j == i + 1) ? d : c;
        bad = orient2d(e1, shared, e2) == 0 && dot(e1 - shared, e2 - shared) > 0.0;
      } else {
        bad = segments_intersect_closed(a, b, c, d);
      }
      if (bad)
        return "polygon " + ring_name(k) + " is self-intersecting: edge " + fmt_point(a) + "-" +
               fmt_point(b) + " meets edge " + fmt_point(c) + "-" + fmt_point(d);
    }
  }
  return "";
}

// True if any edge of ring r meets any edge of ring s (closed segments).
bool rings_touch(const Ring &r, const Ring &s)
{
  for (std::size_t i = 0; i < r.size(); ++i)
    for (std::size_t j = 0; j < s.size(); ++j)
      if (segments_intersect_closed(r[i], r[(i + 1) % r.size()], s[j], s[(j + 1) % s.size()]))
        return true;
  return false;
}

} // namespace

double ring_signed_area(const Ring &r)
{
  double a = 0.0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) a += cross(r[i], r[(i + 1) % n]);
  return 0.5 * a;
}

double point_segment_distance(const Vec2 &p, const Vec2 &a, const Vec2 &b)
{
  const Vec2 ab = b - a;
  const double l2 = ab.norm2();
  double t = l2 > 0.0 ? dot(p - a, ab) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (p - (a + ab * t)).norm();
}

Polygon::Polygon(Ring outer, std::vector<Ring> holes) : outer_(clean_ring(std::move(outer)))
{
  if (ring_signed_area(outer_) < 0.0) std::reverse(outer_.begin(), outer_.end());
  for (auto &h : holes) {
    Ring c = clean_ring(std::move(h));
    if (ring_signed_area(c) > 0.0) std::reverse(c.begin(), c.end());
    holes_.push_back(std::move(c));
  }
}

std::size_t Polygon::num_vertices() const
{
  std::size_t n = outer_.size();
  for (const auto &h : holes_) n += h.size();
  return n;
}

double Polygon::area() const
{
  // Holes are CW, so their signed areas are negative and subtract themselves.
  double a = ring_signed_area(outer_);
  for (const auto &h : holes_) a += ring_signed_area(h);
  return a;
}

Vec2 Polygon::centroid() const
{
  // Standard polygon centroid, summed over all rings with their signed areas.
  double a = 0.0, cx = 0.0, cy = 0.0;
  for (std::size_t k = 0; k < num_rings(); ++k) {
    const Ring &r = ring(k);
    for (std::size_t i = 0, n = r.size(); i < n; ++i) {
      const Vec2 &p = r[i], &q = r[(i + 1) % n];
      const double c = cross(p, q);
      a += c;
      cx += (p.x + q.x) * c;
      cy += (p.y + q.y) * c;
    }
  }
  return {cx / (3.0 * a), cy / (3.0 * a)};
}

BoundingBox Polygon::bounding_box() const
{
  BoundingBox b;
  const double inf = std::numeric_limits<double>::infinity();
  b.lo = {inf, inf};
  b.hi = {-inf, -inf};
  for (const Vec2 &p : outer_) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
  }
  return b;
}

double Polygon::max_radius() const
{
  double r = 0.0;
  for (const Vec2 &p : outer_) r = std::max(r, p.norm());
  return r;
}

double Polygon::boundary_distance(const Vec2 &p) const
{
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < num_rings(); ++k) {
    const Ring &r = ring(k);
    for (std::size_t i = 0, n = r.size(); i < n; ++i)
      d = std::min(d, point_segment_distance(p, r[i], r[(i + 1) % n]));
  }
  return d;
}

double Polygon::default_tolerance() const
{
  return 1e-12 * bounding_box().diagonal();
}

int Polygon::locate(const Vec2 &p) const
{
  const int o = locate_in_ring(outer_, p);
  if (o <= 0) return o;
  for (const auto &h : holes_) {
    const int l = locate_in_ring(h, p);
    if (l >= 0) return -l; // inside a hole: exterior; on its ring: boundary
  }
  return 1;
}

bool Polygon::contains_exact(const Vec2 &p) const
{
  return locate(p) >= 0;
}

bool Polygon::contains(const Vec2 &p, double tol) const
{
  if (contains_exact(p)) return true;
  if (tol < 0.0) tol = default_tolerance();
  return tol > 0.0 && boundary_distance(p) <= tol;
}

Polygon &Polygon::translate(const Vec2 &d)
{
  for (std::size_t k = 0; k < num_rings(); ++k)
    for (Vec2 &p : (k == 0 ? outer_ : holes_[k - 1])) p = p + d;
  return *this;
}

Polygon &Polygon::rotate(double angle, const Vec2 &c)
{
  const double cs = std::cos(angle), sn = std::sin(angle);
  for (std::size_t k = 0; k < num_rings(); ++k)
    for (Vec2 &p : (k == 0 ? outer_ : holes_[k - 1])) {
      const Vec2 d = p - c;
      p = c + Vec2(cs * d.x - sn * d.y, sn * d.x + cs * d.y);
    }
  return *this;
}

Polygon &Polygon::scale(double s, const Vec2 &c)
{
  if (!(s > 0.0)) throw GeometryError("polygon scale factor must be positive");
  for (std::size_t k = 0; k < num_rings(); ++k)
    for (Vec2 &p : (k == 0 ? outer_ : holes_[k - 1])) p = c + (p - c) * s;
  return *this;
}

std::string Polygon::validation_error() const
{
  const double diag = bounding_box().diagonal();
  for (std::size_t k = 0; k < num_rings(); ++k) {
    const Ring &r = ring(k);
    if (r.size() < 3)
      return "polygon " + ring_name(k) + " has fewer than 3 distinct vertices (" +
             std::to_string(r.size()) + ")";
    for (const Vec2 &p : r)
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        return "polygon " + ring_name(k) + " has a non-finite vertex";
    // All vertices on one line: zero area (reported as such, not as a fold).
    bool collinear = true;
    for (const Vec2 &p : r) collinear = collinear && orient2d(r[0], r[1], p) == 0;
    if (collinear) return "polygon " + ring_name(k) + " has zero area";
    const std::string s = ring_self_intersection(r, k);
    if (!s.empty()) return s;
    if (!(std::fabs(ring_signed_area(r)) > 1e-14 * diag * diag))
      return "polygon " + ring_name(k) + " has zero area";
  }
  for (std::size_t k = 1; k < num_rings(); ++k) {
    const Ring &h = ring(k);
    if (rings_touch(h, outer_) || locate_in_ring(outer_, h[0]) <= 0)
      return "polygon " + ring_name(k) + " is not strictly inside the outer ring";
    for (std::size_t m = 1; m < k; ++m) {
      const Ring &g = ring(m);
      if (rings_touch(h, g) || locate_in_ring(g, h[0]) >= 0 || locate_in_ring(h, g[0]) >= 0)
        return "polygon holes " + std::to_string(m) + " and " + std::to_string(k) + " overlap";
    }
  }
  if (!(area() > 0.0)) return "polygon has zero area";
  return "";
}

void Polygon::validate() const
{
  const std::string e = validation_error();
  if (!e.empty()) throw GeometryError("invalid polygon: " + e);
}

} // namespace peridem
