/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/grain, the state of every grain as one row of a
   global array (for fix ave/time, thermo and variables).

   Periodic images: the nodes of a grain are placed relative to one anchor
   node (its smallest atom ID) by the minimum image, so a grain across a
   periodic boundary is whole; the anchor itself is unwrapped with its
   image flags, so the centroid moves continuously through the boundaries.
   This needs a grain smaller than half the periodic box length (the bond
   forces need the same).

   Shape: principal axes of the volume-weighted central second moment of
   the node positions (core: peridem::principal_axes). Damage: the mean of
   the nodes' bond-fraction damage (Bhattacharya & Lipton 2023, §7.4 "particle
   damage"), from a compute peridem/damage.
------------------------------------------------------------------------- */

#include "compute_peridem_grain.h"

#include "atom.h"
#include "compute_peridem_damage.h"
#include "compute_peridem_fragments.h"
#include "domain.h"
#include "error.h"
#include "lmp_peridem_grains.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "peridem_grain_shape.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "compute peridem/grain";
// output columns (0-based)
enum {
  CX = 0,
  VX = 3,
  VOLUME = 6,
  MASS = 7,
  NODES = 8,
  DAMAGE = 9,
  FRAGMENTS = 10,
  EXTENT = 11,
  EIGEN = 12,
  AXIS = 15,
  ANGLE = 18
};
// columns of the summation pass
enum { S_VOL, S_MASS, S_NODES, S_D, S_P = S_D + 3, S_DD = S_P + 3, S_PHI = S_DD + 6, S_NCOLS };
} // namespace

/* ----------------------------------------------------------------------
   compute ID group peridem/grain [damage ID] [fragments ID]
------------------------------------------------------------------------- */

ComputePeridemGrain::ComputePeridemGrain(LAMMPS *lmp, int narg, char **arg)
    : Compute(lmp, narg, arg), maxmol(0), grains(nullptr), id_damage(nullptr),
      id_fragments(nullptr), damage(nullptr), fragments(nullptr)
{
  if (!atom->molecular || !atom->molecule_flag || !atom->x0_flag || !atom->vfrac_flag ||
      !atom->rmass_flag)
    error->all(FLERR, "{} requires atom style peridem (grain IDs, volumes and masses)", STYLE);
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 2 > narg)
      error->all(FLERR, "Illegal {} command: {} needs a compute ID", STYLE, arg[iarg]);
    if (strcmp(arg[iarg], "damage") == 0) {
      delete[] id_damage;
      id_damage = utils::strdup(arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "fragments") == 0) {
      delete[] id_fragments;
      id_fragments = utils::strdup(arg[iarg + 1]);
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword {}", STYLE, arg[iarg]);
  }

  array_flag = 1;
  extarray = 0;
  maxmol = PERIDEM_NS::max_grain_id(lmp);
  size_array_rows = std::max<tagint>(maxmol, 1);
  size_array_cols = NCOLS;
  memory->create(grains, size_array_rows, NCOLS, "peridem/grain:grains");
  array = grains;
}

ComputePeridemGrain::~ComputePeridemGrain()
{
  memory->destroy(grains);
  delete[] id_damage;
  delete[] id_fragments;
}

void ComputePeridemGrain::init()
{
  if (PERIDEM_NS::max_grain_id(lmp) > maxmol)
    error->all(FLERR, "{} {}: grain IDs beyond {} were added after the compute was defined", STYLE,
               id, maxmol);
  auto find = [&](const char *cid, const char *kind) -> Compute * {
    if (!cid) return nullptr;
    const int icompute = modify->find_compute(cid);
    if (icompute < 0) error->all(FLERR, "{}: {} compute {} does not exist", STYLE, kind, cid);
    return modify->compute[icompute];
  };
  Compute *c = find(id_damage, "damage");
  damage = dynamic_cast<ComputePeridemDamage *>(c);
  if (c && !damage)
    error->all(FLERR, "{}: damage compute {} is a compute {}, not peridem/damage", STYLE, id_damage,
               c->style);
  c = find(id_fragments, "fragments");
  fragments = dynamic_cast<ComputePeridemFragments *>(c);
  if (c && !fragments)
    error->all(FLERR, "{}: fragments compute {} is a compute {}, not peridem/fragments", STYLE,
               id_fragments, c->style);
}

/* ---------------------------------------------------------------------- */

