/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/bed. See doc/compute_peridem_bed.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(peridem/bed,ComputePeridemBed);
// clang-format on
#else

#ifndef LMP_COMPUTE_PERIDEM_BED_H
#define LMP_COMPUTE_PERIDEM_BED_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputePeridemBed : public Compute {
 public:
  ComputePeridemBed(class LAMMPS *, int, char **);
  ~ComputePeridemBed() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;

 private:
  enum { TOP_SURFACE, TOP_MAX, TOP_REGION, TOP_VARIABLE };
  char *id_region, *id_variable;
  int top_kind, ivariable;
  double bin_width;    // 0: the mean grain diameter
  double lo[3], hi[3]; // container: bounding box of the region
  double stats[8];
  std::vector<double> holes; // per grain ID: hole volume (2d), from x0, once
  bool holes_ready;

  void find_holes();
};

} // namespace LAMMPS_NS

#endif
#endif
