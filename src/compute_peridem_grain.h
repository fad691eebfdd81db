/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/grain. See doc/compute_peridem_grain.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(peridem/grain,ComputePeridemGrain);
// clang-format on
#else

#ifndef LMP_COMPUTE_PERIDEM_GRAIN_H
#define LMP_COMPUTE_PERIDEM_GRAIN_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputePeridemGrain : public Compute {
 public:
  ComputePeridemGrain(class LAMMPS *, int, char **);
  ~ComputePeridemGrain() override;
  void init() override;
  void compute_array() override;

  static constexpr int NCOLS = 19;

 private:
  tagint maxmol;
  double **grains;
  char *id_damage, *id_fragments;
  class ComputePeridemDamage *damage;
  class ComputePeridemFragments *fragments;
};

} // namespace LAMMPS_NS

#endif
#endif
