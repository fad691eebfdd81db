/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Bond creation (cell list vs brute force), notch/crack removal, 3D grains and
// the one-call grain helpers with their input errors.
#include "peridem_geometry_grain.h"
#include "peridem_geometry_shapes.h"

#include "geometry_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <functional>
#include <map>

using namespace peridem;

namespace {
std::vector<Bond> bruteForce(const std::vector<Vec2> &x, double eps)
{
  std::vector<Bond> b;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j)
      if (within_horizon((x[i] - x[j]).norm2(), eps)) b.emplace_back(int(i), int(j));
  return b;
}
} // namespace

TEST(GeometryBonds, CellListEqualsBruteForce)
{
  const Polygon sq = make_shape("square", {{"side", 2.0}});
  for (double h : {0.2, 0.1, 0.05}) {
    for (double m : {1.0, 3.0, 4.0}) {
      const Nodes2D n = lattice_nodes(sq, h);
      const auto b = pairs_within_horizon(n.x, m * h);
      EXPECT_EQ(b, bruteForce(n.x, m * h)) << h << " " << m;
      for (const Bond &p : b) EXPECT_LT(p.first, p.second);
      // Convex square: no pruning, and the interior node degree matches the
      // lattice count of points with |(i, j)| <= m (m = 3: 28, m = 4: 48).
      EXPECT_EQ(create_bonds(sq, n.x, m * h, Pruning::ExtendedBoundary), b);
    }
  }
  const Nodes2D n = lattice_nodes(sq, 0.1);
  const auto b = pairs_within_horizon(n.x, 0.3);
  std::vector<int> degree(n.size(), 0);
  for (const Bond &p : b) ++degree[p.first], ++degree[p.second];
  int center = -1;
  for (std::size_t i = 0; i < n.size(); ++i)
    if (n.x[i].norm() < 1e-12) center = int(i);
  ASSERT_GE(center, 0);
  EXPECT_EQ(degree[center], 28);
  // Random points, 3D, vs brute force.
  std::vector<double> c;
  unsigned s = 12345;
  auto rnd = [&] { return (s = s * 1103515245u + 12345u) / 4294967296.0; };
  for (int i = 0; i < 3 * 400; ++i) c.push_back(rnd());
  const auto b3 = pairs_within_horizon(c, 3, 0.15);
  std::size_t brute = 0;
  for (int i = 0; i < 400; ++i)
    for (int j = i + 1; j < 400; ++j) {
      double d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += std::pow(c[3 * i + d] - c[3 * j + d], 2);
      brute += within_horizon(d2, 0.15);
    }
  EXPECT_EQ(b3.size(), brute);
  EXPECT_GT(brute, 100u);
}

TEST(GeometryBonds, CutsRemoveBondsAcrossNotch)
{
  // Bhattacharya & Lipton 2023, §6.4: unit square with a notch from the left edge to the centre.
  const Polygon sq = make_shape("square", {{"side", 1.0}});
  const double h = 0.05;
  LatticeOptions lo;
  lo.offset = {0.5 * h, 0.5 * h}; // no node on the crack line y = 0
  const Nodes2D n = lattice_nodes(sq, h, lo);
  auto bonds = create_bonds(sq, n.x, 3 * h);
  const auto before = bonds;
  const std::size_t removed = remove_bonds_crossing(bonds, n.x, {{{-0.5, 0.0}, {0.0, 0.0}}});
  EXPECT_GT(removed, 0u);
  EXPECT_EQ(before.size() - bonds.size(), removed);
  for (const Bond &b : bonds) {
    const Vec2 &p = n.x[b.first], &q = n.x[b.second];
    const bool crossesLine = (p.y > 0) != (q.y > 0);
    if (crossesLine) {
      // Where the bond meets y = 0 must be right of the notch tip.
      const double x0 = p.x + (q.x - p.x) * (0 - p.y) / (q.y - p.y);
      EXPECT_GT(x0, 0.0);
    }
  }
  // Touching at an end node or running along the cut does not cut.
  EXPECT_FALSE(bond_crosses_cut({0, 0}, {1, 1}, {{-1, 0}, {1, 0}}));
  EXPECT_FALSE(bond_crosses_cut({-0.5, 0}, {0.5, 0}, {{-1, 0}, {1, 0}}));
  EXPECT_TRUE(bond_crosses_cut({0, -1}, {0, 1}, {{-1, 0}, {0, 0}})); // through the tip
  EXPECT_FALSE(bond_crosses_cut({0.1, -1}, {0.1, 1}, {{-1, 0}, {0, 0}}));
}

