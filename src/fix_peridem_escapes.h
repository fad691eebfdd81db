/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/escapes, nodes that leave the box through a fixed
   boundary. Created by the bond styles (ID PERIDEM_ESCAPES); see
   doc/fix_peridem_escapes.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(peridem/escapes,FixPeridemEscapes);
// clang-format on
#else

#ifndef LMP_FIX_PERIDEM_ESCAPES_H
#define LMP_FIX_PERIDEM_ESCAPES_H

#include "fix.h"

namespace LAMMPS_NS {

class FixPeridemEscapes : public Fix {
 public:
  static constexpr const char *ID = "PERIDEM_ESCAPES";

  FixPeridemEscapes(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void post_run() override;
  double compute_scalar() override;

 private:
  bool walls_delete = false; // a fix peridem/wall with 'lost delete' removes them instead
  bool lost_allowed = false; // thermo_modify lost ignore|warn: delete them here
  bigint deleted_run = 0, deleted_total = 0;
  void check();
};

} // namespace LAMMPS_NS

#endif
#endif
