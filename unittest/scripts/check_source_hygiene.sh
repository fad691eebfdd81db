#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Source hygiene of src/ that an upstream LAMMPS reviewer checks by grep:
#  - no M_PI (LAMMPS glue: MathConst::MY_PI; core: peridem::kPi in peridem_math.h),
#    no GCC builtins, no LAMMPS_VERSION_NUMBER (not a LAMMPS macro);
#  - papers cited by author and year, not by project shorthand;
#  - the LAMMPS-free core (src/peridem_*) includes no LAMMPS header;
#  - the style macros of src/*.h list the styles of driver/register_peridem.cpp.
# Usage: check_source_hygiene.sh REPO_ROOT. Prints PERIDEM-PASS or the offending lines.
set -uo pipefail
root="${1:?usage: check_source_hygiene.sh REPO_ROOT}"
cd "$root/src" || exit 1
bad=0
report() { # what, grep output
  if [ -n "$2" ]; then
    echo "$1:"
    echo "$2"
    bad=1
  fi
}
report "M_PI (use MathConst::MY_PI or peridem::kPi)" "$(grep -nw 'M_PI' -- *.cpp *.h)"
report "compiler builtins" "$(grep -n '__builtin_' -- *.cpp *.h)"
report "LAMMPS_VERSION_NUMBER is not a LAMMPS macro" "$(grep -n 'LAMMPS_VERSION_NUMBER' -- *.cpp *.h)"
report "project shorthand instead of an author-year citation" \
  "$(grep -nE '\[BL\]|\[JDBL\]|\bseed (§|Sec\.|eq\.|Table)|\bseed'"'"'s\b|grain-shape seed|PeriDEM seed|\bissue [0-9]+|shared/seeds|in the seed\b|[Tt]he seed \(|grain-shape paper|PeriDEM paper' -- *.cpp *.h)"
# the history of a measurement belongs in bench/README.md, not in a comment
report "development-log labels or dates in src/ (measurement history: bench/README.md)" \
  "$(grep -nE '\b[Ss]ession [0-9]+|\b20[0-9]{2}-[01][0-9]-[0-3][0-9]\b|[0-9.]+ -> [0-9.]+ ns' -- *.cpp *.h)"
for f in peridem_*.cpp peridem_*.h; do
  for inc in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$f"); do
    case "$inc" in
    peridem_*) ;;
    *) report "$f: the LAMMPS-free core includes \"$inc\"" "$f" ;;
    esac
  done
done
# the styles a LAMMPS tree registers (the *Style(...) macros of src/*.h) are the ones the
# stand-alone routes register (for_each_style() in driver/register_peridem.cpp)
macros="$(sed -n 's/^\([A-Z][a-z]*\)Style(\([^,]*\),\([A-Za-z]*\));.*/\1 \2 \3/p' -- *.h |
  sed 's/^Atom /atom /; s/^Bond /bond /; s/^Pair /pair /; s/^Fix /fix /; s/^Compute /compute /; s/^Command /command /' | sort)"
listed="$(sed -n 's/^ *sink\.\([a-z]*\)("\([^"]*\)", &[a-z_]*<\([A-Za-z]*\)>);.*/\1 \2 \3/p' \
  "$root/driver/register_peridem.cpp" | sort)"
report "style macros in src/*.h (<) and for_each_style() in driver/register_peridem.cpp (>) differ" \
  "$(diff <(echo "$macros") <(echo "$listed") | grep '^[<>]')"
[ -n "$macros" ] || report "no style macro found in src/*.h" "(none)"
if [ $bad -eq 0 ]; then
  echo "PERIDEM-PASS source hygiene of src/"
  exit 0
fi
echo "PERIDEM-FAIL source hygiene of src/"
exit 1
