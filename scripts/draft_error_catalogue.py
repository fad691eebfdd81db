#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Drafts rows of doc/errors.md from the tests that exist: runs the error tests
(and the tests that expect a warning) verbosely, reads the source file and line
LAMMPS prints with each ERROR/WARNING, and prints one catalogue row per error
call of src/ with the tests that reach it (or `untested`). A maintenance tool:
review its output before pasting; scripts/check_error_catalogue.py checks the
result.

  draft_error_catalogue.py BUILD_DIR [ctest -R regex] > rows.md
"""
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_error_catalogue as cec  # noqa: E402

build = sys.argv[1]
regex = sys.argv[2] if len(sys.argv) > 2 else None
info = json.loads(subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True,
                                 text=True, check=True).stdout)
commands, selected = {}, []
for t in info["tests"]:
    cmd = t.get("command", [])
    commands[t["name"]] = cmd
    # error tests, and warning tests (expect_pass.sh --regex "WARNING: ...", which echoes the
    # output, so the warning's src/<file>:<line> is in the log)
    if any("expect_error" in c for c in cmd) or any("WARNING" in c for c in cmd):
        selected.append(t["name"])
if regex:
    selected = [n for n in selected if re.search(regex, n)]
pattern = "^(" + "|".join(re.escape(n) for n in selected) + ")$"
log = subprocess.run(["ctest", "-V", "-j2", "-R", pattern], cwd=build, capture_output=True,
                     text=True).stdout
num_to_name = dict(re.findall(r"Start\s+(\d+): (\S+)", log))
hits = {}
line_re = re.compile(r"^(\d+): .*?(ERROR|WARNING)(?: on proc \d+)?: .*\((?:[^()]*/)?([\w.]+\.(?:cpp|h)):(\d+)\)")
for line in log.splitlines():
    m = line_re.match(line)
    if not m or m.group(1) not in num_to_name:
        continue
    hits.setdefault((m.group(3), int(m.group(4))), set()).add(num_to_name[m.group(1)])


def trigger(name):
    cmd = commands.get(name, [])
    if "-in" in cmd:
        i = cmd.index("-in")
        rest = [c for c in cmd[i + 2:] if c not in ("-log", "none", "-echo", "screen")]
        return f"`{os.path.basename(cmd[i + 1])}` " + " ".join(
            f'"{c}"' if " " in c else c for c in rest)
    return "see the test"


for f, line, kind, msg in cec.error_calls(os.path.join(cec.ROOT, "src")):
    tests = sorted(hits.get((f, line), []))
    trig = trigger(tests[0]).replace("|", "\\|") if tests else ""
    names = ", ".join(f"`{t}`" for t in tests) if tests else "untested"
    print(f"| `{f}` | {kind} | `{msg.replace('|', chr(92) + '|')}` | {trig} | {names} |")
