#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Builds LAMMPS 4 Feb 2025 (the source of Debian 13 "trixie", lammps 20250204+dfsg.1-2)
# outside the repository and checks PERIDEM against it, three ways:
#   1. out of tree: libperidem, lmp_peridem and the LAMMPS-level tests (ctest) built
#      against a LAMMPS with MOLECULE, PERI, RIGID (examples/rigid-grains) and PLUGIN;
#   2. as a plugin: peridemplugin.so loaded with `plugin load` into that LAMMPS's lmp;
#   3. in tree: src/ copied to lammps/src/PERIDEM and built into LAMMPS through
#      its CMake package mechanism (PKG_PERIDEM, cmake/Modules/Packages/PERIDEM.cmake);
#   then the LAMMPS-level tests of 1. again through the in-tree lmp and the plugin;
#   4. in tree with the traditional make build (`intree-make`): src/ copied to src/PERIDEM of a
#      second, make-only copy of the LAMMPS tree, `make yes-peridem` and `make mpi`;
#   5. `bpm`: one lmp_bpm with LAMMPS's BPM package and PERIDEM, for bench/fracture's
#      side-by-side measurement with BPM (run_bpm_impact.sh).
# Everything is cached under $PERIDEM_LAMMPS2025_DIR (default /opt/peridem/lammps-2025):
# a second call only rebuilds what changed. Usage:
#   scripts/build_lammps_2025.sh [stage ...]     stages: fetch lammps outoftree reference plugin intree
#                                                 intree-tests plugin-tests intree-make bpm
# (default: all but intree-make and bpm, in that order). Logs: $PERIDEM_LAMMPS2025_DIR/logs/. Exit code 0 when
# every stage passed.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="${PERIDEM_LAMMPS2025_DIR:-/opt/peridem/lammps-2025}"
version="20250204+dfsg.1-2"
src="$root/lammps-4Feb2025"
build="$root/build"              # LAMMPS build folder (shared by the plain and in-tree builds)
plain="$root/install-plain"      # LAMMPS without PERIDEM
intree="$root/install-peridem"   # LAMMPS with PERIDEM in tree
pbuild="$root/peridem-build"     # this repository built against $plain
mtree="$root/make-tree"          # a second LAMMPS tree, for the traditional make build only
jobs="${PERIDEM_JOBS:-2}"
logs="$root/logs"
mkdir -p "$root" "$logs"
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(fetch lammps outoftree reference plugin intree intree-tests plugin-tests)

log() { echo "[$(date -u +%H:%M:%S)] $*"; }
timed() { # name command...: runs the command with its output in $logs/name.log, times it
  local name="$1" t0 rc
  shift
  t0=$(date +%s)
  # a subshell with set -e (the caller turned it off, so that a failing stage is reported)
  (
    set -e
    "$@"
  ) >"$logs/$name.log" 2>&1
  rc=$?
  log "$name: $(($(date +%s) - t0)) s, exit $rc (log $logs/$name.log)"
  return $rc
}

fetch() {
  [ -f "$src/cmake/CMakeLists.txt" ] && return 0
  # trixie's source package from the mirror (proxy, key) that serves this machine's own release
  # (PERIDEM_APT_DIR: a fake apt folder, for unittest/scripts/test_apt_deb_src.sh)
  local apt="${PERIDEM_APT_DIR:-/etc/apt}" list entry codename
  list="$apt/sources.list.d/peridem-trixie-src.sources"
  codename="$(. /etc/os-release 2>/dev/null; echo "${VERSION_CODENAME:-bookworm}")"
  entry="$("$here/scripts/apt_deb_src.sh" "$apt" "$codename" trixie)" || return 1
  if [ "$(cat "$list" 2>/dev/null)" != "$entry" ]; then
    echo "$entry" >"$list"
    apt-get update
  fi
  # the .dsc has answered 404 while the orig tarball downloads: unpack the tarball directly
  (cd "$root" && apt-get source --download-only "lammps=$version" || true)
  local tarball="$root/lammps_${version%-*}.orig.tar.xz"
  [ -f "$tarball" ] || { echo "no $tarball: apt-get source failed" >&2; return 1; }
  tar -C "$root" -xf "$tarball"
}

