/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Discretization: lattice nodes and volumes (h^2 or exactly clipped cells),
// Gmsh import with P1/Q1 nodal volumes (Jha et al. 2021, §3.1 eq. 31), and
// lattice grains with the nodes of boundary cells moved onto the outline
// (NodePlacement::Outline): positions on the boundary, exact volumes, the
// merge distance, bond pruning with both ends on the boundary.
#include "peridem_geometry_bonds.h"
#include "peridem_geometry_discretize.h"
#include "peridem_geometry_grain.h"
#include "peridem_geometry_shapes.h"
#include "peridem_geometry_visibility.h"

#include "geometry_test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <set>

using namespace peridem;

namespace {
double sum(const std::vector<double> &v)
{
  return std::accumulate(v.begin(), v.end(), 0.0);
}
const std::string kData = std::string(PERIDEM_SOURCE_DIR) + "/unittest/core/data/";
std::string errorOf(const std::string &path)
{
  return geometryErrorOf([&] { read_gmsh_mesh(path); });
}
std::string writeTemp(const std::string &name, const std::string &text)
{
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}
// the built-in shapes, a star and a plate with holes
std::vector<Polygon> test_shapes()
{
  std::vector<Polygon> shapes;
  for (const auto &name : builtin_shape_names()) shapes.push_back(make_shape(name));
  for (const char *file : {"star.poly", "plate_with_holes.poly"})
    shapes.push_back(
        read_polygon_file(std::string(PERIDEM_SOURCE_DIR) + "/potentials/shapes/" + file));
  return shapes;
}

LatticeOptions outline(Vec2 offset = {0.0, 0.0})
{
  LatticeOptions o;
  o.offset = offset;
  o.volume = NodalVolume::ExactClip;
  o.placement = NodePlacement::Outline;
  return o;
}

double smallest_distance(const Nodes2D &n)
{
  std::vector<double> c;
  for (const Vec2 &p : n.x) c.insert(c.end(), {p.x, p.y});
  return smallest_pair_distance(c, 2, 1e-3);
}

double ring_distance(const Ring &r, const Vec2 &p)
{
  double d = INFINITY;
  for (std::size_t i = 0; i < r.size(); ++i)
    d = std::min(d, point_segment_distance(p, r[i], r[(i + 1) % r.size()]));
  return d;
}

} // namespace

TEST(GeometryDiscretize, SquareLatticeCounts)
{
  // [-1,1]^2 with h = 0.2 and the default lattice through the origin: nodes at
  // -1, -0.8, ..., 1 in each direction (boundary nodes kept): 11 x 11.
  const Polygon sq = make_shape("square", {{"side", 2.0}});
  const Nodes2D n = lattice_nodes(sq, 0.2);
  EXPECT_EQ(n.size(), 121u);
  for (double v : n.volume) EXPECT_DOUBLE_EQ(v, 0.04);
  // Half-cell offset: nodes at +-0.1 ... +-0.9: 10 x 10, exact volumes = h^2.
  LatticeOptions o;
  o.offset = {0.1, 0.1};
  o.volume = NodalVolume::ExactClip;
  const Nodes2D m = lattice_nodes(sq, 0.2, o);
  EXPECT_EQ(m.size(), 100u);
  for (double v : m.volume) EXPECT_NEAR(v, 0.04, 1e-15);
  // Every node is exactly inside the shape.
  for (const Vec2 &p : n.x) EXPECT_TRUE(sq.contains_exact(p));
}

TEST(GeometryDiscretize, ExactClippedVolumesSumToArea)
{
  std::vector<Polygon> shapes = test_shapes();
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    for (double h : {0.2, 0.05, 0.0123}) {
      LatticeOptions o;
      o.volume = NodalVolume::ExactClip;
      o.offset = {0.013 * s, -0.007};
      Polygon D = shapes[s];
      D.rotate(0.1 * s);
      const Nodes2D n = lattice_nodes(D, h, o);
      const double total = sum(n.volume), area = D.area();
      EXPECT_NEAR(total, area, 1e-12 * area) << "shape " << s << " h " << h;
      for (double v : n.volume) {
        EXPECT_GT(v, 0.0);
        EXPECT_LE(v, 3.0 * h * h); // a cell plus at most a few orphan slivers
      }
      // h^2 volumes approximate the area to O(h * perimeter).
      const Nodes2D c = lattice_nodes(D, h);
      EXPECT_NEAR(sum(c.volume), area, 0.2 * h * 12.0) << "shape " << s;
    }
  }
}

