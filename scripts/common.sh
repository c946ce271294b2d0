# Sourced by the launch scripts: finds the repository, builds it once if the jars are missing,
# and runs a RoboSim main class on the built class path.
ROBOSIM_HOME="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ROBOSIM_LIB="$ROBOSIM_HOME/runner/target/lib"

robosim_build_if_missing() {
  if ! ls "$ROBOSIM_HOME"/runner/target/runner-*.jar >/dev/null 2>&1 || [ ! -d "$ROBOSIM_LIB" ]; then
    echo "RoboSim is not built yet: building it once with ./mvnw package -DskipTests ..." >&2
    (cd "$ROBOSIM_HOME" && ./mvnw -q -B package -DskipTests) >&2 || { echo "build failed" >&2; exit 1; }
  fi
}

robosim_java() {
  robosim_build_if_missing
  local main="$1"; shift
  local jar
  jar=$(ls "$ROBOSIM_HOME"/runner/target/runner-*.jar | head -n 1)
  # shellcheck disable=SC2086
  exec java ${ROBOSIM_JAVA_OPTS:-} -cp "$ROBOSIM_LIB/*:$jar" "$main" "$@"
}

# For the screenshot scripts: makes sure Xvfb is there (installs Debian's xvfb when we are root).
robosim_need_xvfb() {
  if ! command -v Xvfb >/dev/null; then
    if [ "$(id -u)" = 0 ]; then apt-get update -qq && apt-get install -y -qq xvfb >/dev/null; else
      echo "$1: needs Xvfb (apt-get install xvfb)" >&2; exit 2; fi
  fi
}
