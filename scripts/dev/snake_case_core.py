#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Renames the camelCase functions and variables of the LAMMPS-free core (src/peridem_*) to
snake_case, the one naming style of LAMMPS (and of the rest of the core), everywhere they are
used (src, driver, plugin, unittest, bench, doc).

  scripts/dev/snake_case_core.py [REPO_ROOT]

Idempotent: the names are collected from the core's files each time, so a second run finds
none left. Kept: type names (CamelCase, as LAMMPS's classes), kConstants, Eigen's member
functions, one-letter math names with a capital (dE, dV, detJ: the formulas' symbols).
Stops without changing anything when a new name would collide with an existing identifier.
Prints the files it changed (the caller runs clang-format on the C++ ones).
"""
import pathlib
import re
import sys

DIRS = ("src", "driver", "plugin", "unittest", "bench", "doc")
SUFFIXES = (".cpp", ".h", ".md", ".rst")
CAMEL = re.compile(r"\b[a-z][a-z0-9]*(?:[A-Z][a-z0-9]*)+\b")
# Eigen API used by the core, and formula symbols
KEEP = {"computeDirect", "eigenvalues", "eigenvectors", "normalized", "dE", "dV", "dU", "dW",
        "detJ", "bestD", "ccwerrboundA"}
# names whose plain snake_case form exists elsewhere: a distinct name, or allowed (a
# parameter name of another function)
OVERRIDE = {"requirePositive": "require_positive_parameter"}
ALLOWED_SAME = {"sourceName"}


def snake(name):
    # 2D/3D stay together: createBonds3D -> create_bonds_3d
    s = re.sub(r"([23])D\b", r"_\1d", name)
    s = re.sub(r"(?<=[a-z0-9])([A-Z])", r"_\1", s)
    return s.lower().replace("__", "_")


def strip(text):
    """C++ text without comments and string literals."""
    return re.sub(r"//[^\n]*|/\*.*?\*/|\"(?:\\.|[^\"\\])*\"", " ", text, flags=re.S)


def main(argv):
    root = pathlib.Path(argv[0] if argv else pathlib.Path(__file__).resolve().parents[2])
    core = sorted((root / "src").glob("peridem_*.[ch]*"))
    names = set()
    for p in core:
        text = p.read_text(encoding="utf-8")
        # identifiers in code, not in comments or strings
        code = strip(text)
        names |= {n for n in CAMEL.findall(code) if n not in KEEP and not re.match(r"k[A-Z]", n)}
    if not names:
        return 0
    files = [p for d in DIRS for p in sorted((root / d).rglob("*"))
             if p.is_file() and p.suffix in SUFFIXES]
    existing = set()
    for p in files:
        if p.suffix in (".cpp", ".h"):
            existing |= set(re.findall(r"\b[a-z_][a-z0-9_]*\b", strip(p.read_text(encoding="utf-8"))))
    mapping = {n: OVERRIDE.get(n, snake(n)) for n in names}
    clash = sorted(n for n, s in mapping.items() if s in existing and n not in ALLOWED_SAME)
    if clash:
        for n in clash:
            print("collision: %s -> %s exists already" % (n, mapping[n]), file=sys.stderr)
        return 1
    rx = re.compile(r"\b(" + "|".join(sorted(mapping, key=len, reverse=True)) + r")\b")
    for p in files:
        t = p.read_text(encoding="utf-8")
        n = rx.sub(lambda m: mapping[m.group(1)], t)
        if n != t:
            p.write_text(n, encoding="utf-8")
            print(p.relative_to(root))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
