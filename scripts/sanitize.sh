#!/usr/bin/env bash
# The test suite built with clang -fsanitize=address,undefined (all of it with --all), then every fuzz target
# briefly (issue 13 §2–§3). One build serves both: build-sanitize is configured with
# -DSIGNSTIM_FUZZ=ON, which instruments our code for the sanitizers, the libraries the fuzz
# binary links for libFuzzer's coverage, and also builds the fuzz binaries. Vulkan tests run under the validation layer as in the
# ordinary suite. Any sanitizer report fails the test that made it (UBSan does not recover;
# LeakSanitizer's suppressions, tests/sanitizers/lsan.supp, name only the Vulkan driver's and
# system libraries).
#
# The sweeps that cost minutes under ASan take a sample that still runs every code path
# (SIGNSTIM_TEST_BREADTH=sanitizer, tests/test_breadth.hpp: 3 of the 12 default stories in the
# motion and clearance tests, 6 of 20 loci pairs per verb slot, one seed of the mixed models' no-effect fits;
# docs/fuzzing.md); the gcc suite (./run.sh test)
# sweeps them whole, and so does SIGNSTIM_TEST_BREADTH=full scripts/sanitize.sh.
#
# Usage: scripts/sanitize.sh [--all] [--fuzz-seconds N] [--no-fuzz] [-- CTEST-ARGS...]
#   --all             also the 4 tests left out by default to keep CI within 45 minutes:
#                     CrashSafety.* (SIGKILL at 10 moments per command) and the Slurm
#                     test. They test what the kernel and Slurm do to a run (killed, cancelled,
#                     resumed); every line of ours they reach also runs under the sanitizers in
#                     the StudyCli, VerbOutCli and RenderGltfCli tests (SIGTERM mid-study,
#                     resume, shards and merge). Under ASan they took 4.6 CPU-minutes with 20 kills.
#   --fuzz-seconds N  how long each fuzz target runs afterwards (default 5: a smoke run)
#   --no-fuzz         only the test suite
#   CTEST-ARGS        passed to ctest (e.g. -R gltf)
# Needs clang (scripts/setup.sh --with-sanitizers installs it). Build folder:
# $SIGNSTIM_SANITIZE_BUILD_DIR, default build-sanitize. Exit status: 0 clean, 1 otherwise.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

fuzz_seconds=5 fuzz=1 all=0 ctest_args=()
while (($#)); do
  case "$1" in
    --fuzz-seconds) fuzz_seconds=${2:?--fuzz-seconds needs a number}; shift 2 ;;
    --no-fuzz) fuzz=0; shift ;;
    --all) all=1; shift ;;
    --) shift; ctest_args=("$@"); break ;;
    -h|--help) sed -n '2,27p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "sanitize: unknown option '$1' (see --help)" >&2; exit 1 ;;
  esac
done
command -v clang++ >/dev/null ||
  { echo "sanitize: clang++ is missing: scripts/setup.sh --with-sanitizers (or apt-get install clang)" >&2; exit 1; }

build=${SIGNSTIM_SANITIZE_BUILD_DIR:-build-sanitize}
jobs=$(nproc 2>/dev/null || echo 2)
start=$SECONDS
# -O2 (the suite runs long computations: -O1 takes half as long again); -g1: line tables.
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" -DSIGNSTIM_FUZZ=ON >/dev/null
cmake --build "$build" -j "$jobs"
built=$SECONDS
echo "sanitize: build $((built - start)) s"

supp=$PWD/tests/sanitizers/lsan.supp
# Keeps the Vulkan driver and layers mapped after the loader dlcloses them, so their memory is
# not mistaken for a leak of "<unknown module>" (tests/sanitizers/keep_vulkan_loaded.cpp).
export LD_PRELOAD=$(cd "$build" && pwd)/tests/sanitizers/libsignstim_keep_vulkan_loaded.so${LD_PRELOAD:+:$LD_PRELOAD}
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:check_initialization_order=1:strict_init_order=1
export LSAN_OPTIONS=suppressions=$supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# tests/test_breadth.hpp: the long sweeps take a sample here (SIGNSTIM_TEST_BREADTH=full: all of it).
export SIGNSTIM_TEST_BREADTH=${SIGNSTIM_TEST_BREADTH:-sanitizer}
status=0
skip=()
((all)) || skip=(-E '^CrashSafety\.|^slurm_')
# One CPU test per core, and a browser test beside them (run.sh; tests/CMakeLists.txt, "CPU slots").
ctest --test-dir "$build" --output-on-failure -j "$((jobs + 1))" --resource-spec-file "$(cd "$build" && pwd)/ctest-resources.json" \
  --timeout 900 "${skip[@]}" "${ctest_args[@]}" || status=1
tested=$SECONDS
echo "sanitize: tests $((tested - built)) s"
if ((fuzz)); then
  scripts/fuzz.sh --build "$build" --jobs "$jobs" "$fuzz_seconds" || status=1
  echo "sanitize: fuzz smoke $((SECONDS - tested)) s"
fi
((status == 0)) && echo "sanitize: clean ($((SECONDS - start)) s)" || echo "sanitize: FAILED (above)"
exit "$status"
