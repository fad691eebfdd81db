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

namespace peridem_lmp {

inline void minimum_image(LAMMPS_NS::Domain *domain, double &dx, double &dy, double &dz)
{
  if ((domain->xperiodic && std::fabs(dx) > domain->xprd_half) ||
      (domain->yperiodic && std::fabs(dy) > domain->yprd_half) ||
      (domain->zperiodic && std::fabs(dz) > domain->zprd_half))
    domain->minimum_image(dx, dy, dz);
}

} // namespace peridem_lmp

#endif
