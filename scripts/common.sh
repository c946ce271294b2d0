#!/usr/bin/env bash
# common.sh: a library sourced by every script in scripts/, not a command: finds the repository,
# rebuilds it when a source is newer than the build, takes --classpath out of the arguments, picks the
# JDK (robosim_pick_java) and runs a RoboSim main class on the built class path. See runner/README.md.
if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  case ${1:-} in
    -h|--help) sed -nE '2,/^[^#]/s/^# ?//p' "$0"; exit 0 ;;
    *) echo "common.sh: a library for the scripts in scripts/, not a command (given: $*; see --help)" >&2; exit 2 ;;
  esac
fi
# (paths by bash's own expansions, not dirname and basename: every script pays for its start-up)
case ${BASH_SOURCE[0]} in */*) ROBOSIM_HOME=${BASH_SOURCE[0]%/*}/.. ;; *) ROBOSIM_HOME=.. ;; esac
ROBOSIM_HOME="$(cd "$ROBOSIM_HOME" && pwd)"
ROBOSIM_LIB="$ROBOSIM_HOME/runner/target/lib"
ROBOSIM_SCRIPT=${0##*/}
ROBOSIM_SCRIPT=${ROBOSIM_SCRIPT%.sh}
ROBOSIM_CALLER_DIR=$PWD   # where the user started the script, before any cd

# The JDK every script and process runs on: JAVA_HOME's when it is set, else the newest of `java` on the
# path and the JDKs under /usr/lib/jvm (or /Library/Java/JavaVirtualMachines) that have javac; put first on the path,
# so the floors of the benchmarks run on it too. JDK 21 and later run control code on virtual threads.
# Which one, and why, goes to the processes as ROBOSIM_JAVA_CHOICE (the robot processes and headless
# print it in their first lines; a script prints nothing of its own, so bad input stays one line).
# io.netty.noUnsafe, msgpack.universal-buffer: netty (the control and web links) and msgpack-core (the robot link)
# would warn about sun.misc.Unsafe on JDK 24+.
# JDK home $1 -> its feature version (17, 21, 25), or 0, in ROBOSIM_JAVA_VERSION. Read by bash itself,
# like the paths below: every script pays this at its start, and a fork and exec costs milliseconds.
robosim_java_version() {
  local line v=""
  if [ -f "$1/release" ]; then
    while IFS= read -r line || [ -n "$line" ]; do
      case $line in JAVA_VERSION=\"*) v=${line#JAVA_VERSION=\"} v=${v%%[!0-9]*}; break ;; esac
    done <"$1/release"
  fi
  [ -n "$v" ] || v=$("$1/bin/java" -version 2>&1 | sed -n '1s/.*version "\([0-9]*\).*/\1/p')
  [ "$v" = 1 ] && v=8
  ROBOSIM_JAVA_VERSION=${v:-0}
}
robosim_pick_java() {
  [ -n "${ROBOSIM_JAVA_CHOICE:-}" ] && return 0 # (chosen already: a script run by another)
  local home="" best=0 why c h
  if [ -n "${JAVA_HOME:-}" ] && [ -x "$JAVA_HOME/bin/java" ]; then
    [ -x "$JAVA_HOME/bin/javac" ] || robosim_fail "JAVA_HOME=$JAVA_HOME is a JRE (no bin/javac): RoboSim needs a JDK 17 or later"
    home=$JAVA_HOME why="JAVA_HOME"
  else
    for c in "$(command -v java 2>/dev/null)" /usr/lib/jvm/*/bin/java /Library/Java/JavaVirtualMachines/*/Contents/Home/bin/java; do
      [ -n "$c" ] && [ -x "$c" ] || continue
      h=$c
      [ -L "$c" ] && h=$(readlink -f "$c") # (java on the path: a link, e.g. to /etc/alternatives/java)
      h=${h%/bin/java}
      [ -x "$h/bin/javac" ] || continue # (a JRE cannot build the project)
      robosim_java_version "$h"
      if [ "$ROBOSIM_JAVA_VERSION" -gt "$best" ]; then best=$ROBOSIM_JAVA_VERSION home=$h; fi
    done
    why="the newest JDK found"
  fi
  [ -n "$home" ] || robosim_fail "no JDK found (java with javac, on the path or under /usr/lib/jvm): install a JDK 17 or later, or set JAVA_HOME"
  export PATH="$home/bin:$PATH"
  export ROBOSIM_JAVA_CHOICE="$home ($why)"
  robosim_cds_dir "$home"
}

