/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/bed, measures of a bed of grains in a
   container for thermo and variables.

   Volume fraction (Bhattacharya & Lipton 2023, §7.3-7.4): the grains' volume over the
   container's volume, the container being the region's lateral extent
   times the height from the region's bottom to the top (the settled bed's
   surface in §7.3, the moving top wall l (h - v t) in §7.4). Bhattacharya & Lipton's (2023)
   ring-grain fraction 0.92 (Table 3) exceeds the densest disk packing
   (0.907), so there the grain volume includes the holes (the excluded
   volume of §7.4.2): both are reported, the second with the hole area of
   each grain (found once from its reference positions, 2d).
------------------------------------------------------------------------- */

#include "compute_peridem_bed.h"
#include "lmp_peridem_compat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "lmp_peridem_grains.h"
#include "lmp_peridem_parse.h"
#include "math_const.h"
#include "region.h"
#include "update.h"
#include "variable.h"

#include "peridem_bed.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

namespace {
const char *const STYLE = "compute peridem/bed";
enum { HMAX, HSURF, HEIGHT, VCONT, VGRAIN, PHI, VFILLED, PHI_FILLED };
} // namespace

/* ----------------------------------------------------------------------
   compute ID group peridem/bed region-ID [top surface|max|region|v_name] [bin W]
------------------------------------------------------------------------- */

ComputePeridemBed::ComputePeridemBed(LAMMPS *lmp, int narg, char **arg)
    : Compute(lmp, narg, arg), id_region(nullptr), id_variable(nullptr), top_kind(TOP_SURFACE),
      ivariable(-1), bin_width(0.0), lo{0, 0, 0}, hi{0, 0, 0}, stats{}, holes_ready(false)
{
  if (!atom->molecular || !atom->molecule_flag || !atom->x0_flag || !atom->vfrac_flag)
    error->all(FLERR, "{} requires atom style peridem (grain IDs, volumes and x0)", STYLE);
  if (narg < 4) error->all(FLERR, "Illegal {} command: expected a region ID", STYLE);
  id_region = utils::strdup(arg[3]);
  for (int iarg = 4; iarg < narg; iarg += 2) {
    if (iarg + 2 > narg)
      error->all(FLERR, "Illegal {} command: {} needs a value", STYLE, arg[iarg]);
    const char *value = arg[iarg + 1];
    if (strcmp(arg[iarg], "top") == 0) {
      if (strcmp(value, "surface") == 0)
        top_kind = TOP_SURFACE;
      else if (strcmp(value, "max") == 0)
        top_kind = TOP_MAX;
      else if (strcmp(value, "region") == 0)
        top_kind = TOP_REGION;
      else if (strncmp(value, "v_", 2) == 0) {
        top_kind = TOP_VARIABLE;
        delete[] id_variable;
        id_variable = utils::strdup(value + 2);
      } else
        error->all(FLERR, "Illegal {} command: top {}: expected surface, max, region or v_name",
                   STYLE, value);
    } else if (strcmp(arg[iarg], "bin") == 0) {
      bin_width = PERIDEM_NS::number(lmp, STYLE, "bin", value);
      if (bin_width <= 0.0)
        error->all(FLERR, "Illegal {} command: bin {} must be positive", STYLE, value);
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword {}", STYLE, arg[iarg]);
  }
  scalar_flag = vector_flag = 1;
  size_vector = 8;
  extscalar = extvector = 0;
  vector = stats;
}

ComputePeridemBed::~ComputePeridemBed()
{
  delete[] id_region;
  delete[] id_variable;
}

void ComputePeridemBed::init()
{
  Region *region = PERIDEM_NS::find_region(domain, id_region);
  if (!region) error->all(FLERR, "{}: region {} does not exist", STYLE, id_region);
  if (!region->bboxflag)
    error->all(FLERR, "{}: region {} has no bounding box to serve as the container", STYLE,
               id_region);
  lo[0] = region->extent_xlo, hi[0] = region->extent_xhi;
  lo[1] = region->extent_ylo, hi[1] = region->extent_yhi;
  lo[2] = region->extent_zlo, hi[2] = region->extent_zhi;
  if (top_kind == TOP_VARIABLE) {
    ivariable = input->variable->find(id_variable);
    if (ivariable < 0) error->all(FLERR, "{}: variable {} does not exist", STYLE, id_variable);
    if (!input->variable->equalstyle(ivariable))
      error->all(FLERR, "{}: variable {} is not equal-style", STYLE, id_variable);
  }
}

/* ----------------------------------------------------------------------
   hole area of every grain from the reference positions of its nodes
   (2d; gathered on every rank once: the holes do not change)
------------------------------------------------------------------------- */

void ComputePeridemBed::find_holes()
{
  const tagint maxmol = PERIDEM_NS::max_grain_id(lmp);
  holes.assign(maxmol + 1, 0.0);
  holes_ready = true;
  if (domain->dimension != 2) return;
  std::vector<double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    mine.insert(mine.end(),
                {double(atom->molecule[i]), atom->x0[i][0], atom->x0[i][1], atom->vfrac[i]});
  }
  const std::vector<double> all = PERIDEM_NS::gather_all(lmp, mine);
  std::vector<std::vector<double>> xy(maxmol + 1);
  std::vector<double> vmax(maxmol + 1, 0.0);
  for (size_t k = 0; k < all.size(); k += 4) {
    const auto g = size_t(all[k]);
    xy[g].insert(xy[g].end(), {all[k + 1], all[k + 2]});
    vmax[g] = std::max(vmax[g], all[k + 3]);
  }
  // node spacing: a full lattice cell has volume h^2
  for (tagint g = 1; g <= maxmol; g++)
    if (!xy[g].empty()) holes[g] = peridem::hole_area_2d(xy[g], std::sqrt(vmax[g]));
}

