#!/usr/bin/env bash
# Makes a simulation's keys: the shared secret every process proves in its handshake (challenge and
# response: the secret itself never crosses the network) and the simulation's own TLS key pair:
#   scripts/make-keys.sh DIR [--help]
# Creates DIR (mode 700) unless it exists, and writes into it
#   secret           32 random bytes as 64 hex characters (mode 600)
#   simulation.p12   a new self-signed EC key pair (P-256, 10 years) in a PKCS#12 file locked with the secret
# and refuses to overwrite either. Then, on every machine of the simulation (the Environment, Geometry,
# robots, viewers, the Control Panel and the Remote Control):
#   export ROBOSIM_KEYS=DIR
# Every connection then speaks TLS 1.3 (both ends show the key pair; nothing else is trusted) and proves
# the secret. The Environment refuses to listen beyond loopback (--bind) without them. Copy DIR to the
# other machines by a secure channel (scp -r); make new keys for a new simulation. Needs the JDK's keytool.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_one_arg DIR "$@"
dir=$ROBOSIM_ONE
[ -n "$dir" ] || robosim_fail "needs a DIR to write the keys into (see --help)"
dir=$(robosim_abs "$dir")
[ ! -e "$dir/secret" ] || robosim_fail "$dir/secret already exists: not overwritten (use a new DIR for new keys)"
[ ! -e "$dir/simulation.p12" ] || robosim_fail "$dir/simulation.p12 already exists: not overwritten (use a new DIR for new keys)"
[ -d "$(dirname "$dir")" ] || robosim_fail "$(dirname "$dir"): no such directory"
keytool=""
if [ -n "${JAVA_HOME:-}" ] && [ -x "$JAVA_HOME/bin/keytool" ]; then
  keytool=$JAVA_HOME/bin/keytool
elif command -v keytool >/dev/null; then
  keytool=$(command -v keytool)
elif command -v java >/dev/null && [ -x "$(dirname "$(readlink -f "$(command -v java)")")/keytool" ]; then
  keytool=$(dirname "$(readlink -f "$(command -v java)")")/keytool
fi
[ -n "$keytool" ] || robosim_fail "keytool not found: it comes with every JDK (set JAVA_HOME)"
(umask 077 && mkdir -p "$dir")
secret=$(od -An -tx1 -N32 /dev/urandom | tr -d ' \n')
(umask 077 && printf '%s\n' "$secret" > "$dir/secret")
# the secret reaches keytool through its environment, never its command line (ps would show it)
if ! out=$(umask 077 && ROBOSIM_MAKE_KEYS_PASS=$secret "$keytool" -genkeypair -alias simulation -keyalg EC \
    -groupname secp256r1 -validity 3650 -dname "CN=RoboSim simulation" -storetype PKCS12 \
    -keystore "$dir/simulation.p12" -storepass:env ROBOSIM_MAKE_KEYS_PASS 2>&1); then
  rm -f "$dir/secret" "$dir/simulation.p12"
  robosim_fail "keytool could not make the key pair: $out"
fi
echo "make-keys: wrote a new secret and TLS key pair to $dir (secret, simulation.p12); on every machine of the simulation:"
echo "  export ROBOSIM_KEYS=$dir"
