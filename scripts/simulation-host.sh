#!/usr/bin/env bash
# Simulations of the testkit served to one tester over the simulation link (Python's robosim.testing starts this
# itself; python/README.md, "Testing controllers"):
#   scripts/simulation-host.sh [--port PORT] [--accept-timeout-s S]    (--help lists the options)
# Its first line says where it listens; it serves the first tester whose hello carries ROBOSIM_LINK_KEY (which
# must be set: the tester runs worlds and writes files as this user).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.testhost.SimulationHostMain "$@"
