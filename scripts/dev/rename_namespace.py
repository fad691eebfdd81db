#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Renames the LAMMPS-glue namespace PERIDEM to peridem_lmp, so that the package's two
namespaces do not differ only by case (the LAMMPS-free core keeps `peridem`).

  scripts/dev/rename_namespace.py [REPO_ROOT]

Idempotent (a second run changes nothing). Touches C++ sources and the Markdown/rst
docs that name glue functions (`PERIDEM::grain_reduce` ...); the word PERIDEM elsewhere
(messages, macros, the package name) is left alone. Prints the C++ files it changed,
so that the caller can run clang-format on them (lines grow by 4 characters).
"""
import pathlib
import re
import sys

OLD, NEW = "PERIDEM", "peridem_lmp"
DIRS = ("src", "driver", "plugin", "unittest", "bench", "python", "doc")
SUFFIXES = (".cpp", ".h", ".md", ".rst", ".py")
PATTERNS = [(re.compile(r"\bnamespace %s\b" % OLD), "namespace " + NEW),
            (re.compile(r"(?<![\w:])%s::" % OLD), NEW + "::")]


def main(argv):
    root = pathlib.Path(argv[0] if argv else pathlib.Path(__file__).resolve().parents[2])
    for d in DIRS:
        for p in sorted((root / d).rglob("*")):
            if not p.is_file() or p.suffix not in SUFFIXES or p.name == "rename_namespace.py":
                continue
            t = p.read_text(encoding="utf-8")
            n = t
            for rx, rep in PATTERNS:
                n = rx.sub(rep, n)
            if n != t:
                p.write_text(n, encoding="utf-8")
                print(p.relative_to(root))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
