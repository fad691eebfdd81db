/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM core: measures of a bed of grains (height, holes of grains).
   No LAMMPS types.
------------------------------------------------------------------------- */

#ifndef PERIDEM_BED_H
#define PERIDEM_BED_H

#include <vector>

namespace peridem {

// Area of the holes of a 2d grain from its node positions xy (x0, y0,
// x1, y1, ...) and node spacing h: the nodes are dilated by h/sqrt(2)
// (which covers the solid of a square lattice of spacing h, however it is
// turned) on a grid of spacing h/4; the empty grid cells that cannot be
// reached from outside the grain's bounding box are holes, unless smaller
// than a disk of radius 2h (pockets of the dilation along the stepped
// boundary of a turned lattice). The hole radius comes out short by about
// (1/sqrt(2) - 1/2) h = 0.21 h.
double hole_area_2d(const std::vector<double> &xy, double h);

// Surface height of a bed: the median over lateral bins of the highest
// node in each bin; bins without nodes (value < -1e300) are skipped.
// Returns 0 when every bin is empty.
double median_of_bins(std::vector<double> bin_max);

} // namespace peridem

#endif
