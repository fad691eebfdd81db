/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: per-grain reductions, see lmp_peridem_grains.h.
------------------------------------------------------------------------- */

#include "lmp_peridem_grains.h"

#include "atom.h"
#include "lammps.h"

#include <algorithm>

using namespace LAMMPS_NS;

namespace peridem_lmp {

tagint max_grain_id(LAMMPS *lmp)
{
  const Atom *atom = lmp->atom;
  tagint local = 0, global = 0;
  for (int i = 0; i < atom->nlocal; i++) local = std::max(local, atom->molecule[i]);
  MPI_Allreduce(&local, &global, 1, MPI_LMP_TAGINT, MPI_MAX, lmp->world);
  return global;
}

std::vector<double> grain_reduce(LAMMPS *lmp, int groupbit, tagint maxmol, int ncol,
                                 const std::function<void(int, double *)> &fill, MPI_Op op,
                                 double init)
{
  const Atom *atom = lmp->atom;
  const size_t n = size_t(maxmol + 1) * ncol;
  std::vector<double> local(n, init), global(n, init);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    fill(i, &local[size_t(atom->molecule[i]) * ncol]);
  }
  MPI_Allreduce(local.data(), global.data(), int(n), MPI_DOUBLE, op, lmp->world);
  return global;
}

std::vector<double> gather_all(LAMMPS *lmp, const std::vector<double> &mine)
{
  int nprocs = 1;
  MPI_Comm_size(lmp->world, &nprocs);
  int count = int(mine.size());
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, lmp->world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> all(size_t(displs[nprocs - 1]) + counts[nprocs - 1]);
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, lmp->world);
  return all;
}

} // namespace peridem_lmp
