// Bond creation (cell list vs brute force), notch/crack removal, 3D grains and
// the one-call grain helpers with their input errors.
#include "peridem_geometry_grain.h"
#include "peridem_geometry_shapes.h"

#include "geometry_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace peridem;

namespace {
std::vector<Bond> bruteForce(const std::vector<Vec2> &x, double eps)
{
  std::vector<Bond> b;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j)
      if (withinHorizon((x[i] - x[j]).norm2(), eps)) b.emplace_back(int(i), int(j));
  return b;
}
} // namespace

TEST(GeometryBonds, CellListEqualsBruteForce)
{
  const Polygon sq = makeShape("square", {{"side", 2.0}});
  for (double h : {0.2, 0.1, 0.05}) {
    for (double m : {1.0, 3.0, 4.0}) {
      const Nodes2D n = latticeNodes(sq, h);
      const auto b = pairsWithinHorizon(n.x, m * h);
      EXPECT_EQ(b, bruteForce(n.x, m * h)) << h << " " << m;
      for (const Bond &p : b) EXPECT_LT(p.first, p.second);
      // Convex square: no pruning, and the interior node degree matches the
      // lattice count of points with |(i, j)| <= m (m = 3: 28, m = 4: 48).
      EXPECT_EQ(createBonds(sq, n.x, m * h, Pruning::Seed), b);
    }
  }
  const Nodes2D n = latticeNodes(sq, 0.1);
  const auto b = pairsWithinHorizon(n.x, 0.3);
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
  const auto b3 = pairsWithinHorizon(c, 3, 0.15);
  std::size_t brute = 0;
  for (int i = 0; i < 400; ++i)
    for (int j = i + 1; j < 400; ++j) {
      double d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += std::pow(c[3 * i + d] - c[3 * j + d], 2);
      brute += withinHorizon(d2, 0.15);
    }
  EXPECT_EQ(b3.size(), brute);
  EXPECT_GT(brute, 100u);
}

TEST(GeometryBonds, CutsRemoveBondsAcrossNotch)
{
  // Bhattacharya & Lipton 2023, §6.4: unit square with a notch from the left edge to the centre.
  const Polygon sq = makeShape("square", {{"side", 1.0}});
  const double h = 0.05;
  LatticeOptions lo;
  lo.offset = {0.5 * h, 0.5 * h}; // no node on the crack line y = 0
  const Nodes2D n = latticeNodes(sq, h, lo);
  auto bonds = createBonds(sq, n.x, 3 * h);
  const auto before = bonds;
  const std::size_t removed = removeBondsCrossing(bonds, n.x, {{{-0.5, 0.0}, {0.0, 0.0}}});
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
  EXPECT_FALSE(bondCrossesCut({0, 0}, {1, 1}, {{-1, 0}, {1, 0}}));
  EXPECT_FALSE(bondCrossesCut({-0.5, 0}, {0.5, 0}, {{-1, 0}, {1, 0}}));
  EXPECT_TRUE(bondCrossesCut({0, -1}, {0, 1}, {{-1, 0}, {0, 0}})); // through the tip
  EXPECT_FALSE(bondCrossesCut({0.1, -1}, {0.1, 1}, {{-1, 0}, {0, 0}}));
}

