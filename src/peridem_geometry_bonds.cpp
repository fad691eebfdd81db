/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Cell-list bond search, pruning and notch/crack bond removal.
#include "peridem_geometry_bonds.h"
#include "peridem_geometry_predicates.h"
#include "peridem_geometry_visibility.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace peridem {

std::vector<Bond> pairs_within_horizon(const std::vector<double> &c, int dim, double eps)
{
  if (dim < 1 || dim > 3) throw GeometryError("pairs_within_horizon: dim must be 1, 2 or 3");
  if (!(eps > 0.0) || !std::isfinite(eps)) throw GeometryError("horizon must be positive");
  const std::size_t n = c.size() / dim;
  std::vector<Bond> bonds;
  if (n < 2) return bonds;
  double lo[3] = {0, 0, 0};
  for (int d = 0; d < dim; ++d) {
    lo[d] = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) lo[d] = std::min(lo[d], c[i * dim + d]);
  }
  // Cells slightly larger than the (slackened) horizon: every bond joins
  // points in the same or adjacent cells.
  const double cell = eps * (1.0 + 1e-9);
  constexpr std::int64_t kStride = std::int64_t(1) << 20; // cells per axis
  auto cell_of = [&](std::size_t i, int d) {
    return static_cast<std::int64_t>(std::floor((c[i * dim + d] - lo[d]) / cell));
  };
  auto key = [&](const std::int64_t *ic) {
    std::int64_t k = 0;
    for (int d = 0; d < dim; ++d) k = k * kStride + ic[d];
    return k;
  };
  std::vector<std::pair<std::int64_t, int>> sorted(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::int64_t ic[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d) {
      ic[d] = cell_of(i, d);
      if (ic[d] >= kStride - 1) throw GeometryError("horizon too small for the grain extent");
    }
    sorted[i] = {key(ic), static_cast<int>(i)};
  }
  std::sort(sorted.begin(), sorted.end());
  const int span = dim == 1 ? 3 : dim == 2 ? 9 : 27;
  for (std::size_t i = 0; i < n; ++i) {
    std::int64_t ic[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d) ic[d] = cell_of(i, d);
    for (int s = 0; s < span; ++s) {
      std::int64_t jc[3] = {0, 0, 0};
      bool valid = true;
      for (int d = 0, r = s; d < dim; ++d, r /= 3) {
        jc[d] = ic[d] + (r % 3) - 1;
        valid = valid && jc[d] >= 0;
      }
      if (!valid) continue;
      const std::int64_t k = key(jc);
      auto it = std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(k, -1));
      for (; it != sorted.end() && it->first == k; ++it) {
        const std::size_t j = static_cast<std::size_t>(it->second);
        if (j <= i) continue; // each pair once, never i == j
        double d2 = 0.0;
        for (int d = 0; d < dim; ++d) {
          const double dx = c[j * dim + d] - c[i * dim + d];
          d2 += dx * dx;
        }
        if (within_horizon(d2, eps)) bonds.emplace_back(static_cast<int>(i), static_cast<int>(j));
      }
    }
  }
  std::sort(bonds.begin(), bonds.end());
  return bonds;
}

std::vector<Bond> pairs_within_horizon(const std::vector<Vec2> &x, double eps)
{
  std::vector<double> c;
  c.reserve(2 * x.size());
  for (const Vec2 &p : x) {
    c.push_back(p.x);
    c.push_back(p.y);
  }
  return pairs_within_horizon(c, 2, eps);
}

double smallest_pair_distance(const std::vector<double> &coords, int dim, double r0)
{
  const std::size_t n = coords.size() / static_cast<std::size_t>(dim);
  if (n < 2) return std::numeric_limits<double>::infinity();
  if (!(r0 > 0.0) || !std::isfinite(r0)) throw GeometryError("search radius must be positive");
  for (double r = r0;; r *= 2.0) {
    const std::vector<Bond> pairs = pairs_within_horizon(coords, dim, r);
    if (pairs.empty()) continue;
    double best2 = std::numeric_limits<double>::infinity();
    for (const Bond &b : pairs) {
      double d2 = 0.0;
      for (int d = 0; d < dim; ++d) {
        const double dx = coords[b.second * dim + d] - coords[b.first * dim + d];
        d2 += dx * dx;
      }
      best2 = std::min(best2, d2);
    }
    return std::sqrt(best2);
  }
}

std::vector<Bond> create_bonds(const Polygon &D, const std::vector<Vec2> &x, double eps,
                               Pruning pruning)
{
  std::vector<Bond> bonds = pairs_within_horizon(x, eps);
  if (pruning == Pruning::None) return bonds;
  if (pruning == Pruning::ExtendedBoundary) {
    const ExtendedBoundaryPruner pruner(D);
    if (pruner.convex()) return bonds;
    bonds.erase(
        std::remove_if(bonds.begin(), bonds.end(),
                       [&](const Bond &b) { return !pruner.keeps(x[b.first], x[b.second]); }),
        bonds.end());
  } else {
    bonds.erase(std::remove_if(bonds.begin(), bonds.end(),
                               [&](const Bond &b) {
                                 return !segment_inside_exact(D, x[b.first], x[b.second]);
                               }),
                bonds.end());
  }
  return bonds;
}

bool bond_crosses_cut(const Vec2 &xi, const Vec2 &xj, const CutSegment &cut)
{
  // A node exactly on the cut's line counts as lying on its left (orient2d >= 0), as if
  // the cut were moved an infinitesimal distance to its right. With strict sides a notch
  // drawn along a node row (a lattice grain's centre line, Bhattacharya & Lipton 2023
  // §6.4) cut no bond at all: every bond crossing it has an end node on the line.
  const bool left_i = orient2d(cut.a, cut.b, xi) >= 0, left_j = orient2d(cut.a, cut.b, xj) >= 0;
  return left_i != left_j && orient2d(xi, xj, cut.a) * orient2d(xi, xj, cut.b) <= 0;
}

std::size_t remove_bonds_crossing(std::vector<Bond> &bonds, const std::vector<Vec2> &x,
                                  const std::vector<CutSegment> &cuts)
{
  const std::size_t before = bonds.size();
  bonds.erase(std::remove_if(bonds.begin(), bonds.end(),
                             [&](const Bond &b) {
                               for (const auto &cut : cuts)
                                 if (bond_crosses_cut(x.at(b.first), x.at(b.second), cut))
                                   return true;
                               return false;
                             }),
              bonds.end());
  return before - bonds.size();
}

} // namespace peridem