# Class-data archives (runner/README.md, "How the scripts behave"): on JDK 19 and later each JVM a script
# starts maps the classes an earlier run of the same main class, class path and options loaded, from an
# archive under runner/target/cds/ (per JDK): on JDK 25 and later an AOT cache (KEY.aot: the classes loaded
# and linked, and the methods' profiles), assembled in the background from the configuration such a run
# recorded at its exit; on JDK 19-24 a dynamic CDS archive (KEY.jsa) written at its exit. The directory goes
# to the processes as ROBOSIM_CDS_DIR (the runner's children use it, ClassDataArchives), its kind as
# ROBOSIM_CDS_KIND (aot or jsa); empty when
# ROBOSIM_CDS=off, on JDK 17 (whose dynamic dump stops the JVM when the JDK's own archive is not mapped)
# and on a JDK without a default CDS archive.
robosim_cds_dir() {
  local home=$1
  ROBOSIM_CDS_DIR="" ROBOSIM_CDS_KIND=""
  if [ "${ROBOSIM_CDS:-on}" != off ] && [ -f "$home/lib/server/classes.jsa" ] && [ -f "$home/release" ]; then
    robosim_java_version "$home"
    if [ "$ROBOSIM_JAVA_VERSION" -ge 19 ]; then
      # shellcheck disable=SC2046
      set -- $(cksum <"$home/release")
      ROBOSIM_CDS_DIR="$ROBOSIM_HOME/runner/target/cds/java-$ROBOSIM_JAVA_VERSION-$1"
      ROBOSIM_CDS_KIND=jsa
      [ "$ROBOSIM_JAVA_VERSION" -ge 25 ] && ROBOSIM_CDS_KIND=aot
    fi
  fi
  export ROBOSIM_CDS_DIR ROBOSIM_CDS_KIND # (a script started by another keeps both: it chooses no JDK again)
}

# Bad input: one line naming the script, exit 2.
robosim_fail() {
  echo "$ROBOSIM_SCRIPT: $*" >&2
  exit 2
}
robosim_pick_java

# The calling script's usage: its header comment (from line 2 to the first line that is not a comment).
robosim_usage() {
  sed -nE '2,/^[^#]/s/^# ?//p' "$0"
}

