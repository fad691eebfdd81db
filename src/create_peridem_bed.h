/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: command create_peridem_bed, see doc/create_peridem_bed.rst.

   Generates a shape-agnostic initial bed (Bhattacharya & Lipton 2023, §7-7.1): a
   jammed packing of security disks (spheres in 3D) with radii from a
   distribution, shrunk by R_c/2, each with a random angle and a label
   drawn with given proportions, written to a file that
   create_peridem_grains places grains from (positions FILE label NAME).
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(create_peridem_bed,CreatePeridemBed);
// clang-format on
#else

#ifndef LMP_CREATE_PERIDEM_BED_H
#define LMP_CREATE_PERIDEM_BED_H

#include "command.h"

namespace LAMMPS_NS {

class CreatePeridemBed : public Command {
 public:
  CreatePeridemBed(class LAMMPS *);
  void command(int, char **) override;
};

} // namespace LAMMPS_NS

#endif
#endif
