/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Benchmark: build 500 grains of ~150 nodes each (lattice nodes + bonds with
// Bhattacharya & Lipton 2023, §5 pruning), as the grain-creation command
// does. Not a unit test; build by hand, e.g. from the repo root:
//   g++ -O2 -std=c++17 -Isrc bench/bench_geometry_bonds.cpp src/peridem_geometry_*.cpp \
//       -o /tmp/bench_geometry_bonds && /tmp/bench_geometry_bonds
#include "peridem_geometry_grain.h"
#include "peridem_geometry_shapes.h"

#include <chrono>
#include <cstdio>

using namespace peridem;

int main()
{
  const int grains = 500;
  // Mix of shapes; h chosen so that a grain has about 150 nodes.
  const char *names[] = {"perturbed_disk", "plus", "ring", "hexagon", "notched_plate"};
  const double sizes[] = {1.0, 1.0, 1.0, 1.0, 0.5};
  const double hs[] = {0.125, 0.1, 0.13, 0.13, 0.075};
  for (const Pruning pruning : {Pruning::ExtendedBoundary, Pruning::Exact}) {
    std::size_t nodes = 0, bonds = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int g = 0; g < grains; ++g) {
      const int s = g % 5;
      std::map<std::string, double> params;
      if (s == 0) params["seed"] = g;
      Polygon shape = make_shape(names[s], params);
      shape.rotate(0.37 * g).translate({3.0 * g * sizes[s], 0.0}); // distinct grains
      GrainOptions opt;
      opt.pruning = pruning;
      const Grain2D gr = discretize_grain(shape, hs[s], 3.0 * hs[s], opt);
      nodes += gr.nodes.size();
      bonds += gr.bonds.size();
    }
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s pruning: %d grains, %zu nodes (%.0f per grain), %zu bonds: %.3f s\n",
                pruning == Pruning::ExtendedBoundary ? "extended" : "exact", grains, nodes,
                double(nodes) / grains, bonds, sec);
  }
  return 0;
}
