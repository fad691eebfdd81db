/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Error type of the LAMMPS-independent PERIDEM geometry library.
//
// The geometry code (shapes, discretization, bonds) must not depend on LAMMPS,
// so it reports bad input by throwing this exception; the LAMMPS commands catch
// it and turn the message into a LAMMPS error (bad input gets a clear
// error).
#ifndef PERIDEM_GEOMETRY_ERROR_H
#define PERIDEM_GEOMETRY_ERROR_H

#include <stdexcept>
#include <string>

namespace peridem {

class GeometryError : public std::runtime_error {
 public:
  explicit GeometryError(const std::string &msg) : std::runtime_error(msg) {}
};

} // namespace peridem

#endif
