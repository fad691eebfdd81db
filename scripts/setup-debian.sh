#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Installs what PERIDEM needs on Debian bookworm (as root) and unpacks the
# matching LAMMPS source package whose headers the build needs.
# Idempotent: returns in about a second when everything is already there.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
lammps_src_root="${PERIDEM_LAMMPS_SRC_ROOT:-/opt/peridem/lammps-source}"

# python3-scipy: the Delaunay triangulation of examples/plate-hole/make_mesh.py (ctest plate_hole_*)
packages=(build-essential cmake dpkg-dev lammps liblammps-dev lammps-examples
          libeigen3-dev libopenmpi-dev openmpi-bin libgtest-dev python3-lammps
          python3-numpy python3-scipy libyaml-dev libgmock-dev)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

need_src=0
ls -d "$lammps_src_root"/lammps-*/src/version.h >/dev/null 2>&1 || need_src=1

if [ ${#missing[@]} -eq 0 ] && [ $need_src -eq 0 ]; then
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"

# a deb-src entry for the release of this machine, outside the file written below
# (PERIDEM_APT_DIR: a fake apt folder, for unittest/scripts/test_apt_deb_src.sh)
apt="${PERIDEM_APT_DIR:-/etc/apt}"
ours="$apt/sources.list.d/peridem-deb-src.sources"
codename="$(. /etc/os-release 2>/dev/null; echo "${VERSION_CODENAME:-bookworm}")"
has_deb_src() {
  grep -qsE "^deb-src .*[[:space:]]$codename([[:space:]]|$)" "$apt/sources.list" "$apt"/sources.list.d/*.list &&
    return 0
  local f
  for f in "$apt"/sources.list.d/*.sources; do
    [ "$f" != "$ours" ] || continue
    grep -qsiE '^Types:.*deb-src' "$f" && grep -qsiE "^Suites:.*[[:space:]]$codename([[:space:]]|$)" "$f" &&
      return 0
  done
  return 1
}
if [ $need_src -eq 1 ] && ! has_deb_src; then
  # the source package must come from the same archive as the binary packages (a mirror,
  # a proxy): the deb-src entry repeats the URIs, components and key of the deb entries
  src_entry="$("$here/scripts/apt_deb_src.sh" "$apt" "$codename $codename-updates")" || {
    echo "peridem setup: cannot add the deb-src entry for the LAMMPS source package" >&2; exit 1; }
  if [ "$(cat "$ours" 2>/dev/null)" != "$src_entry" ]; then
    echo "$src_entry" | $SUDO tee "$ours" >/dev/null
  fi
fi

export DEBIAN_FRONTEND=noninteractive
if [ ${#missing[@]} -gt 0 ] || [ $need_src -eq 1 ]; then
  $SUDO apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "peridem setup: installing ${missing[*]}"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [ $need_src -eq 1 ]; then
  echo "peridem setup: fetching the LAMMPS source package into $lammps_src_root"
  $SUDO mkdir -p "$lammps_src_root"
  (cd "$lammps_src_root" && $SUDO apt-get source -qq lammps >/dev/null 2>&1 || \
     (cd "$lammps_src_root" && $SUDO apt-get source lammps))
fi
