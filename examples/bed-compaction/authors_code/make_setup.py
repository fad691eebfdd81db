#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Build the setup file (all.h5) of the authors' 2D bulk compaction
(debdeepbh/perigrain, scripts/2d_bulk_diffmesh_nogravity/setup.py) at a
chosen container size, by calling THEIR library (exp_dict, shape_dict,
material_dict) from a checkout of their repository.  Our driver, not their
code: the constants below are read off their setup.py and base.conf.

usage: PERIGRAIN=/path/to/perigrain python3 make_setup.py OUT.h5 \
           [--half-width 5e-3] [--shape pertdisk|n4|plus|0.3|...] [--material authors|text]

Run it with the current directory = the perigrain checkout (their shape
functions write meshdata/ files relative to it).  gekko and pathos are not
packaged for Debian: shims/ holds stand-ins (an SLSQP maximin solver and a
serial map).
"""
import argparse, os, sys
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, 'shims'))
src = os.environ.get('PERIGRAIN', os.getcwd())
sys.path.insert(1, src)

import numpy as np
from random import seed, random
import shape_dict, material_dict
from exp_dict import ShapeList, Wall, Contact, Experiment, get_incenter_mesh_loc

ap = argparse.ArgumentParser()
ap.add_argument('out')
ap.add_argument('--half-width', type=float, default=5e-3, help='container [-w, w]^2 (theirs: 20e-3)')
ap.add_argument('--shape', default='pertdisk')
ap.add_argument('--material', default='authors', choices=['authors', 'text'])
ap.add_argument('--P-meshsize', type=float, default=3.5e-3)
ap.add_argument('--no-nodal-circles', action='store_true')
a = ap.parse_args()

# their constants (setup.py)
delta = 1e-3 / 2
meshsize = 1e-3 / 5          # h = eps/2.5
contact_radius = delta / 4   # R_c = eps/4
min_particle_spacing = contact_radius * 1.001
w = a.half_width
wall = Wall(1, -w, w, w, -w)
c = min_particle_spacing / 2
P = np.array([[-w + c, -w + c], [w - c, -w + c], [w - c, w - c], [-w + c, w - c]])
msh = get_incenter_mesh_loc(P, a.P_meshsize, modify_nodal_circles=not a.no_nodal_circles, gen_bdry=False)
msh.incircle_rad -= min_particle_spacing / 2
msh.info()


def material():
    m = material_dict.peridem_deformable(delta, Gnot_scale=0.5, rho_scale=0.8)
    if a.material == 'text':
        # the text's Table 1: c = 9E/(pi eps^3), same E, rho, s0 from G_c as theirs
        m.cnot = 9 * m.E / (np.pi * delta**3)
    return m


SL = ShapeList()
for i in range(msh.count()):
    r = msh.incircle_rad[i]
    if a.shape == 'pertdisk':
        sh = shape_dict.perturbed_disk(seed=i, steps=16, scaling=r, std=0.3)
    elif a.shape == 'plus':
        sh = shape_dict.plus_inscribed(notch_dist=0.2, scaling=r)
    elif a.shape == 'n4':
        sh = shape_dict.small_disk(steps=4, scaling=r)
    elif a.shape == 'ring':
        sh = shape_dict.wheel_annulus(scaling=r, inner_circle_ratio=0.6, meshsize=meshsize, filename_suffix=str(i))
    else:
        sh = shape_dict.perturbed_disk(seed=i, steps=16, scaling=r, std=float(a.shape))
    SL.append(shape=sh, count=1, meshsize=meshsize, material=material())

particles = SL.generate_mesh(dimension=2, contact_radius=contact_radius, plot_mesh=False, plot_shape=False, shapes_in_parallel=False)
seed(1)
for i in range(msh.count()):
    particles[i][0].rotate(0 + (random() * (2 * np.pi - 0)))
    particles[i][0].shift(msh.incenter[i])

normal_stiffness = 18 * material_dict.peridem(delta).bulk_modulus / (np.pi * np.power(delta, 4))
contact = Contact(contact_radius, normal_stiffness, 0.8, 0.8)  # base.conf overrides both with 0.9
exp = Experiment(particles, wall, contact)
exp.save(a.out)

# summary
nn = sum(len(p[0].pos) for p in particles)
m = particles[0][0].material
print('grains', msh.count(), 'nodes', nn, 'cnot', m.cnot, 'snot', m.snot, 'rho', m.rho, 'E', m.E)