/* ---------------------------------------------------------------------- */

void ComputePeridemBed::compute_vector()
{
  invoked_vector = update->ntimestep;
  // grains added since the holes were found (create_peridem_grains between
  // runs) need their holes, and rows in the per-grain sums
  if (!holes_ready || PERIDEM_NS::max_grain_id(lmp) != tagint(holes.size()) - 1) find_holes();
  const int vd = domain->dimension == 2 ? 1 : 2; // vertical: y in 2d, z in 3d
  const int nlat = domain->dimension == 2 ? 1 : 2;
  double **x = atom->x;
  const int *mask = atom->mask;
  const tagint maxmol = tagint(holes.size()) - 1;

  // volume per grain: the bed's volume, its grains and their mean size
  const std::vector<double> per_grain = PERIDEM_NS::grain_reduce(
      lmp, groupbit, maxmol, 1, [&](int i, double *r) { r[0] += atom->vfrac[i]; });
  double vgrain = 0.0, vholes = 0.0;
  int ngrains = 0;
  for (tagint g = 1; g <= maxmol; g++) {
    if (per_grain[g] <= 0.0) continue;
    vgrain += per_grain[g];
    vholes += holes[g];
    ngrains++;
  }

  // lateral bins of the surface: width W, by default the mean grain diameter
  double w = bin_width;
  if (w <= 0.0 && ngrains > 0) {
    const double v = vgrain / ngrains;
    w = domain->dimension == 2 ? 2.0 * std::sqrt(v / MY_PI) : std::cbrt(6.0 * v / MY_PI);
  }
  int nbin[2] = {1, 1};
  for (int d = 0; d < nlat; d++)
    if (w > 0.0) nbin[d] = std::max(1, int(std::floor((hi[d] - lo[d]) / w)));
  std::vector<double> bins(size_t(nbin[0]) * nbin[1], -1e308), all_bins(bins.size());
  double hmax_local = -1e308;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    hmax_local = std::max(hmax_local, x[i][vd]);
    int b[2] = {0, 0}, inside = 1;
    for (int d = 0; d < nlat; d++) {
      if (x[i][d] < lo[d] || x[i][d] > hi[d]) inside = 0;
      b[d] = std::min(nbin[d] - 1, int((x[i][d] - lo[d]) / (hi[d] - lo[d]) * nbin[d]));
    }
    if (!inside) continue;
    double &m = bins[size_t(b[0]) * nbin[1] + b[1]];
    m = std::max(m, x[i][vd]);
  }
  double hmax = 0.0;
  MPI_Allreduce(&hmax_local, &hmax, 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(bins.data(), all_bins.data(), int(bins.size()), MPI_DOUBLE, MPI_MAX, world);
  if (hmax < -1e300) hmax = 0.0;
  const double surface = peridem::median_of_bins(all_bins);

  double top = surface;
  if (top_kind == TOP_MAX) top = hmax;
  if (top_kind == TOP_REGION) top = hi[vd];
  if (top_kind == TOP_VARIABLE) top = input->variable->compute_equal(ivariable);
  const double height = top - lo[vd];
  double vcont = height;
  for (int d = 0; d < nlat; d++) vcont *= hi[d] - lo[d];

  stats[HMAX] = hmax;
  stats[HSURF] = surface;
  stats[HEIGHT] = height;
  stats[VCONT] = vcont;
  stats[VGRAIN] = vgrain;
  stats[PHI] = vcont > 0.0 ? vgrain / vcont : 0.0;
  stats[VFILLED] = vgrain + vholes;
  stats[PHI_FILLED] = vcont > 0.0 ? (vgrain + vholes) / vcont : 0.0;
}

double ComputePeridemBed::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  compute_vector();
  scalar = stats[PHI];
  return scalar;
}