TEST(GeometryDiscretize, ClippedBoxArea)
{
  const Polygon ring = make_ring(1.0, 0.5, 8);
  EXPECT_NEAR(clipped_box_area(ring, {-2, -2}, {2, 2}), ring.area(), 1e-15);
  EXPECT_NEAR(clipped_box_area(ring, {0, 0}, {2, 2}), ring.area() / 4, 1e-15);
  EXPECT_NEAR(clipped_box_area(ring, {-0.1, -0.1}, {0.1, 0.1}), 0.0, 1e-16); // in the hole
  const Polygon L({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  EXPECT_NEAR(clipped_box_area(L, {0.5, 0.5}, {1.5, 1.5}), 0.75, 1e-15);
}

TEST(GeometryDiscretize, GmshTrianglesV22AndV41)
{
  // Unit square with a 0.2 x 0.2 hole; the two files hold the same mesh.
  for (const char *f : {"square_hole_v22.msh", "square_hole_v41.msh"}) {
    const Mesh2D m = read_gmsh_mesh(kData + f);
    EXPECT_GT(m.triangles.size(), 10u) << f;
    EXPECT_TRUE(m.quads.empty());
    EXPECT_NEAR(m.area(), 0.96, 1e-14) << f;
    const Nodes2D n = mesh_nodes(m);
    EXPECT_NEAR(sum(n.volume), m.area(), 1e-14) << f;
    // Only vertices of triangles are nodes; none inside the hole.
    for (const Vec2 &p : n.x)
      EXPECT_FALSE(p.x > 0.4 + 1e-12 && p.x < 0.6 - 1e-12 && p.y > 0.4 + 1e-12 &&
                   p.y < 0.6 - 1e-12);
  }
  EXPECT_EQ(read_gmsh_mesh(kData + "square_hole_v22.msh").triangles.size(),
            read_gmsh_mesh(kData + "square_hole_v41.msh").triangles.size());
}

TEST(GeometryDiscretize, GmshQuads)
{
  // 2 x 1 rectangle, 4 x 2 transfinite quads of 0.5 x 0.5: corner nodes get
  // 1/4 of a quad, edge nodes 2/4, interior nodes 4/4 (bilinear functions).
  const Mesh2D m = read_gmsh_mesh(kData + "rect_quads_v41.msh");
  EXPECT_EQ(m.quads.size(), 8u);
  const Nodes2D n = mesh_nodes(m);
  EXPECT_EQ(n.size(), 15u);
  EXPECT_NEAR(sum(n.volume), m.area(), 1e-14);
  EXPECT_NEAR(m.area(), 2.0, 1e-12);
  for (std::size_t i = 0; i < n.size(); ++i) {
    const bool ex = std::fabs(n.x[i].x) < 1e-12 || std::fabs(n.x[i].x - 2) < 1e-12;
    const bool ey = std::fabs(n.x[i].y) < 1e-12 || std::fabs(n.x[i].y - 1) < 1e-12;
    const double expect = 0.25 * (ex && ey ? 0.25 : ex || ey ? 0.5 : 1.0);
    EXPECT_NEAR(n.volume[i], expect, 1e-12); // Gmsh prints ~13 digits
  }
}

TEST(GeometryDiscretize, GmshHandWrittenAndErrors)
{
  // Two triangles forming the unit square: corner volumes 1/3*1/2 (twice for
  // the diagonal nodes).
  const std::string ok =
      writeTemp("two.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n"
                           "2 1 0 0\n3 1 1 0\n4 0 1 0\n9 5 5 0\n$EndNodes\n$Elements\n3\n"
                           "1 15 2 0 1 1\n2 2 2 0 1 1 2 3\n3 2 2 0 1 1 3 4\n$EndElements\n");
  const Nodes2D n = mesh_nodes(read_gmsh_mesh(ok));
  ASSERT_EQ(n.size(), 4u); // node 9 belongs to no element
  EXPECT_NEAR(n.volume[0], 1.0 / 3.0, 1e-16);
  EXPECT_NEAR(n.volume[1], 1.0 / 6.0, 1e-16);

  std::string e = errorOf("/nonexistent/grain.msh");
  EXPECT_NE(e.find("cannot open Gmsh file '/nonexistent/grain.msh'"), std::string::npos) << e;
  e = errorOf(writeTemp("bin.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n"));
  EXPECT_NE(e.find("bin.msh:2: binary"), std::string::npos) << e;
  e = errorOf(writeTemp("v3.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n"));
  EXPECT_NE(e.find("unsupported Gmsh format 3.0"), std::string::npos) << e;
  e = errorOf(writeTemp("badnode.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 x 0\n"
                                       "$EndNodes\n"));
  EXPECT_NE(e.find("badnode.msh:6: expected a number, got 'x'"), std::string::npos) << e;
  e = errorOf(writeTemp("unk.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n"
                                   "$EndNodes\n$Elements\n1\n1 2 0 1 2 3\n$EndElements\n"));
  EXPECT_NE(e.find("unk.msh:10: element refers to unknown node 2"), std::string::npos) << e;
  e = errorOf(writeTemp("p2.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n"
                                  "$EndNodes\n$Elements\n1\n1 9 0 1 1 1 1 1 1\n$EndElements\n"));
  EXPECT_NE(e.find("unsupported element type 9"), std::string::npos) << e;
  e = errorOf(writeTemp("noel.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n"
                                    "$EndNodes\n"));
  EXPECT_NE(e.find("no triangle"), std::string::npos) << e;
  e = errorOf(writeTemp("trunc.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n"));
  EXPECT_NE(e.find("unexpected end of file"), std::string::npos) << e;
}

TEST(GeometryOutline, AlignedSquareKeepsLatticeNodesWithOuterOnesOnTheEdges)
{
  // side 2m h: the outermost lattice rows lie on the edges (up to round-off of
  // m h), so outline keeps the node count and puts them exactly on the edges
  for (const double side : {2.0, 1.41421}) {
    const int m = 7;
    const double h = side / (2 * m), half = 0.5 * side;
    const Polygon sq = make_shape("square", {{"side", side}});
    const double edge = sq.outer()[0].x > 0 ? sq.outer()[0].x : -sq.outer()[0].x;
    ASSERT_EQ(edge, half);
    LatticeOptions exact;
    exact.volume = NodalVolume::ExactClip;
    const Nodes2D lat = lattice_nodes(sq, h, exact), out = lattice_nodes(sq, h, outline());
    ASSERT_EQ(out.size(), lat.size());
    EXPECT_EQ(out.size(), static_cast<std::size_t>((2 * m + 1) * (2 * m + 1)));
    int on_edge = 0;
    for (std::size_t k = 0; k < out.size(); ++k) {
      const Vec2 p = out.x[k];
      EXPECT_NEAR((p - lat.x[k]).norm(), 0.0, 1e-12 * side);
      if (std::fabs(lat.x[k].x) > half - 0.25 * h || std::fabs(lat.x[k].y) > half - 0.25 * h) {
        EXPECT_TRUE(std::fabs(p.x) == half || std::fabs(p.y) == half) << p.x << " " << p.y;
        on_edge++;
      }
    }
    EXPECT_EQ(on_edge, 8 * m);
    EXPECT_NEAR(sum(out.volume), sq.area(), 1e-12 * sq.area());
    EXPECT_NEAR(smallest_distance(out), h, 1e-12 * h);
  }
}

TEST(GeometryOutline, DiskOuterNodesOnTheOutline)
{
  // the disk is a 64-gon: its boundary points lie between R cos(pi/64) and R
  const double R = 1.0, h = 0.1;
  const Polygon disk = make_shape("disk", {{"radius", R}});
  const Nodes2D n = lattice_nodes(disk, h, outline({0.031, -0.017}));
  std::vector<double> angles;
  for (const Vec2 &p : n.x) {
    const double d = disk.boundary_distance(p);
    // a node is on the outline or the lattice point of a cell inside the disk
    EXPECT_TRUE(d <= 1e-12 * R || d >= 0.5 * h) << d;
    if (d > 1e-12 * R) continue;
    EXPECT_LE(p.norm(), R * (1 + 1e-12));
    EXPECT_GE(p.norm(), R * std::cos(M_PI / 64) * (1 - 1e-12));
    angles.push_back(std::atan2(p.y, p.x));
  }
  // the outline nodes go all round, about h apart (no gap above 1.5 h)
  ASSERT_GT(angles.size(), 50u);
  std::sort(angles.begin(), angles.end());
  angles.push_back(angles.front() + 2 * M_PI);
  for (std::size_t k = 1; k < angles.size(); ++k)
    EXPECT_LT(R * (angles[k] - angles[k - 1]), 1.5 * h);
  EXPECT_NEAR(sum(n.volume), disk.area(), 1e-12 * disk.area());
  // no light nodes: a cell that only just reaches into the disk joins a neighbour
  for (double v : n.volume) EXPECT_GE(v, outline_small_fraction * h * h);
}

TEST(GeometryOutline, RingNodesOnBothCircles)
{
  const double R = 1.0, r = 0.6, h = 0.07;
  const Polygon ring = make_shape("ring", {{"radius", R}, {"inner_radius", r}});
  const Nodes2D n = lattice_nodes(ring, h, outline({0.011, 0.023}));
  int inner = 0, outer = 0;
  for (const Vec2 &p : n.x) {
    if (ring_distance(ring.ring(1), p) <= 1e-12 * R) {
      inner++;
      EXPECT_LE(p.norm(), r * (1 + 1e-12));
      EXPECT_GE(p.norm(), r * std::cos(M_PI / 64) * (1 - 1e-12));
    } else if (ring_distance(ring.ring(0), p) <= 1e-12 * R) {
      outer++;
    } else {
      EXPECT_GE(ring.boundary_distance(p), 0.5 * h);
    }
  }
  // about one node per h of each circle
  EXPECT_GT(inner, 0.8 * 2 * M_PI * r / h);
  EXPECT_GT(outer, 0.8 * 2 * M_PI * R / h);
  EXPECT_NEAR(sum(n.volume), ring.area(), 1e-12 * ring.area());
}

TEST(GeometryOutline, VolumesSumToAreaAndNodesAreApart)
{
  std::vector<Polygon> shapes = test_shapes();
  // arms thinner than h and than h/2: their nodes merge across the arm
  shapes.push_back(make_plus(1.0, 0.07));
  shapes.push_back(make_plus(1.0, 0.03));
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    for (double h : {0.2, 0.1, 0.0123}) {
      Polygon D = shapes[s];
      D.rotate(0.1 * s);
      const Nodes2D n = lattice_nodes(D, h, outline({0.013 * s, -0.007}));
      ASSERT_GE(n.size(), 2u);
      const double area = D.area();
      EXPECT_NEAR(sum(n.volume), area, 1e-12 * area) << "shape " << s << " h " << h;
      EXPECT_GE(smallest_distance(n), outline_merge_fraction * h) << "shape " << s << " h " << h;
      for (std::size_t k = 0; k < n.size(); ++k) {
        EXPECT_TRUE(D.contains_exact(n.x[k])) << "shape " << s << " h " << h << " node " << k;
        EXPECT_GT(n.volume[k], 0.0);
      }
    }
  }
}

TEST(GeometryOutline, CornersCarryNodes)
{
  // a square turned by 30 degrees: the cell holding a corner puts its node on
  // it, the cells near it that project close to it are merged into it
  Polygon sq = make_shape("square", {{"side", 1.0}});
  sq.rotate(M_PI / 6);
  const double h = 0.1;
  const Nodes2D n = lattice_nodes(sq, h, outline({0.004, 0.009}));
  for (const Vec2 &v : sq.outer()) {
    int near = 0, at = 0;
    for (const Vec2 &p : n.x) {
      near += (p - v).norm() < 0.5 * h;
      at += p == v;
    }
    EXPECT_EQ(near, 1);
    EXPECT_EQ(at, 1); // a node on every corner: the node hull is the square
  }
  EXPECT_GE(smallest_distance(n), 0.5 * h);
}

TEST(GeometryOutline, LightCellsMoveTheRowInside)
{
  // half side 2.506 h: the edges just reach into the cells of the row at 3 h (0.006 h^2
  // each); the row at 2 h moves onto the edges instead, corners on the vertices. Half side
  // 2.795 h: light corner cells (0.087 h^2) take over their neighbour on the edge.
  const double h = 0.1;
  for (const double half : {2.506 * h, 2.795 * h}) {
    const Polygon sq = make_shape("square", {{"side", 2 * half}});
    const Nodes2D n = lattice_nodes(sq, h, outline());
    int on_edge = 0;
    for (std::size_t k = 0; k < n.size(); ++k) {
      const Vec2 p = n.x[k];
      EXPECT_GE(n.volume[k], outline_small_fraction * h * h) << p.x << " " << p.y;
      if (std::fabs(p.x) == half || std::fabs(p.y) == half) on_edge++;
    }
    EXPECT_EQ(on_edge, half < 2.6 * h ? 16 : 20);
    for (const Vec2 &v : sq.outer()) EXPECT_EQ(std::count(n.x.begin(), n.x.end(), v), 1);
    EXPECT_NEAR(sum(n.volume), sq.area(), 1e-12 * sq.area());
    EXPECT_GE(smallest_distance(n), 0.5 * h);
  }
}

TEST(GeometryOutline, PruningWithBothEndsOnTheBoundary)
{
  // plus of arm width 0.4: the top edge of the right arm is y = 0.2 (x > 0.2), the
  // right edge of the top arm x = 0.2 (y > 0.2); the notch between them is outside
  const double w = 0.2, h = 0.05, eps = 0.15;
  const Polygon plus = make_plus(1.0, 2 * w);
  for (const Pruning pruning : {Pruning::ExtendedBoundary, Pruning::Exact}) {
    GrainOptions opt;
    opt.lattice = outline({0.013, 0.021});
    opt.pruning = pruning;
    const Grain2D g = discretize_grain(plus, h, eps, opt);
    const std::set<Bond> bonds(g.bonds.begin(), g.bonds.end());
    std::vector<int> arm_top, arm_side;
    for (std::size_t k = 0; k < g.nodes.size(); ++k) {
      const Vec2 p = g.nodes.x[k];
      if (std::fabs(p.y - w) <= 1e-12 && p.x > w + 1e-9) arm_top.push_back(static_cast<int>(k));
      if (std::fabs(p.x - w) <= 1e-12 && p.y > w + 1e-9) arm_side.push_back(static_cast<int>(k));
    }
    ASSERT_GT(arm_top.size(), 5u);
    ASSERT_GT(arm_side.size(), 5u);
    int along = 0, across = 0;
    for (int a : arm_top) {
      for (int b : arm_top) {
        const Vec2 d = g.nodes.x[a] - g.nodes.x[b];
        if (a < b && within_horizon(d.norm2(), eps)) {
          EXPECT_TRUE(bonds.count({a, b})) << "bond along the edge pruned";
          along++;
        }
      }
      for (int b : arm_side) {
        const Vec2 d = g.nodes.x[a] - g.nodes.x[b];
        if (!within_horizon(d.norm2(), eps)) continue;
        EXPECT_FALSE(segment_inside_exact(plus, g.nodes.x[a], g.nodes.x[b]));
        EXPECT_FALSE(bonds.count({std::min(a, b), std::max(a, b)})) << "bond across the notch";
        across++;
      }
    }
    EXPECT_GT(along, 10);
    EXPECT_GE(across, 3);
    // no bond leaves the shape
    for (const Bond &b : g.bonds)
      EXPECT_TRUE(segment_inside_exact(plus, g.nodes.x[b.first], g.nodes.x[b.second]));
  }
}

TEST(GeometryOutline, LatticePlacementIsTheDefault)
{
  for (const auto &name : builtin_shape_names()) {
    for (const NodalVolume v : {NodalVolume::CellArea, NodalVolume::ExactClip}) {
      LatticeOptions def, lat;
      def.volume = lat.volume = v;
      def.offset = lat.offset = {0.017, -0.004};
      lat.placement = NodePlacement::Lattice;
      const Polygon D = make_shape(name);
      const Nodes2D a = lattice_nodes(D, 0.09, def), b = lattice_nodes(D, 0.09, lat);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a.x[k], b.x[k]);
        EXPECT_EQ(a.volume[k], b.volume[k]);
      }
    }
  }
}