cmake_lammps() { # BUILD-DIR ON|OFF [cmake options]: configure LAMMPS, PERIDEM in tree or not
  local dir=$1 peridem=$2
  shift 2
  cmake -S "$src/cmake" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DBUILD_MPI=ON -DBUILD_OMP=OFF \
    -DWITH_JPEG=OFF -DWITH_PNG=OFF -DWITH_FFMPEG=OFF -DPKG_MOLECULE=ON -DPKG_PERI=ON \
    -DPKG_PERIDEM="$peridem" "$@"
}
configure_lammps() { # ON|OFF: the shared LAMMPS of the routes
  # -O1: LAMMPS's own files compile about twice as fast as with -O3 on a busy 2-core
  # machine; PERIDEM's files get their own -O3 (out of tree) and the package's flags.
  cmake_lammps "$build" "$1" -DCMAKE_CXX_FLAGS_RELEASE="${PERIDEM_LAMMPS_OPT:--O1} -DNDEBUG" \
    -DBUILD_SHARED_LIBS=ON -DPKG_RIGID=ON -DPKG_PLUGIN=ON
}

lammps() { # plain LAMMPS 2025 (the long part: about 600 files), built once
  # LAMMPS's source never changes here: its install is the cache (delete it to rebuild); a
  # cache from before RIGID was in the package list is built again
  if [ -x "$plain/bin/lmp" ] &&
    LD_LIBRARY_PATH="$plain/lib:${LD_LIBRARY_PATH:-}" "$plain/bin/lmp" -h 2>/dev/null | grep -w RIGID >/dev/null; then
    echo "cached: $plain (delete it to build LAMMPS again)"
    return 0
  fi
  configure_lammps OFF
  nice -n 10 cmake --build "$build" -j "$jobs"
  rm -rf "$plain"
  cmake --install "$build" --prefix "$plain"
}

# ccache (when installed) for this repository's files: a rerun after a change elsewhere in the
# tree, or from another worktree, recompiles nothing that ccache has seen
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)

outoftree() { # this repository against the plain LAMMPS 2025, then its tests
  restore_driver
  cmake -S "$here" -B "$pbuild" -DCMAKE_BUILD_TYPE=Release -DLAMMPS_DIR="$plain/lib/cmake/LAMMPS" \
    -DPERIDEM_LAMMPS_SRC="$src/src" -DPERIDEM_WERROR=ON "${launcher[@]}"
  nice -n 10 cmake --build "$pbuild" -j "$jobs"
  (cd "$pbuild" && LD_LIBRARY_PATH="$plain/lib:${LD_LIBRARY_PATH:-}" \
    ctest -j "$jobs" --output-on-failure ${PERIDEM_CTEST_ARGS:-})
}

# all_styles.in (every PERIDEM style in one short 2d run) through lmp_peridem built against
# the plain LAMMPS 2025: the reference thermo output of the plugin and in-tree routes
reference() {
  local d="$root/runs/driver"
  rm -rf "$d" && mkdir -p "$d"
  (cd "$d" && LD_LIBRARY_PATH="$plain/lib:${LD_LIBRARY_PATH:-}" mpirun -np 2 "$pbuild/lmp_peridem" \
    -in "$here/unittest/plugin/all_styles.in" -var potentials "$here/potentials" -log log.lammps \
    -echo none -screen none) || return 1
}

fresh_reference() { # the reference again when this repository's build is newer than it
  if [ ! "$root/runs/driver/log.lammps" -nt "$pbuild/libperidem.so" ]; then reference; fi
}

plugin() { # peridemplugin.so loaded by the plain LAMMPS's own lmp: the same thermo output
  fresh_reference
  local d="$root/runs/plugin"
  rm -rf "$d" && mkdir -p "$d"
  (cd "$d" && LD_LIBRARY_PATH="$plain/lib:${LD_LIBRARY_PATH:-}" mpirun -np 2 "$plain/bin/lmp" \
    -in "$here/unittest/plugin/plugin_load.in" -var plugin "$pbuild/peridemplugin.so" \
    -var input "$here/unittest/plugin/all_styles.in" -var potentials "$here/potentials" \
    -log log.lammps -echo none -screen none) || return 1
  python3 "$here/unittest/scripts/thermo_compare.py" "$d/log.lammps" "$root/runs/driver/log.lammps"
}

