/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Exact orientation predicate and segment tests built on it.
// See peridem_geometry_predicates.h for why exactness matters (Bhattacharya & Lipton 2023, §5).
#include "peridem_geometry_predicates.h"
#include "peridem_geometry_polygon.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace peridem {

namespace {

// Error-free transformations (Shewchuk 1997, Knuth): a + b = s + e exactly.
inline void two_sum(double a, double b, double &s, double &e)
{
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  e = (a - av) + (b - bv);
}

// a * b = p + e exactly (needs a correctly rounded fma).
inline void two_product(double a, double b, double &p, double &e)
{
  p = a * b;
  e = std::fma(a, b, -p);
}

// Adds b to the non-overlapping expansion e (increasing magnitude), in place.
void grow_expansion(std::vector<double> &e, double b)
{
  double q = b;
  std::size_t k = 0;
  for (double ei : e) {
    double s, err;
    two_sum(q, ei, s, err);
    q = s;
    if (err != 0.0) e[k++] = err;
  }
  e.resize(k);
  if (q != 0.0) e.push_back(q);
}

// Exact sign of bx*cy - bx*ay - ax*cy - by*cx + by*ax + ay*cx, i.e. the
// expanded form of (b-a) x (c-a), whose products are all exact as two doubles.
int orient2d_exact(const Vec2 &a, const Vec2 &b, const Vec2 &c)
{
  const double f[6][2] = {{b.x, c.y},  {-b.x, a.y}, {-a.x, c.y},
                          {-b.y, c.x}, {b.y, a.x},  {a.y, c.x}};
  std::vector<double> e;
  e.reserve(24);
  for (const auto &t : f) {
    double p, err;
    two_product(t[0], t[1], p, err);
    grow_expansion(e, err);
    grow_expansion(e, p);
  }
  // Non-overlapping expansion: the sign is that of the largest component.
  for (auto it = e.rbegin(); it != e.rend(); ++it)
    if (*it != 0.0) return *it > 0.0 ? 1 : -1;
  return 0;
}

} // namespace

int orient2d(const Vec2 &a, const Vec2 &b, const Vec2 &c)
{
  const double detl = (b.x - a.x) * (c.y - a.y);
  const double detr = (b.y - a.y) * (c.x - a.x);
  const double det = detl - detr;
  // Shewchuk's ccwerrboundA: if |det| exceeds it, the double sign is right.
  constexpr double eps = 0.5 * 2.220446049250313e-16;
  constexpr double bound = (3.0 + 16.0 * eps) * eps;
  const double errbound = bound * (std::fabs(detl) + std::fabs(detr));
  if (det > errbound) return 1;
  if (-det > errbound) return -1;
  return orient2d_exact(a, b, c);
}

bool on_segment(const Vec2 &a, const Vec2 &b, const Vec2 &c)
{
  if (orient2d(a, b, c) != 0) return false;
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

bool segments_intersect_closed(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d)
{
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const int o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

bool segment_hits_open_segment(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d)
{
  const int o1 = orient2d(c, d, a), o2 = orient2d(c, d, b);
  if (o1 == 0 && o2 == 0) {
    // Collinear: compare the closed interval [a,b] with the open (c,d) along
    // the dominant axis of c->d (exact coordinate comparisons).
    const bool use_x = std::fabs(d.x - c.x) >= std::fabs(d.y - c.y);
    double pa = use_x ? a.x : a.y, pb = use_x ? b.x : b.y;
    double pc = use_x ? c.x : c.y, pd = use_x ? d.x : d.y;
    if (pa > pb) std::swap(pa, pb);
    if (pc > pd) std::swap(pc, pd);
    return pc < pd && pa < pd && pb > pc;
  }
  if (o1 * o2 > 0) return false; // [a,b] strictly on one side of line cd
  // [a,b] reaches line cd at one point; it is interior to (c,d) iff c and d are
  // strictly on opposite sides of line ab.
  return orient2d(a, b, c) * orient2d(a, b, d) < 0;
}

bool segments_cross_properly(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d)
{
  return orient2d(a, b, c) * orient2d(a, b, d) < 0 && orient2d(c, d, a) * orient2d(c, d, b) < 0;
}

} // namespace peridem
