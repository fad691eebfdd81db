#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# expect_pass.sh [--regex REGEX]... [--absent REGEX]... COMMAND...: passes when COMMAND
# exits with code 0, prints a line matching each REGEX (extended regex, default
# PERIDEM-PASS), no line matching an --absent REGEX, and neither PERIDEM-FAIL nor a
# LAMMPS ERROR line nor a crash. (ctest's PASS_REGULAR_EXPRESSION alone ignores the exit
# code, so a crash after the PASS line would pass.)
set -u
regexes=()
absent=()
while [ "${1:-}" = "--regex" ] || [ "${1:-}" = "--absent" ]; do
  if [ "$1" = "--regex" ]; then regexes+=("$2"); else absent+=("$2"); fi
  shift 2
done
[ ${#regexes[@]} -eq 0 ] && regexes=("PERIDEM-PASS")
source "$(dirname "$0")/mpi_env.sh"
out="$("$@" 2>&1)"
rc=$?
echo "$out"
if [ $rc -ne 0 ]; then echo "FAIL: exit code $rc (expected 0)"; exit 1; fi
if grep -E "PERIDEM-FAIL|ERROR|Segmentation|signal [0-9]+|core dumped" <<<"$out" >/dev/null; then
  echo "FAIL: a failure, an error or a crash was reported"; exit 1
fi
for regex in "${regexes[@]}"; do
  if ! grep -E -- "${regex}" <<<"$out" >/dev/null; then echo "FAIL: no line matching /${regex}/"; exit 1; fi
done
for regex in ${absent[@]+"${absent[@]}"}; do
  if grep -E -- "${regex}" <<<"$out" >/dev/null; then echo "FAIL: a line matches /${regex}/"; exit 1; fi
done
echo "OK: exit code 0 and a line matching each of: ${regexes[*]}"
