/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Polygon with holes: areas, centroid, point location, transforms, validity.
#include "peridem_geometry_polygon.h"
#include "peridem_geometry_predicates.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace peridem;

namespace {
void expectInvalid(const Polygon &p, const std::string &fragment)
{
  EXPECT_THROW(p.validate(), GeometryError);
  try {
    p.validate();
  } catch (const GeometryError &e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}
} // namespace

TEST(GeometryPolygon, OrientationIsNormalized)
{
  // Outer given clockwise, hole counter-clockwise: both get flipped.
  const Polygon p({{0, 0}, {0, 2}, {2, 2}, {2, 0}}, {{{0.5, 0.5}, {1, 0.5}, {1, 1}, {0.5, 1}}});
  EXPECT_GT(ring_signed_area(p.outer()), 0.0);
  EXPECT_LT(ring_signed_area(p.holes()[0]), 0.0);
  EXPECT_DOUBLE_EQ(p.area(), 4.0 - 0.25);
  // A repeated closing vertex is dropped.
  EXPECT_EQ(Polygon({{0, 0}, {1, 0}, {1, 1}, {0, 0}}).outer().size(), 3u);
}

TEST(GeometryPolygon, CentroidAndBoundingBox)
{
  // L = 2x2 square minus its upper-right unit square: area 3, centroid
  // (4 * (1, 1) - 1 * (1.5, 1.5)) / 3 in both coordinates.
  const Polygon L({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  EXPECT_DOUBLE_EQ(L.area(), 3.0);
  EXPECT_NEAR(L.centroid().x, (4.0 - 1.5) / 3.0, 1e-15);
  EXPECT_NEAR(L.centroid().y, (4.0 - 1.5) / 3.0, 1e-15);
  const BoundingBox b = L.bounding_box();
  EXPECT_EQ(b.lo, Vec2(0, 0));
  EXPECT_EQ(b.hi, Vec2(2, 2));
  // Hole off-centre shifts the centroid away from it.
  const Polygon h({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}},
                  {{{0.2, -0.2}, {0.6, -0.2}, {0.6, 0.2}, {0.2, 0.2}}});
  EXPECT_NEAR(h.centroid().x, -(0.16 * 0.4) / (4 - 0.16), 1e-15);
  EXPECT_NEAR(h.centroid().y, 0.0, 1e-15);
}

TEST(GeometryPolygon, PointInShape)
{
  const Polygon p({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}});
  EXPECT_TRUE(p.contains({0.5, 0.5}));
  EXPECT_FALSE(p.contains({2, 2})); // in the hole
  EXPECT_TRUE(p.contains({1, 2}));  // on the hole boundary
  EXPECT_TRUE(p.contains({4, 4}));  // outer corner
  EXPECT_TRUE(p.contains({0, 2}));  // outer edge
  EXPECT_FALSE(p.contains({4.1, 2}));
  EXPECT_FALSE(p.contains({-1e-6, 2}));
  EXPECT_TRUE(p.contains({-1e-13, 2})); // within the default tolerance
  EXPECT_FALSE(p.contains_exact({-1e-13, 2}));
  EXPECT_EQ(p.locate({0, 2}), 0);
  EXPECT_EQ(p.locate({2, 2}), -1);
  EXPECT_EQ(p.locate({0.5, 2}), 1);
  EXPECT_EQ(p.locate({2, 1}), 0);
}

TEST(GeometryPolygon, Transforms)
{
  Polygon p({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
  p.translate({1, 1}).scale(2.0, {1, 1});
  EXPECT_DOUBLE_EQ(p.area(), 8.0);
  EXPECT_NEAR(p.centroid().x, 3.0, 1e-14);
  EXPECT_NEAR(p.centroid().y, 2.0, 1e-14);
  p.rotate(M_PI / 2, {3, 2});
  EXPECT_NEAR(p.area(), 8.0, 1e-13);
  EXPECT_NEAR(p.bounding_box().hi.x - p.bounding_box().lo.x, 2.0, 1e-13);
  EXPECT_NEAR(p.bounding_box().hi.y - p.bounding_box().lo.y, 4.0, 1e-13);
  EXPECT_THROW(p.scale(-1.0), GeometryError);
}

TEST(GeometryPolygon, ValidityErrors)
{
  EXPECT_TRUE(Polygon({{0, 0}, {1, 0}, {0, 1}}).validation_error().empty());
  expectInvalid(Polygon({{0, 0}, {1, 0}}), "fewer than 3");
  expectInvalid(Polygon({{0, 0}, {1, 0}, {2, 0}}), "zero area");
  expectInvalid(Polygon({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), "self-intersecting"); // bow tie
  expectInvalid(Polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{5, 5}, {6, 5}, {6, 6}}}),
                "not strictly inside");
  expectInvalid(Polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{-1, 1}, {1, 1}, {1, 2}}}),
                "not strictly inside");
  expectInvalid(Polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{2, 2}, {4, 2}, {4, 4}, {2, 4}}}),
                "not strictly inside"); // hole touching the outer ring
  expectInvalid(Polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                        {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}, {{1.5, 1.5}, {3, 1.5}, {3, 3}}}),
                "overlap");
  expectInvalid(Polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                        {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}, {{1.5, 1.5}, {2, 1.5}, {2, 2}}}),
                "overlap"); // hole inside a hole
}

TEST(GeometryPolygon, ExactOrientation)
{
  // Nearly collinear points where naive double evaluation is unreliable:
  // points on the line y = x at coordinates that are not exactly halves.
  const Vec2 a(0.5, 0.5), b(12, 12), c(24, 24);
  EXPECT_EQ(orient2d(a, b, c), 0);
  EXPECT_EQ(orient2d(a, b, Vec2(0.1, 0.1)), 0);
  // 0.1 + 1e-17 rounds up to the next double: one ulp above the line.
  EXPECT_EQ(orient2d(a, b, Vec2(0.1, 0.1 + 1e-17)), 1);
  EXPECT_EQ(orient2d(a, b, Vec2(0.1, std::nextafter(0.1, 0.0))), -1);
  const Vec2 e(0.5, std::nextafter(0.5, 1.0));
  EXPECT_EQ(orient2d(b, c, e), 1);
  EXPECT_EQ(orient2d(c, b, e), -1);
}
