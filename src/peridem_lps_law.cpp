/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: constants of the linear peridynamic solid (see peridem_lps_law.h).

#include "peridem_lps_law.h"

namespace peridem {

LpsConstants lps_constants(int dimension, LpsPlane plane, double K, double G)
{
  if (!(K > 0.0)) throw ParameterError("bulk modulus K must be > 0");
  if (!(G > 0.0)) throw ParameterError("shear modulus G must be > 0");
  if (dimension != 2 && dimension != 3) throw ParameterError("dimension must be 2 or 3");
  LpsConstants c;
  const double lambda = K - 2.0 * G / 3.0;
  if (dimension == 3 || plane == LpsPlane::ThreeD) {
    c.d = 3.0;
    c.a = K;
  } else if (plane == LpsPlane::PlaneStrain) {
    c.d = 2.0;
    c.a = lambda + G; // sigma_zz free to act, eps_zz = 0
  } else {
    c.d = 2.0;
    // sigma_zz = 0 eliminates eps_zz: lambda* = 2 lambda G / (lambda + 2 G)
    if (!(lambda + 2.0 * G > 0.0))
      throw ParameterError("plane stress needs lambda + 2G > 0 (K + 4G/3 > 0)");
    c.a = 2.0 * lambda * G / (lambda + 2.0 * G) + G;
  }
  c.b = c.d * (c.d + 2.0) * G;
  c.c_vol = c.d * c.a - c.b / c.d;
  c.c_dev = c.b;
  return c;
}

} // namespace peridem
