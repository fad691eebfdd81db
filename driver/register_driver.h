/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: registration of all PERIDEM styles into a LAMMPS instance
   (lmp_peridem, libperidem, the Python routes); see register_driver.cpp.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_REGISTER_DRIVER_H
#define LMP_PERIDEM_REGISTER_DRIVER_H

#include "register_peridem.h"

#include <string>

extern "C" {
/* Register every PERIDEM style into the LAMMPS instance `lmp` (a
   LAMMPS_NS::LAMMPS *, e.g. from lammps_open() or the Python module's
   lmp.lmp pointer). Safe to call more than once. Returns 0 on success; a
   LAMMPS version other than the one PERIDEM was compiled against is a
   LAMMPS error (the process ends). */
int peridem_register(void *lmp);

/* The LAMMPS version string PERIDEM was compiled against. */
const char *peridem_lammps_version();
}

namespace LAMMPS_NS {
namespace PERIDEM_NS {

/* The message for a version mismatch, empty when the versions agree. */
std::string version_mismatch_message(const std::string &compiled, const std::string &running);

/* A LAMMPS error (the process ends) unless `lmp` is LAMMPS version
   `expected_version`. */
void check_lammps_version(LAMMPS_NS::LAMMPS *lmp, const std::string &expected_version);

/* Register the styles after checking that `lmp` is the LAMMPS version
   `expected_version`; peridem_register() passes the compiled-in version. */
void register_styles(LAMMPS_NS::LAMMPS *lmp, const std::string &expected_version);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
