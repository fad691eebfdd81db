/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: command cut_peridem_bonds, see doc/cut_peridem_bonds.rst.

   Removes the existing bonds that cross given line segments (pre-notches,
   cracks) in the reference configuration x0, e.g. on grains read from a
   data file. In 3D a segment cuts along z (a vertical plane through it).
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(cut_peridem_bonds,CutPeridemBonds);
// clang-format on
#else

#ifndef LMP_CUT_PERIDEM_BONDS_H
#define LMP_CUT_PERIDEM_BONDS_H

#include "command.h"

namespace LAMMPS_NS {

class CutPeridemBonds : public Command {
 public:
  CutPeridemBonds(class LAMMPS *);
  void command(int, char **) override;
};

} // namespace LAMMPS_NS

#endif
#endif
