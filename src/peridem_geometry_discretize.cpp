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
#include <map>
#include <utility>

namespace peridem {

namespace {

// A cell of size h whose centre is farther than cell_reach * h (> h / sqrt(2))
// from the boundary lies entirely inside or outside D.
constexpr double cell_reach = 0.7072;

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

// Moves p to the nearest point of the boundary (any ring) and, where round-off
// puts that point outside, a few ulps inward, so that D.contains_exact() holds.
// Returns false if that fails.
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

// The lattice cells to visit: the bounding box of D and one extra cell of
// margin, so that ExactClip and Outline see every cell touching D.
struct CellRange {
  long i0, i1, j0, j1;
};

CellRange lattice_cells(const Polygon &D, double h, const Vec2 &offset)
{
  if (!(h > 0.0) || !std::isfinite(h)) throw GeometryError("lattice spacing must be positive");
  const BoundingBox bb = D.bounding_box();
  CellRange r;
  r.i0 = static_cast<long>(std::floor((bb.lo.x - offset.x) / h)) - 1;
  r.i1 = static_cast<long>(std::ceil((bb.hi.x - offset.x) / h)) + 1;
  r.j0 = static_cast<long>(std::floor((bb.lo.y - offset.y) / h)) - 1;
  r.j1 = static_cast<long>(std::ceil((bb.hi.y - offset.y) / h)) + 1;
  if ((r.i1 - r.i0) * (r.j1 - r.j0) > 100000000L)
    throw GeometryError("lattice spacing too small for the grain size (more than 1e8 cells)");
  return r;
}

bool box_meets_boundary(const Polygon &D, const Vec2 &lo, const Vec2 &hi)
{
  for (std::size_t k = 0; k < D.num_rings(); ++k) {
    const Ring &r = D.ring(k);
    for (std::size_t i = 0; i < r.size(); ++i)
      if (segment_meets_box(r[i], r[(i + 1) % r.size()], lo, hi)) return true;
  }
  return false;
}

struct OutlineNode {
  Vec2 x;
  double volume;
  std::size_t cell;    // row-major cell index: the output order
  bool moved = false;  // moved onto the boundary
  bool corner = false; // moved onto a corner of D
  bool placed = true;  // false: no point of D found for it
};

// The corner of D in the closed box [lo, hi] nearest to c; false if there is none.
// A corner is a vertex where the outline turns by more than outline_corner_angle,
// so that the gentle vertices of a polygon standing for a curve are not preferred
// to its edges (their nodes would crowd the vertices and leave gaps between).
bool nearest_corner_in_box(const Polygon &D, const Vec2 &c, const Vec2 &lo, const Vec2 &hi,
                           Vec2 &corner)
{
  const double cos_min = std::cos(outline_corner_angle);
  bool found = false;
  for (std::size_t k = 0; k < D.num_rings(); ++k) {
    const Ring &r = D.ring(k);
    const std::size_t n = r.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 &v = r[i];
      if (v.x < lo.x || v.x > hi.x || v.y < lo.y || v.y > hi.y) continue;
      const Vec2 a = v - r[(i + n - 1) % n], b = r[(i + 1) % n] - v;
      if (dot(a, b) > cos_min * a.norm() * b.norm()) continue; // turns less
      if (!found || (v - c).norm2() < (corner - c).norm2()) corner = v, found = true;
    }
  }
  return found;
}

// Nodes closer than d to a point, found in a grid of cells of size d.
class NearGrid {
 public:
  explicit NearGrid(double d) : d_(d) {}
  void insert(const Vec2 &p, std::size_t index) { cells_[key(p, 0, 0)].push_back(index); }
  void move(std::size_t index, const Vec2 &from, const Vec2 &to)
  {
    auto &cell = cells_[key(from, 0, 0)];
    cell.erase(std::find(cell.begin(), cell.end(), index));
    insert(to, index);
  }
  // index of the node nearest to p among those closer than r (d by default), or npos
  std::size_t nearest(const Vec2 &p, const std::vector<OutlineNode> &nodes, double r = 0.0) const
  {
    if (!(r > 0.0)) r = d_;
    const int span = static_cast<int>(std::ceil(r / d_));
    std::size_t best = npos;
    double best2 = r * r;
    for (int di = -span; di <= span; ++di)
      for (int dj = -span; dj <= span; ++dj) {
        const auto it = cells_.find(key(p, di, dj));
        if (it == cells_.end()) continue;
        for (std::size_t n : it->second) {
          const double d2 = (nodes[n].x - p).norm2();
          if (d2 < best2 || (d2 == best2 && best != npos && n < best)) best2 = d2, best = n;
        }
      }
    return best;
  }
  // number of nodes closer than r to p
  std::size_t count(const Vec2 &p, const std::vector<OutlineNode> &nodes, double r) const
  {
    const int span = static_cast<int>(std::ceil(r / d_));
    std::size_t n = 0;
    for (int di = -span; di <= span; ++di)
      for (int dj = -span; dj <= span; ++dj) {
        const auto it = cells_.find(key(p, di, dj));
        if (it == cells_.end()) continue;
        for (std::size_t k : it->second) n += (nodes[k].x - p).norm2() < r * r;
      }
    return n;
  }
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

