#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Applies the package-wide mechanical edits to a PERIDEM tree (default: this repository):
#   1. the GPL-2.0 short header in every source file (scripts/dev/license_headers.py);
#   2. the glue namespace PERIDEM -> peridem_lmp (scripts/dev/rename_namespace.py);
#   3. snake_case names in the LAMMPS-free core (scripts/dev/snake_case_core.py);
#   then clang-format on the C++ files 2 and 3 changed.
# Idempotent: a second run changes nothing. Meant to be run on a merged tree and
# committed alone ("MECHANICAL: ..."), so that it can be dropped and re-run after merges.
set -euo pipefail
# everything in main(): step 1 also puts the header into this very file, which bash would
# otherwise go on reading from a shifted offset
main() {
  root="$(cd "${1:-$(dirname "${BASH_SOURCE[0]}")/../..}" && pwd)"
  dev="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
  list="$(mktemp)"
  python3 "$dev/rename_namespace.py" "$root" >"$list"
  python3 "$dev/snake_case_core.py" "$root" >>"$list"
  mapfile -t renamed < <(sort -u "$list")
  rm -f "$list"
  cxx=()
  for f in "${renamed[@]}"; do
    case "$f" in *.cpp | *.h) cxx+=("$root/$f") ;; esac
  done
  if [ ${#cxx[@]} -gt 0 ]; then
    (cd "$root" && clang-format -i "${cxx[@]}")
  fi
  echo "namespace and core names renamed in ${#renamed[@]} files"
  python3 "$dev/license_headers.py" "$root"
  python3 "$dev/license_headers.py" --check "$root"
}
main "$@"; exit $?
