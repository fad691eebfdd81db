/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the fixes that PERIDEM styles create for themselves (fix
   peridem/bonds, peridem/escapes, peridem/order, peridem/vhistory): one
   instance each, under a fixed ID.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_OWN_FIX_H
#define LMP_PERIDEM_OWN_FIX_H

#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

#include <string>

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// The fix F (of style `style`, ID F::ID), created at the first call; an existing fix of that
// ID and another style ends the run with an error naming `caller`.
template <typename F> F *own_fix(LAMMPS_NS::LAMMPS *lmp, const char *style, const char *caller)
{
  LAMMPS_NS::Modify *modify = lmp->modify;
  const int i = modify->find_fix(F::ID);
  auto *fix = dynamic_cast<F *>(i >= 0 ? modify->fix[i]
                                       : modify->add_fix(fmt::format("{} all {}", F::ID, style)));
  if (!fix) lmp->error->all(FLERR, "{}: fix {} is not a fix {}", caller, F::ID, style);
  return fix;
}

// The constructor's checks of such a fix: no arguments after the style, and only the ID
// `own_id` (`creator` names the styles that create it).
void check_own_fix(LAMMPS_NS::LAMMPS *lmp, int narg, const LAMMPS_NS::Fix *fix, const char *own_id,
                   const char *creator);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