void ComputePeridemGrain::compute_array()
{
  invoked_array = update->ntimestep;
  double **x = atom->x, **v = atom->v;
  const tagint *tag = atom->tag, *molecule = atom->molecule;
  const imageint *image = atom->image;
  const double *vfrac = atom->vfrac, *rmass = atom->rmass;
  const size_t rows = size_t(maxmol) + 1;

  double **phi = nullptr;
  if (damage) {
    if (damage->invoked_peratom != update->ntimestep) damage->compute_peratom();
    phi = damage->array_atom;
  }
  if (fragments) fragments->refresh();

  // anchor of each grain: its smallest atom ID, unwrapped
  const std::vector<double> anchor_tag = PERIDEM_NS::grain_reduce(
      lmp, groupbit, maxmol, 1, [&](int i, double *r) { r[0] = std::min(r[0], double(tag[i])); },
      MPI_MIN, std::numeric_limits<double>::max());
  const std::vector<double> anchor =
      PERIDEM_NS::grain_reduce(lmp, groupbit, maxmol, 3, [&](int i, double *r) {
        if (double(tag[i]) != anchor_tag[molecule[i]]) return;
        domain->unmap(x[i], image[i], r);
      });
  auto offset = [&](int i, double *d) {
    const double *a = &anchor[3 * size_t(molecule[i])];
    for (int k = 0; k < 3; k++) d[k] = x[i][k] - a[k];
    domain->minimum_image(d[0], d[1], d[2]);
  };

  // volume, mass, nodes, first and second moments, momentum, damage
  const std::vector<double> sums =
      PERIDEM_NS::grain_reduce(lmp, groupbit, maxmol, S_NCOLS, [&](int i, double *r) {
        double d[3];
        offset(i, d);
        const double V = vfrac[i], m = rmass[i];
        r[S_VOL] += V;
        r[S_MASS] += m;
        r[S_NODES] += 1.0;
        for (int k = 0; k < 3; k++) {
          r[S_D + k] += V * d[k];
          r[S_P + k] += m * v[i][k];
        }
        r[S_DD + 0] += V * d[0] * d[0];
        r[S_DD + 1] += V * d[1] * d[1];
        r[S_DD + 2] += V * d[2] * d[2];
        r[S_DD + 3] += V * d[0] * d[1];
        r[S_DD + 4] += V * d[0] * d[2];
        r[S_DD + 5] += V * d[1] * d[2];
        if (phi) r[S_PHI] += phi[i][0];
      });

  std::vector<double> centre(3 * rows, 0.0), major(3 * rows, 0.0);
  for (tagint g = 1; g <= maxmol; g++) {
    double *row = grains[g - 1];
    const double *s = &sums[S_NCOLS * size_t(g)];
    std::fill(row, row + NCOLS, 0.0);
    if (s[S_NODES] == 0.0) continue;
    const double V = s[S_VOL], m = s[S_MASS];
    double c[3];
    for (int k = 0; k < 3; k++) {
      c[k] = s[S_D + k] / V;
      centre[3 * g + k] = c[k];
      row[CX + k] = anchor[3 * g + k] + c[k];
      row[VX + k] = m > 0.0 ? s[S_P + k] / m : 0.0;
    }
    row[VOLUME] = V;
    row[MASS] = m;
    row[NODES] = s[S_NODES];
    row[DAMAGE] = s[S_PHI] / s[S_NODES];
    row[FRAGMENTS] = fragments ? fragments->grain_fragments(g) : 0.0;
    const double S[6] = {s[S_DD] / V - c[0] * c[0],     s[S_DD + 1] / V - c[1] * c[1],
                         s[S_DD + 2] / V - c[2] * c[2], s[S_DD + 3] / V - c[0] * c[1],
                         s[S_DD + 4] / V - c[0] * c[2], s[S_DD + 5] / V - c[1] * c[2]};
    const peridem::PrincipalAxes p = peridem::principal_axes(S);
    for (int k = 0; k < 3; k++) {
      row[EIGEN + k] = std::max(p.values[k], 0.0);
      row[AXIS + k] = p.axes[0][k];
      major[3 * g + k] = p.axes[0][k];
    }
    row[ANGLE] = peridem::axis_angle_xy(p.axes[0]);
  }

  // extent: the length of the grain's node cloud along its major axis
  const std::vector<double> reach = PERIDEM_NS::grain_reduce(
      lmp, groupbit, maxmol, 2,
      [&](int i, double *r) {
        double d[3];
        offset(i, d);
        const size_t g = molecule[i];
        double proj = 0.0;
        for (int k = 0; k < 3; k++) proj += (d[k] - centre[3 * g + k]) * major[3 * g + k];
        r[0] = std::max(r[0], proj);
        r[1] = std::max(r[1], -proj);
      },
      MPI_MAX, 0.0);
  for (tagint g = 1; g <= maxmol; g++)
    if (grains[g - 1][NODES] > 0.0) grains[g - 1][EXTENT] = reach[2 * g] + reach[2 * g + 1];
}
