/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

#include "lmp_peridem_own_fix.h"

#include <cstring>

namespace LAMMPS_NS {
namespace PERIDEM_NS {

void check_own_fix(LAMMPS_NS::LAMMPS *lmp, int narg, const LAMMPS_NS::Fix *fix, const char *own_id,
                   const char *creator)
{
  if (narg != 3)
    lmp->error->all(FLERR, "Illegal fix {} command: it takes no arguments", fix->style);
  // one instance, the creator's: a second one would do the work twice or not at all
  if (std::strcmp(fix->id, own_id) != 0)
    lmp->error->all(FLERR,
                    "fix {} is created by {} (as fix {}); do not define it yourself (fix {})",
                    fix->style, creator, own_id, fix->id);
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
