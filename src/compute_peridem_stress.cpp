/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/stress, the average Cauchy stress of the nodes of
   a group in a volume V (the virial stress; e.g. ParticLS's eq. 24 at the
   level of nodes):
     sigma = -(1/V) sum_i [ m_i v_i (x) v_i + W_i ]
   W_i the per-atom virial that LAMMPS's force styles tally (half of each
   pair's or bond's r (x) f; a wall is a partner on its plane), kept apart by
   source: contact (pair_style), bond (bond_style), wall (fix peridem/wall).
   The same sum as compute stress/atom, split and reduced in one pass. The
   sign is the solid's: tension positive.
------------------------------------------------------------------------- */

#include "compute_peridem_stress.h"
#include "lmp_peridem_compat.h"

#include "atom.h"
#include "bond.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "input.h"
#include "lmp_peridem_parse.h"
#include "memory.h"
#include "modify.h"
#include "pair.h"
#include "update.h"
#include "variable.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "compute peridem/stress";
enum { TOTAL = 0, KINETIC = 6, CONTACT = 12, BOND = 18, WALL = 24 };
constexpr int NVIR = 18; // contact, bond, wall: 6 components each
} // namespace

/* ----------------------------------------------------------------------
   compute ID group peridem/stress volume V|v_name|box
------------------------------------------------------------------------- */

ComputePeridemStress::ComputePeridemStress(LAMMPS *lmp, int narg, char **arg)
    : Compute(lmp, narg, arg), volume_kind(VOLUME_BOX), volume_value(0.0), id_variable(nullptr),
      ivariable(-1), nmax(0), vir(nullptr), stress{}
{
  if (!atom->rmass_flag)
    error->all(FLERR, "{} requires per-atom masses (atom style peridem)", STYLE);
  bool volume_given = false;
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 2 > narg)
      error->all(FLERR, "Illegal {} command: {} needs a value", STYLE, arg[iarg]);
    const char *value = arg[iarg + 1];
    if (strcmp(arg[iarg], "volume") != 0)
      error->all(FLERR, "Illegal {} command: unknown keyword {} (the only keyword is volume)",
                 STYLE, arg[iarg]);
    volume_given = true;
    if (strcmp(value, "box") == 0)
      volume_kind = VOLUME_BOX;
    else if (strncmp(value, "v_", 2) == 0) {
      volume_kind = VOLUME_VARIABLE;
      delete[] id_variable;
      id_variable = utils::strdup(value + 2);
    } else {
      volume_kind = VOLUME_NUMBER;
      volume_value = PERIDEM_NS::number(lmp, STYLE, "volume", value);
      if (volume_value <= 0.0)
        error->all(FLERR, "Illegal {} command: volume {} must be positive", STYLE, value);
    }
  }
  // the box is rarely the bed's volume (walls inside a padded box): ask for it
  if (!volume_given)
    error->all(FLERR,
               "Illegal {} command: expected volume V, v_name or box (the volume the stress "
               "is averaged over, an area in 2d)",
               STYLE);

  scalar_flag = vector_flag = 1;
  size_vector = 30;
  extscalar = extvector = 0;
  vector = stress;
  pressatomflag = 1; // LAMMPS tallies the per-atom virial on the steps this compute is used
  timeflag = 1;
  comm_reverse = NVIR;
}

ComputePeridemStress::~ComputePeridemStress()
{
  delete[] id_variable;
  memory->destroy(vir);
}

void ComputePeridemStress::init()
{
  if (volume_kind == VOLUME_VARIABLE) {
    ivariable = input->variable->find(id_variable);
    if (ivariable < 0) error->all(FLERR, "{}: variable {} does not exist", STYLE, id_variable);
    if (!input->variable->equalstyle(ivariable))
      error->all(FLERR, "{}: variable {} is not equal-style", STYLE, id_variable);
  }
  // a fix's per-atom virial is tallied only with fix_modify virial yes: without it the
  // wall part would read zero
  walls.clear();
  for (int i = 0; i < modify->nfix; i++) {
    Fix *fix = modify->fix[i];
    if (!utils::strmatch(fix->style, "^peridem/wall")) continue;
    if (!fix->thermo_virial)
      error->all(FLERR,
                 "{}: fix {} ({}) tallies no virial: add 'fix_modify {} virial yes' for the "
                 "wall part of the stress",
                 STYLE, fix->id, fix->style, fix->id);
    walls.push_back(fix);
  }
}

