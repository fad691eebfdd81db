/* -*- c++ -*- ----------------------------------------------------------
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

#ifndef LMP_PERIDEM_RESTART_H
#define LMP_PERIDEM_RESTART_H

#include "peridem_contact_law.h"

#include <cstdio>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// Restart sections of the PERIDEM force styles start with a tag that names
// the style and the version of its format. A file of another format (an
// older PERIDEM, before a field was added) is refused with a clear message
// instead of being misread; raise the version whenever a field changes.
enum RestartTag : int {
  RESTART_BOND_PERIDEM = 0x50444201,     // bond_style peridem: format 1
  RESTART_BOND_PERIDEM_LPS = 0x50444c01, // bond_style peridem/lps: format 1
  RESTART_PAIR_CONTACT = 0x50445003,     // pair_style peridem/contact: format 3
};

// The format version of a tag (its low byte).
inline int restart_format_version(int tag)
{
  return tag & 0xff;
}

void write_restart_tag(FILE *fp, RestartTag tag);

// reads the tag on rank 0, broadcasts it, and ends the run with an error
// naming the style when it is not `tag`
void check_restart_tag(LAMMPS_NS::LAMMPS *lmp, FILE *fp, RestartTag tag, const char *style);

// As check_restart_tag, but also accepts the older formats of the same style from
// version `oldest` on; returns the version read (the same on every rank).
int read_restart_version(LAMMPS_NS::LAMMPS *lmp, FILE *fp, RestartTag tag, int oldest,
                         const char *style);

// Contact parameters in a restart file, field by field (format 2 of pair_style
// peridem/contact): a field count, then each field as a double, so that a field added to
// peridem::ContactParams changes the count and the old files are refused by name instead of
// being misread.
void write_contact_params(FILE *fp, const peridem::ContactParams &p);

// Restart files are trusted input of LAMMPS; what a PERIDEM style reads from one is checked
// all the same, so that a damaged file stops with the style named instead of crashing later:
// every value finite and within [lo, hi].
void check_restart_values(LAMMPS_NS::LAMMPS *lmp, const char *style, const char *what,
                          const double *values, int n, double lo, double hi);
void check_restart_values(LAMMPS_NS::LAMMPS *lmp, const char *style, const char *what,
                          const int *values, int n, int lo, int hi);
peridem::ContactParams read_contact_params(LAMMPS_NS::LAMMPS *lmp, FILE *fp, const char *style);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
