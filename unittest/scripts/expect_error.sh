#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# expect_error.sh [--warning WREGEX] [--cmake] REGEX COMMAND...: passes when COMMAND exits
# non-zero and its output contains a LAMMPS "ERROR" line matching REGEX (extended regex).
# --warning: a "WARNING: " line matching WREGEX must come before that ERROR line (a warning
# that announces the error). --cmake: the error is CMake's ("CMake Error"), whose message
# CMake wraps at word boundaries: line breaks and runs of blanks count as one space.
set -u
warning=""; prefix="ERROR"; cmake=0
while [ $# -gt 0 ]; do
  case "$1" in
  --warning) warning="$2"; shift 2 ;;
  --cmake) prefix="CMake Error"; cmake=1; shift ;;
  *) break ;;
  esac
done
regex="$1"; shift
source "$(dirname "$0")/mpi_env.sh"
out="$("$@" 2>&1)"
rc=$?
text="$out"
[ $cmake -eq 0 ] || text="$(tr -s ' \n' ' ' <<<"$out")"
if [ $rc -eq 0 ]; then
  echo "FAIL: expected a non-zero exit code, got 0. Output:"; echo "$out"; exit 1
fi
if ! grep -E "${prefix}.*${regex}" <<<"$text" >/dev/null; then
  echo "FAIL: exit code $rc but no $prefix line matching /${regex}/. Output:"; echo "$out"; exit 1
fi
if grep -E "Segmentation|signal [0-9]+|core dumped" <<<"$out" >/dev/null; then
  echo "FAIL: crashed instead of a clean error. Output:"; echo "$out"; exit 1
fi
if [ -n "$warning" ]; then
  w=$(grep -nE "WARNING: ${warning}" <<<"$out" | head -n 1 | cut -d: -f1)
  e=$(grep -nE "ERROR.*${regex}" <<<"$out" | head -n 1 | cut -d: -f1)
  if [ -z "$w" ] || [ "$w" -ge "$e" ]; then
    echo "FAIL: no WARNING line matching /${warning}/ before the error. Output:"; echo "$out"; exit 1
  fi
fi
# the first ERROR line whole: scripts/draft_error_catalogue.py reads its (src/<file>:<line>)
first="$(grep -E "ERROR" <<<"$out" | head -n 1)"
[ $cmake -eq 0 ] || first="$(grep -oE "${prefix}.*${regex}" <<<"$text" | head -n 1)"
echo "OK: exit code $rc with: $first"
