#!/usr/bin/env bash
# Seed and parameter sweeps (docs/EXPERIMENTS.md):
#   scripts/sweep.sh SPEC.xml [--out DIR] [--resume] [--keep-recordings] [--jobs N]
#   scripts/sweep.sh SPEC.xml --slurm [--partition P] [--time LIMIT] [--max-parallel K] [--wait] --out DIR
#   scripts/sweep.sh status DIR | gather DIR | task DIR INDEX
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
# a Slurm sweep's tasks and gather job call this script again, on the node that runs them
export ROBOSIM_SWEEP_SCRIPT="$ROBOSIM_HOME/scripts/sweep.sh"
robosim_java robosim.sweep.SweepMain "$@"
