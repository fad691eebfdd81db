/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: start-up checks (see lmp_peridem_startup.h)
------------------------------------------------------------------------- */

#include "lmp_peridem_startup.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"
#include "math_const.h"
#include "neighbor.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

namespace LAMMPS_NS {
namespace PERIDEM_NS {

void OverlapReport::add(tagint grain, const std::string &partner)
{
  count++;
  // a grain through a wall has many nodes near it: name each grain / partner once
  std::string example = fmt::format("grain {} / {}", grain, partner);
  if (examples.size() < 8 && std::find(examples.begin(), examples.end(), example) == examples.end())
    examples.push_back(std::move(example));
}

bigint OverlapReport::total(LAMMPS *lmp) const
{
  // a copy: the send buffers of LAMMPS's serial MPI stubs (STUBS/mpi.h) are void *
  bigint mine = count, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  return all;
}

std::string OverlapReport::example_list() const
{
  std::string list;
  for (int k = 0; k < (int)examples.size() && k < 5; k++) list += (k ? ", " : "") + examples[k];
  return list.empty() ? "on other MPI ranks" : list;
}

bigint OverlapReport::report(LAMMPS *lmp, const std::string &style, const std::string &what,
                             double Rc)
{
  const bigint all = total(lmp);
  if (all > 0 && lmp->comm->me == 0) {
    const std::string list = example_list();
    lmp->error->warning(FLERR,
                        "{}: {} {} are closer than the contact radius Rc = {} at the first step "
                        "(e.g. {}): they start with a contact force. Check the placement of "
                        "grains and walls (a wall through a grain, overlapping grains)",
                        style, all, what, Rc, list);
  }
  return all;
}

double half_list_partners(int dimension, double reach, double volume)
{
  const double ball =
      dimension == 2 ? MY_PI * reach * reach : 4.0 / 3.0 * MY_PI * reach * reach * reach;
  return 0.5 * ball / volume;
}

void check_neighbor_skin(LAMMPS *lmp, const std::string &style, double cutoff)
{
  double vmin = std::numeric_limits<double>::max(), all = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++) vmin = std::min(vmin, lmp->atom->vfrac[i]);
  MPI_Allreduce(&vmin, &all, 1, MPI_DOUBLE, MPI_MIN, lmp->world);
  if (lmp->atom->natoms == 0 || !(all > 0.0) || lmp->comm->me != 0) return;
  const int dim = lmp->domain->dimension;
  const double skin = lmp->neighbor->skin;
  // no more partners than nodes: a few small grains never overflow
  const double partners =
      std::min(half_list_partners(dim, cutoff + skin, all), (double)lmp->atom->natoms);
  const int one = lmp->neighbor->oneatom;
  if (partners <= one) return;
  // the skin for which a node inside a grain has one/2 partners
  const double target = 0.5 * one;
  const double reach = dim == 2 ? std::sqrt(2.0 * target * all / MY_PI)
                                : std::cbrt(2.0 * target * all * 3.0 / (4.0 * MY_PI));
  const double spacing = dim == 2 ? std::sqrt(all) : std::cbrt(all);
  lmp->error->warning(FLERR,
                      "{}: the neighbour list reaches {} (cutoff {} + neighbor skin {}), where a "
                      "node inside a grain of spacing {:.3g} has about {:.0f} partners, more than "
                      "neigh_modify one {}: LAMMPS will stop with 'Neighbor list overflow'. Use "
                      "a smaller skin (neighbor {:.3g} bin fits half of that; a few node "
                      "spacings is typical) or a larger neigh_modify one",
                      style, cutoff + skin, cutoff, skin, spacing, partners, one,
                      std::max(0.0, reach - cutoff));
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
