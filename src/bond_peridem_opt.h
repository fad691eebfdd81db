/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: bond_style peridem/opt, bond_style peridem with its force loop
   compiled for the machine's vector units, as LAMMPS's OPT package has
   pair_style lj/cut/opt: selected by -sf opt or the suffix command, the
   same keywords, coefficients, restart and results. See doc/bond_peridem.rst.
------------------------------------------------------------------------- */

#ifdef BOND_CLASS
// clang-format off
BondStyle(peridem/opt,BondPeridemOpt);
// clang-format on
#else

#ifndef LMP_BOND_PERIDEM_OPT_H
#define LMP_BOND_PERIDEM_OPT_H

#include "bond_peridem.h"

namespace LAMMPS_NS {

class BondPeridemOpt : public BondPeridem {
 public:
  BondPeridemOpt(class LAMMPS *);

 protected:
  void compute_chunked() override;

 private:
  void vectorised_passes();
};

} // namespace LAMMPS_NS

#endif
#endif
