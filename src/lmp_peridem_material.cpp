/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: material files seen from LAMMPS commands.
------------------------------------------------------------------------- */

#include "lmp_peridem_material.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <mpi.h>

using namespace LAMMPS_NS;

namespace LAMMPS_NS {
namespace PERIDEM_NS {

std::string read_text_file(LAMMPS *lmp, const std::string &command, const std::string &kind,
                           const std::string &file, bool potential)
{
  std::string text;
  long long n = -1;
  if (lmp->comm->me == 0) {
    FILE *fp = potential ? utils::open_potential(file, lmp, nullptr) : fopen(file.c_str(), "r");
    // Debian's LAMMPS 29 Sep 2021 patches open_potential to look in /usr/share/lammps/potentials
    // instead of LAMMPS_POTENTIALS: look there too, so the variable works with every LAMMPS
    const char *dirs = getenv("LAMMPS_POTENTIALS");
    if (!fp && potential && dirs) {
      const std::string base = file.substr(file.find_last_of('/') + 1), list = dirs;
      for (std::size_t a = 0; !fp && a <= list.size();) {
        const std::size_t b = std::min(list.find(':', a), list.size());
        if (b > a) fp = fopen((list.substr(a, b - a) + "/" + base).c_str(), "r");
        a = b + 1;
      }
    }
    if (fp) {
      char buf[4096];
      size_t got;
      while ((got = fread(buf, 1, sizeof(buf), fp)) > 0) text.append(buf, got);
      fclose(fp);
      n = (long long)text.size();
    }
  }
  MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, lmp->world);
  if (n < 0)
    lmp->error->all(FLERR, "{}: cannot open {} file '{}'{}", command, kind, file,
                    potential ? " (looked for it as given and in LAMMPS_POTENTIALS)" : "");
  if (n > INT_MAX) lmp->error->all(FLERR, "{}: {} file '{}' is too large", command, kind, file);
  text.resize((size_t)n);
  MPI_Bcast(&text[0], (int)n, MPI_CHAR, 0, lmp->world);
  return text;
}

peridem::Material load_material(LAMMPS *lmp, const std::string &command, const std::string &file,
                                const std::string &name)
{
  try {
    const peridem::MaterialFile materials =
        peridem::parse_material_text(read_text_file(lmp, command, "material", file, true), file);
    if (materials.units != lmp->update->unit_style)
      lmp->error->all(FLERR, "{}: material file {} is in units {} but the simulation uses units {}",
                      command, file, materials.units, lmp->update->unit_style);
    return materials.get(name);
  } catch (peridem::ParameterError &e) {
    lmp->error->all(FLERR, "{}: {}", command, e.what());
  }
  return {};
}

peridem::Micromodulus parse_micromodulus(LAMMPS *lmp, const std::string &command,
                                         const std::string &word)
{
  if (word == "constant") return peridem::Micromodulus::Constant;
  if (word == "conic") return peridem::Micromodulus::Conic;
  lmp->error->all(FLERR, "{}: unknown micromodulus '{}' (use constant or conic)", command, word);
  return peridem::Micromodulus::Constant;
}

const char *micromodulus_name(peridem::Micromodulus m)
{
  return m == peridem::Micromodulus::Conic ? "conic" : "constant";
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