// A cut drawn along a node row (a lattice grain's centre line, Bhattacharya & Lipton 2023 §6.4) cut
// nothing while the row's nodes were on neither side. Now each node belongs to one side
// (the row to the left of a -> b), so the cut separates the grain.
TEST(GeometryBonds, CutAlongNodeRowSeparates)
{
  const Polygon sq = make_shape("square", {{"side", 1.0}});
  const double h = 0.05;
  const Nodes2D n = lattice_nodes(sq, h, LatticeOptions{}); // rows at y = j h, one at y = 0
  const auto all = create_bonds(sq, n.x, 3 * h);
  // connected pieces of a bond list (union-find)
  auto pieces = [&](const std::vector<Bond> &bonds) {
    std::vector<std::size_t> up(n.size());
    for (std::size_t i = 0; i < up.size(); i++) up[i] = i;
    std::function<std::size_t(std::size_t)> root = [&](std::size_t i) {
      return up[i] == i ? i : up[i] = root(up[i]);
    };
    for (const Bond &b : bonds) up[root(b.first)] = root(b.second);
    std::map<std::size_t, std::size_t> size;
    for (std::size_t i = 0; i < up.size(); i++) size[root(i)]++;
    std::vector<std::size_t> s;
    for (const auto &kv : size) s.push_back(kv.second);
    std::sort(s.begin(), s.end());
    return s;
  };
  ASSERT_EQ(pieces(all).size(), 1u);
  const std::size_t row = 21, above = 10 * row, below = 10 * row;
  ASSERT_EQ(n.size(), above + row + below);

  // a cut across the whole grain on the row y = 0: two pieces, the row with the left side
  for (const bool leftToRight : {true, false}) {
    auto bonds = all;
    const CutSegment c =
        leftToRight ? CutSegment{{-0.6, 0.0}, {0.6, 0.0}} : CutSegment{{0.6, 0.0}, {-0.6, 0.0}};
    remove_bonds_crossing(bonds, n.x, {c});
    EXPECT_EQ(pieces(bonds), (std::vector<std::size_t>{below, above + row}));
    for (const Bond &b : bonds) {
      const double y0 = n.x[b.first].y, y1 = n.x[b.second].y;
      if (leftToRight) // left of a -> b is y > 0: the row stays with the upper half
        EXPECT_FALSE((y0 < 0) != (y1 < 0));
      else
        EXPECT_FALSE((y0 > 0) != (y1 > 0));
    }
    // the same bonds as a cut moved a hundred-millionth of a spacing to its right
    auto shifted = all;
    const double dy = leftToRight ? -1e-8 * h : 1e-8 * h;
    remove_bonds_crossing(shifted, n.x, {{{c.a.x, dy}, {c.b.x, dy}}});
    EXPECT_EQ(bonds, shifted);
  }

  // the notch of Bhattacharya & Lipton 2023 (§6.4), from the left edge to the centre along the row:
  // still one piece, and every bond from a node below the row to a node on or above it that meets
  // the row left of the tip (x <= 0) is gone; all other bonds are kept
  auto bonds = all;
  remove_bonds_crossing(bonds, n.x, {{{-0.6, 0.0}, {0.0, 0.0}}});
  EXPECT_EQ(pieces(bonds).size(), 1u);
  std::size_t expect_removed = 0;
  for (const Bond &b : all) {
    Vec2 p = n.x[b.first], q = n.x[b.second];
    if (p.y > q.y) std::swap(p, q);
    if (!(p.y < 0 && q.y >= 0)) continue;
    const double x0 = p.x + (q.x - p.x) * (0 - p.y) / (q.y - p.y);
    if (x0 <= 1e-12) expect_removed++;
  }
  EXPECT_GT(expect_removed, 0u);
  EXPECT_EQ(all.size() - bonds.size(), expect_removed);
}