double ComputePeridemStress::volume() const
{
  if (volume_kind == VOLUME_NUMBER) return volume_value;
  double v = 0.0;
  if (volume_kind == VOLUME_VARIABLE)
    v = input->variable->compute_equal(ivariable);
  else
    v = domain->xprd * domain->yprd * (domain->dimension == 3 ? domain->zprd : 1.0);
  if (!(v > 0.0)) error->all(FLERR, "{}: the volume ({}) must be positive", STYLE, v);
  return v;
}

/* ---------------------------------------------------------------------- */

void ComputePeridemStress::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (update->vflag_atom != invoked_vector)
    error->all(FLERR,
               "{}: the per-atom virial was not tallied on step {} (use it from thermo, "
               "fix ave/time or a dump, which LAMMPS schedules, or 'run 0')",
               STYLE, update->ntimestep);

  if (atom->nmax > nmax) {
    memory->destroy(vir);
    nmax = atom->nmax;
    memory->create(vir, nmax, NVIR, "peridem/stress:vir");
  }
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  for (int i = 0; i < nall; i++)
    for (int k = 0; k < NVIR; k++) vir[i][k] = 0.0;

  // ghosts hold shares of pairs and bonds across ranks when newton is on
  auto add = [&](double **v, int n, int offset) {
    if (!v) return;
    for (int i = 0; i < n; i++)
      for (int k = 0; k < 6; k++) vir[i][offset + k] += v[i][k];
  };
  Pair *pair = force->pair;
  if (pair && pair->compute_flag) add(pair->vatom, force->newton_pair ? nall : nlocal, 0);
  Bond *bond = force->bond;
  if (bond) add(bond->vatom, force->newton_bond ? nall : nlocal, 6);
  for (Fix *wall : walls) add(wall->vatom, nlocal, 12);
  if (force->newton) PERIDEM_NS::reverse_comm(comm, this);

  double local[30] = {};
  const double mvv2e = force->mvv2e;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double m = atom->rmass[i] * mvv2e;
    const double *v = atom->v[i];
    const double kin[6] = {m * v[0] * v[0], m * v[1] * v[1], m * v[2] * v[2],
                           m * v[0] * v[1], m * v[0] * v[2], m * v[1] * v[2]};
    for (int k = 0; k < 6; k++) {
      local[KINETIC + k] += kin[k];
      local[CONTACT + k] += vir[i][k];
      local[BOND + k] += vir[i][6 + k];
      local[WALL + k] += vir[i][12 + k];
    }
  }
  double sum[30];
  MPI_Allreduce(local, sum, 30, MPI_DOUBLE, MPI_SUM, world);
  const double scale = -force->nktv2p / volume();
  for (int k = 0; k < 6; k++) {
    stress[TOTAL + k] = 0.0;
    for (int part : {KINETIC, CONTACT, BOND, WALL}) {
      stress[part + k] = scale * sum[part + k];
      stress[TOTAL + k] += stress[part + k];
    }
  }
}

// the mean normal stress as a pressure: -tr(sigma)/d, positive in compression
double ComputePeridemStress::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  if (invoked_vector != invoked_scalar) compute_vector();
  const int dim = domain->dimension;
  scalar = -(stress[0] + stress[1] + (dim == 3 ? stress[2] : 0.0)) / dim;
  return scalar;
}

/* ---------------------------------------------------------------------- */

int ComputePeridemStress::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < NVIR; k++) buf[m++] = vir[i][k];
  return m;
}

void ComputePeridemStress::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < NVIR; k++) vir[list[i]][k] += buf[m++];
}

double ComputePeridemStress::memory_usage()
{
  return double(nmax) * NVIR * sizeof(double);
}
