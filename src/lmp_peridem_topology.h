/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: bookkeeping after a command edits bonds.

   Commands that add or remove peridynamic bonds on owned atoms
   (create_peridem_grains, cut_peridem_bonds) finish the way LAMMPS's
   create_bonds and delete_bonds do: recount the global number of bonds
   and rebuild the 1-2 (and, if weighted, 1-3/1-4) special lists.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_TOPOLOGY_H
#define LMP_PERIDEM_TOPOLOGY_H

#include "lmptype.h"

#include <functional>
#include <vector>

namespace LAMMPS_NS {
class Domain;
class LAMMPS;
} // namespace LAMMPS_NS

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// Recounts atom->nbonds on all ranks (bonds stored twice when newton_bond
// is off count once) and rebuilds the special lists. Returns the new total.
LAMMPS_NS::bigint finish_bond_edit(LAMMPS_NS::LAMMPS *lmp);

// The face (0..5 = xlo xhi ylo yhi zlo zhi) of a fixed ('f') box boundary
// that position x lies beyond, where LAMMPS would lose the atom at the next
// reneighbouring; -1 if none (or a triclinic box, not checked).
int outside_fixed_boundary(const LAMMPS_NS::Domain *domain, const double *x);

// Deletes the owned atoms at the local indices `doomed` (every rank calls it,
// with its own list) together with their bonds: bonds stored on partners and
// the partners' 1-2 special entries go too, on every rank, and
// lost_partner(i, tag) is called once for each owned atom i that had an
// intact bond to a deleted atom. Recounts atoms and bonds and rebuilds the
// atom map. Call it where atoms may be deleted (pre_exchange, as fix
// evaporate does). Returns the number of atoms deleted on all ranks.
LAMMPS_NS::bigint delete_nodes(LAMMPS_NS::LAMMPS *lmp, std::vector<int> doomed,
                               const std::function<void(int, LAMMPS_NS::tagint)> &lost_partner);

// delete_nodes(), with each intact bond to a deleted node counted as broken by its partner
// in fix peridem/bonds (when a bond style has created it): fix peridem/escapes and fix
// peridem/wall 'lost delete' delete escaping nodes so.
LAMMPS_NS::bigint delete_nodes_breaking_bonds(LAMMPS_NS::LAMMPS *lmp, std::vector<int> doomed);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
