#!/usr/bin/env bash
# Checks that headless.sh --one-jvm runs every world as every part in its own process does:
#   scripts/check-one-jvm.sh [--steps N] [--process-per-robot-up-to R] [--out DIR] [--keep] [FILE.xml...]
# For every world in test-envs/ (or each FILE.xml given) that runs headless, runs headless.sh twice for N
# steps (default 300), with --pose-log and --record, once as separate processes and once with --one-jvm,
# then compares the two pose logs byte for byte and what record-tool.sh poses and messages print of the two
# recordings. Prints one line per world: `same maze 300 steps`, `DIFFERENT maze: pose log differs at line L`
# (then that line of each run), `FAILED maze: ...` (a run that did not complete) or `skipped remote: why`.
# Exits 1 if any world differs or fails, else 0.
# Skipped, saying why: a file that is no environment (RobotInfo.xml), a world with a robot that has no
# control class, and a world of RemoteControlRobots (remote.xml: they stand still, waiting for commands on
# the fixed ports of RobotInfo.xml), and a world of more than 2048 robots (bench-10000: more than one shared
# connection carries). Robots that may join later (join="any-time", <join>) start in neither run.
# A world of more than R robots (default 10: bench-100, swarm-100 and bench-1000) has its robots in one
# process in the separate run (--robots-in-one-process: still sockets, serialization and a Geometry process).
# The default check takes about 2 minutes on 2 cores; --process-per-robot-up-to 100 adds about 45 s for each
# 100-robot world (a JVM per robot), and 1000 robot JVMs need more memory than most machines have.
# Writes each world's logs, recordings and run output into a fresh temporary directory, or DIR with
# --out DIR (both said on stderr), never into the repository; the files of a world that is the same are
# removed unless --keep. --classpath PATH[:PATH...] (or ROBOSIM_CLASSPATH) reaches every process, as in
# headless.sh.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_take_classpath "$@"
set -- "${ROBOSIM_ARGS[@]}"
steps=300 per_robot_up_to=10 out_arg="" keep=0 worlds=()
while [ $# -gt 0 ]; do
  case $1 in
    -h|--help) robosim_usage; exit 0 ;;
    --steps) [ -n "${2:-}" ] || robosim_fail "--steps needs a number"; steps=$2; shift ;;
    --process-per-robot-up-to) [ -n "${2:-}" ] || robosim_fail "--process-per-robot-up-to needs a number"
      per_robot_up_to=$2; shift ;;
    --out) [ -n "${2:-}" ] || robosim_fail "--out needs a directory"; out_arg=$2; shift ;;
    --keep) keep=1 ;;
    -?*) robosim_fail "unknown option $1 (see --help)" ;;
    *) worlds+=("$(robosim_abs "$1")") ;;
  esac
  shift
done
robosim_count --steps "$steps"
[[ "$per_robot_up_to" =~ ^[0-9]+$ ]] \
  || robosim_fail "--process-per-robot-up-to must be a whole number >= 0, got '$per_robot_up_to'"
for w in "${worlds[@]}"; do
  [ -f "$w" ] || robosim_fail "no such world file: $w"
