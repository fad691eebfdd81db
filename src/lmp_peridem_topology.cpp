/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: bookkeeping after a command edits bonds.
------------------------------------------------------------------------- */

#include "lmp_peridem_topology.h"
#include "lmp_peridem_grains.h"

#include "atom.h"
#include "atom_vec.h"
#include "domain.h"
#include "fix_peridem_bonds.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "special.h"

#include <algorithm>
#include <functional>
#include <mpi.h>
#include <utility>

using namespace LAMMPS_NS;

namespace LAMMPS_NS {
namespace PERIDEM_NS {

bigint finish_bond_edit(LAMMPS *lmp)
{
  Atom *atom = lmp->atom;
  bigint nlocal_bonds = 0;
  for (int i = 0; i < atom->nlocal; i++) nlocal_bonds += atom->num_bond[i];
  MPI_Allreduce(&nlocal_bonds, &atom->nbonds, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  if (!lmp->force->newton_bond) atom->nbonds /= 2;

  Special special(lmp);
  special.build();
  return atom->nbonds;
}

int outside_fixed_boundary(const Domain *domain, const double *x)
{
  if (domain->triclinic) return -1;
  for (int d = 0; d < domain->dimension; d++) {
    // boundary 1 = f; s and m move the box, p wraps
    if (domain->boundary[d][0] == 1 && x[d] < domain->boxlo[d]) return 2 * d;
    if (domain->boundary[d][1] == 1 && x[d] >= domain->boxhi[d]) return 2 * d + 1;
  }
  return -1;
}

bigint delete_nodes(LAMMPS *lmp, std::vector<int> doomed,
                    const std::function<void(int, tagint)> &lost_partner)
{
  Atom *atom = lmp->atom;
  MPI_Comm world = lmp->world;

  // every rank needs the IDs of all deleted atoms: partners may be anywhere
  std::vector<tagint> mine;
  for (int i : doomed) mine.push_back(atom->tag[i]);
  const int nmine = static_cast<int>(mine.size());
  std::vector<int> counts, displs;
  const int ngone = PERIDEM_NS::gather_counts(world, nmine, counts, displs);
  if (ngone == 0) return 0;
  std::vector<tagint> gone(ngone);
  MPI_Allgatherv(mine.data(), nmine, MPI_LMP_TAGINT, gone.data(), counts.data(), displs.data(),
                 MPI_LMP_TAGINT, world);
  std::sort(gone.begin(), gone.end());
  auto is_gone = [&](tagint t) { return std::binary_search(gone.begin(), gone.end(), t); };

  std::vector<char> dies(atom->nlocal, 0);
  for (int i : doomed) dies[i] = 1;
  for (int i = 0; i < atom->nlocal; i++) {
    if (dies[i]) continue;
    int &nb = atom->num_bond[i];
    for (int m = nb - 1; m >= 0; m--) {
      if (!is_gone(atom->bond_atom[i][m])) continue;
      atom->bond_atom[i][m] = atom->bond_atom[i][nb - 1];
      atom->bond_type[i][m] = atom->bond_type[i][nb - 1];
      nb--;
    }
    // the 1-2 special list names every intact bond partner, wherever the
    // bond is stored (newton_bond on stores it once)
    int *nspecial = atom->nspecial[i];
    tagint *special = atom->special[i];
    for (int k = 0; k < nspecial[0];) {
      if (!is_gone(special[k])) {
        k++;
        continue;
      }
      lost_partner(i, special[k]);
      for (int m = k; m < nspecial[2] - 1; m++) special[m] = special[m + 1];
      nspecial[0]--;
      nspecial[1]--;
      nspecial[2]--;
    }
  }

  // remove the atoms (highest index first: the last atom moves into the hole)
  std::sort(doomed.begin(), doomed.end(), std::greater<int>());
  for (int i : doomed) {
    atom->avec->copy(atom->nlocal - 1, i, 1);
    atom->nlocal--;
  }
  bigint nlocal = atom->nlocal, nbonds = 0;
  MPI_Allreduce(&nlocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  for (int i = 0; i < atom->nlocal; i++) nbonds += atom->num_bond[i];
  MPI_Allreduce(&nbonds, &atom->nbonds, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (!lmp->force->newton_bond) atom->nbonds /= 2;
  if (atom->map_style != Atom::MAP_NONE) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
  return ngone;
}

bigint delete_nodes_breaking_bonds(LAMMPS *lmp, std::vector<int> doomed)
{
  const int ibonds = lmp->modify->find_fix(FixPeridemBonds::ID);
  auto *bonds = ibonds < 0 ? nullptr : dynamic_cast<FixPeridemBonds *>(lmp->modify->fix[ibonds]);
  return delete_nodes(lmp, std::move(doomed), [bonds](int i, tagint) {
    if (bonds) bonds->partner_deleted(i);
  });
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
