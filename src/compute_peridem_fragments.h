/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: compute peridem/fragments. See doc/compute_peridem_fragments.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(peridem/fragments,ComputePeridemFragments);
// clang-format on
#else

#ifndef LMP_COMPUTE_PERIDEM_FRAGMENTS_H
#define LMP_COMPUTE_PERIDEM_FRAGMENTS_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputePeridemFragments : public Compute {
 public:
  ComputePeridemFragments(class LAMMPS *, int, char **);
  ~ComputePeridemFragments() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_array() override;
  void compute_peratom() override;
  void compute_local() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // number of fragments of grain g passing the size filter (after refresh)
  double grain_fragments(tagint g) const;
  // recompute if atoms or bonds may have changed since the last call
  void refresh();

  // one fragment: its ID (smallest atom ID), grain, nodes, volume, mass
  static constexpr int NCOLS = 5;

 private:
  enum { NODES, VOLUME };
  int min_kind;    // filter on NODES or VOLUME
  double min_size; // fragments smaller than this are debris
  int nmax;
  double *label;         // per atom and ghost: fragment ID (smallest atom ID), 0 outside the group
  std::vector<int> root; // per atom and ghost: local union-find root
  std::vector<double> rootmin; // per root: smallest label of its local component
  tagint maxmol;
  double stats[4];               // fragments, fragments passing the filter, debris, debris volume
  double **per_grain;            // per grain: fragments, fragments passing the filter
  std::vector<double> fragments; // NCOLS per fragment (rank 0 holds all for local output)
  bigint last_step;
  bigint last_ncalls;
  int iterations; // label propagation rounds at the last refresh

  void propagate();
  void collect();
  bool passes(const double *frag) const;
};

} // namespace LAMMPS_NS

#endif
#endif
