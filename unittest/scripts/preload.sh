#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# preload.sh LIBRARY COMMAND...: run COMMAND with LIBRARY appended to LD_PRELOAD,
# for COMMAND only, not for the test scripts around it. Under the sanitizers
# (scripts/run_tests_asan.sh) LD_PRELOAD already holds the ASan runtime, which
# must come first; a bash or timeout with both it and the ASan build of
# libperidem.so preloaded hangs at exit (glibc's setlocale lock, taken again by
# a destructor of libp11-kit, which liblammps pulls in).
lib="$1"; shift
export LD_PRELOAD="${LD_PRELOAD:+$LD_PRELOAD:}$lib"
exec "$@"
