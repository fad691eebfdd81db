/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: format tags at the start of the restart sections of PERIDEM
   styles.
------------------------------------------------------------------------- */

#include "lmp_peridem_restart.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cmath>
#include <cstdlib>
#include <limits>

#include <mpi.h>
#include <vector>

using namespace LAMMPS_NS;

namespace LAMMPS_NS {
namespace PERIDEM_NS {

void write_restart_tag(FILE *fp, RestartTag tag)
{
  const int value = tag;
  fwrite(&value, sizeof(int), 1, fp);
}

namespace {

int read_tag(LAMMPS *lmp, FILE *fp)
{
  int value = 0;
  // a file without a tag holds other data at this place: read its bytes
  // without sfread's end-of-file error so that the message of the caller is
  // the one the user sees
  if (lmp->comm->me == 0 && fread(&value, sizeof(int), 1, fp) != 1) value = 0;
  MPI_Bcast(&value, 1, MPI_INT, 0, lmp->world);
  return value;
}

[[noreturn]] void refuse(LAMMPS *lmp, int value, RestartTag tag, const char *style)
{
  lmp->error->all(FLERR,
                  "{}: the restart file was written by an older PERIDEM (its {} settings are in "
                  "another format, tag {:#x}, expected {:#x}); restart it with the version "
                  "that wrote it, or go through write_data in that version and read_data in "
                  "this one",
                  style, style, (unsigned)value, (unsigned)tag);
  std::abort(); // not reached: Error::all ends the run
}

// the fields of ContactParams in file order; a new field goes at the end, with the version
// of RESTART_PAIR_CONTACT raised
std::vector<double> contact_fields(const peridem::ContactParams &p)
{
  return {p.Kn,
          p.Rc,
          (double)static_cast<int>(p.damping),
          p.r_d,
          p.eps_n,
          p.C,
          p.kappa_eff,
          p.damp_approach_only ? 1.0 : 0.0,
          (double)static_cast<int>(p.friction),
          p.mu};
}

peridem::ContactParams contact_from_fields(const std::vector<double> &v)
{
  peridem::ContactParams p;
  p.Kn = v[0];
  p.Rc = v[1];
  p.damping = static_cast<peridem::ContactDamping>(static_cast<int>(v[2]));
  p.r_d = v[3];
  p.eps_n = v[4];
  p.C = v[5];
  p.kappa_eff = v[6];
  p.damp_approach_only = v[7] != 0.0;
  p.friction = static_cast<peridem::ContactFriction>(static_cast<int>(v[8]));
  p.mu = v[9];
  return p;
}

} // namespace

void check_restart_tag(LAMMPS *lmp, FILE *fp, RestartTag tag, const char *style)
{
  const int value = read_tag(lmp, fp);
  if (value != tag) refuse(lmp, value, tag, style);
}

int read_restart_version(LAMMPS *lmp, FILE *fp, RestartTag tag, int oldest, const char *style)
{
  const int value = read_tag(lmp, fp);
  const int version = restart_format_version(value);
  if ((value & ~0xff) != (tag & ~0xff) || version < oldest || version > restart_format_version(tag))
    refuse(lmp, value, tag, style);
  return version;
}

void check_restart_values(LAMMPS *lmp, const char *style, const char *what, const double *values,
                          int n, double lo, double hi)
{
  for (int k = 0; k < n; k++)
    if (!std::isfinite(values[k]) || values[k] < lo || values[k] > hi)
      lmp->error->all(FLERR,
                      "{}: the restart file holds {} {} for entry {} (damaged file? expected a "
                      "finite value from {} to {})",
                      style, what, values[k], k + 1, lo, hi);
}

void check_restart_values(LAMMPS *lmp, const char *style, const char *what, const int *values,
                          int n, int lo, int hi)
{
  for (int k = 0; k < n; k++)
    if (values[k] < lo || values[k] > hi)
      lmp->error->all(FLERR,
                      "{}: the restart file holds {} {} for entry {} (damaged file? expected {} "
                      "to {})",
                      style, what, values[k], k + 1, lo, hi);
}

void write_contact_params(FILE *fp, const peridem::ContactParams &p)
{
  const std::vector<double> v = contact_fields(p);
  const int n = (int)v.size();
  fwrite(&n, sizeof(int), 1, fp);
  fwrite(v.data(), sizeof(double), n, fp);
}

peridem::ContactParams read_contact_params(LAMMPS *lmp, FILE *fp, const char *style)
{
  const int want = (int)contact_fields(peridem::ContactParams()).size();
  int n = 0;
  if (lmp->comm->me == 0) utils::sfread(FLERR, &n, sizeof(int), 1, fp, nullptr, lmp->error);
  MPI_Bcast(&n, 1, MPI_INT, 0, lmp->world);
  if (n != want)
    lmp->error->all(FLERR,
                    "{}: the restart file holds {} contact parameters per type pair, this "
                    "PERIDEM {}: it was written by another version; restart it with the version "
                    "that wrote it, or go through write_data",
                    style, n, want);
  std::vector<double> v(n);
  if (lmp->comm->me == 0)
    utils::sfread(FLERR, v.data(), sizeof(double), n, fp, nullptr, lmp->error);
  MPI_Bcast(v.data(), n, MPI_DOUBLE, 0, lmp->world);
  // Kn, Rc > 0; the enums (damping, friction) and the flag within their ranges
  constexpr double big = std::numeric_limits<double>::max();
  check_restart_values(lmp, style, "contact stiffness and radius", &v[0], 2, 1e-300, big);
  check_restart_values(lmp, style, "contact damping", &v[2], 1, 0.0, 2.0);
  check_restart_values(lmp, style, "damping constants", &v[3], 5, -big, big);
  check_restart_values(lmp, style, "contact friction", &v[8], 1, 0.0, 2.0);
  check_restart_values(lmp, style, "friction coefficient", &v[9], 1, 0.0, big);
  return contact_from_fields(v);
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
