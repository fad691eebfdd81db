/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/order, the nodes in memory grain by grain.
   Created by the bond styles (ID PERIDEM_ORDER); see doc/fix_peridem_order.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(peridem/order,FixPeridemOrder);
// clang-format on
#else

#ifndef LMP_FIX_PERIDEM_ORDER_H
#define LMP_FIX_PERIDEM_ORDER_H

#include "fix.h"

namespace LAMMPS_NS {

class FixPeridemOrder : public Fix {
 public:
  static constexpr const char *ID = "PERIDEM_ORDER";

  FixPeridemOrder(class LAMMPS *, int, char **);
  int setmask() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;

  // order the nodes (at LAMMPS's sort frequency) or leave them as they are
  void set_active(bool on) { active = on; }

 private:
  bool active = false;
  bigint next_order = 0; // the step from which pre_exchange() orders the nodes again
  void order_atoms();
};

} // namespace LAMMPS_NS

#endif
#endif
