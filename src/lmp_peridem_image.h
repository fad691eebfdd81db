/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the minimum image of a displacement, only where a periodic
   dimension needs it. Domain::minimum_image is not inline; in the loops
   over all bonds the call costs more than the test, and most grain
   displacements are far shorter than half the box.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_IMAGE_H
#define LMP_PERIDEM_IMAGE_H

#include "domain.h"

#include <cmath>

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// LAMMPS 29Sep2021's Domain::minimum_image subtracts one period at a time while the distance
// exceeds half of it: a non-finite or huge distance (x0 = 1e30 from a data file) never ends
// there. Beyond a few periods the exact remainder is taken first (the same result, since both
// are exact; not finite stays not finite, and the caller's checks see it).
inline void reduce_far_image(double &d, double period)
{
  if (!(std::fabs(d) <= 4.0 * period)) d = std::remainder(d, period);
}

inline void minimum_image(LAMMPS_NS::Domain *domain, double &dx, double &dy, double &dz)
{
  if ((domain->xperiodic && std::fabs(dx) > domain->xprd_half) ||
      (domain->yperiodic && std::fabs(dy) > domain->yprd_half) ||
      (domain->zperiodic && std::fabs(dz) > domain->zprd_half)) {
    if (domain->xperiodic) reduce_far_image(dx, domain->xprd);
    if (domain->yperiodic) reduce_far_image(dy, domain->yprd);
    if (domain->zperiodic) reduce_far_image(dz, domain->zprd);
    domain->minimum_image(dx, dy, dz);
  }
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
