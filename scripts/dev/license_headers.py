#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Adds the GPL-2.0 short header to every PERIDEM source file, or checks that it is there.

  scripts/dev/license_headers.py [--check] [REPO_ROOT]

Idempotent: a file that already carries the header (its SPDX line within the first
20 lines) is left alone. C++ files get the LAMMPS-style block comment (headers keep
LAMMPS's "-*- c++ -*-" mode line on the first line); shell, Python and CMake files a
'#' block after any "#!" line. --check exits 0 when every file has it, 1 when any file
lacks it (listing those) or when there is no source file at all (a wrong REPO_ROOT), so
that the check fails if every header disappears.
"""
import pathlib
import sys

SPDX = "SPDX-License-" + "Identifier: GPL-2.0-only"  # split: this file is checked too
TEXT = [
    "PERIDEM - peridynamic grains (PeriDEM) for LAMMPS",
    "",
    "Copyright (C) 2026 The PERIDEM developers.",
    "This software is distributed under the GNU General Public License,",
    "version 2; see the LICENSE file in the top-level PERIDEM directory.",
    SPDX,
]
# what counts as a source file (the listed folders, and CMake files anywhere)
DIRS = ("src", "unittest", "driver", "plugin", "bench", "python", "scripts", "cmake",
        "examples", "doc")
CXX = (".cpp", ".h")
HASH = (".py", ".sh", ".cmake")
SKIP_PARTS = ("build", ".git")


def sources(root):
    out = []
    for p in sorted(root.rglob("*")):
        if not p.is_file() or any(s in p.relative_to(root).parts[:1] for s in SKIP_PARTS):
            continue
        rel = p.relative_to(root)
        if rel.parts[0].startswith("build"):
            continue
        if p.name == "CMakeLists.txt" or p.suffix == ".cmake":
            out.append(p)
        elif rel.parts[0] in DIRS and (p.suffix in CXX or p.suffix in HASH):
            out.append(p)
    return out


def has_header(text):
    return SPDX in "\n".join(text.splitlines()[:20])


def cxx_header(text):
    mode = text.startswith("/* -*- c++ -*-")
    first = "/* -*- c++ -*- ----------------------------------------------------------" if mode \
        else "/* ----------------------------------------------------------------------"
    block = [first] + [("   " + t).rstrip() for t in TEXT] + [
        "------------------------------------------------------------------------- */", ""]
    if mode:
        # the mode line moves to the licence block; the file's own block keeps its text
        text = "/* " + "-" * 70 + text[text.index("\n"):]
    return "\n".join(block) + "\n" + text


def hash_header(text):
    lines = text.splitlines(keepends=True)
    head = []
    if lines and lines[0].startswith("#!"):
        head, lines = [lines[0]], lines[1:]
    block = ["# " + "-" * 70 + "\n"] + [("# " + t).rstrip() + "\n" for t in TEXT] + \
        ["# " + "-" * 70 + "\n"]
    return "".join(head + block + lines)


def main(argv):
    check = "--check" in argv
    args = [a for a in argv if a != "--check"]
    root = pathlib.Path(args[0] if args else pathlib.Path(__file__).resolve().parents[2])
    files = sources(root)
    missing = [f for f in files if not has_header(f.read_text(encoding="utf-8"))]
    if check:
        if not files:
            print("PERIDEM-FAIL no source file under %s" % root)
            return 1
        if not missing:
            print("PERIDEM-PASS licence header in all %d source files" % len(files))
            return 0
        for f in missing:
            print("missing licence header: %s" % f.relative_to(root))
        print("PERIDEM-FAIL %d of %d source files without the licence header "
              "(run scripts/dev/license_headers.py)" % (len(missing), len(files)))
        return 1
    for f in missing:
        t = f.read_text(encoding="utf-8")
        f.write_text(cxx_header(t) if f.suffix in CXX else hash_header(t), encoding="utf-8")
    print("licence header added to %d of %d files" % (len(missing), len(files)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
