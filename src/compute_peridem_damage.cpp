/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/damage.

   Per node (Bhattacharya & Lipton 2023, §3.1, Jha et al. 2021, eqs. 14-15):
     phi = broken / reference bonds of the node
     Z   = max over the node's intact reference bonds of |s| / s0 (z stretch, the default),
           or of |u_j - u_i| / |xi| / s0 (z displacement, eq. 14 as printed),
           and over its broken bonds of the s / s0 (>= 1) at which each broke.
   Eq. 14 as printed counts a rigid rotation as strain (a grain turned by
   2 s0 radians reads Z >= 1 on every node); the authors' PeriDEM code takes
   the bond strain instead, max |S / Sc|, which is the default here. Broken
   bonds have left the bond arrays, so their value is the one recorded when
   they broke (the authors' code keeps evaluating them; both read >= 1).
   per grain: the mean of phi over the grain's nodes; bulk damage: the mean
   over grains of the grain damage.

   Intact bonds are counted from the bond arrays (with newton_bond on a
   bond is stored by one node, and the partner's share travels through its
   ghost copy); broken bonds have left the bond arrays and are counted by
   fix peridem/bonds, with the Z they had when they broke.
------------------------------------------------------------------------- */

#include "compute_peridem_damage.h"
#include "lmp_peridem_compat.h"

#include "atom.h"
#include "bond.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "lmp_peridem_grains.h"
#include "lmp_peridem_image.h"
#include "lmp_peridem_parse.h"
#include "fix_peridem_bonds.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "peridem_bond_law.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "compute peridem/damage";
enum { PHI = 0, ZMAX = 1, GRAIN = 2 };
} // namespace

/* ---------------------------------------------------------------------- */

ComputePeridemDamage::ComputePeridemDamage(LAMMPS *lmp, int narg, char **arg)
    : Compute(lmp, narg, arg), nmax(0), damage(nullptr), intact(nullptr), zintact(nullptr),
      stats(nullptr), s0(nullptr), bonds_fix(nullptr), z_displacement(0)
{
  // z stretch (default) | displacement: the bond strain measure of column 2 (see the header)
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (std::strcmp(arg[iarg], "z") != 0)
      error->all(FLERR, "Illegal {} command: unknown keyword {} (the only keyword is z)", STYLE,
                 arg[iarg]);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal {} command: keyword z needs a value (stretch or displacement)",
                 STYLE);
    z_displacement =
        PERIDEM_NS::choice(lmp, STYLE, "z", arg[iarg + 1], {"stretch", "displacement"});
  }
  if (!atom->molecular || !atom->molecule_flag || !atom->x0_flag)
    error->all(FLERR, "{} requires atom style peridem (bonds, grain IDs and x0)", STYLE);

  peratom_flag = 1;
  size_peratom_cols = 3;
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 4;
  extscalar = 0;
  extvector = 0;
  comm_reverse = 2;
  stats = new double[4]();
}

ComputePeridemDamage::~ComputePeridemDamage()
{
  memory->destroy(damage);
  memory->destroy(intact);
  memory->destroy(zintact);
  delete[] stats;
}

/* ---------------------------------------------------------------------- */

void ComputePeridemDamage::init()
{
  int dim = 0;
  s0 = force->bond ? static_cast<double *>(force->bond->extract("s0", dim)) : nullptr;
  const int ifix = modify->find_fix(FixPeridemBonds::ID);
  bonds_fix = ifix >= 0 ? dynamic_cast<FixPeridemBonds *>(modify->fix[ifix]) : nullptr;
  if (!s0 || dim != 1 || !bonds_fix) error->all(FLERR, "{} needs bond_style peridem", STYLE);
}

/* ---------------------------------------------------------------------- */

void ComputePeridemDamage::refresh()
{
  if (atom->nmax > nmax) {
    memory->destroy(damage);
    memory->destroy(intact);
    memory->destroy(zintact);
    nmax = atom->nmax;
    memory->create(damage, nmax, 3, "peridem/damage:damage");
    memory->create(intact, nmax, "peridem/damage:intact");
    memory->create(zintact, nmax, "peridem/damage:zintact");
    refreshed = false;
  }
  // thermo asks for the scalar and the vector one after the other: count the bonds once per
  // timestep and state of the bonds (fix peridem/bonds' stamp changes at every run's setup and
  // every break), not once per output (half of this compute's time in in.peri_impact). A bond
  // breaks on one rank only, and counting communicates: all ranks count again if one must.
  const bigint stamp = bonds_fix->change_stamp();
  // not const: the send buffers of LAMMPS's serial MPI stubs (STUBS/mpi.h) are void *
  int stale_here = !(refreshed && refreshed_step == update->ntimestep && refreshed_stamp == stamp);
  int stale = 0;
  MPI_Allreduce(&stale_here, &stale, 1, MPI_INT, MPI_MAX, world);
  if (!stale) return;
  count_bonds();
  grain_means();
  refreshed = true;
  refreshed_step = update->ntimestep;
  refreshed_stamp = stamp;
}

/* ----------------------------------------------------------------------
   phi and Z of every owned node, and the global bond counts
------------------------------------------------------------------------- */