TEST(GeometryBonds, Shapes3D)
{
  const double pi = M_PI;
  EXPECT_NEAR(Shape3D::sphere(2).volume(), 32.0 / 3.0 * pi, 1e-13);
  EXPECT_DOUBLE_EQ(Shape3D::box(1, 2, 3).volume(), 6.0);
  EXPECT_NEAR(Shape3D::cylinder(1, 2).volume(), 2 * pi, 1e-14);
  const Shape3D plus = Shape3D::extrusion(make_shape("plus"), 0.5);
  EXPECT_NEAR(plus.volume(), 0.5 * (1.6 - 0.16), 1e-14);
  EXPECT_TRUE(Shape3D::sphere(1).contains({0, 0, 1}));
  EXPECT_FALSE(Shape3D::sphere(1).contains({0.6, 0.6, 0.6}));
  EXPECT_TRUE(Shape3D::cylinder(1, 2).contains({0.7, 0.7, -1}));
  EXPECT_FALSE(Shape3D::cylinder(1, 2).contains({0.8, 0.8, 0}));
  EXPECT_TRUE(plus.contains({0.9, 0.1, 0.25}));
  EXPECT_FALSE(plus.contains({0.9, 0.9, 0}));
  EXPECT_FALSE(plus.convex());
  EXPECT_TRUE(Shape3D::extrusion(make_shape("hexagon"), 1).convex());

  // Lattice volume converges to the analytic volume.
  const Nodes3D s = lattice_nodes_3d(Shape3D::sphere(1), 0.05);
  EXPECT_NEAR(s.size() * std::pow(0.05, 3), 4.0 / 3.0 * pi, 0.02);
  const Nodes3D b = lattice_nodes_3d(Shape3D::box(1, 1, 1), 0.25);
  EXPECT_EQ(b.size(), 125u); // -0.5 .. 0.5 in steps of 0.25

  // Extruded plus: bonds across the gap between arms are pruned; Bhattacharya & Lipton 2023, §5 on
  // the projection agrees with the exact prism test; cell list vs brute.
  const double h = 0.1;
  const Nodes3D n = lattice_nodes_3d(plus, h);
  const auto all = create_bonds_3d(plus, n.x, 3 * h, Pruning::None);
  const auto extended = create_bonds_3d(plus, n.x, 3 * h, Pruning::ExtendedBoundary);
  const auto exact = create_bonds_3d(plus, n.x, 3 * h, Pruning::Exact);
  EXPECT_EQ(extended, exact);
  EXPECT_LT(extended.size(), all.size());
  std::size_t brute = 0;
  for (std::size_t i = 0; i < n.size(); ++i)
    for (std::size_t j = i + 1; j < n.size(); ++j)
      brute += within_horizon((n.x[i] - n.x[j]).norm2(), 3 * h);
  EXPECT_EQ(all.size(), brute);
  EXPECT_TRUE(segment_inside_exact_3d(plus, {0.9, 0.1, -0.25}, {-0.1, 0.15, 0.25}));
  EXPECT_FALSE(segment_inside_exact_3d(plus, {0.9, 0.15, 0}, {0.15, 0.9, 0}));
  EXPECT_FALSE(segment_inside_exact_3d(plus, {0.9, 0.1, 0}, {0.9, 0.1, 0.3})); // leaves in z
}

TEST(GeometryBonds, GrainHelpersAndErrors)
{
  const Grain2D g = discretize_shape("plus", {}, 0.1, 0.3);
  EXPECT_GT(g.nodes.size(), 100u);
  EXPECT_FALSE(g.bonds.empty());
  GrainOptions o;
  o.cuts = {{{-1, 0.05}, {0, 0.05}}};
  o.lattice.volume = NodalVolume::ExactClip;
  const Grain2D c = discretize_shape("plus", {}, 0.1, 0.3, o);
  EXPECT_LT(c.bonds.size(), g.bonds.size());
  double vsum = 0;
  for (double v : c.nodes.volume) vsum += v;
  EXPECT_NEAR(vsum, make_shape("plus").area(), 1e-12);

  std::string e = geometryErrorOf([] { discretize_shape("disk", {}, 3.0, 4.0); });
  EXPECT_NE(e.find("node spacing 3 is larger than the grain"), std::string::npos) << e;
  e = geometryErrorOf([] { discretize_shape("disk", {}, 0.1, 0.05); });
  EXPECT_NE(e.find("horizon 0.05 is smaller than the node spacing 0.1"), std::string::npos) << e;
  e = geometryErrorOf([] { discretize_shape("blob", {}, 0.1, 0.3); });
  EXPECT_NE(e.find("unknown grain shape 'blob'; known shapes: disk"), std::string::npos) << e;
  e = geometryErrorOf([] { discretize_polygon_file("/nope.poly", 0.1, 0.3); });
  EXPECT_NE(e.find("cannot open polygon file '/nope.poly'"), std::string::npos) << e;
  e = geometryErrorOf([] {
    discretize_grain(Polygon({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), 0.1, 0.3);
  });
  EXPECT_NE(e.find("self-intersecting"), std::string::npos) << e;
  e = geometryErrorOf([] { discretize_grain_3d(Shape3D::sphere(1), 5, 6); });
  EXPECT_NE(e.find("larger than the grain"), std::string::npos) << e;

  // Mesh grain: volumes from eq. 31 and bonds (square with a hole, pruned).
  const Mesh2D m =
      read_gmsh_mesh(std::string(PERIDEM_SOURCE_DIR) + "/unittest/core/data/square_hole_v41.msh");
  const Polygon D({{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                  {{{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}});
  const Grain2D mg = mesh_grain(m, 0.7, &D);
  const Grain2D mu = mesh_grain(m, 0.7);
  EXPECT_LT(mg.bonds.size(), mu.bonds.size()); // bonds across the hole pruned
  EXPECT_THROW(mesh_grain(m, 0.01), GeometryError);
}
