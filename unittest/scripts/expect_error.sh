#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# expect_error.sh REGEX COMMAND...: passes when COMMAND exits non-zero and its
# output contains a LAMMPS "ERROR" line matching REGEX (extended regex).
set -u
regex="$1"; shift
source "$(dirname "$0")/mpi_env.sh"
out="$("$@" 2>&1)"
rc=$?
if [ $rc -eq 0 ]; then
  echo "FAIL: expected a non-zero exit code, got 0. Output:"; echo "$out"; exit 1
fi
if ! grep -E "ERROR.*${regex}" <<<"$out" >/dev/null; then
  echo "FAIL: exit code $rc but no ERROR line matching /${regex}/. Output:"; echo "$out"; exit 1
fi
if grep -E "Segmentation|signal [0-9]+|core dumped" <<<"$out" >/dev/null; then
  echo "FAIL: crashed instead of a clean error. Output:"; echo "$out"; exit 1
fi
echo "OK: exit code $rc with: $(grep -E "ERROR" <<<"$out" | head -n 1)"
