#!/usr/bin/env bash
# Installs the Debian 12 packages signstim needs, only those that are missing, then jsPsych
# (scripts/fetch-jspsych.sh: pinned npm tarballs, SHA-512 checked, into third_party/jspsych/).
# Idempotent; runs apt-get as root, or through sudo when not root. Prints what it installs
# and that it is done; apt's own output goes to a log, shown only when apt fails.
#
# Usage: scripts/setup.sh [--with-slurm] [--with-sanitizers]
#   --with-slurm  also Slurm and munge (slurm-wlm munge, ~13 MB), only for the test of the
#                 Slurm scripts (tests/slurm, docs/slurm.md), which is skipped without them.
#                 Not by default: they are daemons (on a systemd machine their services are
#                 enabled on install), and on a cluster's login node Debian's sbatch could
#                 shadow the site's own Slurm.
#   --with-sanitizers  also clang, its sanitizer and libFuzzer runtimes, llvm-symbolizer and
#                 LLVM's linker (clang libclang-rt-14-dev llvm lld), for scripts/sanitize.sh and
#                 scripts/fuzz.sh (docs/fuzzing.md); CI runs both.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

with_slurm=0 with_sanitizers=0
for arg in "$@"; do
  case "$arg" in
    --with-slurm) with_slurm=1 ;;
    --with-sanitizers) with_sanitizers=1 ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "setup: unknown option '$arg' (see --help)" >&2; exit 1 ;;
  esac
done

packages=(
  build-essential cmake pkg-config git
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools
  libglm-dev libtinygltf-dev nlohmann-json3-dev libeigen3-dev
  libcli11-dev libgtest-dev
  # SHA-256 of every file a manifest lists (common/sha256.hpp): Nettle, small and well kept.
  nettle-dev
  # `signstim analyze`: Boost.Math's chi-squared, normal and Student's t distributions
  # (header-only; the package brings libboost1.74-dev and its CMake config).
  libboost-math-dev
  # `signstim analyze`'s mixed models (docs/analysis.md, "Mixed models"): R with lme4 (GLMM) and
  # ordinal (CLMM), run as Rscript. Without recommends: 52 packages, 57.6 MB to download, 105 MB
  # installed, 24 s to install on Debian 12 (measured 2026-11-25; r-base-dev and compilers are
  # not needed: the packages come built). Without R the analysis still runs (the report says
  # how to get the models) and the tests that need R are skipped.
  r-base-core r-cran-lme4 r-cran-ordinal
  # The figures' PNGs: FreeType draws their text in DejaVu Sans, which fontconfig finds; zlib
  # for the PNG's resolution chunk (analysis/figure_png.hpp).
  libfreetype-dev libfontconfig-dev fonts-dejavu-core zlib1g-dev
  ffmpeg
  # Mouthing of English words (stimuli/story/mouthing.hpp, docs/mouthing.md): the phonemes of a
  # word and when each is said, from espeak-ng, a maintained synthesizer, instead of a hand-made
  # letter table; espeak-ng-data holds its dictionaries and voices, read at run time.
  libespeak-ng-dev espeak-ng-data
  # xmllint: the ELAN-file test (tests/stimuli/elan_export_test.cpp) has a real XML parser check
  # that each .eaf is well formed (ELAN's EAFv3.0.xsd is in no Debian or npm package).
  libxml2-utils
  # OpenImageIO's CMake package (libopenimageio-dev) names its command-line tools as imported
  # targets and refuses to configure when /usr/bin/iconvert & co. are missing; they live in
  # openimageio-tools, which --no-install-recommends leaves out.
  libopenimageio-dev openimageio-tools
  # The review-page test (tests/browser/check_review_page.py) opens the study's index.html in
  # headless Chromium and plays every clip; it runs with Debian's /usr/bin/python3 and is
  # skipped, not passed, without these.
  chromium chromium-driver python3-selenium
  # scripts/fetch-jspsych.sh downloads jsPsych for `study --experiment jspsych` (HTTPS).
  curl ca-certificates
)
((with_slurm)) && packages+=(slurm-wlm munge)
# Debian 12's clang is clang-14; --no-install-recommends would leave out its runtimes. lld:
# LLVM 14's linker (1.2 MB beside the libllvm14 that clang brings anyway), which CMake uses
# where it is installed (CMakeLists.txt, SIGNSTIM_LLD): it links each sanitizer-built binary in
# 0.2-0.3 s of CPU instead of GNU ld's 1.2-1.6 s, ~40 binaries a build (BENCHMARKS.md).
((with_sanitizers)) && packages+=(clang libclang-rt-14-dev llvm lld)

# jsPsych is needed only by `signstim study --experiment jspsych`: without a network it is a
# warning, and everything else still builds and runs (that test is then skipped).
fetch_jspsych() {
  scripts/fetch-jspsych.sh ||
    echo "setup: warning: jsPsych was not fetched; \`signstim study --experiment jspsych\` needs it (run scripts/fetch-jspsych.sh)" >&2
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} Debian packages present."
  fetch_jspsych
  exit 0
fi

if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "setup: these packages are missing and I am neither root nor able to sudo:" >&2
  printf '  %s\n' "${missing[@]}" >&2
  echo "setup: install them with: apt-get install ${missing[*]}" >&2
  exit 1
fi

echo "setup: installing ${#missing[@]} missing package(s): ${missing[*]}"
log=$(mktemp "${TMPDIR:-/tmp}/signstim-setup.XXXXXX.log")
export DEBIAN_FRONTEND=noninteractive
if ! { "${sudo[@]}" apt-get update -q && \
       "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"; } >"$log" 2>&1; then
  echo "setup: apt-get failed; its last lines (whole log: $log):" >&2
  tail -n 25 "$log" >&2
  exit 1
fi
rm -f "$log"
fetch_jspsych
echo "setup: done."
