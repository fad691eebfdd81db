/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: small helpers for parsing style arguments.
------------------------------------------------------------------------- */

#include "lmp_peridem_parse.h"

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

using namespace LAMMPS_NS;

namespace LAMMPS_NS {
namespace PERIDEM_NS {

int choice(LAMMPS *lmp, const std::string &command, const std::string &keyword,
           const std::string &value, std::initializer_list<const char *> options)
{
  int index = 0;
  std::string listed;
  for (const char *option : options) {
    if (value == option) return index;
    listed += (index == 0 ? "" : (index + 1 == int(options.size()) ? " or " : ", "));
    listed += option;
    index++;
  }
  lmp->error->all(FLERR, "{}: {} must be {}, not {}", command, keyword, listed, value);
  return -1;
}

int yes_no(LAMMPS *lmp, const std::string &command, const std::string &keyword,
           const std::string &value)
{
  return choice(lmp, command, keyword, value, {"yes", "no"}) == 0 ? 1 : 0;
}

double number(LAMMPS *lmp, const std::string &command, const std::string &keyword,
              const char *value)
{
  // read whole, and a number by LAMMPS's own test (utils::numeric: utils::is_double; before
  // 2023 that test looks at the characters only), in a message that names the command and
  // the keyword; inf, nan and overflows are named as such
  const std::string text = value ? value : "";
  char *end = nullptr;
  const double v = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
  const bool parsed = !text.empty() && end != text.c_str() && *end == '\0';
  if (parsed && !std::isfinite(v))
    lmp->error->all(FLERR, "{}: {} must be a finite number, not {}", command, keyword, text);
  if (!parsed || !utils::is_double(text))
    lmp->error->all(FLERR, "{}: {} must be a number, not '{}'", command, keyword, text);
  return v;
}

long long integer(LAMMPS *lmp, const std::string &command, const std::string &keyword,
                  const char *value)
{
  const std::string text = value ? value : "";
  char *end = nullptr;
  errno = 0;
  const long long v = text.empty() ? 0 : std::strtoll(text.c_str(), &end, 10);
  // LAMMPS's integers (utils::inumeric: utils::is_integer), within range
  if (!utils::is_integer(text) || *end != '\0' || errno == ERANGE)
    lmp->error->all(FLERR, "{}: {} must be an integer, not '{}'", command, keyword, text);
  return v;
}

int integer(LAMMPS *lmp, const std::string &command, const std::string &keyword, const char *value,
            int lo, int hi)
{
  const long long v = integer(lmp, command, keyword, value);
  if (v < lo || v > hi)
    lmp->error->all(FLERR, "{}: {} must be an integer from {} to {}, not {}", command, keyword, lo,
                    hi, v);
  return static_cast<int>(v);
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
