/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: damping between grain centres and walls, for fix peridem/wall.

   Jha et al. (2021), §3.2 "Particle-wall damping force": the dashpot
   between grain centres (§2.3.2, eq. 26-28) with the wall as the opposite
   particle. For a flat wall the direction from the grain's centre to the
   wall is the wall's outward normal n, so
     F = -beta_bar max(0, (v_c - v_wall) . n) n
   acts on the grain while one of its nodes is within the reach (R_c, or
   centroid_range) of the wall, with beta_bar from eq. 28 and
   M_eq = 2 M_p (eq. 29 for a partner of infinite mass). Every node x of
   the grain gets the share m_x/M_p of F (as pair_style peridem/contact
   does between grains), so the dashpot only decelerates the centre: the
   work of the shares, sum_x (m_x/M_p) F . (v_x - v_wall), is that of F on
   the centre, F . (v_c - v_wall).

   Every rank gathers all (grain, wall) touches and sums the centre
   velocities of those grains, so all ranks compute the same forces in
   the same order.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_WALL_DAMPING_H
#define LMP_PERIDEM_WALL_DAMPING_H

#include "lmptype.h"
#include "peridem_contact_law.h"

#include <array>
#include <functional>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace LAMMPS_NS {
namespace PERIDEM_NS {

class WallCentroidDamping {
 public:
  // per atom type t: the dashpot's parameters (eps_n, C, kappa_eff, R_c of eq. 28) and its
  // reach (0: type t has no damping between centres)
  void set_types(const std::vector<peridem::ContactParams> &params,
                 const std::vector<double> &reach);
  bool any() const { return enabled; }
  double reach(int type) const { return type_reach[type]; }
  double max_reach() const;

  // a step: clear(), touch() for every local node within reach of a wall, then apply()
  void clear() { touch_local.clear(); }
  void touch(LAMMPS_NS::tagint grain, int wall, int type)
  {
    touch_local.push_back({grain, (LAMMPS_NS::tagint)wall, (LAMMPS_NS::tagint)type});
  }

  // The forces of all touches: on_force(i, w, f) is called for every local node i of a touching
  // grain and every wall w it touches, f the node's share; outward[w] is the wall's outward normal,
  // wall_velocity[w] its velocity. (The caller counts their work with the nodes' velocities.)
  void apply(LAMMPS_NS::LAMMPS *lmp, const double *velocities, const double (*outward)[3],
             const double (*wall_velocity)[3],
             const std::function<void(int, int, const double *)> &on_force);

 private:
  bool enabled = false;
  std::vector<peridem::ContactParams> type_params;
  std::vector<double> type_reach;
  std::vector<std::array<LAMMPS_NS::tagint, 3>> touch_local, touch_all;
  std::vector<LAMMPS_NS::tagint> grains; // touching grains, sorted
  std::vector<int> counts, displs, grain_of;
  std::vector<double> sum_local, sum_all, force; // per grain: M, M v; per touch: F
};

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
