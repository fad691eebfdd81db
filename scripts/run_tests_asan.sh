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
# part of its tests in build-asan/ (or $PERIDEM_ASAN_BUILD_DIR), then that part of
# the suite under the sanitizers (unittest/README.md, "Sanitizers", says what and
# why):
#   * built: lmp_peridem and libperidem.so ($PERIDEM_ASAN_TARGETS; "all" builds
#     everything, also test_core, the force-style drivers and the gtests);
#   * run: the bad-input catalogue (catalogue_*: every style's argument parsing and
#     init, and LAMMPS's error exit), eleven LAMMPS-level inputs (contact, breakage,
#     walls, LPS, restart and data files, cuts, files) and the python3 route; with
#     PERIDEM_ASAN_TARGETS=all also the core unit tests and the force-style drivers
#     (their tests run when built). Not the examples, the multi-rank variants and
#     the long physics runs, which are 2-20x slower under ASan and exercise the
#     same code paths ($PERIDEM_ASAN_TESTS, a ctest -R regex; $PERIDEM_ASAN_EXCLUDE).
# Any sanitizer report fails its test: halt_on_error, -fno-sanitize-recover.
#
# Open MPI leaks at MPI_Init/MPI_Finalize (not ours), so leak detection is off.
# The `python3` and preload routes load libperidem.so into executables built without
# ASan: the ASan runtime has to come first, so it is LD_PRELOADed for those tests only. detect_odr_violation=0: liblammps and libperidem.so both define
# LAMMPS's inline statics (one copy per library, as in the normal build).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PERIDEM_ASAN_BUILD_DIR:-$here/build-asan}"
jobs="${PERIDEM_ASAN_JOBS:-$(nproc)}"
"$here/scripts/setup-debian.sh"
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
# set before the build too: gtest_discover_tests runs each gtest executable at build time
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:halt_on_error=1:detect_odr_violation=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
launcher=()
if command -v ccache >/dev/null; then # a rebuild after a small change takes seconds
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
fi
targets="${PERIDEM_ASAN_TARGETS:-lmp_peridem}"
target_args=()
[ "$targets" = all ] || for t in $targets; do target_args+=(--target "$t"); done
# -Wall -Wextra are on for our targets: the build must succeed with no warning
start=$SECONDS
if ! cmake --build "$build" -j "$jobs" "${target_args[@]}" >"$build/build.log" 2>&1; then
  tail -n 30 "$build/build.log"; echo "run_tests_asan.sh: build failed (see $build/build.log)"; exit 1
fi
if grep -E "warning:" "$build/build.log"; then
  echo "run_tests_asan.sh: compiler warnings (see $build/build.log)"; exit 1
fi
echo "run_tests_asan.sh: built in $((SECONDS - start)) s"
[ "${PERIDEM_ASAN_BUILD_ONLY:-0}" = 1 ] && exit 0

core='^(Bed|BondLaw|ContactLaw|Geometry[A-Za-z]+|GrainShape|LpsLaw|Material|WallGeometry[A-Za-z0-9]*)\.'
inputs='contact_after_break_2d|contact_incline_regularized_0\.95|contact_pair_local'
inputs="$inputs|contact_startup_wall_overlap_warns|bond_lps_material|escaped_nodes_beyond_wall_deleted"
inputs="$inputs|notch_node_row_np1|data_file_keeps_damage_np1|centroid_range_closed_form_np1"
inputs="$inputs|files\.found_in_potentials_np1|driver\.clear_keeps_styles"
# the core unit tests and the force-style drivers when they were built
built="catalogue_|^($inputs)\$"
[ -x "$build/unittest/test_core" ] && built="$core|$built"
[ -x "$build/unittest/force-styles/lammps_test_bond_style" ] && built="^ForceStyles\.|$built"
cd "$build"
start=$SECONDS
# our executables carry the ASan runtime: no preload (preloading it into every bash,
# grep and python3 of the test scripts makes them 3x slower)
ctest -j "$jobs" --output-on-failure --timeout 900 \
  -R "${PERIDEM_ASAN_TESTS:-$built}" \
  -E "${PERIDEM_ASAN_EXCLUDE:-_NOT_BUILT\$|_np2\$|^(python|preload)\.}"
# python3 and the stock lmp load libperidem.so into executables built without ASan:
# its runtime has to come first. preload.clear_keeps_styles appends libperidem.so
# for lmp only (unittest/scripts/preload.sh). ess_singleton_isolated: no orted daemon
# for the singleton MPI_Init of lmp; it inherited both preloads and hung at exit in
# glibc's setlocale lock (a destructor of libp11-kit). Not python.lmp_command_route:
# the stock lmp with the ASan runtime preloaded hangs in Py_Initialize (setlocale,
# the same lock, already held before libperidem.so is loaded; unittest/README.md).
OMPI_MCA_ess_singleton_isolated=1 \
LD_PRELOAD="$(gcc -print-file-name=libasan.so):$(gcc -print-file-name=libubsan.so)" \
  ctest -j "$jobs" --output-on-failure --timeout 900 \
  -R "${PERIDEM_ASAN_PRELOAD_TESTS:-^(python\.module_route|preload\.clear_keeps_styles)\$}"
echo "run_tests_asan.sh: tests ran in $((SECONDS - start)) s"
