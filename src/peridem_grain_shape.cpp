/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM core: principal axes of a grain, see peridem_grain_shape.h.
   The symmetric 3x3 eigenproblem is solved by Eigen's closed-form solver.
------------------------------------------------------------------------- */

#include "peridem_grain_shape.h"
#include "peridem_math.h"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace peridem {

PrincipalAxes principal_axes(const double s[6])
{
  Eigen::Matrix3d m;
  m << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
  // the iterative solver: computeDirect() (closed form) loses about half the digits when two
  // eigenvalues are (nearly) equal, as for a disk or a square: 1e-9 of 0.37 for a square of
  // 21 x 21 nodes, depending on the order of the sums over its nodes
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
  PrincipalAxes p{};
  for (int k = 0; k < 3; k++) {
    const int col = 2 - k; // Eigen sorts ascending
    p.values[k] = solver.eigenvalues()(col);
    Eigen::Vector3d v = solver.eigenvectors().col(col).normalized();
    int big = 0;
    for (int d = 1; d < 3; d++)
      if (std::fabs(v(d)) > std::fabs(v(big)) + 1e-12) big = d;
    if (v(big) < 0.0) v = -v;
    for (int d = 0; d < 3; d++) p.axes[k][d] = v(d);
  }
  return p;
}

double axis_angle_xy(const double axis[3])
{
  double a = std::atan2(axis[1], axis[0]) * 180.0 / kPi;
  if (a > 90.0) a -= 180.0;
  if (a <= -90.0) a += 180.0;
  return a;
}

} // namespace peridem