TEST(GeometryBonds, Shapes3D)
{
  const double pi = M_PI;
  EXPECT_NEAR(Shape3D::sphere(2).volume(), 32.0 / 3.0 * pi, 1e-13);
  EXPECT_DOUBLE_EQ(Shape3D::box(1, 2, 3).volume(), 6.0);
  EXPECT_NEAR(Shape3D::cylinder(1, 2).volume(), 2 * pi, 1e-14);
  const Shape3D plus = Shape3D::extrusion(makeShape("plus"), 0.5);
  EXPECT_NEAR(plus.volume(), 0.5 * (1.6 - 0.16), 1e-14);
  EXPECT_TRUE(Shape3D::sphere(1).contains({0, 0, 1}));
  EXPECT_FALSE(Shape3D::sphere(1).contains({0.6, 0.6, 0.6}));
  EXPECT_TRUE(Shape3D::cylinder(1, 2).contains({0.7, 0.7, -1}));
  EXPECT_FALSE(Shape3D::cylinder(1, 2).contains({0.8, 0.8, 0}));
  EXPECT_TRUE(plus.contains({0.9, 0.1, 0.25}));
  EXPECT_FALSE(plus.contains({0.9, 0.9, 0}));
  EXPECT_FALSE(plus.convex());
  EXPECT_TRUE(Shape3D::extrusion(makeShape("hexagon"), 1).convex());

  // Lattice volume converges to the analytic volume.
  const Nodes3D s = latticeNodes3D(Shape3D::sphere(1), 0.05);
  EXPECT_NEAR(s.size() * std::pow(0.05, 3), 4.0 / 3.0 * pi, 0.02);
  const Nodes3D b = latticeNodes3D(Shape3D::box(1, 1, 1), 0.25);
  EXPECT_EQ(b.size(), 125u); // -0.5 .. 0.5 in steps of 0.25

  // Extruded plus: bonds across the gap between arms are pruned; Bhattacharya & Lipton 2023, §5 on
  // the projection agrees with the exact prism test; cell list vs brute.
  const double h = 0.1;
  const Nodes3D n = latticeNodes3D(plus, h);
  const auto all = createBonds3D(plus, n.x, 3 * h, Pruning::None);
  const auto seed = createBonds3D(plus, n.x, 3 * h, Pruning::Seed);
  const auto exact = createBonds3D(plus, n.x, 3 * h, Pruning::Exact);
  EXPECT_EQ(seed, exact);
  EXPECT_LT(seed.size(), all.size());
  std::size_t brute = 0;
  for (std::size_t i = 0; i < n.size(); ++i)
    for (std::size_t j = i + 1; j < n.size(); ++j)
      brute += withinHorizon((n.x[i] - n.x[j]).norm2(), 3 * h);
  EXPECT_EQ(all.size(), brute);
  EXPECT_TRUE(segmentInsideExact3D(plus, {0.9, 0.1, -0.25}, {-0.1, 0.15, 0.25}));
  EXPECT_FALSE(segmentInsideExact3D(plus, {0.9, 0.15, 0}, {0.15, 0.9, 0}));
  EXPECT_FALSE(segmentInsideExact3D(plus, {0.9, 0.1, 0}, {0.9, 0.1, 0.3})); // leaves in z
}

TEST(GeometryBonds, GrainHelpersAndErrors)
{
  const Grain2D g = discretizeShape("plus", {}, 0.1, 0.3);
  EXPECT_GT(g.nodes.size(), 100u);
  EXPECT_FALSE(g.bonds.empty());
  GrainOptions o;
  o.cuts = {{{-1, 0.05}, {0, 0.05}}};
  o.lattice.volume = NodalVolume::ExactClip;
  const Grain2D c = discretizeShape("plus", {}, 0.1, 0.3, o);
  EXPECT_LT(c.bonds.size(), g.bonds.size());
  double vsum = 0;
  for (double v : c.nodes.volume) vsum += v;
  EXPECT_NEAR(vsum, makeShape("plus").area(), 1e-12);

  std::string e = geometryErrorOf([] { discretizeShape("disk", {}, 3.0, 4.0); });
  EXPECT_NE(e.find("node spacing 3 is larger than the grain"), std::string::npos) << e;
  e = geometryErrorOf([] { discretizeShape("disk", {}, 0.1, 0.05); });
  EXPECT_NE(e.find("horizon 0.05 is smaller than the node spacing 0.1"), std::string::npos) << e;
  e = geometryErrorOf([] { discretizeShape("blob", {}, 0.1, 0.3); });
  EXPECT_NE(e.find("unknown grain shape 'blob'; known shapes: disk"), std::string::npos) << e;
  e = geometryErrorOf([] { discretizePolygonFile("/nope.poly", 0.1, 0.3); });
  EXPECT_NE(e.find("cannot open polygon file '/nope.poly'"), std::string::npos) << e;
  e = geometryErrorOf([] { discretizeGrain(Polygon({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), 0.1, 0.3); });
  EXPECT_NE(e.find("self-intersecting"), std::string::npos) << e;
  e = geometryErrorOf([] { discretizeGrain3D(Shape3D::sphere(1), 5, 6); });
  EXPECT_NE(e.find("larger than the grain"), std::string::npos) << e;

  // Mesh grain: volumes from eq. 31 and bonds (square with a hole, pruned).
  const Mesh2D m =
      readGmshMesh(std::string(PERIDEM_SOURCE_DIR) + "/unittest/core/data/square_hole_v41.msh");
  const Polygon D({{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                  {{{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}});
  const Grain2D mg = meshGrain(m, 0.7, &D);
  const Grain2D mu = meshGrain(m, 0.7);
  EXPECT_LT(mg.bonds.size(), mu.bonds.size()); // bonds across the hole pruned
  EXPECT_THROW(meshGrain(m, 0.01), GeometryError);
}
