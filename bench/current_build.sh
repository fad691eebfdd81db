#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Sourced by the bench scripts: require_current_build DIR stops the bench when the build in
# DIR is older than its sources, i.e. when make would compile or link anything for the
# library or the driver. Timing such a build measures old code: in session 10 a stale
# /work/main/build (a library from before session 9) made a change look 35 % faster.
# Builds that make cannot query (no Makefile, e.g. Ninja) are not checked.
# PERIDEM_BENCH_STALE_OK=1 times them anyway.
require_current_build() {
  local dir="$1"
  [ -f "$dir/Makefile" ] || return 0
  [ "${PERIDEM_BENCH_STALE_OK:-0}" = 1 ] && return 0
  local work
  work=$(make -n -C "$dir" peridem lmp_peridem 2>/dev/null | grep -cE '(Building|Linking) CXX' || true)
  if [ "$work" != 0 ]; then
    echo "ERROR: the build in $dir is older than its sources (make would run $work compile or link steps):" \
      "rebuild it (cmake --build $dir) or set PERIDEM_BENCH_STALE_OK=1" >&2
    exit 1
  fi
}
