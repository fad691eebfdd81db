/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM core: bed measures, see peridem_bed.h.
------------------------------------------------------------------------- */

#include "peridem_bed.h"
#include "peridem_math.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace peridem {

double hole_area_2d(const std::vector<double> &xy, double h)
{
  const size_t n = xy.size() / 2;
  if (n == 0 || h <= 0.0) return 0.0;
  double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
  for (size_t k = 0; k < n; k++)
    for (int d = 0; d < 2; d++) {
      lo[d] = std::min(lo[d], xy[2 * k + d]);
      hi[d] = std::max(hi[d], xy[2 * k + d]);
    }
  const double cell = 0.25 * h, r = h / std::sqrt(2.0) * (1.0 + 1e-9);
  const int pad = 2 + int(std::ceil(r / cell));
  const int nx = int(std::ceil((hi[0] - lo[0]) / cell)) + 2 * pad + 1;
  const int ny = int(std::ceil((hi[1] - lo[1]) / cell)) + 2 * pad + 1;
  // cell (i, j) has centre lo + (i - pad + 0.5) * cell
  std::vector<char> state(size_t(nx) * ny, 0); // 0 empty, 1 solid, 2 outside
  const int reach = int(std::ceil(r / cell)) + 1;
  for (size_t k = 0; k < n; k++) {
    const double x = xy[2 * k], y = xy[2 * k + 1];
    const int ci = int(std::floor((x - lo[0]) / cell)) + pad;
    const int cj = int(std::floor((y - lo[1]) / cell)) + pad;
    for (int i = std::max(0, ci - reach); i <= std::min(nx - 1, ci + reach); i++)
      for (int j = std::max(0, cj - reach); j <= std::min(ny - 1, cj + reach); j++) {
        const double cx = lo[0] + (i - pad + 0.5) * cell, cy = lo[1] + (j - pad + 0.5) * cell;
        if ((cx - x) * (cx - x) + (cy - y) * (cy - y) <= r * r) state[size_t(i) * ny + j] = 1;
      }
  }
  // flood fill (4-connected) from a seed cell; returns the cells reached
  auto flood = [&](size_t seed, char mark) {
    std::vector<size_t> stack{seed};
    state[seed] = mark;
    size_t count = 0;
    while (!stack.empty()) {
      const size_t c = stack.back();
      stack.pop_back();
      count++;
      const int i = int(c / ny), j = int(c % ny);
      const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
      for (const auto &q : nb) {
        if (q[0] < 0 || q[1] < 0 || q[0] >= nx || q[1] >= ny) continue;
        const size_t e = size_t(q[0]) * ny + q[1];
        if (state[e] == 0) {
          state[e] = mark;
          stack.push_back(e);
        }
      }
    }
    return count;
  };
  flood(0, 2); // cell (0, 0) lies in the padding: outside
  // every other empty region is enclosed; pockets smaller than a disk of
  // radius 2h are gaps of the dilation along the stepped boundary of a
  // turned lattice, not holes
  const double min_hole = kPi * 4.0 * h * h;
  double area = 0.0;
  for (size_t c = 0; c < state.size(); c++) {
    if (state[c] != 0) continue;
    const double a = double(flood(c, 3)) * cell * cell;
    if (a >= min_hole) area += a;
  }
  return area;
}

double median_of_bins(std::vector<double> bin_max)
{
  bin_max.erase(std::remove_if(bin_max.begin(), bin_max.end(), [](double v) { return v < -1e300; }),
                bin_max.end());
  if (bin_max.empty()) return 0.0;
  std::sort(bin_max.begin(), bin_max.end());
  const size_t m = bin_max.size();
  return m % 2 ? bin_max[m / 2] : 0.5 * (bin_max[m / 2 - 1] + bin_max[m / 2]);
}

} // namespace peridem
