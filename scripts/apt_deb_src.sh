#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# apt_deb_src.sh APT_DIR MATCH_SUITES [SUITES]
# Prints deb-src stanzas (deb822) for the enabled `deb` entries of APT_DIR (sources.list,
# sources.list.d/*.list one-line, sources.list.d/*.sources deb822) that serve one of
# MATCH_SUITES (space-separated): the same URIs, components and Signed-By, with the suites
# matched, or SUITES in their place (a source package of another release from the same
# mirror). A source package must come from the archive the binary packages come from (a
# mirror, a local proxy), so the address is read from the machine, not written in here.
# Exits 1 with a message when no deb entry serves those suites. Reads only; needs no root.
set -euo pipefail
dir="${1:?usage: apt_deb_src.sh APT_DIR MATCH_SUITES [SUITES]}"
match="${2:?usage: apt_deb_src.sh APT_DIR MATCH_SUITES [SUITES]}"
write="${3:-}"
files=()
for f in "$dir/sources.list" "$dir"/sources.list.d/*.list "$dir"/sources.list.d/*.sources; do
  if [ -f "$f" ]; then files+=("$f"); fi
done

# one stanza per deb entry (deduplicated); deb822 continuation lines (an embedded
# Signed-By key) are kept as they are
prog='
function trim(s) { sub(/^[ \t]+/, "", s); sub(/[ \t]+$/, "", s); return s }
function reset() { isdeb = 0; enabled = 1; uris = ""; suites = ""; comps = ""; key = ""; last = "" }
function emit(u, s, c, k,   n, a, i, keep, out) {
  n = split(s, a, /[ \t]+/); keep = ""
  for (i = 1; i <= n; i++)
    if (a[i] != "" && index(" " match_suites " ", " " a[i] " ") > 0) keep = keep (keep == "" ? "" : " ") a[i]
  if (keep == "" || u == "" || c == "") return
  out = "Types: deb-src\nURIs: " u "\nSuites: " (write_suites != "" ? write_suites : keep) "\nComponents: " c
  if (k != "") out = out "\nSigned-By:" (k ~ /^\n/ ? "" : " ") k
  if (!(out in seen)) { seen[out] = 1; order[++nout] = out }
}
function flush() { if (isdeb && enabled) emit(uris, suites, comps, key); reset() }
FNR == 1 { flush(); deb822 = (FILENAME ~ /\.sources$/) }
deb822 && /^[ \t]*#/ { next }
deb822 && /^[ \t]*$/ { flush(); next }
deb822 && /^[ \t]/ {
  if (last == "signed-by") key = key "\n" $0
  else if (last == "uris") uris = trim(uris " " trim($0))
  else if (last == "suites") suites = trim(suites " " trim($0))
  else if (last == "components") comps = trim(comps " " trim($0))
  next
}
deb822 {
  i = index($0, ":"); if (i == 0) next
  last = tolower(trim(substr($0, 1, i - 1))); v = trim(substr($0, i + 1))
  if (last == "types") isdeb = (index(" " v " ", " deb ") > 0)
  else if (last == "uris") uris = v
  else if (last == "suites") suites = v
  else if (last == "components") comps = v
  else if (last == "signed-by") key = v
  else if (last == "enabled") enabled = (tolower(v) != "no")
  next
}
{
  line = $0; sub(/#.*/, "", line); opts = ""
  if (match(line, /\[[^]]*\]/)) {
    opts = substr(line, RSTART + 1, RLENGTH - 2)
    line = substr(line, 1, RSTART - 1) " " substr(line, RSTART + RLENGTH)
  }
  n = split(trim(line), w, /[ \t]+/)
  if (n < 4 || w[1] != "deb") next
  k = ""; m = split(opts, o, /[ \t]+/)
  for (i = 1; i <= m; i++) if (tolower(substr(o[i], 1, 10)) == "signed-by=") k = substr(o[i], 11)
  c = w[4]; for (i = 5; i <= n; i++) c = c " " w[i]
  emit(w[2], w[3], c, k)
}
END { flush(); for (i = 1; i <= nout; i++) printf "%s%s\n", (i > 1 ? "\n" : ""), order[i] }
'
out=""
if [ ${#files[@]} -gt 0 ]; then
  out="$(awk -v match_suites="$match" -v write_suites="$write" "$prog" "${files[@]}")"
fi
if [ -z "$out" ]; then
  echo "apt_deb_src.sh: no enabled 'deb' entry for suite(s) '$match' in $dir/sources.list or" \
    "$dir/sources.list.d/*.list, *.sources: cannot tell which archive the binary packages" \
    "come from. Add a deb-src entry for that archive by hand." >&2
  exit 1
fi
echo "$out"
