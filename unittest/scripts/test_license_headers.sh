#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# test_license_headers.sh REPO_ROOT: scripts/dev/license_headers.py --check on small trees:
# it passes when every file has the header and fails (exit 1) when one file, every file
# (the case it once skipped) or no file at all (a wrong root) lacks it. Prints PERIDEM-PASS.
set -uo pipefail
tool="${1:?usage: test_license_headers.sh REPO_ROOT}/scripts/dev/license_headers.py"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
bad=0
check() { # name expected-exit-code tree
  python3 "$tool" --check "$3" >"$tmp/out" 2>&1
  local rc=$?
  [ $rc -eq "$2" ] || { echo "FAIL: $1: exit code $rc, expected $2"; cat "$tmp/out"; bad=1; }
}
tree() { # name: src/a.cpp and scripts/b.sh without the header
  mkdir -p "$tmp/$1/src" "$tmp/$1/scripts"
  printf 'int a;\n' >"$tmp/$1/src/a.cpp"
  printf '#!/bin/sh\necho b\n' >"$tmp/$1/scripts/b.sh"
}
tree none
check "no file with the header" 1 "$tmp/none"
tree all
python3 "$tool" "$tmp/all" >/dev/null
check "every file with the header" 0 "$tmp/all"
tree one
python3 "$tool" "$tmp/one" >/dev/null
printf 'int c;\n' >"$tmp/one/src/c.cpp"
check "one file without the header" 1 "$tmp/one"
mkdir -p "$tmp/empty"
check "no source file" 1 "$tmp/empty"
if [ $bad -eq 0 ]; then echo "PERIDEM-PASS license_headers.py --check"; exit 0; fi
exit 1
