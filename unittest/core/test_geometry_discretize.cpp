/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Discretization: lattice nodes and volumes (h^2 or exactly clipped cells),
// Gmsh import with P1/Q1 nodal volumes (Jha et al. 2021, §3.1 eq. 31).
#include "peridem_geometry_discretize.h"
#include "peridem_geometry_shapes.h"

#include "geometry_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numeric>

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
  std::vector<Polygon> shapes;
  for (const auto &name : builtin_shape_names()) shapes.push_back(make_shape(name));
  shapes.push_back(
      read_polygon_file(std::string(PERIDEM_SOURCE_DIR) + "/potentials/shapes/star.poly"));
  shapes.push_back(read_polygon_file(std::string(PERIDEM_SOURCE_DIR) +
                                     "/potentials/shapes/plate_with_holes.poly"));
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
