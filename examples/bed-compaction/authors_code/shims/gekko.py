# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Minimal stand-in for the `gekko` package (not packaged for Debian).

Only what perigrain's exp_dict.get_incenter_mesh_loc uses: a maximin
problem in three variables (x1, x2, Z) with inequality constraints built
from +, -, *, **, abs and comparisons, solved here with scipy's SLSQP.
Written for PERIDEM's check of the authors' code; not the real GEKKO.
"""
import numpy as np
from scipy.optimize import minimize


class _Expr:
    def __init__(self, f):
        self.f = f  # f(x) -> float, x the vector of variable values

    @staticmethod
    def wrap(o):
        if isinstance(o, _Expr):
            return o
        c = float(o)
        return _Expr(lambda x: c)

    def _bin(self, o, op, rev=False):
        o = _Expr.wrap(o)
        a, b = (o, self) if rev else (self, o)
        return _Expr(lambda x: op(a.f(x), b.f(x)))

    def __add__(self, o): return self._bin(o, lambda a, b: a + b)
    def __radd__(self, o): return self._bin(o, lambda a, b: a + b, True)
    def __sub__(self, o): return self._bin(o, lambda a, b: a - b)
    def __rsub__(self, o): return self._bin(o, lambda a, b: a - b, True)
    def __mul__(self, o): return self._bin(o, lambda a, b: a * b)
    def __rmul__(self, o): return self._bin(o, lambda a, b: a * b, True)
    def __truediv__(self, o): return self._bin(o, lambda a, b: a / b)
    def __pow__(self, o): return self._bin(o, lambda a, b: abs(a) ** b if b != int(b) else a ** b)
    def __neg__(self): return _Expr(lambda x: -self.f(x))
    def __abs__(self): return _Expr(lambda x: abs(self.f(x)))
    # constraints: g(x) >= 0
    def __le__(self, o): return ('ineq', _Expr.wrap(o) - self)
    def __ge__(self, o): return ('ineq', self - _Expr.wrap(o))


class _Var(_Expr):
    def __init__(self, k, model):
        self.k = k
        self.model = model
        self.value = [0.0]
        super().__init__(lambda x: x[self.k])

    # numpy reads a solved variable as the list [value]
    def __len__(self): return 1
    def __getitem__(self, i): return self.value[i]

    def __setattr__(self, name, val):
        # a start value set by the caller (x1.value = ...)
        if name == 'value' and 'value' in self.__dict__:
            object.__setattr__(self, '_given', True)
        object.__setattr__(self, name, val)


class _Options:
    SOLVER = 1
    DIAGLEVEL = 0


class GEKKO:
    def __init__(self, remote=False):
        self._variables = []
        self._cons = []
        self._obj = None
        self.options = _Options()

    def Var(self, value=None):
        v = _Var(len(self._variables), self)
        if value is not None:
            v.value = [float(value)]
        self._variables.append(v)
        return v

    def Array(self, f, n):
        return [f() for _ in range(n)]

    def Equation(self, c):
        if isinstance(c, (bool, np.bool_)):
            return
        self._cons.append(c)

    def Maximize(self, e):
        self._obj = _Expr.wrap(e)

    def solve(self, disp=False):
        x0 = np.array([float(np.ravel(v.value)[0]) for v in self._variables])
        cons = [{'type': t, 'fun': (lambda x, e=e: e.f(x))} for t, e in self._cons]
        # SLSQP from the given start, with each variable that has no start
        # value (perigrain's Z) set to the largest value all constraints allow
        # there; keep the best feasible result of a few starts around it
        free = [k for k, v in enumerate(self._variables) if not getattr(v, '_given', False)]
        best = None
        rng = np.random.default_rng(0)
        scale = np.max(np.abs(x0)) * 0.05 + 1e-12
        for trial in range(8):
            start = x0.copy()
            if trial:
                start = start + rng.normal(0, scale, size=len(start))
            for k in free:
                start[k] = -1.0
            res = minimize(lambda x: -self._obj.f(x), start, method='SLSQP',
                           constraints=cons, options={'maxiter': 1000, 'ftol': 1e-15})
            feas = all(c['fun'](res.x) >= -1e-12 for c in cons)
            if feas and (best is None or res.fun < best.fun):
                best = res
        if best is None:
            best = res
        for v, val in zip(self._variables, best.x):
            v.value = [float(val)]
