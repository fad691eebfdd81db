/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: mathematical constants of the LAMMPS-free core. The core does not include
// LAMMPS headers, so it cannot use MathConst::MY_PI (math_const.h); the LAMMPS glue does.
#ifndef PERIDEM_MATH_H
#define PERIDEM_MATH_H

namespace peridem {

// pi to double precision (the value of LAMMPS's MathConst::MY_PI)
constexpr double kPi = 3.14159265358979323846;

} // namespace peridem

#endif