# Path $1 made absolute against the directory the user started the script in.
robosim_abs() {
  case $1 in /*) echo "$1" ;; *) echo "$ROBOSIM_CALLER_DIR/$1" ;; esac
}

# The log level $1 (trace, debug, info, warn, error, off) into ROBOSIM_LOG_LEVEL, or a one-line refusal.
robosim_log_level() {
  case ${1:-} in
    trace|debug|info|warn|error|off) ROBOSIM_LOG_LEVEL=$1 ;;
    *) robosim_fail "--log-level (or ROBOSIM_LOG_LEVEL) needs one of trace, debug, info, warn, error, off, got '${1:-}'" ;;
  esac
}

# Takes every --classpath PATH[:PATH...] and --classpath=PATH[:PATH...] before a `--` out of the
# arguments, and --quiet (the log level warn) and --log-level LEVEL; the rest are left in ROBOSIM_ARGS. Their
# entries, then those of ROBOSIM_CLASSPATH, made absolute, become ROBOSIM_CLASSPATH, exported so that scripts
# started from here add the same entries; the level, ROBOSIM_LOG_LEVEL, is exported likewise (the JVM's
# robosim_java starts, and every JVM RoboSim starts from it, log at that level).
robosim_take_classpath() {
  local given=() entries=() parts=() joined e
  ROBOSIM_ARGS=()
  while [ $# -gt 0 ]; do
    case $1 in
      --) ROBOSIM_ARGS+=("$@"); break ;;
      --classpath) [ -n "${2:-}" ] || robosim_fail "--classpath needs a value: PATH[:PATH...]"
        given+=("$2"); shift ;;
      --classpath=*) [ -n "${1#--classpath=}" ] || robosim_fail "--classpath needs a value: PATH[:PATH...]"
        given+=("${1#--classpath=}") ;;
      --quiet) ROBOSIM_LOG_LEVEL=warn ;;
      --log-level) robosim_log_level "${2:-}"; shift ;;
      --log-level=*) robosim_log_level "${1#--log-level=}" ;;
      *) ROBOSIM_ARGS+=("$1") ;;
    esac
    shift
  done
  given+=("${ROBOSIM_CLASSPATH:-}")
  for joined in "${given[@]}"; do
    IFS=: read -ra parts <<<"$joined"
    for e in "${parts[@]}"; do
      [ -n "$e" ] || continue
      e=$(robosim_abs "$e")
      [ -e "${e%/\*}" ] || robosim_fail "class path entry $e does not exist (from --classpath or ROBOSIM_CLASSPATH)"
      entries+=("$e")
    done
  done
  ROBOSIM_CLASSPATH=$(IFS=:; echo "${entries[*]}")
  export ROBOSIM_CLASSPATH
  if [ -n "${ROBOSIM_LOG_LEVEL:-}" ]; then
    robosim_log_level "$ROBOSIM_LOG_LEVEL"
    export ROBOSIM_LOG_LEVEL
  fi
}

# ROBOSIM_JAVA_OPTS may not set the class path: java would take the last -cp and drop RoboSim's own.
robosim_check_java_opts() {
  local words=() w
  read -ra words <<<"${ROBOSIM_JAVA_OPTS:-}"
  for w in "${words[@]}"; do
    case $w in
      -cp|-classpath|--class-path|--class-path=*|-Djava.class.path=*)
        robosim_fail "ROBOSIM_JAVA_OPTS may not set the class path ($w): use --classpath PATH[:PATH...] or ROBOSIM_CLASSPATH" ;;
    esac
  done
}

# The runner's jar: rewritten by every `./mvnw package` (forceCreation), so it dates the last build.
robosim_runner_jar() {
  find "$ROBOSIM_HOME/runner/target" -maxdepth 1 -name 'runner-*.jar' ! -name '*-sources.jar' \
    ! -name '*-tests.jar' -print -quit 2>/dev/null
}

# The first file under a module's src/main, a module's pom.xml or the parent pom.xml that is newer
# than file $1; every <module> of the parent pom counts.
robosim_newer_source() {
  local paths=("$ROBOSIM_HOME/pom.xml") m p
  while read -r m; do
    for p in "$ROBOSIM_HOME/$m/pom.xml" "$ROBOSIM_HOME/$m/src/main"; do
      [ -e "$p" ] && paths+=("$p")
    done
  done < <(sed -nE 's|.*<module>([^<]+)</module>.*|\1|p' "$ROBOSIM_HOME/pom.xml")
  find "${paths[@]}" -newer "$1" -print -quit
}

# Why a build is needed (nothing built, or the first source newer than the build), or nothing.
robosim_why_build() {
  local jar changed
  jar=$(robosim_runner_jar)
  if [ -z "$jar" ] || [ ! -d "$ROBOSIM_LIB" ]; then
    echo "RoboSim is not built yet"
  else
    changed=$(robosim_newer_source "$jar")
    [ -z "$changed" ] || echo "RoboSim sources changed since the last build (${changed#"$ROBOSIM_HOME"/})"
  fi
}

# Builds (quietly, output on stderr) when nothing is built yet or a source is newer than the build.
# One build at a time per repository: scripts started together wait (flock) and find it done.
# ROBOSIM_NO_BUILD=1: never (a Slurm sweep's tasks, on nodes that share the build its submission made).
robosim_build_if_stale() {
  local why lock
  if [ "${ROBOSIM_NO_BUILD:-}" = 1 ]; then
    [ -n "$(robosim_runner_jar)" ] || robosim_fail "ROBOSIM_NO_BUILD=1, but RoboSim is not built"
    return 0
  fi
  why=$(robosim_why_build)
  [ -n "$why" ] || return 0
  lock="${TMPDIR:-/tmp}/robosim-build-$(echo "$ROBOSIM_HOME" | cksum | cut -d' ' -f1).lock"
  exec 9>"$lock"
  if command -v flock >/dev/null; then
    flock 9
    why=$(robosim_why_build)
  fi
  if [ -n "$why" ]; then
    robosim_build "$why"
  fi
  exec 9>&-
}

# Builds RoboSim (./mvnw package -DskipTests), saying why ($1) and then each module as Maven starts it (a first
# build, which fetches Maven and the libraries, takes a minute or two); on failure, Maven's errors, exit 1.
robosim_build() {
  local log rc
  log=$(mktemp "${TMPDIR:-/tmp}/robosim-build.XXXXXX")
  echo "$1: rebuilding (./mvnw package -DskipTests; a first build fetches Maven and the libraries) ..." >&2
  # (its exit code through a file: the pipe's is awk's, and under a caller's errexit a failing command would end it)
  (cd "$ROBOSIM_HOME" && ./mvnw -B -ntp package -DskipTests && echo 0 >"$log.rc" || echo $? >"$log.rc") 2>&1 \
    | tee "$log" \
    | awk '/^\[INFO\] Building .* \[[0-9]+\/[0-9]+\]$/ { n = split($0, w, " "); printf "  building";
        for (i = 3; i <= n - 2; i++) printf " %s", w[i]; printf " %s\n", w[n]; fflush() }' >&2
  rc=$(cat "$log.rc" 2>/dev/null || echo 1)
  if [ "$rc" != 0 ]; then
    { grep -E '^\[ERROR\]' "$log" || tail -n 30 "$log"; } | head -n 40 >&2 || true # (no [ERROR]: the wrapper's own)
    rm -f "$log" "$log.rc"
    echo "$ROBOSIM_SCRIPT: the build failed (its errors are above); nothing was started" >&2
    exit 1
  fi
  rm -f "$log" "$log.rc"
}

# RoboSim's class path: every module's jar and dependency, then the user's ROBOSIM_CLASSPATH entries
# (after, so a user class never shadows one of RoboSim's by accident).
robosim_classpath() {
  echo "$ROBOSIM_LIB/*:$(robosim_runner_jar)${ROBOSIM_CLASSPATH:+:$ROBOSIM_CLASSPATH}"
}

# Runs main class $1 with the other arguments (less --classpath) on RoboSim's class path. With -h or
# --help it prints the main class's usage and the options this library takes, and builds nothing: the
# jars there are (even if older than the sources), or, before the first build, this script's own header.
robosim_java() {
  local main=$1 a cp
  shift
  robosim_take_classpath "$@"
  robosim_check_java_opts
  for a in "${ROBOSIM_ARGS[@]}"; do
    case $a in
      --) break ;;
      -h|--help)
        if [ -n "$(robosim_runner_jar)" ] && [ -d "$ROBOSIM_LIB" ]; then
          # shellcheck disable=SC2086
          java -Dio.netty.noUnsafe=true -Dmsgpack.universal-buffer=true ${ROBOSIM_JAVA_OPTS:-} -cp "$(robosim_classpath)" "$main" "${ROBOSIM_ARGS[@]}" || exit
        else
          robosim_usage
          echo "(RoboSim is not built yet: its full usage is printed once it is, e.g. after ./mvnw package -DskipTests.)"
        fi
        echo "This script also takes --classpath PATH[:PATH...] (anywhere, or ROBOSIM_CLASSPATH): entries added"
        echo "after RoboSim's own jars to every process it starts; --quiet (warnings and errors only) or"
        echo "--log-level trace|debug|info|warn|error|off (or ROBOSIM_LOG_LEVEL; default info): how much every"
        echo "process it starts logs. JVM options: ROBOSIM_JAVA_OPTS."
        exit 0 ;;
    esac
  done
  robosim_build_if_stale
  cp=$(robosim_classpath)
  robosim_cds_opts "$main" "$cp"
  # shellcheck disable=SC2086
  local level=()
  [ -z "${ROBOSIM_LOG_LEVEL:-}" ] || level=("-Dorg.slf4j.simpleLogger.defaultLogLevel=$ROBOSIM_LOG_LEVEL")
  exec java -Dio.netty.noUnsafe=true -Dmsgpack.universal-buffer=true "${level[@]}" "${ROBOSIM_CDS_OPTS[@]}" ${ROBOSIM_JAVA_OPTS:-} -cp "$cp" "$main" "${ROBOSIM_ARGS[@]}"
}

# The class-data archive options of the JVM that runs main class $1 on class path $2 (into
# ROBOSIM_CDS_OPTS; none when ROBOSIM_CDS_DIR is empty): it maps KEY.aot or KEY.jsa, the archive of its main
# class, class path and ROBOSIM_JAVA_OPTS (the key), when that is there and newer than every jar of the class
# path; else, unless a live process is writing it, it is the key's training run, under a claim: an empty
# KEY.PID.start that dates its start, next to what it writes at its exit: KEY.PID.aotconf (the AOT
# configuration, which the next start has assembled, robosim_cds_settle) or KEY.PID.tmp (the dynamic
# archive, which the next start puts in place). None for a class path with a directory (the JVM refuses to
# archive those, and says so on every run) or with ROBOSIM_JAVA_OPTS of the user's own about class-data
# sharing. The JVM's cds and aot logs are off (they warn about the classes it cannot archive), and a training
# run prints no output of the JVM's own (it would say where it recorded its configuration as it exits). The
# same rules for the runner's children: ClassDataArchives.java.
robosim_cds_opts() {
  local main=$1 cp=$2 dir=${ROBOSIM_CDS_DIR:-} parts=() e key pid quiet=('-Xlog:cds*=off' '-Xlog:aot*=off')
  ROBOSIM_CDS_OPTS=()
  case $dir in ''|*:*) return 0 ;; esac
  case ${ROBOSIM_CDS_KIND:-} in aot|jsa) ;; *) return 0 ;; esac
  IFS=: read -ra parts <<<"${ROBOSIM_CLASSPATH:-}"
  for e in "${parts[@]}"; do
    [ -d "$e" ] && return 0
  done
  case ${ROBOSIM_JAVA_OPTS:-} in
    *Xshare*|*SharedArchiveFile*|*ArchiveClassesAtExit*|*AOTCache*|*AOTMode*|*AOTConfiguration*) return 0 ;;
  esac
  [ -d "$dir" ] || mkdir -p "$dir" 2>/dev/null || return 0
  # shellcheck disable=SC2046
  set -- $(printf '%s\n' "$main" "$cp" "${ROBOSIM_JAVA_OPTS:-}" | cksum)
  key="${main##*.}-$1"
  robosim_cds_settle "$dir" "$cp" "$key"
  if [ -f "$dir/$key.$ROBOSIM_CDS_KIND" ] && [ -z "$(robosim_cds_changed_since "$dir/$key.$ROBOSIM_CDS_KIND" "$cp")" ]; then
    if [ "$ROBOSIM_CDS_KIND" = aot ]; then
      ROBOSIM_CDS_OPTS=("-XX:AOTCache=$dir/$key.aot" "${quiet[@]}")
    else
      ROBOSIM_CDS_OPTS=("-XX:SharedArchiveFile=$dir/$key.jsa" "${quiet[@]}")
    fi
  elif [ "$ROBOSIM_CDS_BUSY" = 0 ]; then
    pid=${BASHPID:-$$} # (the JVM's: exec keeps it)
    if (: >"$dir/$key.$pid.start") 2>/dev/null; then
      if [ "$ROBOSIM_CDS_KIND" = aot ]; then
        ROBOSIM_CDS_OPTS=(-XX:AOTMode=record "-XX:AOTConfiguration=$dir/$key.$pid.aotconf" "${quiet[@]}"
          -XX:+UnlockDiagnosticVMOptions -XX:-DisplayVMOutput)
      else
        ROBOSIM_CDS_OPTS=("-XX:ArchiveClassesAtExit=$dir/$key.$pid.tmp" "${quiet[@]}")
      fi
    fi
  fi
}

# The first entry of class path $2 (a jar, or for DIR/* the directory or a file in it) that is newer
# than file $1, or nothing.
robosim_cds_changed_since() {
  local paths=() parts=() e
  IFS=: read -ra parts <<<"$2"
  for e in "${parts[@]}"; do
    paths+=("${e%/\*}")
  done
  find "${paths[@]}" -maxdepth 1 -newer "$1" -print -quit 2>/dev/null
}

# The first four bytes of file $1 in hex, as the machine orders them (an archive's magic number).
robosim_magic() {
  od -An -tx4 -N4 "$1" 2>/dev/null | tr -d ' '
}

# Settles the claims on KEY $3 in directory $1 (of JVMs on class path $2) whose writer has ended (the pid in
# KEY.ID.start, else the one ID starts with, is gone, or the claim is over an hour old): KEY.ID.tmp becomes
# the archive (a rename: a JVM never maps a file being written) when it is whole (the JVM writes an
# archive's header, with its magic number, last) and no jar changed since KEY.ID.start; else it is removed.
# A training run's whole configuration (KEY.ID.aotconf) of unchanged jars is assembled into the cache by a
# JVM started in the background under a claim of its own (its pid in its .start; it puts the cache in place
# itself, and an assembly that fails is not tried again); the run that found it does not wait for it. Then
# archives older than the runner's jar (the last build) go, and any claim left over an hour old. Sets
# ROBOSIM_CDS_BUSY to 1 when a live process is writing KEY's archive, else 0.
robosim_cds_settle() {
  local dir=$1 cp=$2 key=$3 start id pid owner settled=0
  ROBOSIM_CDS_BUSY=0
  for start in "$dir/$key".*.start; do
    [ -f "$start" ] || continue
    id=${start%.start}
    id=${id##*.}
    owner=""
    { read -r owner <"$start"; } 2>/dev/null # (gone meanwhile: settled by another start)
    pid=${owner:-${id%%-*}}
    if kill -0 "$pid" 2>/dev/null && [ -z "$(find "$start" -mmin +60 2>/dev/null)" ]; then
      ROBOSIM_CDS_BUSY=1
      continue
    fi
    if [ -f "$dir/$key.$id.tmp" ]; then
      if [ "$(robosim_magic "$dir/$key.$id.tmp")" = "$( [ "$ROBOSIM_CDS_KIND" = aot ] && echo f00baba2 || echo f00baba8)" ] \
        && [ -z "$(robosim_cds_changed_since "$start" "$cp")" ]; then
        mv -f "$dir/$key.$id.tmp" "$dir/$key.$ROBOSIM_CDS_KIND" 2>/dev/null
      else
        rm -f "$dir/$key.$id.tmp"
      fi
    elif [ -z "$owner" ] && [ "$ROBOSIM_CDS_KIND" = aot ] && [ "$(robosim_magic "$dir/$key.$id.aotconf")" = cafea07c ] \
      && [ -z "$(robosim_cds_changed_since "$start" "$cp")" ]; then
      robosim_cds_assemble "$dir" "$cp" "$key" "$dir/$key.$id.aotconf"
      ROBOSIM_CDS_BUSY=1 # (the assembler takes the configuration: it is not removed here)
      rm -f "$start" # (after the assembler's claim is made: no second training run in between)
      settled=1
      continue
    fi
    rm -f "$start" "$dir/$key.$id.aotconf"
    settled=1
  done
  if [ "$settled" = 1 ]; then
    find "$dir" -maxdepth 1 \( \( -name '*.jsa' -o -name '*.aot' \) ! -newer "$(robosim_runner_jar)" \
      -o \( -name '*.tmp' -o -name '*.aotconf' -o -name '*.start' \) -mmin +60 \) -exec rm -f {} + 2>/dev/null
  fi
  return 0
}

# Assembles the AOT cache of KEY $3 in directory $1 (class path $2) from configuration $4, in the background:
# a subshell that takes the configuration (a rename: of two starts that found it, one takes it; touched
# first, so the hourly clean-up leaves it), runs java -XX:AOTMode=create into KEY.PID.tmp and puts the
# cache in place when it is done; its output goes nowhere, and the user's Ctrl-C does not stop it. Its claim,
# KEY.PID.start with its pid in it (java keeps the pid), is made here before this returns. It runs with the
# options of ROBOSIM_JAVA_OPTS the cache depends on, not those that write files or print (robosim_jvm_quiet).
robosim_cds_assemble() {
  local dir=$1 cp=$2 key=$3 configuration=$4 pid opts
  touch "$configuration" 2>/dev/null
  opts=$(robosim_jvm_quiet "${ROBOSIM_JAVA_OPTS:-}")
  (
    trap '' INT
    pid=$BASHPID
    mv "$configuration" "$dir/$key.$pid.aotconf" || exit 1
    # shellcheck disable=SC2086
    if java $opts -XX:AOTMode=create "-XX:AOTConfiguration=$dir/$key.$pid.aotconf" \
      "-XX:AOTCache=$dir/$key.$pid.tmp" '-Xlog:cds*=off' '-Xlog:aot*=off' -cp "$cp" \
      && [ "$(robosim_magic "$dir/$key.$pid.tmp")" = f00baba2 ] && [ -z "$(robosim_cds_changed_since "$dir/$key.$pid.start" "$cp")" ]; then
      mv -f "$dir/$key.$pid.tmp" "$dir/$key.aot"
    fi
    rm -f "$dir/$key.$pid.tmp" "$dir/$key.$pid.aotconf" "$dir/$key.$pid.start"
  ) </dev/null >/dev/null 2>&1 &
  pid=$!
  echo "$pid" >"$dir/$key.$pid.start"
}

# The JVM options of $1 less those that write files or print (logs, flight recordings, heap dumps, error
# files, agents, statistics at exit): what a second JVM of the same options, the AOT cache's assembler, takes.
robosim_jvm_quiet() {
  local words=() w kept=()
  read -ra words <<<"$1"
  for w in "${words[@]}"; do
    case $w in
      -Xlog*|-Xloggc*|-verbose*|-XX:StartFlightRecording*|-XX:FlightRecorderOptions*|-XX:+HeapDump*|-XX:HeapDumpPath*\
        |-XX:ErrorFile*|-javaagent*|-agentlib*|-agentpath*|-XX:+Print*|-XX:NativeMemoryTracking*) ;;
      *) kept+=("$w") ;;
    esac
  done
  echo "${kept[*]}"
}

# For the screenshot scripts: makes sure Xvfb is there (installs Debian's xvfb when we are root).
robosim_need_xvfb() {
  if ! command -v Xvfb >/dev/null; then
    if [ "$(id -u)" = 0 ]; then apt-get update -qq && apt-get install -y -qq xvfb >/dev/null; else
      echo "$1: needs Xvfb (apt-get install xvfb)" >&2; exit 2; fi
  fi
}

# The arguments of the benchmark and screenshot scripts: -h/--help (prints the usage, exits 0),
# --classpath (robosim_take_classpath), anything after `--` (into ROBOSIM_PASS, for the tool the
# script runs) and, when $1 names the docs/ directory the script writes to, --write-docs and --out DIR.
# Leaves the other arguments in ROBOSIM_ARGS; any other option: one line, exit 2.
robosim_script_args() {
  local docs=$1
  shift
  robosim_take_classpath "$@"
  set -- "${ROBOSIM_ARGS[@]}"
  ROBOSIM_ARGS=() ROBOSIM_PASS=() ROBOSIM_WRITE_DOCS=0 ROBOSIM_OUT_ARG="" ROBOSIM_DOCS=$docs
  # shellcheck disable=SC2034  # ROBOSIM_PASS is read by the calling script
  while [ $# -gt 0 ]; do
    case $1 in
      -h|--help) robosim_usage; exit 0 ;;
      --) shift; ROBOSIM_PASS=("$@"); break ;;
      --write-docs) [ -n "$docs" ] || robosim_fail "unknown option $1 (see --help)"; ROBOSIM_WRITE_DOCS=1 ;;
      --out) [ -n "$docs" ] || robosim_fail "unknown option $1 (see --help)"
        [ -n "${2:-}" ] || robosim_fail "--out needs a directory"; ROBOSIM_OUT_ARG=$2; shift ;;
      --out=*) [ -n "$docs" ] || robosim_fail "unknown option --out (see --help)"; ROBOSIM_OUT_ARG=${1#--out=} ;;
      -?*) robosim_fail "unknown option $1 (see --help)" ;;
      *) ROBOSIM_ARGS+=("$1") ;;
    esac
    shift
  done
}

# Checks that positional argument $1 (its name) has a whole number >= 1 as its value $2.
robosim_count() {
  [[ "$2" =~ ^[1-9][0-9]*$ ]] || robosim_fail "$1 must be a whole number >= 1, got '$2'"
}

# A script that takes one positional argument ($1 says what, e.g. FILE) and --help: sets ROBOSIM_ONE
# to it (empty if none was given); an unknown option or a second argument is one line and exit 2.
robosim_one_arg() {
  local what=$1 a
  shift
  ROBOSIM_ONE=""
  for a in "$@"; do
    case $a in
      -h|--help) robosim_usage; exit 0 ;;
      -?*) robosim_fail "unknown option $a (see --help)" ;;
      *) [ -z "$ROBOSIM_ONE" ] || robosim_fail "takes one $what, got $ROBOSIM_ONE and $a (see --help)"; ROBOSIM_ONE=$a ;;
    esac
  done
}

# A benchmark's arguments: [REPS] [--quick] and robosim_script_args' own (docs directory $2), nothing
# after --. Sets BENCH_REPS (default $1; 1 with --quick) and BENCH_QUICK (0 or 1) and cds to the home.
# For the paper-benchmark scripts: [REPS] [STEPS] (defaults 3 and 5000) into BENCH_REPS and BENCH_STEPS,
# the options after -- into ROBOSIM_PASS; then cd to the repository, build if stale and compile
# bench/FloorProcesses into bench/classes.
robosim_paper_bench_args() {
  robosim_script_args "" "$@"
  [ ${#ROBOSIM_ARGS[@]} -le 2 ] || robosim_fail "takes at most REPS and STEPS, got ${ROBOSIM_ARGS[*]} (see --help)"
  BENCH_REPS=${ROBOSIM_ARGS[0]:-3}; BENCH_STEPS=${ROBOSIM_ARGS[1]:-5000}
  robosim_count REPS "$BENCH_REPS"; robosim_count STEPS "$BENCH_STEPS"
  cd "$ROBOSIM_HOME"
  robosim_build_if_stale
  mkdir -p bench/classes && javac -d bench/classes bench/FloorProcesses.java
}

robosim_bench_args() {
  local default=$1 docs=$2 a args=()
  shift 2
  BENCH_QUICK=0
  for a in "$@"; do
    if [ "$a" = --quick ]; then BENCH_QUICK=1; else args+=("$a"); fi
  done
  robosim_script_args "$docs" "${args[@]}"
  [ ${#ROBOSIM_ARGS[@]} -le 1 ] || robosim_fail "takes at most one argument, REPS, got ${ROBOSIM_ARGS[*]} (see --help)"
  [ ${#ROBOSIM_PASS[@]} = 0 ] || robosim_fail "takes nothing after -- (see --help)"
  BENCH_REPS=${ROBOSIM_ARGS[0]:-$default}
  robosim_count REPS "$BENCH_REPS"
  [ "$BENCH_QUICK" = 1 ] && BENCH_REPS=1
  cd "$ROBOSIM_HOME"
}

# robosim_bench_args with one more option, --peers PREFIX: the peer simulators built there by the peers'
# build-peers.sh (ARGoS 3 at least), run through their side-by-side.sh (../shared/peers/, or PEERS_SCRIPT).
# Sets BENCH_PEERS (absolute; empty without --peers) and BENCH_PEER_SCRIPT.
robosim_peer_bench_args() {
  local default=$1 rest=()
  shift
  BENCH_PEERS=""
  while [ $# -gt 0 ]; do
    case $1 in
      --peers) [ $# -ge 2 ] || robosim_fail "--peers needs the peers' PREFIX (see --help)"; BENCH_PEERS=$2; shift 2 ;;
      --peers=*) BENCH_PEERS=${1#--peers=}; shift ;;
      *) rest+=("$1"); shift ;;
    esac
  done
  robosim_bench_args "$default" docs/perf "${rest[@]}"
  BENCH_PEER_SCRIPT=${PEERS_SCRIPT:-$ROBOSIM_HOME/../shared/peers/side-by-side.sh}
  if [ -n "$BENCH_PEERS" ]; then
    BENCH_PEERS=$(robosim_abs "$BENCH_PEERS")
    [ -x "$BENCH_PEERS/argos3/bin/argos3" ] \
      || robosim_fail "--peers $BENCH_PEERS: no argos3/bin/argos3 there (build the peers with their build-peers.sh)"
    [ -f "$BENCH_PEER_SCRIPT" ] || robosim_fail "no side-by-side script at $BENCH_PEER_SCRIPT (set PEERS_SCRIPT)"
  fi
}

# Where a benchmark or screenshot script writes (after robosim_script_args): the docs/ directory with
# --write-docs, DIR with --out DIR (relative to where the user started the script), else a fresh
# temporary directory. Makes it, says where on stderr, and prints it.
robosim_out_dir() {
  local out
  if [ "$ROBOSIM_WRITE_DOCS" = 1 ] && [ -n "$ROBOSIM_OUT_ARG" ]; then
    robosim_fail "give --write-docs or --out DIR, not both"
  elif [ "$ROBOSIM_WRITE_DOCS" = 1 ]; then
    out="$ROBOSIM_HOME/$ROBOSIM_DOCS"
  elif [ -n "$ROBOSIM_OUT_ARG" ]; then
    out=$(robosim_abs "$ROBOSIM_OUT_ARG")
  else
    out=$(mktemp -d "${TMPDIR:-/tmp}/robosim-$ROBOSIM_SCRIPT.XXXXXX")
  fi
  mkdir -p "$out" || robosim_fail "cannot create the output directory $out"
  echo "$ROBOSIM_SCRIPT: writing to $out" >&2
  echo "$out"
}