sync_file() { # from to: copies only a changed file, so that make recompiles only what changed
  cmp -s "$1" "$2" || cp "$1" "$2"
}

# LAMMPS's Makefiles make every object of liblammps depend on lammps.dir/flags.make, which
# also lists the per-file options of the package's files (PERIDEM.cmake): a change of those
# alone would recompile all of LAMMPS (47 min). When flags.make differs from the one of the
# last in-tree build only in lines naming src/PERIDEM/ (and blank lines), it gets that build's time back and the
# package's own objects are removed, so that only they recompile. The first in-tree build after the
# plain one also adds the package's folder to every file's include path (CXX_INCLUDES): that
# changes no LAMMPS object as long as no header of the package has the name of one of LAMMPS's
# (checked), so that folder is left out of the comparison too (without this, the first in-tree
# build recompiled all of LAMMPS: 27 min at -j2).
flags_last="$build/peridem-flags.make.last"
save_flags() { cp -p "$build/CMakeFiles/lammps.dir/flags.make" "$flags_last"; }
flags_outside_package() { # flags.make without the package's lines and include folder
  sed -e "s# -I$src/src/PERIDEM\( \|\$\)# #" -e 's/ *$//' "$1" | grep -v -e /PERIDEM/ -e '^$'
}
package_header_shadows() { # true if a header of the package has the name of one of LAMMPS's
  local h
  for h in "$src"/src/PERIDEM/*.h; do
    [ -n "$(find "$src/src" -maxdepth 2 -name "$(basename "$h")" -not -path '*/PERIDEM/*')" ] && return 0
  done
  return 1
}
keep_lammps_objects() {
  local flags="$build/CMakeFiles/lammps.dir/flags.make"
  [ -f "$flags_last" ] && [ -f "$flags" ] || return 0
  cmp -s "$flags" "$flags_last" && return 0
  package_header_shadows && return 0
  if cmp -s <(flags_outside_package "$flags") <(flags_outside_package "$flags_last"); then
    echo "flags.make: only the package's lines changed; LAMMPS's objects kept"
    touch -r "$flags_last" "$flags"
    find "$build/CMakeFiles/lammps.dir" -path '*/src/PERIDEM/*.o' -delete
  fi
}

sync_package() { # src/ as src/PERIDEM of the LAMMPS tree, registered with its CMake
  local f pkg="$src/src/PERIDEM"
  mkdir -p "$pkg"
  for f in "$pkg"/*; do # files no longer in src/
    if [ -e "$f" ] && [ ! -e "$here/src/$(basename "$f")" ]; then rm -f "$f"; fi
  done
  for f in "$here"/src/*.cpp "$here"/src/*.h "$here/src/README"; do
    sync_file "$f" "$pkg/$(basename "$f")"
  done
  sync_file "$here/cmake/Modules/Packages/PERIDEM.cmake" "$src/cmake/Modules/Packages/PERIDEM.cmake"
  # register the package with LAMMPS's CMake: one more standard package with a module
  if ! grep -q "^  PERIDEM$" "$src/cmake/CMakeLists.txt"; then
    sed -i 's/^  PERI$/  PERI\n  PERIDEM/' "$src/cmake/CMakeLists.txt"
    sed -i 's/^\(foreach(PKG_WITH_INCL KSPACE PYTHON\)/\1 PERIDEM/' "$src/cmake/CMakeLists.txt"
  fi
}

intree() { # src/ as the PERIDEM package of the LAMMPS tree: the same thermo output
  sync_package
  # the first run after a build that predates save_flags: that build's flags.make
  if [ ! -f "$flags_last" ] && [ "$build/liblammps.so" -nt "$build/CMakeFiles/lammps.dir/flags.make" ]; then
    save_flags
  fi
  configure_lammps ON
  keep_lammps_objects
  nice -n 10 cmake --build "$build" -j "$jobs"
  save_flags
  rm -rf "$intree"
  cmake --install "$build" --prefix "$intree"
  # the folder stays configured with PERIDEM (switching back would recompile LAMMPS's
  # style-list files twice per run); the plain LAMMPS is its install, $plain
  # bond_style peridem/opt's chunked loop vectorised (-fno-math-errno, PERIDEM.cmake): packed sqrt
  local obj="$build/CMakeFiles/lammps.dir$src/src/PERIDEM/bond_peridem_opt.cpp.o" n
  n=$(objdump -d "$obj" | grep -c sqrtpd || true)
  echo "bond_peridem_opt.cpp.o in tree: $n sqrtpd"
  [ "$n" -gt 0 ] || { echo "no sqrtpd in $obj: -fno-math-errno missing?" >&2; return 1; }
  fresh_reference
  local d="$root/runs/intree"
  rm -rf "$d" && mkdir -p "$d"
  (cd "$d" && LD_LIBRARY_PATH="$intree/lib:${LD_LIBRARY_PATH:-}" mpirun -np 2 "$intree/bin/lmp" \
    -in "$here/unittest/plugin/all_styles.in" -var potentials "$here/potentials" \
    -log log.lammps -echo none -screen none) || return 1
  python3 "$here/unittest/scripts/thermo_compare.py" "$d/log.lammps" "$root/runs/driver/log.lammps"
}

# The LAMMPS-level tests (the input-driven ctests: every test whose name does not start with
# a capital letter, i.e. all but the GoogleTest programs, which link libperidem) with LAMMPS
# 2025's own lmp in place of lmp_peridem: `intree-tests` runs the in-tree build's lmp,
# `plugin-tests` the plain lmp loading peridemplugin.so through LAMMPS_PLUGIN_PATH (LAMMPS
# loads it at start and again after every `clear`, as `plugin load` does). The test build's
# lmp_peridem is replaced by a wrapper for the run and restored afterwards.
restore_driver() {
  if [ -f "$pbuild/lmp_peridem.real" ]; then mv -f "$pbuild/lmp_peridem.real" "$pbuild/lmp_peridem"; fi
}
route_tests() { # intree|plugin
  local lmp libs env=""
  case "$1" in
  intree) lmp="$intree/bin/lmp" libs="$intree/lib" ;;
  plugin)
    lmp="$plain/bin/lmp" libs="$plain/lib"
    mkdir -p "$root/plugin-path" # a folder with peridemplugin.so alone
    ln -sf "$pbuild/peridemplugin.so" "$root/plugin-path/peridemplugin.so"
    env="export LAMMPS_PLUGIN_PATH=$root/plugin-path"
    ;;
  esac
  restore_driver
  mv "$pbuild/lmp_peridem" "$pbuild/lmp_peridem.real"
  trap restore_driver EXIT
  cat >"$pbuild/lmp_peridem" <<EOF
#!/bin/sh
# LAMMPS 2025 ($1) in place of lmp_peridem (scripts/build_lammps_2025.sh)
$env
export LD_LIBRARY_PATH=$libs\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}
exec $lmp "\$@"
EOF
  chmod +x "$pbuild/lmp_peridem"
  # PERIDEM_ROUTE_EXCLUDE (optional): a regex of more tests to leave out, e.g. the longest
  (cd "$pbuild" && ctest -j "$jobs" -E "^[A-Z]${PERIDEM_ROUTE_EXCLUDE:+|$PERIDEM_ROUTE_EXCLUDE}" \
    --output-on-failure ${PERIDEM_CTEST_ARGS:-})
}
intree-tests() { route_tests intree; }

# src/ as the PERIDEM package of LAMMPS's traditional make build, in a copy of the LAMMPS tree
# of its own (the CMake build folder of $src stays as it is): `make yes-molecule yes-peri
# yes-peridem` (src/Install.sh), `make mpi` (serial when mpi fails), no warning in PERIDEM's
# files, the per-file flags of src/Makefile.lammps on the bond styles' compile lines, and the
# all_styles.in thermo output of lmp_peridem. LAMMPS's own flags but -O3: ${PERIDEM_LAMMPS_OPT:--O1}
# (and no -g), as the CMake route. PERIDEM's objects are compiled on every run, so that the
# warning count covers all of them; LAMMPS's stay. PERIDEM_MAKE_MACHINE=serial: the serial
# build (LAMMPS's MPI stubs) without trying mpi.
intree-make() {
  local t="$mtree/lammps-4Feb2025" f b machine="" pkg
  if [ ! -f "$t/src/Makefile" ]; then
    rm -rf "$mtree" && mkdir -p "$mtree"
    tar -C "$mtree" -xf "$root/lammps_${version%-*}.orig.tar.xz" lammps-4Feb2025/src lammps-4Feb2025/lib
  fi
  pkg="$t/src/PERIDEM"
  mkdir -p "$pkg"
  for f in "$pkg"/*; do # files no longer in src/, and their installed copies
    b="$(basename "$f")"
    if [ -e "$f" ] && [ ! -e "$here/src/$b" ]; then rm -f "$f" "$t/src/$b"; fi
  done
  for f in "$here"/src/*.cpp "$here"/src/*.h "$here/src/README" "$here/src/Install.sh" \
    "$here/src/Makefile.lammps"; do
    sync_file "$f" "$pkg/$(basename "$f")"
  done
  mkdir -p "$t/src/MAKE/MINE"
  for m in mpi serial; do
    sed -e "s/^\(CCFLAGS =\s*\)-g -O3/\1${PERIDEM_LAMMPS_OPT:--O1}/" \
      -e "s/^\(LINKFLAGS =\s*\)-g -O3/\1${PERIDEM_LAMMPS_OPT:--O1}/" "$t/src/MAKE/Makefile.$m" \
      >"$t/src/MAKE/MINE/Makefile.$m.new"
    sync_file "$t/src/MAKE/MINE/Makefile.$m.new" "$t/src/MAKE/MINE/Makefile.$m"
    rm -f "$t/src/MAKE/MINE/Makefile.$m.new"
  done
  cd "$t/src"
  # PERIDEM in the package list of src/Makefile, after PERI (as LAMMPS's "Adding a package"
  # describes): `make package-status` knows it, and `lmp -h` lists it among the installed
  # packages
  if ! grep -q '^[[:space:]]peridem \\$' Makefile; then
    sed -i '0,/^\tperi \\$/s//\tperi \\\n\tperidem \\/' Makefile
  fi
  make yes-molecule yes-peri yes-peridem
  for f in "$pkg"/*.cpp; do rm -f "Obj_mpi/$(basename "${f%.cpp}").o" "Obj_serial/$(basename "${f%.cpp}").o"; done
  if [ "${PERIDEM_MAKE_MACHINE:-mpi}" = mpi ] && nice -n 10 make -j "$jobs" mpi >"$mtree/make.log" 2>&1; then
    machine=mpi
  else
    [ "${PERIDEM_MAKE_MACHINE:-mpi}" = serial ] ||
      { echo "make mpi failed (tail of $mtree/make.log):" && tail -n 30 "$mtree/make.log"; }
    nice -n 10 make -j "$jobs" serial >"$mtree/make.log" 2>&1 || { tail -n 30 "$mtree/make.log"; return 1; }
    machine=serial
  fi
  echo "make $machine: lmp_$machine built"
  "./lmp_$machine" -h | grep -A 2 '^Installed packages:' | grep -w PERIDEM >/dev/null ||
    { echo "lmp_$machine -h lists no PERIDEM among its installed packages" >&2; return 1; }
  # warnings in PERIDEM's files (the package's .cpp and .h, as make prints them: ../file:line:)
  local names n
  names="$(cd "$pkg" && ls -- *.cpp *.h | sed 's/\./\\./g' | paste -sd'|')"
  grep -E "(^|/)($names):[0-9]+:[0-9]+: warning" "$mtree/make.log" >"$mtree/warnings.log" || true
  cat "$mtree/warnings.log"
  n=$(wc -l <"$mtree/warnings.log")
  echo "warnings in PERIDEM's files: $n"
  [ "$n" -eq 0 ] || return 1
  # the per-file flags reached the compile lines (src/Makefile.lammps)
  grep -E -- "-Wall .*-c \.\./lmp_peridem_parse\.cpp" "$mtree/make.log" >/dev/null ||
    { echo "no -Wall on lmp_peridem_parse.cpp's compile line" >&2; return 1; }
  grep -E -- "-fno-math-errno -ftree-vectorize -ffp-contract=off .*-c \.\./bond_peridem_opt\.cpp" "$mtree/make.log" >/dev/null ||
    { echo "bond_peridem_opt.cpp compiled without its flags" >&2; return 1; }
  for f in bond_peridem bond_peridem_base bond_peridem_lps; do
    grep -E -- "-ffp-contract=off .*-c \.\./$f\.cpp" "$mtree/make.log" >/dev/null ||
      { echo "$f.cpp compiled without -ffp-contract=off" >&2; return 1; }
    ! grep -E -- "-fno-math-errno .*-c \.\./$f\.cpp" "$mtree/make.log" >/dev/null ||
      { echo "$f.cpp compiled with -fno-math-errno (peridem/opt's flag only)" >&2; return 1; }
  done
  n=$(objdump -d "Obj_$machine/bond_peridem_opt.o" | grep -c sqrtpd || true)
  echo "bond_peridem_opt.o (make): $n sqrtpd"
  [ "$n" -gt 0 ] || { echo "no sqrtpd in Obj_$machine/bond_peridem_opt.o" >&2; return 1; }
  local d="$root/runs/intree-make" ref="$root/runs/driver/log.lammps"
  rm -rf "$d" && mkdir -p "$d"
  if [ "$machine" = mpi ]; then
    fresh_reference
    (cd "$d" && mpirun -np 2 "$t/src/lmp_mpi" -in "$here/unittest/plugin/all_styles.in" \
      -var potentials "$here/potentials" -log log.lammps -echo none -screen none) || return 1
  else
    # the reference is a 2-rank run, and the plus grain's orientation (c_grain[3][19], equal
    # principal variances) depends on the summation order: lmp_peridem on 1 rank instead
    ref="$d/driver/log.lammps"
    mkdir -p "$d/driver"
    (cd "$d/driver" && LD_LIBRARY_PATH="$plain/lib:${LD_LIBRARY_PATH:-}" "$pbuild/lmp_peridem" \
      -in "$here/unittest/plugin/all_styles.in" -var potentials "$here/potentials" \
      -log log.lammps -echo none -screen none) || return 1
    (cd "$d" && "$t/src/lmp_serial" -in "$here/unittest/plugin/all_styles.in" \
      -var potentials "$here/potentials" -log log.lammps -echo none -screen none) || return 1
  fi
  python3 "$here/unittest/scripts/thermo_compare.py" "$d/log.lammps" "$ref"
}
plugin-tests() { route_tests plugin; }

# one lmp with LAMMPS's BPM package and PERIDEM in tree, for bench/fracture/run_bpm_impact.sh:
# both codes then run on the same LAMMPS, neighbour code and compiler flags (-O2, LAMMPS's own
# default build type; PERIDEM's files get the package's flags). Its own build folder; static.
bpm() {
  sync_package
  cmake_lammps "$root/build-bpm" ON -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" \
    -DBUILD_SHARED_LIBS=OFF -DPKG_BPM=ON -DLAMMPS_MACHINE=bpm
  nice -n 10 cmake --build "$root/build-bpm" -j "$jobs"
  local help
  help="$("$root/build-bpm/lmp_bpm" -h)"
  grep -qw "bpm/spring" <<< "$help" && grep -qw "peridem" <<< "$help"
  echo "built $root/build-bpm/lmp_bpm"
}

source "$here/unittest/scripts/mpi_env.sh"
t_all=$(date +%s)
rc=0
for s in "${stages[@]}"; do
  set +e
  timed "$s" "$s"
  r=$?
  set -e
  [ $r -eq 0 ] || { rc=1; break; }
done
log "total $(($(date +%s) - t_all)) s, exit $rc"
exit $rc