 private:
  double d_;
  std::map<std::pair<long, long>, std::vector<std::size_t>> cells_;
  std::pair<long, long> key(const Vec2 &p, int di, int dj) const
  {
    return {static_cast<long>(std::floor(p.x / d_)) + di,
            static_cast<long>(std::floor(p.y / d_)) + dj};
  }
};

std::size_t nearest_node(const std::vector<OutlineNode> &nodes, const Vec2 &p)
{
  std::size_t best = NearGrid::npos;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (best == NearGrid::npos || (nodes[n].x - p).norm2() < (nodes[best].x - p).norm2()) best = n;
  return best;
}

// NodePlacement::Outline (see the header): cells of positive area, those the
// boundary meets with their node moved onto it, then merged below the distance
// outline_merge_fraction * h.
Nodes2D outline_nodes(const Polygon &D, double h, const Vec2 &offset, const CellRange &r)
{
  const double half = 0.5 * h, reach = cell_reach * h;
  // a cell with less than this fraction of its area in D (or round-off there) gets
  // no node of its own: its area goes to the nearest node
  const double sliver = 1e-12;
  std::vector<OutlineNode> kept, moved, slivers;
  std::size_t cell = 0;
  for (long j = r.j0; j <= r.j1; ++j) {
    for (long i = r.i0; i <= r.i1; ++i, ++cell) {
      const Vec2 c = offset + Vec2(i * h, j * h);
      if (D.boundary_distance(c) > reach) { // cell fully inside or outside
        if (D.locate(c) == 1) kept.push_back({c, h * h, cell});
        continue;
      }
      const Vec2 lo = c - Vec2(half, half), hi = c + Vec2(half, half);
      const double area = clipped_box_area(D, lo, hi);
      if (!box_meets_boundary(D, lo, hi)) {
        // inside or outside as its centre (a cell in a hole has area 0 up to round-off)
        if (D.locate(c) == 1) kept.push_back({c, area, cell});
      } else if (area > sliver * h * h) {
        // a corner in the cell first, so corners carry nodes and the node hull is the shape
        OutlineNode m{c, area, cell};
        m.moved = true;
        m.corner = nearest_corner_in_box(D, c, lo, hi, m.x);
        if (!m.corner) m.placed = snap_inside(D, m.x);
        moved.push_back(m);
      } else if (area > 0.0) {
        slivers.push_back({c, area, cell});
      }
    }
  }
  // Interior nodes are h apart and, their cells being inside D, at least h/2
  // from every moved node; the vertices, then the largest moved cells claim
  // their place first.
  const double d = outline_merge_fraction * h;
  NearGrid grid(d);
  for (std::size_t n = 0; n < kept.size(); ++n) grid.insert(kept[n].x, n);
  const double light_volume = outline_small_fraction * h * h;
  std::stable_sort(moved.begin(), moved.end(), [&](const OutlineNode &a, const OutlineNode &b) {
    const bool ca = a.corner && a.volume >= light_volume, cb = b.corner && b.volume >= light_volume;
    return ca != cb ? ca : a.volume > b.volume;
  });
  for (const OutlineNode &m : moved) {
    if (!m.placed) { // no point of D found: its area to the nearest node
      const std::size_t into = nearest_node(kept, m.x);
      if (into != NearGrid::npos) kept[into].volume += m.volume;
      continue;
    }
    std::size_t into = grid.nearest(m.x, kept);
    // A light cell (a corner or edge that just reaches into it) joins the nearest node
    // within h, which moves onto its boundary point if it was inside D or the cell has
    // a corner: the outline keeps its nodes without light ones. A node only moves to
    // a point no other node is closer to than d.
    const bool light = m.volume < light_volume;
    if (into == NearGrid::npos && light) into = grid.nearest(m.x, kept, h);
    if (into != NearGrid::npos &&
        ((light && !kept[into].moved) || (m.corner && !kept[into].corner)) &&
        grid.count(m.x, kept, d) <= 1) {
      grid.move(into, kept[into].x, m.x);
      kept[into].x = m.x;
      kept[into].moved = true;
      kept[into].corner = m.corner;
    }
    if (into != NearGrid::npos) {
      kept[into].volume += m.volume;
    } else {
      grid.insert(m.x, kept.size());
      kept.push_back(m);
    }
  }
  for (const OutlineNode &m : slivers) {
    const std::size_t into = nearest_node(kept, m.x);
    if (into != NearGrid::npos) kept[into].volume += m.volume;
  }
  std::sort(kept.begin(), kept.end(),
            [](const OutlineNode &a, const OutlineNode &b) { return a.cell < b.cell; });
  Nodes2D nodes;
  for (const OutlineNode &n : kept) {
    nodes.x.push_back(n.x);
    nodes.volume.push_back(n.volume);
  }
  return nodes;
}

} // namespace

bool segment_meets_box(const Vec2 &a, const Vec2 &b, const Vec2 &lo, const Vec2 &hi)
{
  // clip the parameter range [0, 1] of a + t (b - a) to each slab of the box
  double t0 = 0.0, t1 = 1.0;
  const double p[2] = {a.x, a.y}, e[2] = {b.x - a.x, b.y - a.y};
  const double l[2] = {lo.x, lo.y}, u[2] = {hi.x, hi.y};
  for (int k = 0; k < 2; ++k) {
    if (e[k] == 0.0) {
      if (p[k] < l[k] || p[k] > u[k]) return false;
      continue;
    }
    double ta = (l[k] - p[k]) / e[k], tb = (u[k] - p[k]) / e[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

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
  const CellRange range = lattice_cells(D, h, opt.offset);
  const long i0 = range.i0, i1 = range.i1, j0 = range.j0, j1 = range.j1;
  if (opt.placement == NodePlacement::Outline) {
    if (opt.volume != NodalVolume::ExactClip)
      throw GeometryError("nodes on the outline need the exact clipped cell volumes");
    return outline_nodes(D, h, opt.offset, range);
  }

  const double tol = 1e-9 * h;
  const bool exact = opt.volume == NodalVolume::ExactClip;
  const double half = 0.5 * h, reach = cell_reach * h;
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
