/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Benchmark: jam N polydisperse disks (radius
// 0.4-1.1, mean 0.8, sd 0.09, Bhattacharya & Lipton's (2023) §7.3 bed) in a container
// of width sqrt(N) mean diameters (a square-ish bed), one core. Prints N, the
// median wall and CPU time of `repeats` runs, iterations, packing fraction,
// rattlers, and (unless -DNO_GROW) the CPU time of the rattler growth and the
// rattlers left after it. With -3 first, spheres of the same radii in a box of
// side cbrt(N) mean diameters. Last, the exponent b of a least-squares fit
// CPU ~ N^b over all sizes given (the growth of time with the bed).
// Not a unit test; build by hand from the repo root:
//   g++ -O3 -std=c++17 -Isrc bench/packing/bench_packing.cpp
//       src/peridem_geometry_packing.cpp -o /tmp/bench_packing
//   /tmp/bench_packing 1500 5000 20000 50000 100000
//   /tmp/bench_packing -3 500 2000 10000
// bench/packing/compare.sh REV builds this and REV's packer (-DNO_GROW) and runs
// them alternately, so both see the same load (CPU times, ratios).
#include "peridem_geometry_packing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <string>
#include <vector>

using namespace peridem;

int main(int argc, char **argv)
{
  int dim = 2, first = 1;
  if (argc > 1 && std::string(argv[1]) == "-3") {
    dim = 3;
    first = 2;
  }
  std::vector<double> logn, logcpu;
  for (int a = first; a < argc; a++) {
    const std::size_t n = std::strtoul(argv[a], nullptr, 10);
    const int repeats = n <= 20000 ? 5 : 1;
    const auto r = draw_radii(RadiusDistribution::normal(0.8, 0.09, 0.4, 1.1), n, 1);
    PackingOptions o;
    o.dimension = dim;
    const double side = 1.6 * std::pow(static_cast<double>(n), 1.0 / dim);
    for (int d = 0; d < dim - 1; d++) o.hi[d] = side;
    o.hi[dim - 1] = 4 * side;
    std::vector<double> t, cpu;
    Packing p;
    for (int k = 0; k < repeats; k++) {
      const auto t0 = std::chrono::steady_clock::now();
      const std::clock_t c0 = std::clock();
      p = pack_spheres(r, o);
      cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
      t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(t.begin(), t.end());
    std::sort(cpu.begin(), cpu.end());
    const auto j = jamming_report(p, o.tolerance);
#ifndef NO_GROW
    const std::clock_t g0 = std::clock();
    const RattlerGrowth G = grow_rattlers(p, 1.1, o.tolerance);
    const double gcpu = static_cast<double>(std::clock() - g0) / CLOCKS_PER_SEC;
    std::printf("N %zu  rattler growth cpu %.3f s: rattlers %zu -> %zu (%d passes), fraction "
                "%.4f\n",
                n, gcpu, G.before, G.after, G.passes, p.fraction);
#endif
    std::printf("N %zu  median wall %.3f s, cpu %.3f s (%d runs)  ns per disk-iteration %.0f  "
                "iterations %d  fraction %.4f  rattlers %.1f%%  smallest gap %.2g\n",
                n, t[t.size() / 2], cpu[cpu.size() / 2], repeats,
                1e9 * cpu[cpu.size() / 2] / (static_cast<double>(n) * p.iterations), p.iterations,
                p.fraction, 100.0 * j.rattlers / n, smallest_gaps(p).pair);
    std::fflush(stdout);
    logn.push_back(std::log(static_cast<double>(n)));
    logcpu.push_back(std::log(cpu[cpu.size() / 2]));
  }
  if (logn.size() >= 2) {
    double mn = 0.0, mc = 0.0, snn = 0.0, snc = 0.0;
    for (std::size_t k = 0; k < logn.size(); k++) {
      mn += logn[k] / logn.size();
      mc += logcpu[k] / logn.size();
    }
    for (std::size_t k = 0; k < logn.size(); k++) {
      snn += (logn[k] - mn) * (logn[k] - mn);
      snc += (logn[k] - mn) * (logcpu[k] - mc);
    }
    std::printf("fit: cpu ~ N^%.2f over %zu sizes (%dD)\n", snc / snn, logn.size(), dim);
  }
}
