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

packages=(build-essential cmake dpkg-dev lammps liblammps-dev lammps-examples
          libeigen3-dev libopenmpi-dev openmpi-bin libgtest-dev python3-lammps
          python3-numpy libyaml-dev libgmock-dev)

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

if [ $need_src -eq 1 ] && ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ && \
   ! grep -qs '^deb-src' /etc/apt/sources.list; then
  # the source package must come from the same archive as the binary package
  $SUDO tee /etc/apt/sources.list.d/peridem-deb-src.sources >/dev/null <<'SRC'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
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
