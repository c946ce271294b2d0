#!/usr/bin/env bash
# What is in a recording made with --record (environment.sh, headless.sh):
#   scripts/record-tool.sh summary FILE      the world, the steps, how the run ended (or where the file stops)
#   scripts/record-tool.sh poses FILE        every step's poses as CSV (the --pose-log columns) on stdout
#   scripts/record-tool.sh messages FILE     every message delivered as CSV (step,from,to,text) on stdout
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.runner.RecordToolMain "$@"
