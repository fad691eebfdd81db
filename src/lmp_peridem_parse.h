/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: small helpers for parsing style arguments.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_PARSE_H
#define LMP_PERIDEM_PARSE_H

#include <initializer_list>
#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// The position of `value` among `options` (e.g. {"no", "yes"}); otherwise a
// LAMMPS error "<command>: <keyword> must be a, b or c, not <value>".
int choice(LAMMPS_NS::LAMMPS *lmp, const std::string &command, const std::string &keyword,
           const std::string &value, std::initializer_list<const char *> options);

// 1 for "yes", 0 for "no"; otherwise "<command>: <keyword> must be yes or no, not ...".
int yes_no(LAMMPS_NS::LAMMPS *lmp, const std::string &command, const std::string &keyword,
           const std::string &value);

// A number for <keyword> of <command>, finite: "nan", "inf" and words that are no number
// end the run with "<command>: <keyword> must be a finite number, not nan" (LAMMPS's
// utils::numeric() would name neither the command nor the keyword).
double number(LAMMPS_NS::LAMMPS *lmp, const std::string &command, const std::string &keyword,
              const char *value);

// A whole number (decimal, within 64 bits) for <keyword> of <command>; otherwise
// "<command>: <keyword> must be an integer, not '<value>'" (1.5, nan, words, overflow).
long long integer(LAMMPS_NS::LAMMPS *lmp, const std::string &command, const std::string &keyword,
                  const char *value);

// integer() for a value stored in an int (an atom or bond type): outside [lo, hi] it ends
// the run with "<command>: <keyword> must be an integer from <lo> to <hi>, not <value>"
// instead of wrapping (4294967297 would become 1 in an int).
int integer(LAMMPS_NS::LAMMPS *lmp, const std::string &command, const std::string &keyword,
            const char *value, int lo, int hi);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
