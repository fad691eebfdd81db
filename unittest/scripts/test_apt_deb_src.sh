#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# test_apt_deb_src.sh REPO_ROOT: scripts/apt_deb_src.sh on fake apt source folders (a
# mirror behind a proxy in deb822, a one-line sources.list with signed-by, no deb entry), and
# the two set-up scripts write what it reads instead of a fixed archive address (run on a fake
# apt folder with apt-get stubbed: no root, no network). Prints PERIDEM-PASS.
set -uo pipefail
root="${1:?usage: test_apt_deb_src.sh REPO_ROOT}"
tool="$root/scripts/apt_deb_src.sh"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
bad=0
fail() { echo "FAIL: $*"; bad=1; }
expect() { # name expected-file command...: the command exits 0 and prints the expected text
  local name="$1" want="$2"; shift 2
  local got
  if ! got="$("$@" 2>&1)"; then fail "$name: exit code $? ($got)"; return; fi
  diff <(echo "$got") "$want" >"$tmp/diff" || { fail "$name: output differs (< got, > expected)"; cat "$tmp/diff"; }
}

# deb822: a proxy in front of the mirror, a comment inside the stanza, a second suite line
# (continuation), security and third-party stanzas, a disabled stanza, an existing deb-src
a="$tmp/a"; mkdir -p "$a/sources.list.d"
cat >"$a/sources.list.d/debian.sources" <<'EOF'
Types: deb
# the local proxy
URIs: http://proxy.local:3142/debian
Suites: bookworm
 bookworm-updates
Components: main contrib
Signed-By: /etc/apt/keyrings/mirror.gpg

Types: deb
URIs: http://proxy.local:3142/debian-security
Suites: bookworm-security
Components: main

types: deb deb-src
uris: http://second.example/debian
suites: bookworm
components: main

Types: deb
Enabled: no
URIs: http://disabled.example/debian
Suites: bookworm
Components: main

Types: deb-src
URIs: http://only-source.example/debian
Suites: bookworm
Components: main
EOF
cat >"$a/sources.list.d/vendor.sources" <<'EOF'
Types: deb
URIs: https://vendor.example/apt
Suites: nodistro
Components: main
Signed-By: /usr/share/keyrings/vendor.gpg
EOF
cat >"$tmp/a.want" <<'EOF'
Types: deb-src
URIs: http://proxy.local:3142/debian
Suites: bookworm bookworm-updates
Components: main contrib
Signed-By: /etc/apt/keyrings/mirror.gpg

Types: deb-src
URIs: http://second.example/debian
Suites: bookworm
Components: main
EOF
expect "deb822" "$tmp/a.want" "$tool" "$a" "bookworm bookworm-updates"
# build_lammps_2025.sh: the trixie source from the mirror that serves this bookworm
sed -e 's/^Suites: bookworm.*/Suites: trixie/' "$tmp/a.want" >"$tmp/a_trixie.want"
expect "deb822, other suite" "$tmp/a_trixie.want" "$tool" "$a" bookworm trixie

# one-line format: options with signed-by (and without), comments, a deb-src line, a .list
b="$tmp/b"; mkdir -p "$b/sources.list.d"
cat >"$b/sources.list" <<'EOF'
# deb http://commented.example/debian bookworm main
deb [arch=amd64 signed-by=/usr/share/keyrings/local.gpg] http://mirror.example/debian bookworm main non-free-firmware
deb-src http://mirror.example/debian bookworm main
deb http://mirror.example/debian-security bookworm-security main
EOF
echo "deb [ trusted=yes ] http://apt.lan/debian bookworm-updates main # comment" >"$b/sources.list.d/lan.list"
echo "deb http://ignored.example/debian bookworm main" >"$b/sources.list.d/old.list.disabled"
cat >"$tmp/b.want" <<'EOF'
Types: deb-src
URIs: http://mirror.example/debian
Suites: bookworm
Components: main non-free-firmware
Signed-By: /usr/share/keyrings/local.gpg

Types: deb-src
URIs: http://apt.lan/debian
Suites: bookworm-updates
Components: main
EOF
expect "one-line" "$tmp/b.want" "$tool" "$b" "bookworm bookworm-updates"

