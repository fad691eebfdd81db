/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/dilation, the per-node dilation theta of
   bond_style peridem/lps. See doc/compute_peridem_dilation.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(peridem/dilation,ComputePeridemDilation);
// clang-format on
#else

#ifndef LMP_COMPUTE_PERIDEM_DILATION_H
#define LMP_COMPUTE_PERIDEM_DILATION_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputePeridemDilation : public Compute {
 public:
  ComputePeridemDilation(class LAMMPS *, int, char **);
  ~ComputePeridemDilation() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int nmax;
  double *dilation;
  class BondPeridemLPS *bond;
};

} // namespace LAMMPS_NS

#endif
#endif
