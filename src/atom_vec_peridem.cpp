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
#include "domain.h"
#include "error.h"

#include <cmath>
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
  PERIDEM_NS::set_fields(fields_grow,
                         "molecule num_bond bond_type bond_atom nspecial special rmass vfrac x0");
  PERIDEM_NS::set_fields(fields_copy,
                         "molecule num_bond bond_type bond_atom nspecial special rmass vfrac x0");
  PERIDEM_NS::set_fields(fields_comm, "");
  PERIDEM_NS::set_fields(fields_comm_vel, "");
  PERIDEM_NS::set_fields(fields_reverse, "");
  PERIDEM_NS::set_fields(fields_border, "molecule rmass vfrac x0");
  PERIDEM_NS::set_fields(fields_border_vel, "molecule rmass vfrac x0");
  PERIDEM_NS::set_fields(fields_exchange,
                         "molecule num_bond bond_type bond_atom nspecial special rmass vfrac x0");
  PERIDEM_NS::set_fields(fields_restart, "molecule num_bond bond_type bond_atom rmass vfrac x0");
  PERIDEM_NS::set_fields(fields_create, "molecule num_bond nspecial rmass vfrac x0");
  PERIDEM_NS::set_fields(fields_data_atom, "id molecule type vfrac rmass x x0");
  PERIDEM_NS::set_fields(fields_data_vel, "id v");

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
  check_reference_position(ilocal, "in Atoms section of data file");
  rmass[ilocal] *= vfrac[ilocal];
}

/* ----------------------------------------------------------------------
   x0 must be finite and, along a periodic dimension, within one box
   length of the box: bonds are measured between the minimum images of
   x0, and a reference position many periods away has no meaningful image
   (LAMMPS 29Sep2021's minimum image never ends on x0 = 1e30)
------------------------------------------------------------------------- */

void AtomVecPeridem::check_reference_position(int i, const char *where)
{
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  for (int d = 0; d < 3; d++) {
    const double v = x0[i][d];
    const double lo = domain->boxlo[d], hi = domain->boxhi[d], len = hi - lo;
    if (!std::isfinite(v))
      error->one(FLERR, "Invalid reference position {} {} {} of atom {} {} (atom style peridem)",
                 x0[i][0], x0[i][1], x0[i][2], atom->tag[i], where);
    if (periodic[d] && (v < lo - len || v > hi + len))
      error->one(FLERR,
                 "Reference position {} {} {} of atom {} {} lies more than one box length "
                 "outside the periodic box along {} ({} to {}; atom style peridem)",
                 x0[i][0], x0[i][1], x0[i][2], atom->tag[i], where, "xyz"[d], lo, hi);
  }
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
  check_restart_atom(ilocal);
}

/* ----------------------------------------------------------------------
   a restart file is trusted input of LAMMPS, but what this style reads
   from it is checked, so that a damaged file stops here with a message
   instead of crashing a bond style later (a bond type beyond the types
   indexes their coefficient arrays)
------------------------------------------------------------------------- */

void AtomVecPeridem::check_restart_atom(int i)
{
  const tagint id = atom->tag[i];
  const char *damaged = "(damaged file?)";
  if (id <= 0)
    error->one(FLERR, "Invalid atom ID {} in restart file {} (atom style peridem)", id, damaged);
  if (!(vfrac[i] > 0.0) || !std::isfinite(vfrac[i]) || !(rmass[i] > 0.0) ||
      !std::isfinite(rmass[i]))
    error->one(FLERR,
               "Invalid volume {} or mass {} of atom {} in restart file {} (atom style "
               "peridem)",
               vfrac[i], rmass[i], id, damaged);
  if (atom->molecule[i] <= 0)
    error->one(FLERR, "Invalid grain ID {} of atom {} in restart file {} (atom style peridem)",
               atom->molecule[i], id, damaged);
  if (num_bond[i] < 0 || num_bond[i] > atom->bond_per_atom)
    error->one(FLERR, "Invalid bond count {} of atom {} in restart file {} (atom style peridem)",
               num_bond[i], id, damaged);
  for (int m = 0; m < num_bond[i]; m++) {
    const int t = bond_type[i][m];
    if (t > atom->nbondtypes || -t > atom->nbondtypes || atom->bond_atom[i][m] <= 0)
      error->one(FLERR,
                 "Invalid bond {} (type {}, partner {}) of atom {} in restart file {} (atom "
                 "style peridem, {} bond types)",
                 m + 1, t, atom->bond_atom[i][m], id, damaged, atom->nbondtypes);
  }
  check_reference_position(i, "in restart file");
}

/* ----------------------------------------------------------------------
   compute property/atom names: vfrac, x0x, x0y, x0z
------------------------------------------------------------------------- */

int AtomVecPeridem::property_atom(PERIDEM_NS::PropertyAtomName name)
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
