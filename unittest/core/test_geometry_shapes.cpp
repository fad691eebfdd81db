/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Built-in shapes (areas vs analytic values, Bhattacharya & Lipton 2023, §7.2 parameters) and the
// polygon file reader (format doc/peridem_polygon_format.rst).
#include "peridem_geometry_shapes.h"

#include "geometry_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

using namespace peridem;

namespace {
Polygon parse(const std::string &text)
{
  std::istringstream in(text);
  return parse_polygon(in, "test.poly");
}
} // namespace

TEST(GeometryShapes, AnalyticAreas)
{
  const double pi = M_PI;
  // Regular n-gon of circumradius R: (n/2) R^2 sin(2 pi / n).
  EXPECT_NEAR(make_shape("disk").area(), 32 * std::sin(2 * pi / 64), 1e-14);
  EXPECT_NEAR(make_shape("disk", {{"segments", 4096}}).area(), pi, 1e-5);
  EXPECT_NEAR(make_shape("square").area(), 2.0, 1e-14); // side sqrt(2) R
  EXPECT_DOUBLE_EQ(make_shape("rectangle", {{"width", 3}, {"height", 0.5}}).area(), 1.5);
  EXPECT_NEAR(make_shape("hexagon").area(), 1.5 * std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(make_shape("polygon", {{"sides", 5}, {"radius", 2}}).area(),
              2.5 * 4 * std::sin(2 * pi / 5), 1e-13);
  // Plus: two 2R x w bars minus the doubly counted w x w centre.
  EXPECT_NEAR(make_shape("plus").area(), 2 * 2 * 0.4 - 0.16, 1e-14);
  EXPECT_NEAR(make_shape("ring").area(), 32 * std::sin(2 * pi / 64) * (1 - 0.36), 1e-14);
  EXPECT_NEAR(make_shape("neck").area(), 2 * 2 - 2 * 0.5, 1e-14); // L W - L (W - Wn) / 2
  EXPECT_NEAR(make_shape("notched_plate").area(), 1 - 0.5 * 0.1, 1e-14);
  EXPECT_NEAR(make_shape("v_notched_plate").area(), 1 - 0.5 * 0.5 * 0.2, 1e-14);
  for (const auto &name : builtin_shape_names()) {
    const Polygon p = make_shape(name);
    EXPECT_TRUE(p.validation_error().empty()) << name;
    if (name == "perturbed_disk") continue;
    EXPECT_NEAR(p.centroid().y, 0.0, 1e-14) << name; // symmetric in y...
    if (name.find("notched") == std::string::npos)
      EXPECT_NEAR(p.centroid().x, 0.0, 1e-14) << name; // ...and most in x
    if (name != "ring")
      EXPECT_TRUE(p.contains({0.1, 0.1})) << name;
    else
      EXPECT_FALSE(p.contains({0.1, 0.1}));
  }
}

TEST(GeometryShapes, PerturbedDiskFollowsSeed)
{
  // Bhattacharya & Lipton 2023, §7.2: r_i = R (1 - X_i), X_i in [0, 1 - phi]: radii in [phi R, R].
  const Polygon a = make_perturbed_disk(2.0, 20, 0.6, 7), b = make_perturbed_disk(2.0, 20, 0.6, 7);
  const Polygon c = make_perturbed_disk(2.0, 20, 0.6, 8);
  ASSERT_EQ(a.outer().size(), 20u);
  bool differs = false;
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_EQ(a.outer()[i], b.outer()[i]); // deterministic
    differs = differs || a.outer()[i] != c.outer()[i];
    const double r = a.outer()[i].norm();
    EXPECT_GE(r, 0.6 * 2.0 - 1e-12);
    EXPECT_LE(r, 2.0 + 1e-12);
  }
  EXPECT_TRUE(differs);
  EXPECT_TRUE(a.validation_error().empty());
}

TEST(GeometryShapes, ReflexCorners)
{
  // Plus: 4 reflex corners at (+-w/2, +-w/2); neck: 2; notched plate: 2.
  auto reflex = [](const Polygon &p) {
    int n = 0;
    const Ring &r = p.outer();
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Vec2 &a = r[(i + r.size() - 1) % r.size()], &v = r[i], &c = r[(i + 1) % r.size()];
      n += cross(v - a, c - v) < 0;
    }
    return n;
  };
  EXPECT_EQ(reflex(make_shape("plus")), 4);
  EXPECT_EQ(reflex(make_shape("neck")), 2);
  EXPECT_EQ(reflex(make_shape("notched_plate")), 2);
  EXPECT_EQ(reflex(make_shape("v_notched_plate")), 1);
  EXPECT_EQ(reflex(make_shape("hexagon")), 0);
}

