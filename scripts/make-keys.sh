#!/usr/bin/env bash
# Makes the shared secret that every process of a simulation proves in its handshake (challenge and
# response: the secret itself never crosses the network):
#   scripts/make-keys.sh FILE [--help]
# Writes 32 random bytes as 64 hex characters into FILE (mode 600, refuses to overwrite an existing
# file). Then, on every machine of the simulation (the Environment, Geometry, robots, viewers):
#   export ROBOSIM_SECRET_FILE=FILE
# The Environment refuses to listen beyond loopback (--bind) without a secret. Copy FILE to the other
# machines by a secure channel (scp).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_one_arg FILE "$@"
file=$ROBOSIM_ONE
[ -n "$file" ] || robosim_fail "needs a FILE to write the secret into (see --help)"
file=$(robosim_abs "$file")
[ ! -e "$file" ] || robosim_fail "$file already exists: not overwritten (remove it first to make a new secret)"
[ -d "$(dirname "$file")" ] || robosim_fail "$(dirname "$file"): no such directory"
secret=$(od -An -tx1 -N32 /dev/urandom | tr -d ' \n')
(umask 077 && printf '%s\n' "$secret" > "$file")
echo "make-keys: wrote a new shared secret to $file (mode 600); on every machine of the simulation:"
echo "  export ROBOSIM_SECRET_FILE=$file"
