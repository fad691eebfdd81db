/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

#include "lmp_peridem_wall_damping.h"
#include "lmp_peridem_grains.h"

#include "atom.h"
#include "lammps.h"

#include <algorithm>
#include <mpi.h>

using LAMMPS_NS::tagint;

namespace LAMMPS_NS {
namespace PERIDEM_NS {

void WallCentroidDamping::set_types(const std::vector<peridem::ContactParams> &params,
                                    const std::vector<double> &reach)
{
  type_params = params;
  type_reach = reach;
  enabled = std::any_of(reach.begin(), reach.end(), [](double r) { return r > 0.0; });
}

double WallCentroidDamping::max_reach() const
{
  double r = 0.0;
  for (double t : type_reach) r = std::max(r, t);
  return r;
}

void WallCentroidDamping::apply(LAMMPS_NS::LAMMPS *lmp, const double *vel,
                                const double (*outward)[3], const double (*wall_velocity)[3],
                                const std::function<void(int, int, const double *)> &on_force)
{
  MPI_Comm world = lmp->world;

  // all (grain, wall) touches of all ranks, one entry each (the smallest type of the grain's
  // touching nodes), sorted: every rank applies the same forces in the same order
  auto same = [](const std::array<tagint, 3> &a, const std::array<tagint, 3> &b) {
    return a[0] == b[0] && a[1] == b[1];
  };
  std::sort(touch_local.begin(), touch_local.end());
  touch_local.erase(std::unique(touch_local.begin(), touch_local.end(), same), touch_local.end());
  const int mine = 3 * (int)touch_local.size();
  const int total = LAMMPS_NS::PERIDEM_NS::gather_counts(world, mine, counts, displs);
  if (total == 0) return;
  touch_all.resize(total / 3);
  MPI_Allgatherv(touch_local.empty() ? nullptr : touch_local[0].data(), mine, MPI_LMP_TAGINT,
                 touch_all[0].data(), counts.data(), displs.data(), MPI_LMP_TAGINT, world);
  std::sort(touch_all.begin(), touch_all.end());
  touch_all.erase(std::unique(touch_all.begin(), touch_all.end(), same), touch_all.end());

  grains.clear();
  for (const auto &t : touch_all) grains.push_back(t[0]);
  grains.erase(std::unique(grains.begin(), grains.end()), grains.end());
  const int ng = (int)grains.size();

  // mass and momentum of the touching grains, over the owned nodes of all ranks
  LAMMPS_NS::Atom *atom = lmp->atom;
  const int nlocal = atom->nlocal;
  const tagint *molecule = atom->molecule;
  const double *rmass = atom->rmass;
  grain_of.assign(nlocal, -1);
  sum_local.assign(4 * ng, 0.0);
  for (int i = 0; i < nlocal; i++) {
    const auto it = std::lower_bound(grains.begin(), grains.end(), molecule[i]);
    if (it == grains.end() || *it != molecule[i]) continue;
    const int g = grain_of[i] = (int)(it - grains.begin());
    sum_local[4 * g] += rmass[i];
    for (int k = 0; k < 3; k++) sum_local[4 * g + 1 + k] += rmass[i] * vel[3 * i + k];
  }
  sum_all.resize(sum_local.size());
  MPI_Allreduce(sum_local.data(), sum_all.data(), 4 * ng, MPI_DOUBLE, MPI_SUM, world);

  // the dashpot of each touch (eq. 26-28, wall as the opposite particle)
  force.assign(3 * touch_all.size(), 0.0);
  // begin[g]: the first touch of grain g (touch_all is sorted by grain)
  std::vector<std::size_t> begin(ng, touch_all.size());
  for (std::size_t n = 0; n < touch_all.size(); n++) {
    const auto &t = touch_all[n];
    const int g = (int)(std::lower_bound(grains.begin(), grains.end(), t[0]) - grains.begin());
    if (begin[g] == touch_all.size()) begin[g] = n;
    const double M = sum_all[4 * g];
    if (!(M > 0.0)) continue;
    const int w = (int)t[1];
    const peridem::ContactParams &p = type_params[t[2]];
    double vrel[3];
    for (int k = 0; k < 3; k++) vrel[k] = sum_all[4 * g + 1 + k] / M - wall_velocity[w][k];
    // eq. 29 with M_p' -> infinity: 2 M_p M_p'/(M_p + M_p') -> 2 M_p
    const double beta =
        peridem::restitution_damping_coefficient(p.eps_n, p.C, p.kappa_eff, p.Rc, 2.0 * M);
    peridem::centroid_damping_force(outward[w], vrel, beta, true, &force[3 * n]);
  }

  // eq. 30 as between grains: the share m_x/M_p of each force to every node of the grain
  for (int i = 0; i < nlocal; i++) {
    const int g = grain_of[i];
    if (g < 0 || !(sum_all[4 * g] > 0.0)) continue;
    const double share = rmass[i] / sum_all[4 * g];
    for (std::size_t n = begin[g]; n < touch_all.size() && touch_all[n][0] == grains[g]; n++) {
      const double *fc = &force[3 * n];
      if (fc[0] == 0.0 && fc[1] == 0.0 && fc[2] == 0.0) continue;
      const double f[3] = {share * fc[0], share * fc[1], share * fc[2]};
      on_force(i, (int)touch_all[n][1], f);
    }
  }
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
