/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: peridynamic grains for LAMMPS.
   atom_style peridem, see doc/atom_style_peridem.rst
------------------------------------------------------------------------- */

#include "atom_vec_peridem.h"
#include "lmp_peridem_compat.h"

#include "atom.h"
#include "error.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace {
// property names for compute property/atom, in the order of their index
const char *const property_names[] = {"vfrac", "x0x", "x0y", "x0z"};
constexpr int num_properties = 4;
} // namespace

/* ---------------------------------------------------------------------- */

AtomVecPeridem::AtomVecPeridem(LAMMPS *lmp)
    : AtomVec(lmp), rmass_one(0.0), bond_negative(nullptr), bond_negative_capacity(0),
      any_bond_negative(0)
{
  molecular = Atom::MOLECULAR;
  bonds_allow = 1;
  mass_type = PER_ATOM;

  atom->molecule_flag = 1;
  atom->rmass_flag = 1;
  atom->vfrac_flag = 1;
  atom->x0_flag = 1;

  // x0 travels with the atom (exchange, restart) and to ghosts (borders):
  // bond styles compute reference bond vectors from the x0 of both nodes.
  peridem_lmp::set_fields(fields_grow,
                          "molecule num_bond bond_type bond_atom nspecial special rmass vfrac x0");
  peridem_lmp::set_fields(fields_copy,
                          "molecule num_bond bond_type bond_atom nspecial special rmass vfrac x0");
  peridem_lmp::set_fields(fields_comm, "");
  peridem_lmp::set_fields(fields_comm_vel, "");
  peridem_lmp::set_fields(fields_reverse, "");
  peridem_lmp::set_fields(fields_border, "molecule rmass vfrac x0");
  peridem_lmp::set_fields(fields_border_vel, "molecule rmass vfrac x0");
  peridem_lmp::set_fields(fields_exchange,
                          "molecule num_bond bond_type bond_atom nspecial special rmass vfrac x0");
  peridem_lmp::set_fields(fields_restart, "molecule num_bond bond_type bond_atom rmass vfrac x0");
  peridem_lmp::set_fields(fields_create, "molecule num_bond nspecial rmass vfrac x0");
  peridem_lmp::set_fields(fields_data_atom, "id molecule type vfrac rmass x x0");
  peridem_lmp::set_fields(fields_data_vel, "id v");

  setup_fields();
}

AtomVecPeridem::~AtomVecPeridem()
{
  delete[] bond_negative;
}

/* ---------------------------------------------------------------------- */

void AtomVecPeridem::grow_pointers()
{
  num_bond = atom->num_bond;
  bond_type = atom->bond_type;
  nspecial = atom->nspecial;
  rmass = atom->rmass;
  vfrac = atom->vfrac;
  x0 = atom->x0;
}

/* ----------------------------------------------------------------------
   create_atoms: unit volume and mass, reference position = position
------------------------------------------------------------------------- */

void AtomVecPeridem::create_atom_post(int ilocal)
{
  vfrac[ilocal] = 1.0;
  rmass[ilocal] = 1.0;
  x0[ilocal][0] = x[ilocal][0];
  x0[ilocal][1] = x[ilocal][1];
  x0[ilocal][2] = x[ilocal][2];
}

/* ----------------------------------------------------------------------
   read_data: the rmass column holds the density; mass = density * volume
------------------------------------------------------------------------- */

void AtomVecPeridem::data_atom_post(int ilocal)
{
  num_bond[ilocal] = 0;
  nspecial[ilocal][0] = nspecial[ilocal][1] = nspecial[ilocal][2] = 0;

  if (vfrac[ilocal] <= 0.0)
    error->one(FLERR,
               "Invalid volume {} for atom {} in Atoms section of data file "
               "(atom style peridem needs volume > 0)",
               vfrac[ilocal], atom->tag[ilocal]);
  if (rmass[ilocal] <= 0.0)
    error->one(FLERR,
               "Invalid density {} for atom {} in Atoms section of data file "
               "(atom style peridem needs density > 0)",
               rmass[ilocal], atom->tag[ilocal]);
  if (atom->molecule[ilocal] <= 0)
    error->one(FLERR,
               "Invalid grain ID {} for atom {} in Atoms section of data file "
               "(atom style peridem needs grain ID > 0)",
               atom->molecule[ilocal], atom->tag[ilocal]);
  rmass[ilocal] *= vfrac[ilocal];
}

/* ----------------------------------------------------------------------
   write_data: write density = mass / volume, then restore the mass
------------------------------------------------------------------------- */

void AtomVecPeridem::pack_data_pre(int ilocal)
{
  rmass_one = rmass[ilocal];
  rmass[ilocal] = rmass_one / vfrac[ilocal];
}

void AtomVecPeridem::pack_data_post(int ilocal)
{
  rmass[ilocal] = rmass_one;
}

/* ----------------------------------------------------------------------
   restart: turned-off bonds (negative type) are written with positive type,
   and turned off again when read, the way atom_style bond handles them
------------------------------------------------------------------------- */

void AtomVecPeridem::pack_restart_pre(int ilocal)
{
  if (bond_negative_capacity < atom->bond_per_atom) {
    delete[] bond_negative;
    bond_negative_capacity = atom->bond_per_atom;
    bond_negative = new int[bond_negative_capacity];
  }
  any_bond_negative = 0;
  for (int m = 0; m < num_bond[ilocal]; m++) {
    bond_negative[m] = bond_type[ilocal][m] < 0;
    if (bond_negative[m]) {
      bond_type[ilocal][m] = -bond_type[ilocal][m];
      any_bond_negative = 1;
    }
  }
}

void AtomVecPeridem::pack_restart_post(int ilocal)
{
  if (!any_bond_negative) return;
  for (int m = 0; m < num_bond[ilocal]; m++)
    if (bond_negative[m]) bond_type[ilocal][m] = -bond_type[ilocal][m];
}

void AtomVecPeridem::unpack_restart_init(int ilocal)
{
  nspecial[ilocal][0] = nspecial[ilocal][1] = nspecial[ilocal][2] = 0;
}

/* ----------------------------------------------------------------------
   compute property/atom names: vfrac, x0x, x0y, x0z
------------------------------------------------------------------------- */

int AtomVecPeridem::property_atom(peridem_lmp::PropertyAtomName name)
{
  const std::string word(name);
  for (int i = 0; i < num_properties; i++)
    if (word == property_names[i]) return i;
  return -1;
}

void AtomVecPeridem::pack_property_atom(int index, double *buf, int nvalues, int groupbit)
{
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0, n = 0; i < nlocal; i++, n += nvalues) {
    if (!(mask[i] & groupbit)) {
      buf[n] = 0.0;
      continue;
    }
    buf[n] = (index == 0) ? vfrac[i] : x0[i][index - 1];
  }
}
