#!/bin/bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Run the authors' simulate2d (debdeepbh/perigrain, built from a checkout)
# on a setup made by make_setup.py, with their base.conf constants
# (scripts/2d_bulk_diffmesh_nogravity/base.conf + run.sh's 'frac' lines).
# usage: run_case.sh SIMULATE2D SETUP.h5 RUNDIR DT TIMESTEPS MODULO
# EXTRA_CONF (environment, optional): lines appended to main.conf; their reader
# (src/read/read_config.h) takes the last value of a key, so e.g.
# EXTRA_CONF='allow_friction = 0' switches friction off.
# simulate2d reads config/main.conf and data/hdf5/all.h5 and writes
# output/hdf5/ relative to the current directory, so each run gets its own.
set -e
bin=$(readlink -f "$1"); setup=$(readlink -f "$2"); dir=$3; dt=$4; steps=$5; modulo=$6
mkdir -p "$dir"/config "$dir"/data/hdf5 "$dir"/output/hdf5
cp "$setup" "$dir"/data/hdf5/all.h5
cat > "$dir"/config/main.conf <<CONF
timesteps = $steps
modulo = $modulo
dt = $dt
is_parallel = 1
do_resume = 0
resume_ind = 100
save_file = 1
nl_bdry_only = 0
allow_damping = 1
allow_friction = 1
damping_ratio = 0.9
friction_coefficient = 0.9
speed_wall_top = -1
enable_fracture = 1
self_contact = 1
${EXTRA_CONF:-}
CONF
cd "$dir"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}
/usr/bin/time -v "$bin" > sim.log 2> time.log
