/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM: bookkeeping after a command edits bonds.

   Commands that add or remove peridynamic bonds on owned atoms
   (create_peridem_grains, cut_peridem_bonds) finish the way LAMMPS's
   create_bonds and delete_bonds do: recount the global number of bonds
   and rebuild the 1-2 (and, if weighted, 1-3/1-4) special lists.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_TOPOLOGY_H
#define LMP_PERIDEM_TOPOLOGY_H

#include "lmptype.h"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace PERIDEM {

// Recounts atom->nbonds on all ranks (bonds stored twice when newton_bond
// is off count once) and rebuilds the special lists. Returns the new total.
LAMMPS_NS::bigint finish_bond_edit(LAMMPS_NS::LAMMPS *lmp);

} // namespace PERIDEM

#endif
