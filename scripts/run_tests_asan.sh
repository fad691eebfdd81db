#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Sanitizer build (AddressSanitizer + UndefinedBehaviorSanitizer) of PERIDEM and
# its tests in build-asan/ (or $PERIDEM_ASAN_BUILD_DIR), then a stated subset of
# the suite under the sanitizers:
#   * the core tests (test_core), the LAMMPS-driven gtests, the force-style drivers
#     and the bad-input catalogue (error.* tests: LAMMPS's error exit must stay
#     clean, no sanitizer report on the way out);
#   * not the examples (example.*), the MPI variants (mpi2.*, *_np2) and the
#     benchmarks: 5-20x slower under ASan and they exercise the same code paths.
# Override the subset with PERIDEM_ASAN_TESTS (a ctest -R regex) and the excluded
# ones with PERIDEM_ASAN_EXCLUDE.
#
# Open MPI leaks at MPI_Init/MPI_Finalize (not ours), so leak detection is off.
# The stock `lmp` and `python3` routes load libperidem.so into an executable built
# without ASan: the ASan runtime has to come first, so it is LD_PRELOADed for the
# whole ctest run (harmless for the executables built with -fsanitize, which carry
# it anyway).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PERIDEM_ASAN_BUILD_DIR:-$here/build-asan}"
"$here/scripts/setup-debian.sh"
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
fi
# -Wall -Wextra are on for our targets: the build log must have no warning
cmake --build "$build" -j "$(nproc)" 2>&1 | tee "$build/build.log" | grep -E "warning:" && {
  echo "run_tests_asan.sh: compiler warnings (see $build/build.log)"; exit 1; } || true

asan_rt="$(gcc -print-file-name=libasan.so)"
ubsan_rt="$(gcc -print-file-name=libubsan.so)"
export LD_PRELOAD="$asan_rt:$ubsan_rt${LD_PRELOAD:+:$LD_PRELOAD}"
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:halt_on_error=1:detect_odr_violation=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$build"
ctest -j "$(nproc)" --output-on-failure --timeout 1800 \
  -R "${PERIDEM_ASAN_TESTS:-.}" \
  -E "${PERIDEM_ASAN_EXCLUDE:-^example\\.|^mpi2\\.|_np2|bench|_2d\$|ranks}"
