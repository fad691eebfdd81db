/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/order. The local nodes in grain-major order
   (peridem_atom_order.h says why), at every run's setup and at the frequency
   of LAMMPS's sort (atom_modify sort N), which the bond style turned off.
------------------------------------------------------------------------- */

#include "fix_peridem_order.h"

#include "atom.h"
#include "atom_vec.h"
#include "lmp_peridem_own_fix.h"
#include "update.h"

#include "peridem_atom_order.h"

#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

FixPeridemOrder::FixPeridemOrder(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  PERIDEM_NS::check_own_fix(lmp, narg, this, ID, "bond_style peridem");
}

int FixPeridemOrder::setmask()
{
  return PRE_EXCHANGE;
}

void FixPeridemOrder::setup_pre_exchange()
{
  if (active) order_atoms(); // at every setup, where LAMMPS would sort
}

void FixPeridemOrder::pre_exchange()
{
  if (active && update->ntimestep >= next_order) order_atoms();
}

/* ----------------------------------------------------------------------
   moved as Atom::sort() moves atoms: each cycle of the permutation through
   a spare slot, with AtomVec::copy(), which also moves the per-atom arrays
   of fixes. Unlike Atom::sort(), this runs before the exchange, while the
   ghosts are still there: the spare slot lies after them, and the map of
   atom IDs is set again for the new positions (a fix called after this one
   in pre_exchange may look atoms up by ID).
------------------------------------------------------------------------- */

void FixPeridemOrder::order_atoms()
{
  const bigint every = atom->sortfreq;
  if (every <= 0) return;
  next_order = (update->ntimestep / every) * every + every;
  const int nlocal = atom->nlocal;
  const std::vector<int> perm = peridem::grain_major_permutation(atom->molecule, atom->tag, nlocal);
  if (perm.empty()) return;

  const int spare = nlocal + atom->nghost;
  if (spare >= atom->nmax) atom->avec->grow(0);
  std::vector<int> current(nlocal); // current[k]: the atom (old position) now at position k
  for (int k = 0; k < nlocal; k++) current[k] = k;
  for (int i = 0; i < nlocal; i++) {
    if (current[i] == perm[i]) continue;
    atom->avec->copy(i, spare, 0);
    int empty = i;
    while (perm[empty] != i) {
      atom->avec->copy(perm[empty], empty, 0);
      empty = current[empty] = perm[empty];
    }
    atom->avec->copy(spare, empty, 0);
    current[empty] = perm[empty];
  }
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_clear();
    atom->map_set();
  }
}
