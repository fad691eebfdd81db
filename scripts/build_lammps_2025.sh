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
#      against a LAMMPS with MOLECULE, PERI and PLUGIN;
#   2. as a plugin: peridemplugin.so loaded with `plugin load` into that LAMMPS's lmp;
#   3. in tree: src/ copied to lammps/src/PERIDEM and built into LAMMPS through
#      its CMake package mechanism (PKG_PERIDEM, cmake/Modules/Packages/PERIDEM.cmake).
# Everything is cached under $PERIDEM_LAMMPS2025_DIR (default /opt/peridem/lammps-2025):
# a second call only rebuilds what changed. Usage:
#   scripts/build_lammps_2025.sh [stage ...]     stages: fetch lammps outoftree reference plugin intree
# (default: all, in that order). Logs: $PERIDEM_LAMMPS2025_DIR/logs/. Exit code 0 when
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
jobs="${PERIDEM_JOBS:-2}"
logs="$root/logs"
mkdir -p "$root" "$logs"
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(fetch lammps outoftree reference plugin intree)

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
  if [ ! -f /etc/apt/sources.list.d/peridem-trixie-src.sources ]; then
    cat >/etc/apt/sources.list.d/peridem-trixie-src.sources <<'EOF'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: trixie
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
    apt-get update
  fi
  # the .dsc has answered 404 while the orig tarball downloads: unpack the tarball directly
  (cd "$root" && apt-get source --download-only "lammps=$version" || true)
  local tarball="$root/lammps_${version%-*}.orig.tar.xz"
  [ -f "$tarball" ] || { echo "no $tarball: apt-get source failed" >&2; return 1; }
  tar -C "$root" -xf "$tarball"
}

configure_lammps() { # ON|OFF: PERIDEM in tree or not
  # -O1: LAMMPS's own files compile about twice as fast as with -O3 on a busy 2-core
  # machine; PERIDEM's files get their own -O3 (out of tree) and the package's flags.
  cmake -S "$src/cmake" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS_RELEASE="${PERIDEM_LAMMPS_OPT:--O1} -DNDEBUG" -DBUILD_SHARED_LIBS=ON \
    -DBUILD_MPI=ON -DBUILD_OMP=OFF -DWITH_JPEG=OFF -DWITH_PNG=OFF \
    -DWITH_FFMPEG=OFF -DPKG_MOLECULE=ON -DPKG_PERI=ON -DPKG_PLUGIN=ON -DPKG_PERIDEM="$1"
}

lammps() { # plain LAMMPS 2025 (the long part: about 600 files)
  configure_lammps OFF
  nice -n 10 cmake --build "$build" -j "$jobs"
  rm -rf "$plain"
  cmake --install "$build" --prefix "$plain"
}

outoftree() { # this repository against the plain LAMMPS 2025, then its tests
  cmake -S "$here" -B "$pbuild" -DCMAKE_BUILD_TYPE=Release -DLAMMPS_DIR="$plain/lib/cmake/LAMMPS" \
    -DPERIDEM_LAMMPS_SRC="$src/src" -DPERIDEM_WERROR=ON
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

plugin() { # peridemplugin.so loaded by the plain LAMMPS's own lmp: the same thermo output
  [ -f "$root/runs/driver/log.lammps" ] || reference
  local d="$root/runs/plugin"
  rm -rf "$d" && mkdir -p "$d"
  (cd "$d" && LD_LIBRARY_PATH="$plain/lib:${LD_LIBRARY_PATH:-}" mpirun -np 2 "$plain/bin/lmp" \
    -in "$here/unittest/plugin/plugin_load.in" -var plugin "$pbuild/peridemplugin.so" \
    -var input "$here/unittest/plugin/all_styles.in" -var potentials "$here/potentials" \
    -log log.lammps -echo none -screen none) || return 1
  python3 "$here/unittest/scripts/thermo_compare.py" "$d/log.lammps" "$root/runs/driver/log.lammps"
}

intree() { # src/ as the PERIDEM package of the LAMMPS tree: the same thermo output
  rm -rf "$src/src/PERIDEM"
  mkdir -p "$src/src/PERIDEM"
  cp "$here"/src/*.cpp "$here"/src/*.h "$here/src/README" "$src/src/PERIDEM/"
  cp "$here/cmake/Modules/Packages/PERIDEM.cmake" "$src/cmake/Modules/Packages/PERIDEM.cmake"
  # register the package with LAMMPS's CMake: one more standard package with a module
  if ! grep -q "^  PERIDEM$" "$src/cmake/CMakeLists.txt"; then
    sed -i 's/^  PERI$/  PERI\n  PERIDEM/' "$src/cmake/CMakeLists.txt"
    sed -i 's/^\(foreach(PKG_WITH_INCL KSPACE PYTHON\)/\1 PERIDEM/' "$src/cmake/CMakeLists.txt"
  fi
  configure_lammps ON
  nice -n 10 cmake --build "$build" -j "$jobs"
  rm -rf "$intree"
  cmake --install "$build" --prefix "$intree"
  configure_lammps OFF # the folder stays the plain build for the next `lammps` stage
  [ -f "$root/runs/driver/log.lammps" ] || reference
  local d="$root/runs/intree"
  rm -rf "$d" && mkdir -p "$d"
  (cd "$d" && LD_LIBRARY_PATH="$intree/lib:${LD_LIBRARY_PATH:-}" mpirun -np 2 "$intree/bin/lmp" \
    -in "$here/unittest/plugin/all_styles.in" -var potentials "$here/potentials" \
    -log log.lammps -echo none -screen none) || return 1
  python3 "$here/unittest/scripts/thermo_compare.py" "$d/log.lammps" "$root/runs/driver/log.lammps"
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
