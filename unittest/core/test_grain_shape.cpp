/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Principal axes of node clouds with known second moments: an nx x ny
// lattice of spacing h has variances h^2 (n^2 - 1) / 12 along its sides.

#include "peridem_grain_shape.h"

#include "gtest/gtest.h"

#include <cmath>
#include <vector>

namespace {

// central second moments of an nx x ny lattice turned by `deg` about z
void lattice_moments(int nx, int ny, double h, double deg, double s[6])
{
  const double c = std::cos(deg * M_PI / 180.0), sn = std::sin(deg * M_PI / 180.0);
  for (int k = 0; k < 6; k++) s[k] = 0.0;
  const int n = nx * ny;
  for (int i = 0; i < nx; i++)
    for (int j = 0; j < ny; j++) {
      const double u = (i - 0.5 * (nx - 1)) * h, v = (j - 0.5 * (ny - 1)) * h;
      const double x = c * u - sn * v, y = sn * u + c * v;
      s[0] += x * x / n;
      s[1] += y * y / n;
      s[3] += x * y / n;
    }
}

} // namespace

TEST(GrainShape, LatticeVariancesAndAngle)
{
  for (const double deg : {0.0, 30.0, -60.0, 89.0, 135.0}) {
    double s[6];
    lattice_moments(21, 11, 0.1, deg, s);
    const peridem::PrincipalAxes p = peridem::principal_axes(s);
    EXPECT_NEAR(p.values[0], 0.01 * (21 * 21 - 1) / 12.0, 1e-12) << deg;
    EXPECT_NEAR(p.values[1], 0.01 * (11 * 11 - 1) / 12.0, 1e-12) << deg;
    EXPECT_NEAR(p.values[2], 0.0, 1e-12) << deg;
    double expect = deg > 90.0 ? deg - 180.0 : deg;
    EXPECT_NEAR(peridem::axis_angle_xy(p.axes[0]), expect, 1e-9) << deg;
    // unit axes, orthogonal
    double dot = 0.0, norm = 0.0;
    for (int d = 0; d < 3; d++) {
      dot += p.axes[0][d] * p.axes[1][d];
      norm += p.axes[0][d] * p.axes[0][d];
    }
    EXPECT_NEAR(dot, 0.0, 1e-12);
    EXPECT_NEAR(norm, 1.0, 1e-12);
  }
}

TEST(GrainShape, GeneralSymmetricTensor)
{
  // S = R diag(3, 2, 1) R^T for a rotation about (1, 1, 1) by 40 degrees
  const double a = 40.0 * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
  const double k[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  double R[3][3];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      const double cross = (i == j) ? 0.0 : ((j == (i + 1) % 3) ? -k[3 - i - j] : k[3 - i - j]);
      R[i][j] = (i == j ? c : 0.0) + (1 - c) * k[i] * k[j] + s * cross;
    }
  const double lam[3] = {3.0, 2.0, 1.0};
  double S[3][3] = {};
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      for (int m = 0; m < 3; m++) S[i][j] += R[i][m] * lam[m] * R[j][m];
  const double six[6] = {S[0][0], S[1][1], S[2][2], S[0][1], S[0][2], S[1][2]};
  const peridem::PrincipalAxes p = peridem::principal_axes(six);
  for (int m = 0; m < 3; m++) {
    EXPECT_NEAR(p.values[m], lam[m], 1e-12);
    // axis m is column m of R up to sign
    double dot = 0.0;
    for (int d = 0; d < 3; d++) dot += p.axes[m][d] * R[d][m];
    EXPECT_NEAR(std::fabs(dot), 1.0, 1e-12);
  }
}
