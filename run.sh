#!/usr/bin/env bash
# signstim quick start. Each form installs missing Debian packages, builds, then:
#   ./run.sh          runs the main job (the default study, quick) and prints where to look
#   ./run.sh test     runs the whole test suite
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

mode=${1:-run}
case "$mode" in
  run|test) ;;
  -h|--help) sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "usage: ./run.sh [run|test]" >&2; exit 1 ;;
esac

start=$SECONDS
scripts/setup.sh
installed=$SECONDS

build=${SIGNSTIM_BUILD_DIR:-build}
jobs=$(nproc 2>/dev/null || echo 2)
# -g1 (line tables: backtraces name file and line) instead of -g: a third less compile time.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" >/dev/null
cmake --build "$build" -j "$jobs"
echo "run.sh: install $((installed - start)) s, build $((SECONDS - installed)) s"

if [[ $mode == test ]]; then
  # lavapipe renders with several threads per draw; one test process per core keeps them busy.
  # The resource file gives each core one slot and every CPU test takes one; the browser tests,
  # which mostly wait on Chromium playing clips, take none: they run beside them in the extra
  # job (tests/CMakeLists.txt, "CPU slots").
  ctest --test-dir "$build" --output-on-failure -j "$((jobs + 1))" \
    --resource-spec-file "$(cd "$build" && pwd)/ctest-resources.json" --timeout 600
else
  # The default study at its quick settings (320x240, 15 fps): a few minutes on 2 cores, into
  # out/study (out/ is in .gitignore, so the clips never show up in `git status`).
  # Full quality: build/signstim study --out out/study-full (docs/study.md).
  echo "run.sh: rendering the default study (quick) into out/study/"
  "$build/signstim" study --out out/study --quick
fi
