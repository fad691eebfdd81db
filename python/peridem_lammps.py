# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Load the PERIDEM styles into a LAMMPS that was not started as lmp_peridem.

Two routes, both calling peridem_register() in libperidem.so:

* From Python, with Debian's ``python3-lammps`` module::

      from lammps import lammps
      import peridem_lammps
      lmp = lammps()
      peridem_lammps.register(lmp)
      lmp.command("atom_style peridem")

* From an input script run by the stock ``lmp`` (PYTHON package)::

      python peridem_load input 1 SELF format p file /path/to/python/peridem_lammps.py
      python peridem_load invoke

The library is found through the environment variable PERIDEM_LIBRARY (a
path to libperidem.so), then the system library path (after ``cmake
--install``), then ../build/libperidem.so next to this file.

The `clear` command removes styles registered this way: register again
after it (lmp_peridem re-registers by itself).
"""
import ctypes
import ctypes.util
import os

_library = None


def library_path():
    """The path of libperidem.so that register() loads."""
    env = os.environ.get("PERIDEM_LIBRARY")
    if env:
        return env
    found = ctypes.util.find_library("peridem")
    if found:
        return found
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "libperidem.so")


def _load():
    global _library
    if _library is None:
        path = library_path()
        if not os.path.exists(path) and os.sep in path:
            raise OSError(f"PERIDEM: no libperidem.so at {path}; build PERIDEM or set PERIDEM_LIBRARY")
        _library = ctypes.CDLL(path, mode=ctypes.RTLD_GLOBAL)
        _library.peridem_register.argtypes = [ctypes.c_void_p]
        _library.peridem_register.restype = ctypes.c_int
        _library.peridem_lammps_version.restype = ctypes.c_char_p
    return _library


def register(lmp):
    """Register the PERIDEM styles into `lmp`: a lammps.lammps object, or
    the LAMMPS pointer as an int or ctypes.c_void_p."""
    ptr = getattr(lmp, "lmp", lmp)
    if isinstance(ptr, ctypes.c_void_p):
        ptr = ptr.value
    if not ptr:
        raise ValueError("PERIDEM: register() needs a LAMMPS instance")
    if _load().peridem_register(ptr) != 0:
        raise RuntimeError("PERIDEM: peridem_register failed")


def peridem_load(lmpptr):
    """Entry point for LAMMPS's `python` command with `input 1 SELF format p`."""
    from lammps import lammps

    register(lammps(ptr=lmpptr))
