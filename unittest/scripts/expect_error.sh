#!/usr/bin/env bash
# expect_error.sh REGEX COMMAND...: passes when COMMAND exits non-zero and its
# output contains a LAMMPS "ERROR" line matching REGEX (extended regex).
set -u
regex="$1"; shift
source "$(dirname "$0")/mpi_env.sh"
out="$("$@" 2>&1)"
rc=$?
if [ $rc -eq 0 ]; then
  echo "FAIL: expected a non-zero exit code, got 0. Output:"; echo "$out"; exit 1
fi
if ! grep -E "ERROR.*${regex}" <<<"$out" >/dev/null; then
  echo "FAIL: exit code $rc but no ERROR line matching /${regex}/. Output:"; echo "$out"; exit 1
fi
if grep -E "Segmentation|signal [0-9]+|core dumped" <<<"$out" >/dev/null; then
  echo "FAIL: crashed instead of a clean error. Output:"; echo "$out"; exit 1
fi
echo "OK: exit code $rc with: $(grep -E "ERROR" <<<"$out" | head -n 1)"
