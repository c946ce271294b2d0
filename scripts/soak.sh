#!/usr/bin/env bash
# The reliability soak: 100 ring-messaging robots for 100,000 steps with faults injected at random
# steps (seeded), then checks that every step ran, every message between robots that were both still
# there arrived exactly once and in order, and the Environment's heap stayed flat.
#   scripts/soak.sh [--robots N] [--steps S] [--seed K] ...   (see --help; about 15 minutes on 2 cores)
# Prints the report on stdout (the processes' logs go to stderr). --classpath PATH[:PATH...] (or
# ROBOSIM_CLASSPATH) adds entries after RoboSim's own jars for every process it starts.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.runner.Soak "$@"
