#!/usr/bin/env bash
# What is in a recording made with --record (environment.sh, headless.sh):
#   scripts/record-tool.sh summary FILE      the world, the steps, how the run ended (or where the file stops)
#   scripts/record-tool.sh poses FILE        every step's poses as CSV (the --pose-log columns) on stdout
#   scripts/record-tool.sh messages FILE     every message delivered as CSV (step,from,to,text) on stdout
#   scripts/record-tool.sh reports FILE      every value the robots reported as CSV (step,robot,name,value)
#   scripts/record-tool.sh readings FILE     every sensor reading as CSV, a value a row (step,robot,sensor,unit,index,value)
#   scripts/record-tool.sh metrics FILE      the run's metrics as a sweep's row has them (CSV)
#   scripts/record-tool.sh plot FILE --out F.png   each robot's trajectory over the arena, drawn into a PNG
#   scripts/record-tool.sh plot FILE --report NAME --out F.png   a reported value over the run, a line per robot
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.runner.RecordToolMain "$@"
