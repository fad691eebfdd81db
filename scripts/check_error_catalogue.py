#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Checks doc/errors.md, the bad-input catalogue, against the sources and the tests.

Every error->all / error->one / error->warning call in src/ must have a row in
doc/errors.md (same source file, same message format string), and every row must
name at least one test that exists (ctest -N in the build directory) or say
"unreachable" with the reason in its trigger column (an internal consistency check
that no input reaches, or a case no test can set up; listed by --report). Those are
the only two states: a row that says "untested" fails the check.

  check_error_catalogue.py [--build BUILD_DIR]      check (ctest runs this)
  check_error_catalogue.py --list                    print the error calls of src/
  check_error_catalogue.py --report                  the unreachable rows and their reasons

Messages are compared after normalising white space. A message that differs a
little from its row (a reworded citation, a typo fixed) still matches the row of
the same file with the most similar text (difflib ratio >= 0.75, each row used
once) and is printed as a notice, so rewording a message does not break the
check; a new error call without a row does.
"""
import argparse
import difflib
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CALL = re.compile(r"error->(all|one|warning)\s*\(")


def c_string_literals(arg):
    """The concatenated C string literals of one argument, or None."""
    parts = re.findall(r'"((?:[^"\\]|\\.)*)"', arg)
    if not parts:
        return None
    text = "".join(parts)
    return text.replace('\\"', '"').replace("\\n", "").replace("\\\\", "\\")


def split_args(text, start):
    """Arguments of the call whose '(' is at text[start - 1]; returns (args, end)."""
    depth, i, args, cur = 1, start, [], []
    while i < len(text) and depth > 0:
        c = text[i]
        if c == '"':
            j = i + 1
            while text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            cur.append(text[i:j + 1])
            i = j + 1
            continue
        if c == "'":
            j = text.index("'", i + 2 if text[i + 1] == "\\" else i + 1)
            cur.append(text[i:j + 1])
            i = j + 1
            continue
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0:
                break
        if c == "," and depth == 1:
            args.append("".join(cur).strip())
            cur = []
        else:
            cur.append(c)
        i += 1
    args.append("".join(cur).strip())
    return args, i


def norm(msg):
    return " ".join(msg.split())


def error_calls(src_dir):
    """[(file, line, kind, message)] of every error call in src/."""
    calls = []
    for name in sorted(os.listdir(src_dir)):
        if not name.endswith((".cpp", ".h")):
            continue
        text = open(os.path.join(src_dir, name), encoding="utf-8").read()
        # drop comments (keeping line numbers)
        text = re.sub(r"/\*.*?\*/", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)
        text = re.sub(r"//[^\n]*", "", text)
        for m in CALL.finditer(text):
            args, _ = split_args(text, m.end())
            line = text.count("\n", 0, m.start()) + 1
            msg_arg = args[1] if len(args) > 1 else ""
            msg = c_string_literals(msg_arg)
            if msg is None:
                msg = "<" + norm(msg_arg) + ">"  # a message built elsewhere
            calls.append((name, line, m.group(1), norm(msg)))
    return calls


ROW = re.compile(r"^\|\s*`([^`]+)`\s*\|\s*(all|one|warning)\s*\|\s*`(.*?)`\s*\|(.*)\|(.*)\|\s*$")


def catalogue_rows(path):
    """[(file, kind, message, trigger, tests)] of the table rows of doc/errors.md."""
    rows = []
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        m = ROW.match(line.rstrip("\n"))
        if not m:
            continue
        tests = [t.strip().strip("`") for t in m.group(5).split(",") if t.strip()]
        rows.append((m.group(1), m.group(2), norm(m.group(3).replace("\\|", "|")),
                     m.group(4).strip(), tests, n))
    return rows


def ctest_names(build):
    out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True,
                         text=True, check=True).stdout
    return {t["name"] for t in json.loads(out)["tests"]}


def match(calls, rows):
    """Pairs each call with a row: exact message first, then the most similar one."""
    free = list(range(len(rows)))
    pairing, notices, missing = {}, [], []
    for ci, (f, line, kind, msg) in enumerate(calls):
        for ri in free:
            if rows[ri][0] == f and rows[ri][2] == msg:
                pairing[ci] = ri
                free.remove(ri)
                break
    for ci, (f, line, kind, msg) in enumerate(calls):
        if ci in pairing:
            continue
        best, best_ratio = None, 0.0
        for ri in free:
            if rows[ri][0] != f:
                continue
            r = difflib.SequenceMatcher(None, rows[ri][2], msg).ratio()
            if r > best_ratio:
                best, best_ratio = ri, r
        if best is not None and best_ratio >= 0.75:
            pairing[ci] = best
            free.remove(best)
            notices.append(f"{f}:{line}: message differs from its catalogue row "
                           f"(line {rows[best][5]}, similarity {best_ratio:.2f}): update doc/errors.md")
        else:
            missing.append(ci)
    return pairing, notices, missing, free


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--build", help="build directory (ctest -N there lists the tests)")
    ap.add_argument("--catalogue", default=os.path.join(ROOT, "doc", "errors.md"))
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--report", action="store_true")
    a = ap.parse_args()

    calls = error_calls(os.path.join(ROOT, "src"))
    if a.list:
        for f, line, kind, msg in calls:
            print(f"{f}:{line}: {kind}: {msg}")
        print(f"{len(calls)} error calls")
        return 0

    rows = catalogue_rows(a.catalogue)
    pairing, notices, missing, unused = match(calls, rows)
    errors = []
    for ci in missing:
        f, line, kind, msg = calls[ci]
        errors.append(f"{f}:{line}: error->{kind} has no row in doc/errors.md: {msg}")
    for ri in unused:
        r = rows[ri]
        errors.append(f"doc/errors.md:{r[5]}: row matches no error call in src/{r[0]}: {r[2]}")
    for ci, ri in pairing.items():
        if calls[ci][2] != rows[ri][1]:
            errors.append(f"doc/errors.md:{rows[ri][5]}: {calls[ci][0]}:{calls[ci][1]} is "
                          f"error->{calls[ci][2]}, the row says {rows[ri][1]}")
    names = ctest_names(a.build) if a.build else None
    unreachable = []
    for ri, r in enumerate(rows):
        if not r[4]:
            errors.append(f"doc/errors.md:{r[5]}: row names no test (or unreachable with a reason)")
        elif r[4] == ["untested"]:
            errors.append(f"doc/errors.md:{r[5]}: untested: add a test of message and exit code, "
                          f"or mark it unreachable with the reason")
        elif r[4] == ["unreachable"]:
            if not r[3]:
                errors.append(f"doc/errors.md:{r[5]}: unreachable without a reason (trigger column)")
            unreachable.append(r)
        elif names is not None:
            for t in r[4]:
                if t not in names:
                    errors.append(f"doc/errors.md:{r[5]}: test {t} does not exist (ctest -N)")
    for n in notices:
        print("notice:", n)
    if a.report:
        for r in unreachable:
            print(f"unreachable: src/{r[0]}: {r[2]}: {r[3]}")
    for e in errors:
        print("ERROR:", e)
    tested = len([r for r in rows if r[4] and r[4] not in (["untested"], ["unreachable"])])
    print(f"{len(calls)} error calls in src/, {len(rows)} catalogue rows, {tested} with a test, "
          f"{len(unreachable)} unreachable, {len(errors)} problems")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
