/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Bed measures: the hole of a ring lattice (the area the ring volume
// fraction 0.92 of Bhattacharya & Lipton 2023, §7.3 counts) and the median surface.

#include "peridem_bed.h"

#include "gtest/gtest.h"

#include <cmath>
#include <vector>

namespace {
// nodes of a square lattice (spacing h, turned by deg) with r_in <= |x| <= R
std::vector<double> ring(double R, double r_in, double h, double deg)
{
  const double c = std::cos(deg * M_PI / 180.0), s = std::sin(deg * M_PI / 180.0);
  std::vector<double> xy;
  const int m = int(R / h) + 1;
  for (int i = -m; i <= m; i++)
    for (int j = -m; j <= m; j++) {
      const double u = i * h, v = j * h, r = std::hypot(u, v);
      if (r < r_in || r > R) continue;
      xy.push_back(c * u - s * v);
      xy.push_back(s * u + c * v);
    }
  return xy;
}
} // namespace

TEST(Bed, RingHoleArea)
{
  for (const double deg : {0.0, 17.0, 45.0}) {
    const double h = 0.025;
    const double a = peridem::hole_area_2d(ring(1.0, 0.5, h, deg), h);
    // the documented bias: the hole radius is short by about 0.21 h plus the
    // staircase of the lattice (measured 0.764 against pi/4 = 0.785)
    EXPECT_NEAR(a, M_PI * 0.25, 0.04 * M_PI * 0.25) << deg;
    EXPECT_GT(a, M_PI * std::pow(0.5 - 0.35 * h, 2)) << deg;
    EXPECT_LT(a, M_PI * 0.25) << deg;
  }
  // a solid disk has no hole, at any orientation
  for (const double deg : {0.0, 17.0, 45.0})
    EXPECT_EQ(peridem::hole_area_2d(ring(1.0, 0.0, 0.05, deg), 0.05), 0.0) << deg;
  // a notch open to the outside is not a hole: a C made by removing a slot
  std::vector<double> xy = ring(1.0, 0.5, 0.05, 0.0), c;
  for (size_t k = 0; k < xy.size(); k += 2)
    if (!(xy[k] > 0.0 && std::fabs(xy[k + 1]) < 0.2)) c.insert(c.end(), {xy[k], xy[k + 1]});
  EXPECT_EQ(peridem::hole_area_2d(c, 0.05), 0.0);
}

TEST(Bed, MedianSurfaceSkipsEmptyBins)
{
  EXPECT_EQ(peridem::median_of_bins({1.0, 5.0, -1e308, 2.0}), 2.0);
  EXPECT_EQ(peridem::median_of_bins({1.0, 3.0, 2.0, 10.0}), 2.5);
  EXPECT_EQ(peridem::median_of_bins({-1e308}), 0.0);
}
