#!/usr/bin/env bash
# The Control Panel for a running Environment:
#   scripts/control-panel.sh HOST [PORT]                      a window (needs a display)
#   scripts/control-panel.sh HOST [PORT] REQUEST              one request (--help lists them all)
# Default port 8100. With the simulation's keys (ROBOSIM_KEYS) it speaks TLS and proves the secret; see --help.
# --classpath PATH[:PATH...] (or ROBOSIM_CLASSPATH) adds entries after RoboSim's own jars.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.control.ControlPanelMain "$@"
