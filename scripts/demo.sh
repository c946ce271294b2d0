#!/usr/bin/env bash
# The demo: the bundled default environment (test-envs/test.xml), with live progress and a summary.
# Extra arguments go to headless.sh (for example --steps 5000).
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
exec scripts/headless.sh --env test-envs/test.xml --steps 5000 --progress "$@"