TEST(GeometryOutline, NeedsExactVolumes)
{
  LatticeOptions o = outline();
  o.volume = NodalVolume::CellArea;
  EXPECT_EQ(geometryErrorOf([&] { lattice_nodes(make_shape("disk"), 0.1, o); }),
            "nodes on the outline need the exact clipped cell volumes");
}

TEST(GeometryOutline, SegmentMeetsBox)
{
  const Vec2 lo(0, 0), hi(1, 1);
  EXPECT_TRUE(segment_meets_box({-1, 0.5}, {2, 0.5}, lo, hi));    // through
  EXPECT_TRUE(segment_meets_box({0.2, 0.2}, {0.3, 0.4}, lo, hi)); // inside
  EXPECT_TRUE(segment_meets_box({1, -1}, {1, 2}, lo, hi));        // along an edge
  EXPECT_TRUE(segment_meets_box({0, 2}, {2, 0}, lo, hi));         // touches a corner
  EXPECT_FALSE(segment_meets_box({0, 2.1}, {2.1, 0}, lo, hi));
  EXPECT_FALSE(segment_meets_box({1.5, -1}, {1.5, 2}, lo, hi));
  EXPECT_FALSE(segment_meets_box({-1, 0.5}, {-0.1, 0.5}, lo, hi));
}

TEST(GeometryOutline, SmallestPairDistance)
{
  EXPECT_TRUE(std::isinf(smallest_pair_distance({1.0, 2.0}, 2, 0.1)));
  // found beyond the first search radius: 0.1 -> 0.2 -> ... -> 3.2
  EXPECT_DOUBLE_EQ(smallest_pair_distance({0, 0, 3, 0, 3, 4, -4, 7}, 2, 0.1), 3.0);
  EXPECT_DOUBLE_EQ(smallest_pair_distance({0, 0, 0, 1, 1, 1, 0, 0, 0.5}, 3, 1.0), 0.5);
}