done
cd "$ROBOSIM_HOME"
[ ${#worlds[@]} -gt 0 ] || worlds=("$ROBOSIM_HOME"/test-envs/*.xml)
if [ -n "$out_arg" ]; then
  out=$(robosim_abs "$out_arg")
  mkdir -p "$out" || robosim_fail "cannot create the output directory $out"
  made_out=0
else
  out=$(mktemp -d "${TMPDIR:-/tmp}/robosim-$ROBOSIM_SCRIPT.XXXXXX") || robosim_fail "cannot create a temporary directory"
  made_out=1
fi
echo "$ROBOSIM_SCRIPT: writing to $out" >&2
robosim_build_if_stale

# The robots the headless runner starts for world file $1, one "name control" a line (none for robots that
# join later), or, when it cannot run the world headless, one line "skip REASON".
started_robots() {
  local xml tag name control
  # one line, comments out (a comment may name a robot)
  xml=$(tr '\n\t' '  ' <"$1" | sed -E 's/<!--([^-]|-[^-])*-->//g')
  if ! grep -qE '<environment[ >]' <<<"$xml"; then
    echo "skip not an environment file (its root is <$(grep -oE '<[a-zA-Z][^ >]*' <<<"$xml" | head -n 1 | tr -d '<')>)"
    return
  fi
  while read -r tag; do
    [ -n "$tag" ] || continue
    grep -qE 'join="any-time"' <<<"$tag" && continue
    name=$(sed -nE 's/.* name="([^"]*)".*/\1/p' <<<"$tag")
    control=$(sed -nE 's/.* control="([^"]*)".*/\1/p' <<<"$tag")
    if [ -z "$control" ]; then
      echo "skip robot $name has no control class (control=\"...\") for the headless runner"
      return
    fi
    if [ "$control" = robosim.examples.RemoteControlRobot ]; then
      echo "skip robot $name is a RemoteControlRobot: it waits for commands on the fixed port RobotInfo.xml gives it"
      return
    fi
    echo "$name $control"
  done < <(grep -oE '<robot[[:space:]][^>]*>' <<<"$xml")
}

# The first line (1-based) at which files $1 and $2 differ, one that has a line the other has not included.
first_different_line() {
  awk -v other="$2" '
    { if ((getline b < other) <= 0 || b != $0) { print NR; found = 1; exit } }
    END { if (!found) print NR + 1 }' "$1"
}

# Line $2 of file $1, or what stands there instead.
line_of() {
  local l
  l=$(sed -n "$2{p;q}" "$1")
  if [ -z "$l" ] && [ "$(wc -l <"$1")" -lt "$2" ]; then echo "(none: the file has $(wc -l <"$1") lines)"; else echo "$l"; fi
}

# The last line a run printed that says something (its error, or its summary).
last_words() {
  grep -vE '^\s*$' "$1" | tail -n 1
}

same=0 different=0 failed=0 skipped=0 started_s=$SECONDS
for f in "${worlds[@]}"; do
  world=$(basename "$f" .xml)
  robots=$(started_robots "$f")
  if [[ "$robots" == skip* ]]; then
    echo "skipped $world: ${robots#skip }"
    skipped=$((skipped + 1))
    continue
  fi
  count=$(grep -c . <<<"$robots")
  if [ "$count" -gt 2048 ]; then # (bench-10000: the one-JVM scale world)
    echo "skipped $world: its $count robots are more than one shared connection carries (2048), and a socket or process each is beyond this check"
    skipped=$((skipped + 1))
    continue
  fi
  d=$out/$world
  mkdir -p "$d" || robosim_fail "cannot create $d"
  rm -f "$d"/{separate,one-jvm}.{csv,rec,out,poses,messages}
  separate=()
  note=""
  if [ "$count" -gt "$per_robot_up_to" ]; then
    separate=(--robots-in-one-process)
    note=" (the separate run's $count robots in one process)"
  fi
  problem=""
  codes=()
  for layout in separate one-jvm; do
    if [ "$layout" = one-jvm ]; then opts=(--one-jvm); else opts=("${separate[@]}"); fi
    scripts/headless.sh --env "$f" --steps "$steps" --pose-log "$d/$layout.csv" --record "$d/$layout.rec" \
      --timeout-s 900 "${opts[@]}" >"$d/$layout.out" 2>&1
    code=$?
    codes+=("$code")
    # 3: the run completed without some of its robots (the same in both, or the pose logs say where not)
    if [ "$code" != 0 ] && [ "$code" != 3 ]; then
      problem="the $layout run exited $code: $(last_words "$d/$layout.out") (see $d/$layout.out)"
      break
    fi
    for what in poses messages; do
      if ! scripts/record-tool.sh "$what" "$d/$layout.rec" >"$d/$layout.$what" 2>>"$d/$layout.out"; then
        problem="record-tool.sh $what of the $layout run failed: $(last_words "$d/$layout.out")"
        break 2
      fi
    done
  done
  if [ -n "$problem" ]; then
    echo "FAILED $world: $problem"
    failed=$((failed + 1))
    continue
  fi
  differences=() details=()
  [ "${codes[0]}" = "${codes[1]}" ] \
    || differences+=("exit codes differ (separate ${codes[0]}, one-jvm ${codes[1]})")
  for pair in "csv:pose log differs" "poses:recorded poses differ" "messages:recorded messages differ"; do
    ext=${pair%%:*}
    if ! cmp -s "$d/separate.$ext" "$d/one-jvm.$ext"; then
      l=$(first_different_line "$d/separate.$ext" "$d/one-jvm.$ext")
      differences+=("${pair#*:} at line $l")
      details+=("  separate.$ext line $l: $(line_of "$d/separate.$ext" "$l")"
        "  one-jvm.$ext  line $l: $(line_of "$d/one-jvm.$ext" "$l")")
    fi
  done
  if [ ${#differences[@]} -gt 0 ]; then
    joined=$(printf '%s; ' "${differences[@]}")
    echo "DIFFERENT $world: ${joined%; }"
    [ ${#details[@]} -eq 0 ] || printf '%s\n' "${details[@]}"
    different=$((different + 1))
  else
    echo "same $world $steps steps$note"
    same=$((same + 1))
    [ "$keep" = 1 ] || rm -rf "$d"
  fi
done
echo "$ROBOSIM_SCRIPT: $same same, $different different, $failed failed, $skipped skipped in $((SECONDS - started_s)) s"
if [ "$made_out" = 1 ] && [ "$keep" = 0 ] && [ $((different + failed)) = 0 ]; then
  rmdir "$out" 2>/dev/null
fi
[ $((different + failed)) = 0 ]
