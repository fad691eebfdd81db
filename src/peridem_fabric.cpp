/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

#include "peridem_fabric.h"

#include <algorithm>
#include <cmath>

namespace peridem {

std::vector<GrainContact> merge_grain_contacts(std::vector<GrainContact> contacts)
{
  std::sort(contacts.begin(), contacts.end(), [](const GrainContact &p, const GrainContact &q) {
    return p.a < q.a || (p.a == q.a && p.b < q.b);
  });
  std::vector<GrainContact> merged;
  for (const GrainContact &c : contacts) {
    if (merged.empty() || merged.back().a != c.a || merged.back().b != c.b) {
      merged.push_back(c);
      continue;
    }
    GrainContact &m = merged.back();
    for (int k = 0; k < 3; k++) m.n[k] += c.n[k];
    m.nodes += c.nodes;
  }
  return merged;
}

std::array<double, 6> fabric_tensor(const std::vector<GrainContact> &merged)
{
  std::array<double, 6> f{};
  long long used = 0;
  for (const GrainContact &c : merged) {
    const double len = std::sqrt(c.n[0] * c.n[0] + c.n[1] * c.n[1] + c.n[2] * c.n[2]);
    if (len == 0.0) continue;
    const double n[3] = {c.n[0] / len, c.n[1] / len, c.n[2] / len};
    f[0] += n[0] * n[0];
    f[1] += n[1] * n[1];
    f[2] += n[2] * n[2];
    f[3] += n[0] * n[1];
    f[4] += n[0] * n[2];
    f[5] += n[1] * n[2];
    used++;
  }
  if (used > 0)
    for (double &v : f) v /= double(used);
  return f;
}

double coordination_number(long long contacts, long long grains)
{
  return grains > 0 ? 2.0 * double(contacts) / double(grains) : 0.0;
}

} // namespace peridem
