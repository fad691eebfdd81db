/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: reductions over the nodes of each grain (molecule ID), shared
   by the computes that report per-grain or per-fragment quantities
   (peridem/damage, peridem/fragments, peridem/grain).
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_GRAINS_H
#define LMP_PERIDEM_GRAINS_H

#include "lmptype.h"

#include <mpi.h>

#include <functional>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// Largest grain (molecule) ID on any rank; grain g has row g of the
// reductions below (row 0 is unused: molecule IDs start at 1).
LAMMPS_NS::tagint max_grain_id(LAMMPS_NS::LAMMPS *lmp);

// Reduces ncol values per grain over the owned atoms in the group:
// fill(i, row) combines atom i's values into its grain's row (for MPI_SUM,
// add; for MPI_MIN/MAX, take the min/max); rows start at `init`.
// Returns (maxmol + 1) * ncol values, the same on every rank.
std::vector<double> grain_reduce(LAMMPS_NS::LAMMPS *lmp, int groupbit, LAMMPS_NS::tagint maxmol,
                                 int ncol, const std::function<void(int, double *)> &fill,
                                 MPI_Op op = MPI_SUM, double init = 0.0);

// The concatenation over ranks (in rank order) of every rank's values, on
// every rank.
std::vector<double> gather_all(LAMMPS_NS::LAMMPS *lmp, const std::vector<double> &mine);

// Counts and displacements of an MPI_Allgatherv of n items from each rank (resized to the
// number of ranks); returns the total.
int gather_counts(MPI_Comm world, int n, std::vector<int> &counts, std::vector<int> &displs);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
