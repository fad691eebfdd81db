/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM core: shape of a grain (or fragment) from the moments of its
   nodes. No LAMMPS types.
------------------------------------------------------------------------- */

#ifndef PERIDEM_GRAIN_SHAPE_H
#define PERIDEM_GRAIN_SHAPE_H

namespace peridem {

// Principal axes of a grain: the eigenvalues (descending) and unit
// eigenvectors of its central second-moment (gyration) tensor
// S = sum_i V_i (x_i - c)(x_i - c)^T / sum_i V_i. values[0] is the variance
// of the node positions along the major axis axes[0]. Each axis is signed
// so that its largest-magnitude component is positive (a grain turned by
// 180 degrees has the same axes).
struct PrincipalAxes {
  double values[3];
  double axes[3][3];
};

// s = (Sxx, Syy, Szz, Sxy, Sxz, Syz)
PrincipalAxes principal_axes(const double s[6]);

// Orientation in the xy plane of an axis (degrees, in (-90, 90]): the angle
// of the line along the axis to the x axis, for 2d grains.
double axis_angle_xy(const double axis[3]);

} // namespace peridem

#endif
