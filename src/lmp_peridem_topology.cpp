/* ----------------------------------------------------------------------
   PERIDEM: bookkeeping after a command edits bonds.
------------------------------------------------------------------------- */

#include "lmp_peridem_topology.h"

#include "atom.h"
#include "force.h"
#include "lammps.h"
#include "special.h"

#include <mpi.h>

using namespace LAMMPS_NS;

namespace PERIDEM {

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

} // namespace PERIDEM