# deb822 with the key embedded in Signed-By (continuation lines, " ." for a blank line)
c="$tmp/c"; mkdir -p "$c/sources.list.d"
cat >"$c/sources.list.d/debian.sources" <<'EOF'
Types: deb
URIs: http://mirror.example/debian
Suites: bookworm
Components: main
Signed-By:
 -----BEGIN PGP PUBLIC KEY BLOCK-----
 .
 mQINBGPL0BUBEADmW5NdOOHwPIJlgPu6JDcKw/NZJPR8lsD9K7UgrY
 -----END PGP PUBLIC KEY BLOCK-----
EOF
sed -e 's/^Types: deb$/Types: deb-src/' "$c/sources.list.d/debian.sources" >"$tmp/c.want"
expect "deb822, embedded key" "$tmp/c.want" "$tool" "$c" bookworm

# no deb entry for the suite (only deb-src, another release, nothing at all): a clear error
for d in "$b" "$tmp/empty"; do
  mkdir -p "$d"
  if out="$("$tool" "$d" bullseye 2>&1)"; then
    fail "no deb entry in $d: exit code 0 ($out)"
  elif ! grep -q "no enabled 'deb' entry for suite(s) 'bullseye'" <<<"$out"; then
    fail "no deb entry in $d: unclear message: $out"
  fi
done

# the set-up scripts on a fake apt folder (PERIDEM_APT_DIR), apt-get and sudo replaced by
# stubs: the entry they write comes from that folder's deb entry; a second run rewrites nothing
codename="$(. /etc/os-release 2>/dev/null; echo "${VERSION_CODENAME:-bookworm}")"
stub="$tmp/bin"; mkdir -p "$stub"
printf '#!/bin/sh\necho "apt-get $*" >>"%s/apt.calls"\n' "$tmp" >"$stub/apt-get"
printf '#!/bin/sh\nexec "$@"\n' >"$stub/sudo"
chmod +x "$stub"/*
s="$tmp/s"; mkdir -p "$s/sources.list.d"
echo "deb [signed-by=/k.gpg] http://proxy.local:3142/debian $codename main" >"$s/sources.list"
setup() {
  PATH="$stub:$PATH" PERIDEM_APT_DIR="$s" PERIDEM_LAMMPS_SRC_ROOT="$tmp/src" \
    "$root/scripts/setup-debian.sh" >"$tmp/setup.out" 2>&1
}
written="$s/sources.list.d/peridem-deb-src.sources"
printf 'Types: deb-src\nURIs: http://proxy.local:3142/debian\nSuites: %s\nComponents: main\nSigned-By: /k.gpg\n' \
  "$codename" >"$tmp/s.want"
setup || fail "setup-debian.sh: exit code $? ($(cat "$tmp/setup.out"))"
cmp -s "$written" "$tmp/s.want" || { fail "setup-debian.sh wrote another entry:"; cat "$written"; }
touch -d 2000-01-01 "$written"
setup || fail "setup-debian.sh, second run: exit code $?"
[ "$(stat -c %Y "$written")" = "$(date -d 2000-01-01 +%s)" ] || fail "setup-debian.sh rewrote an unchanged entry"
rm -f "$written"
echo "deb-src http://proxy.local:3142/debian $codename main" >>"$s/sources.list"
setup || fail "setup-debian.sh with a deb-src entry: exit code $?"
[ ! -e "$written" ] || fail "setup-debian.sh added an entry beside the machine's own deb-src"
rm -f "$s/sources.list"
if setup; then fail "setup-debian.sh without a deb entry: exit code 0"; fi
grep -q "no enabled 'deb' entry" "$tmp/setup.out" || fail "setup-debian.sh without a deb entry: $(cat "$tmp/setup.out")"
# build_lammps_2025.sh fetch: trixie from the same mirror (it then stops: the stub fetched no tarball)
echo "deb [signed-by=/k.gpg] http://proxy.local:3142/debian $codename main" >"$s/sources.list"
PATH="$stub:$PATH" PERIDEM_APT_DIR="$s" PERIDEM_LAMMPS2025_DIR="$tmp/l25" \
  "$root/scripts/build_lammps_2025.sh" fetch >/dev/null 2>&1
sed -e "s/^Suites: .*/Suites: trixie/" "$tmp/s.want" >"$tmp/t.want"
cmp -s "$s/sources.list.d/peridem-trixie-src.sources" "$tmp/t.want" ||
  fail "build_lammps_2025.sh fetch wrote another entry: $(cat "$s/sources.list.d/peridem-trixie-src.sources" 2>&1)"

if [ $bad -eq 0 ]; then echo "PERIDEM-PASS apt_deb_src.sh"; exit 0; fi
exit 1