void ComputePeridemDamage::count_bonds()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  // x and x0 flat (contiguous per-atom arrays), the bond arrays hoisted: this loop runs at
  // every thermo output
  const double *x = nall > 0 ? atom->x[0] : nullptr;
  const double *x0 = nall > 0 ? atom->x0[0] : nullptr;
  const int *num_bond = atom->num_bond;
  int **bond_type = atom->bond_type;
  tagint **bond_atom = atom->bond_atom;
  const int newton_bond = force->newton_bond;

  for (int i = 0; i < nall; i++) intact[i] = zintact[i] = 0.0;

  double bonds_local[2] = {0.0, 0.0}; // intact bonds, broken-bond ends
  for (int i = 0; i < nlocal; i++) {
    for (int m = 0; m < num_bond[i]; m++) {
      const int type = bond_type[i][m];
      if (type <= 0) continue; // turned off by delete_bonds: not a bond
      const tagint partner = bond_atom[i][m];
      const int j = atom->map(partner);
      if (j < 0)
        error->one(FLERR, "{}: atom {} bonded to atom {} is missing on proc {}", STYLE, partner,
                   tag[i], comm->me);
      const double *yi = x + 3 * i, *yj = x + 3 * j, *x0i = x0 + 3 * i, *x0j = x0 + 3 * j;
      double dy[3] = {yj[0] - yi[0], yj[1] - yi[1], yj[2] - yi[2]};
      double xi[3] = {x0j[0] - x0i[0], x0j[1] - x0i[1], x0j[2] - x0i[2]};
      PERIDEM_NS::minimum_image(domain, dy[0], dy[1], dy[2]);
      PERIDEM_NS::minimum_image(domain, xi[0], xi[1], xi[2]);
      const double r0 = std::sqrt(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
      double z;
      if (z_displacement) {
        const double du[3] = {dy[0] - xi[0], dy[1] - xi[1], dy[2] - xi[2]};
        z = peridem::z_displacement_term(std::sqrt(du[0] * du[0] + du[1] * du[1] + du[2] * du[2]),
                                         r0, s0[type]);
      } else {
        z = peridem::z_stretch_term(
            peridem::stretch(std::sqrt(dy[0] * dy[0] + dy[1] * dy[1] + dy[2] * dy[2]), r0),
            s0[type]);
      }
      intact[i] += 1.0;
      zintact[i] = std::max(zintact[i], z);
      if (newton_bond) { // the partner does not store this bond
        intact[j] += 1.0;
        zintact[j] = std::max(zintact[j], z);
      }
      if (newton_bond || tag[i] < partner) bonds_local[0] += 1.0;
    }
  }
  if (newton_bond) PERIDEM_NS::reverse_comm(comm, this);

  const double *nbroken = bonds_fix->broken_count();
  const double *zbroken = bonds_fix->broken_z();
  const int *mask = atom->mask;
  for (int i = 0; i < nlocal; i++) {
    const bool in_group = mask[i] & groupbit;
    const long broken = std::lround(nbroken[i]);
    damage[i][PHI] =
        in_group ? peridem::bond_fraction_damage(broken, broken + std::lround(intact[i])) : 0.0;
    damage[i][ZMAX] = in_group ? std::max(zintact[i], zbroken[i]) : 0.0;
    bonds_local[1] += nbroken[i];
  }
  // a broken bond is counted at both of its nodes
  double bonds_all[2];
  MPI_Allreduce(bonds_local, bonds_all, 2, MPI_DOUBLE, MPI_SUM, world);
  stats[1] = 0.5 * bonds_all[1];
  stats[2] = bonds_all[0] + stats[1];
}

int ComputePeridemDamage::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    buf[m++] = intact[i];
    buf[m++] = zintact[i];
  }
  return m;
}

void ComputePeridemDamage::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    intact[j] += buf[m++];
    zintact[j] = std::max(zintact[j], buf[m++]);
  }
}

/* ----------------------------------------------------------------------
   grain damage = mean phi over the grain's nodes (in the group);
   bulk damage = mean over grains of the grain damage
------------------------------------------------------------------------- */

void ComputePeridemDamage::grain_means()
{
  const int nlocal = atom->nlocal;
  const tagint *molecule = atom->molecule;
  const int *mask = atom->mask;
  const tagint maxmol = PERIDEM_NS::max_grain_id(lmp);
  const std::vector<double> global =
      PERIDEM_NS::grain_reduce(lmp, groupbit, maxmol, 2, [&](int i, double *row) {
        row[0] += damage[i][PHI];
        row[1] += 1.0;
      });

  double sum = 0.0;
  int ngrains = 0;
  for (tagint g = 0; g <= maxmol; g++) {
    if (global[2 * g + 1] == 0.0) continue;
    sum += global[2 * g] / global[2 * g + 1];
    ngrains++;
  }
  for (int i = 0; i < nlocal; i++) {
    const tagint g = molecule[i];
    damage[i][GRAIN] = (mask[i] & groupbit) ? global[2 * g] / global[2 * g + 1] : 0.0;
  }
  stats[0] = ngrains ? sum / ngrains : 0.0;
  stats[3] = ngrains;
}

/* ---------------------------------------------------------------------- */

double ComputePeridemDamage::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  refresh();
  scalar = stats[0];
  return scalar;
}

void ComputePeridemDamage::compute_vector()
{
  invoked_vector = update->ntimestep;
  refresh();
  vector = stats;
}

void ComputePeridemDamage::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  refresh();
  array_atom = damage;
}

double ComputePeridemDamage::memory_usage()
{
  return 5.0 * nmax * sizeof(double);
}
