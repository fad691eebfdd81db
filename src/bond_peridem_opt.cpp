/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: bond_style peridem/opt. Only the force loop of ordinary steps
   differs from bond_style peridem: the same chunked passes
   (bond_peridem_chunked.h), compiled here with -fno-math-errno and
   -ftree-vectorize (cmake/PeridemLAMMPS.cmake,
   cmake/Modules/Packages/PERIDEM.cmake, src/Makefile.lammps), so that GCC
   takes several square roots and divisions per instruction, and built for
   AVX-512, AVX2 and the baseline, chosen when the library loads. Like every
   bond file it is compiled without FMA contraction (-ffp-contract=off; GCC's
   default for C++ is fast): the AVX-512 copy would otherwise fuse the
   products of |y|^2, and its forces would differ from the plain style's and
   from the energy steps' in the last bit.
------------------------------------------------------------------------- */

#include "bond_peridem_opt.h"
#include "bond_peridem_chunked.h"

using namespace LAMMPS_NS;

namespace {
struct Vectorised {}; // the tag of this file's copy of the chunked passes
} // namespace

/* ---------------------------------------------------------------------- */

BondPeridemOpt::BondPeridemOpt(LAMMPS *lmp) : BondPeridem(lmp) {}

/* ---------------------------------------------------------------------- */

// the dispatcher of the copies below is called directly, never through the vtable
void BondPeridemOpt::compute_chunked()
{
  vectorised_passes();
}

// three copies, for AVX-512, AVX2 and the baseline x86-64 (SSE2), one chosen when the library
// loads (GCC's function multiversioning: x86-64 Linux only; elsewhere the one copy the flags
// give): pass (b) then takes eight, four or two bonds per instruction
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void BondPeridemOpt::vectorised_passes()
{
  chunked_passes<Vectorised>();
}
