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

namespace LAMMPS_NS {
namespace PERIDEM_NS {

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
  const int count = int(mine.size());
  std::vector<int> counts, displs;
  std::vector<double> all(size_t(gather_counts(lmp->world, count, counts, displs)));
  // const_cast: the send buffer of LAMMPS's serial MPI stubs (STUBS/mpi.h) is a void *
  MPI_Allgatherv(const_cast<double *>(mine.data()), count, MPI_DOUBLE, all.data(), counts.data(),
                 displs.data(), MPI_DOUBLE, lmp->world);
  return all;
}

int gather_counts(MPI_Comm world, int n, std::vector<int> &counts, std::vector<int> &displs)
{
  int nprocs = 1;
  MPI_Comm_size(world, &nprocs);
  counts.resize(nprocs);
  displs.resize(nprocs);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (int p = 0; p < nprocs; p++) {
    displs[p] = total;
    total += counts[p];
  }
  return total;
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
