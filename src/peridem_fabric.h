/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM core: grain contacts from node contacts, the coordination number
   and the fabric tensor of a bed. No LAMMPS types.
------------------------------------------------------------------------- */

#ifndef PERIDEM_FABRIC_H
#define PERIDEM_FABRIC_H

#include <array>
#include <vector>

namespace peridem {

// Node contacts between grains a < b, or (after merge_grain_contacts) one contact per grain
// pair: n is the sum of the unit vectors from a's node to b's node over the node contacts.
struct GrainContact {
  long long a = 0, b = 0;
  double n[3] = {0.0, 0.0, 0.0};
  long long nodes = 0; // node contacts behind it
};

// One entry per grain pair (sorted by a, then b), the normals and node counts summed; the
// input may hold several entries of a pair (node contacts, or partial sums of several ranks).
std::vector<GrainContact> merge_grain_contacts(std::vector<GrainContact> contacts);

// Fabric tensor of unit contact normals, F = (1/N_c) sum_c n_c (x) n_c (Oda 1982; Satake 1982),
// each n_c the merged normal made unit; components xx yy zz xy xz yz, trace 1. A pair whose
// normals cancel (zero sum) is skipped. All zero without contacts.
std::array<double, 6> fabric_tensor(const std::vector<GrainContact> &merged);

// Mean coordination number: 2 N_c / N_g (0 without grains).
double coordination_number(long long contacts, long long grains);

} // namespace peridem

#endif
