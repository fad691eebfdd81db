/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Helpers shared by the geometry unit tests (test_geometry_*.cpp).
#ifndef PERIDEM_GEOMETRY_TEST_HELPERS_H
#define PERIDEM_GEOMETRY_TEST_HELPERS_H

#include "peridem_geometry_error.h"

#include <functional>
#include <string>

// Message of the GeometryError thrown by f, or "" if f does not throw; lets a
// test check the wording of error messages, not only that something threw.
inline std::string geometryErrorOf(const std::function<void()> &f)
{
  try {
    f();
  } catch (const peridem::GeometryError &e) {
    return e.what();
  }
  return "";
}

#endif