TEST(GeometryShapes, LookupErrors)
{
  const std::string e1 = geometryErrorOf([] { make_shape("banana"); });
  EXPECT_NE(e1.find("unknown grain shape 'banana'"), std::string::npos) << e1;
  EXPECT_NE(e1.find("plus"), std::string::npos) << e1; // lists the known shapes
  EXPECT_NE(e1.find("notched_plate"), std::string::npos) << e1;
  const std::string e2 = geometryErrorOf([] { make_shape("disk", {{"radios", 1}}); });
  EXPECT_NE(e2.find("unknown parameter 'radios'"), std::string::npos) << e2;
  EXPECT_NE(e2.find("radius"), std::string::npos) << e2;
  EXPECT_THROW(make_shape("disk", {{"radius", -1}}), GeometryError);
  EXPECT_THROW(make_shape("disk", {{"segments", 2.5}}), GeometryError);
  EXPECT_THROW(make_shape("ring", {{"inner_radius", 1.5}}), GeometryError);
  EXPECT_THROW(make_shape("plus", {{"arm_width", 3}}), GeometryError);
  EXPECT_THROW(make_shape("notched_plate", {{"notch_length", 2}}), GeometryError);
}

TEST(GeometryShapes, PolygonFiles)
{
  const std::string dir = std::string(PERIDEM_SOURCE_DIR) + "/potentials/shapes/";
  EXPECT_DOUBLE_EQ(read_polygon_file(dir + "L_shape.poly").area(), 3.0);
  // Star: 10 triangles centre-tip-inner, each 0.5 * 1 * 0.5 * sin(36 deg).
  EXPECT_NEAR(read_polygon_file(dir + "star.poly").area(), 10 * 0.25 * std::sin(M_PI / 5), 1e-11);
  const Polygon holes = read_polygon_file(dir + "plate_with_holes.poly");
  EXPECT_NEAR(holes.area(), 2.4 - 0.36 - 0.5 * 0.6 * 0.65, 1e-14);
  EXPECT_EQ(holes.holes().size(), 2u);

  const Polygon p =
      parse("# c\n\nouter  # o\n0 0\n1 0\n1 1\n0 1\nhole\n0.2 0.2\n0.4 0.2\n0.3 0.4\n");
  EXPECT_NEAR(p.area(), 1 - 0.5 * 0.2 * 0.2, 1e-15);

  std::string e = geometryErrorOf([] { read_polygon_file("/nonexistent/x.poly"); });
  EXPECT_NE(e.find("cannot open polygon file '/nonexistent/x.poly'"), std::string::npos) << e;
  e = geometryErrorOf([] { parse("outer\n0 0\n1 zero\n"); });
  EXPECT_NE(e.find("test.poly:3:"), std::string::npos) << e;
  e = geometryErrorOf([] { parse("0 0\n"); });
  EXPECT_NE(e.find("test.poly:1: vertex before any"), std::string::npos) << e;
  e = geometryErrorOf([] { parse("outer\n0 0\n1 0\n1 1\nouter\n"); });
  EXPECT_NE(e.find("test.poly:5: more than one 'outer'"), std::string::npos) << e;
  e = geometryErrorOf([] { parse("hole\n0 0\n1 0\n1 1\n"); });
  EXPECT_NE(e.find("no 'outer' section"), std::string::npos) << e;
  e = geometryErrorOf([] { parse("outer\n0 0\n2 2\n2 0\n0 2\n"); });
  EXPECT_NE(e.find("test.poly: invalid polygon: polygon outer ring is self-intersecting"),
            std::string::npos)
      << e;
  e = geometryErrorOf([] { parse("outer\n0 0\n1 0\n1 1\nhole\n5 5\n6 5\n6 6\n"); });
  EXPECT_NE(e.find("hole 1 is not strictly inside"), std::string::npos) << e;
  e = geometryErrorOf([] { parse("outer\n0 0 0\n"); });
  EXPECT_NE(e.find("test.poly:2: expected a vertex line"), std::string::npos) << e;
}
