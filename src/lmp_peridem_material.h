/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: material files seen from LAMMPS commands.

   Every PERIDEM style that takes material constants accepts
     material FILE NAME
   and reads them from a material file (doc/peridem_material_format.rst),
   so an input script never repeats a number. This glue reads the file
   once per command (on rank 0, found as LAMMPS finds potential files, and
   broadcast), checks its units against LAMMPS's, and turns core errors
   into LAMMPS errors naming the command.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_MATERIAL_H
#define LMP_PERIDEM_MATERIAL_H

#include "peridem_material.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// The material NAME from FILE; `command` (e.g. "bond_coeff") names the
// command in error messages. Errors end the run with a LAMMPS error.
peridem::Material load_material(LAMMPS_NS::LAMMPS *lmp, const std::string &command,
                                const std::string &file, const std::string &name);

// The text of FILE, read on rank 0 and broadcast to every rank (LAMMPS's
// convention: one rank touches the file system). potential = true: FILE is
// found as LAMMPS finds potential files (utils::open_potential: as given,
// then in the folder of the LAMMPS_POTENTIALS environment variable). A file
// that cannot be opened ends the run with "COMMAND: cannot open KIND file
// 'FILE'".
std::string read_text_file(LAMMPS_NS::LAMMPS *lmp, const std::string &command,
                           const std::string &kind, const std::string &file, bool potential);

// Micromodulus by name ("constant" or "conic"), LAMMPS error otherwise.
peridem::Micromodulus parse_micromodulus(LAMMPS_NS::LAMMPS *lmp, const std::string &command,
                                         const std::string &word);
const char *micromodulus_name(peridem::Micromodulus m);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
