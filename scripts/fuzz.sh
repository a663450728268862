#!/usr/bin/env bash
# Fuzzes every parser (tests/fuzz/targets.txt) with libFuzzer, ASan and UBSan, and prints per
# target the executions, the coverage reached and the findings.
#
# Usage: scripts/fuzz.sh [SECONDS] [options] [TARGET...]
#   SECONDS      how long each target runs (default 60)
#   --runs N     stop each target after N executions instead (e.g. --runs 1000000)
#   --jobs N     targets run N at a time (default 1)
#   --build DIR  the clang build to use or make (default build-fuzz; configured with
#                -DSIGNSTIM_FUZZ=ON; scripts/sanitize.sh passes its own build)
#   --list       print the targets and exit
#   TARGET...    only these (default: all)
#
# Needs clang (Debian 12: apt-get install clang, or scripts/setup.sh --with-sanitizers).
# Each target's corpus grows in DIR/fuzz/corpus/NAME (kept between runs; the seeds of
# targets.txt are added to it), its log is DIR/fuzz/logs/NAME.log. A finding is written to
# DIR/fuzz/findings/NAME/ and reported with the command that replays it; keep it as a
# regression case by copying it to tests/fuzz/regressions/NAME/ (the test suite replays that
# folder: fuzz.replay.NAME) once fixed.
# Exit status: 0 no finding, 1 a finding (or a target that did not run), 2 bad usage.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

seconds=60 runs=0 jobs=1 build=build-fuzz list=0
wanted=()
while (($#)); do
  case "$1" in
    --runs) runs=${2:?--runs needs a number}; shift 2 ;;
    --jobs) jobs=${2:?--jobs needs a number}; shift 2 ;;
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --list) list=1; shift ;;
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fuzz: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *)
      if [[ $1 =~ ^[0-9]+$ ]]; then seconds=$1; else wanted+=("$1"); fi
      shift ;;
  esac
done
[[ $runs =~ ^[0-9]+$ && $jobs =~ ^[1-9][0-9]*$ ]] || { echo "fuzz: --runs and --jobs take whole numbers" >&2; exit 2; }

# ---- the targets --------------------------------------------------------------------------
declare -A dict seeds
names=()
while read -r name dictionary rest; do
  [[ -z $name || $name == \#* ]] && continue
  names+=("$name"); dict[$name]=$dictionary; seeds[$name]=$rest
done <tests/fuzz/targets.txt
if ((list)); then printf '%s\n' "${names[@]}"; exit 0; fi
if ((${#wanted[@]})); then
  for w in "${wanted[@]}"; do
    [[ -n ${dict[$w]+x} ]] || { echo "fuzz: no target '$w' (targets: ${names[*]})" >&2; exit 2; }
  done
  names=("${wanted[@]}")
fi

# ---- the build ----------------------------------------------------------------------------
if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ is missing (libFuzzer comes with clang): apt-get install clang, or scripts/setup.sh --with-sanitizers" >&2
  exit 1
fi
if [[ ! -f $build/CMakeCache.txt ]] || ! grep -q '^SIGNSTIM_FUZZ:BOOL=ON' "$build/CMakeCache.txt"; then
  echo "fuzz: configuring $build (clang, libFuzzer, ASan, UBSan)"
  cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" -DSIGNSTIM_FUZZ=ON -DSIGNSTIM_BUILD_TESTS=OFF \
    -DCMAKE_CXX_COMPILER_LAUNCHER=$(command -v ccache || true) >/dev/null
fi
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" --target signstim_fuzz >/dev/null ||
  { echo "fuzz: the build failed: cmake --build $build --target signstim_fuzz" >&2; exit 1; }

# ---- the runs -----------------------------------------------------------------------------
work=$build/fuzz
mkdir -p "$work/logs"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

fuzz_one() {
  local name=$1 corpus=$work/corpus/$1 findings=$work/findings/$1 log=$work/logs/$1.log
  mkdir -p "$corpus" "$findings"
  local seed
  for seed in ${seeds[$name]}; do  # the seeds join the corpus (libFuzzer's first folder)
    if [[ -d $seed ]]; then find "$seed" -maxdepth 1 -type f -exec cp -f {} "$corpus/" \;
    else cp -f "$seed" "$corpus/"; fi
  done
  [[ -d tests/fuzz/regressions/$name ]] && cp -f tests/fuzz/regressions/"$name"/* "$corpus/" 2>/dev/null
  local limit=(-max_total_time="$seconds")
  ((runs > 0)) && limit=(-runs="$runs")
  local options=("${limit[@]}" -print_final_stats=1 -timeout=10 -rss_limit_mb=2048 -max_len=65536
                 -artifact_prefix="$findings/")
  [[ ${dict[$name]} != - ]] && options+=(-dict="tests/fuzz/dictionaries/${dict[$name]}.dict")
  "$build/tests/fuzz/signstim_fuzz" --target="$name" "${options[@]}" "$corpus" >"$log" 2>&1
}

summary() {  # name -> "executions  exec/s  coverage  features  corpus  result"
  local name=$1 log=$work/logs/$1.log status=$2
  local execs rate cov ft corp
  execs=$(awk '/stat::number_of_executed_units:/ {print $2}' "$log" | tail -1)
  rate=$(awk '/stat::average_exec_per_sec:/ {print $2}' "$log" | tail -1)
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | cut -d' ' -f2)
  corp=$(grep -oE 'corp: [0-9]+' "$log" | tail -1 | cut -d' ' -f2)
  local result=ok
  if ((status != 0)); then
    local artifact
    artifact=$(grep -oE "Test unit written to [^ ]+" "$log" | tail -1 | cut -d' ' -f5)
    result="FINDING ${artifact:-(see $log)}"
  fi
  printf '%-20s %12s %8s %6s %7s %6s  %s\n' "$name" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$result"
}

if ((runs > 0)); then what="$runs executions each"; else what="$seconds s each"; fi
echo "fuzz: ${#names[@]} target(s), $what, $jobs at a time; logs in $work/logs/"
declare -A pid_of
failed=0
printf '%-20s %12s %8s %6s %7s %6s  %s\n' target executions exec/s cov ft corpus result
report_finished() {  # prints each target as it ends (a long run shows its progress)
  local name status
  for name in "${!pid_of[@]}"; do
    kill -0 "${pid_of[$name]}" 2>/dev/null && continue
    status=0
    wait "${pid_of[$name]}" || status=$?
    ((status == 0)) || failed=1
    summary "$name" "$status"
    unset "pid_of[$name]"
  done
}
for name in "${names[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; report_finished; done
  fuzz_one "$name" &
  pid_of[$name]=$!
done
while ((${#pid_of[@]})); do wait -n || true; report_finished; done
if ((failed)); then
  echo "fuzz: a finding (above). Replay one: $build/tests/fuzz/signstim_fuzz --target=NAME FILE; once fixed, keep it:"
  echo "      cp FILE tests/fuzz/regressions/NAME/ (the test suite replays it: ctest -R fuzz.replay.NAME)"
  exit 1
fi
echo "fuzz: no finding"
