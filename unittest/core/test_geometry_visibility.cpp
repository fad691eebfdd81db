/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Bond visibility: the pruning of Bhattacharya & Lipton 2023, §5 (extended boundary + cusp
// bisectors) must keep exactly the bonds whose segment stays in the grain, as decided by the exact
// reference test, on every built-in shape and resolution.
#include "peridem_geometry_bonds.h"
#include "peridem_geometry_discretize.h"
#include "peridem_geometry_shapes.h"
#include "peridem_geometry_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <cstdio>
#include <sstream>

using namespace peridem;

namespace {

// Characteristic size R of each built-in shape with default parameters.
double characteristicSize(const std::string &name)
{
  if (name == "notched_plate" || name == "v_notched_plate") return 0.5;
  return 1.0;
}

struct Agreement {
  std::size_t candidates = 0, kept = 0, removed = 0, mismatches = 0, onBoundary = 0;
  std::string firstMismatch;
};

Agreement compare(const Polygon &D, double h, double eps, const Vec2 &offset)
{
  LatticeOptions lo;
  lo.offset = offset;
  const Nodes2D n = lattice_nodes(D, h, lo);
  const ExtendedBoundaryPruner pruner(D);
  Agreement a;
  for (const Vec2 &p : n.x) EXPECT_TRUE(D.contains_exact(p));
  for (const Bond &b : pairs_within_horizon(n.x, eps)) {
    const Vec2 &p = n.x[b.first], &q = n.x[b.second];
    const bool exact = segment_inside_exact(D, p, q);
    const bool viaPruner = pruner.keeps(p, q);
    ++a.candidates;
    exact ? ++a.kept : ++a.removed;
    if (D.locate(p) == 0 || D.locate(q) == 0) ++a.onBoundary;
    if (exact != viaPruner) {
      if (a.mismatches++ == 0) {
        char buf[200];
        std::snprintf(buf, sizeof(buf), "(%.17g,%.17g)-(%.17g,%.17g) exact=%d extended=%d", p.x,
                      p.y, q.x, q.y, exact, viaPruner);
        a.firstMismatch = buf;
      }
    }
  }
  return a;
}

} // namespace

TEST(GeometryVisibility, ExactTestKnownCases)
{
  // L shape: [0,2]x[0,1] U [0,1]x[0,2], reflex corner at (1,1).
  const Polygon L({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  EXPECT_TRUE(segment_inside_exact(L, {0.5, 0.5}, {1.5, 0.5}));
  EXPECT_TRUE(segment_inside_exact(L, {0.5, 1.5}, {1.5, 0.5}));  // through the corner, inside
  EXPECT_FALSE(segment_inside_exact(L, {0.5, 0.5}, {1.5, 1.5})); // corner to exterior
  EXPECT_FALSE(segment_inside_exact(L, {1.5, 0.9}, {0.9, 1.5})); // cuts across the notch
  EXPECT_TRUE(segment_inside_exact(L, {0, 1}, {1, 1}));          // along... interior line
  EXPECT_TRUE(segment_inside_exact(L, {1, 1}, {2, 1}));          // along an edge
  EXPECT_TRUE(segment_inside_exact(L, {1, 2}, {1, 0}));          // edge then interior
  EXPECT_TRUE(segment_inside_exact(L, {0, 0}, {2, 0}));          // whole bottom edge
  EXPECT_FALSE(segment_inside_exact(L, {2, 1}, {1, 2}));         // boundary to boundary, outside
  EXPECT_FALSE(segment_inside_exact(L, {0.5, 0.5}, {3, 0.5}));   // end outside
  // Ring: chord across the hole is cut, chord beside it is kept.
  const Polygon ring = make_ring(1.0, 0.5, 32);
  EXPECT_FALSE(segment_inside_exact(ring, {-0.75, 0}, {0.75, 0}));
  EXPECT_TRUE(segment_inside_exact(ring, {-0.3, 0.8}, {0.3, 0.8}));
  // The extended-boundary pruner agrees on these.
  const ExtendedBoundaryPruner s(L);
  EXPECT_TRUE(s.keeps({0.5, 1.5}, {1.5, 0.5}));
  EXPECT_FALSE(s.keeps({0.5, 0.5}, {1.5, 1.5}));
  EXPECT_FALSE(s.keeps({1.5, 0.9}, {0.9, 1.5}));
  EXPECT_TRUE(s.keeps({1, 1}, {2, 1}));
  EXPECT_FALSE(s.keeps({2, 1}, {1, 2}));
  EXPECT_EQ(s.cusp_bisectors().size(), 1u);
  EXPECT_EQ(s.extended_boundary().size(), 6u);
}

TEST(GeometryVisibility, ExtendedBoundaryPruningEqualsExactOnEveryBuiltinShape)
{
  std::vector<std::pair<std::string, Polygon>> shapes;
  for (const auto &name : builtin_shape_names()) shapes.emplace_back(name, make_shape(name));
  for (int seed = 2; seed <= 4; ++seed)
    shapes.emplace_back("perturbed_disk seed " + std::to_string(seed),
                        make_shape("perturbed_disk", {{"seed", seed}}));
  for (const char *f : {"L_shape.poly", "star.poly", "plate_with_holes.poly"})
    shapes.emplace_back(
        f, read_polygon_file(std::string(PERIDEM_SOURCE_DIR) + "/potentials/shapes/" + f));

  std::size_t totalRemoved = 0, totalBoundary = 0;
  for (const auto &[name, base] : shapes) {
    const double R = name.find("notched") != std::string::npos ? 0.5
                     : name.find(".poly") != std::string::npos ? 1.0
                                                               : characteristicSize(name);
    for (double div : {5.0, 10.0, 20.0}) {
      const double h = R / div;
      for (double m : {3.0, 4.0}) {
        // Aligned lattice (nodes on axis-aligned edges and reflex corners),
        // a half-cell offset, and a rotated shape.
        for (int variant = 0; variant < 3; ++variant) {
          Polygon D = base;
          Vec2 off(0, 0);
          if (variant == 1) off = Vec2(0.5 * h, 0.5 * h);
          if (variant == 2) D.rotate(0.3);
          const Agreement a = compare(D, h, m * h, off);
          totalRemoved += a.removed;
          totalBoundary += a.onBoundary;
          EXPECT_EQ(a.mismatches, 0u)
              << name << " h=R/" << div << " eps=" << m << "h variant " << variant << ": "
              << a.mismatches << " of " << a.candidates << " differ, first " << a.firstMismatch;
        }
      }
    }
  }
  std::printf("[ pruning ] %zu non-bonds removed in total; %zu candidate bonds touch the "
              "boundary\n",
              totalRemoved, totalBoundary);
  EXPECT_GT(totalBoundary, 1000u); // boundary-start/end bonds were exercised
}

TEST(GeometryVisibility, GapsAreCutConvexShapesAreNot)
{
  struct Case {
    const char *name;
    double R;
    bool expectCut;
  };
  for (const Case c :
       {Case{"plus", 1.0, true}, Case{"ring", 1.0, true}, Case{"notched_plate", 0.5, true},
        Case{"v_notched_plate", 0.5, true}, Case{"neck", 1.0, true}, Case{"disk", 1.0, false},
        Case{"square", 1.0, false}, Case{"hexagon", 1.0, false}}) {
    const Polygon D = make_shape(c.name);
    const double h = c.R / 20;
    const Nodes2D n = lattice_nodes(D, h);
    const auto all = pairs_within_horizon(n.x, 4 * h);
    const auto kept = create_bonds(D, n.x, 4 * h, Pruning::ExtendedBoundary);
    const auto keptExact = create_bonds(D, n.x, 4 * h, Pruning::Exact);
    EXPECT_EQ(kept, keptExact) << c.name;
    if (c.expectCut)
      EXPECT_GT(all.size() - kept.size(), 0u) << c.name;
    else
      EXPECT_EQ(all.size(), kept.size()) << c.name;
  }
}

TEST(GeometryVisibility, ExactTestAgreesWithDenseSampling)
{
  // Independent check of the reference itself: a bond with a sample point
  // clearly outside (> 1e-9) must be rejected, and a rejected bond must come
  // within 1e-9 of the exterior (cuts by round-off only happen at that scale).
  for (const char *name : {"plus", "ring", "perturbed_disk", "notched_plate", "neck"}) {
    const Polygon D =
        make_shape(name, std::string(name) == "neck"
                             ? std::map<std::string, double>{{"width", 1.6}, {"neck_width", 0.2}}
                             : std::map<std::string, double>{});
    const double h = 0.05;
    const Nodes2D n = lattice_nodes(D, h);
    std::size_t removed = 0;
    for (const Bond &b : pairs_within_horizon(n.x, 4 * h)) {
      const Vec2 &p = n.x[b.first], &q = n.x[b.second];
      bool clearlyOut = false, nearOut = false;
      for (int k = 1; k < 64; ++k) {
        const Vec2 z = p + (q - p) * (k / 64.0);
        if (D.locate(z) < 0) (D.boundary_distance(z) > 1e-9 ? clearlyOut : nearOut) = true;
        if (D.boundary_distance(z) <= 1e-9) nearOut = true;
      }
      const bool inside = segment_inside_exact(D, p, q);
      removed += !inside;
      if (clearlyOut) EXPECT_FALSE(inside) << name;
      if (!inside) EXPECT_TRUE(clearlyOut || nearOut) << name;
    }
    EXPECT_GT(removed, 0u) << name;
  }
  const Polygon neck = make_shape("neck", {{"width", 1.6}, {"neck_width", 0.2}});
  const Nodes2D n = lattice_nodes(neck, 0.05);
  EXPECT_LT(create_bonds(neck, n.x, 0.2).size(), pairs_within_horizon(n.x, 0.2).size());
}
