#!/usr/bin/env bash
# Fetches jsPsych 8 and the plugins `signstim study --experiment jspsych` copies into a study's
# experiment/ folder (docs/experiment.md), from their npm tarballs, into third_party/jspsych/
# (git-ignored). Versions are pinned below with the SHA-512 `integrity` the npm registry
# publishes for each tarball; a tarball whose digest differs is refused and nothing is
# installed. Idempotent: when the folder holds exactly these pins, nothing is fetched.
# Quiet: one line saying what it did; curl's and tar's messages only on failure.
#
# Usage: scripts/fetch-jspsych.sh [--into DIR]   (default: third_party/jspsych beside scripts/)
# Needs curl, tar, gzip, sha512sum, base64, od (Debian: curl, coreutils, tar, gzip).
# The registry is $NPM_REGISTRY (default https://registry.npmjs.org), e.g. a lab's mirror.
set -euo pipefail

# name version integrity — the npm registry's dist.integrity of each tarball.
pins=(
  "jspsych 8.3.0 sha512-UrwSVG14v8oRX6WFQ1L6uuGT0G7KgRDSH48iKIVIQI+yMRGAlvg+tEUNFKe/1xZxgk3kZiZ5xP0AnpPqPj1zkg=="
  "@jspsych/plugin-html-button-response 2.1.0 sha512-AhJPePA8s/ount+QYtqfgMtEkz7g+j+bnhQ9XqxfsnK2f5MdnlakYtpjxW9YgFx9y0Gs7yb7OZk1+omcKlzaEQ=="
  "@jspsych/plugin-preload 2.1.0 sha512-tQUViQQNK5RXc+sYjNyV1NKl8gt9Wl+sZ55kpW1eEn9I84WCSBtjPDthr7WxGMZeK+E/ybYucWMVcIwlncaHAg=="
  "@jspsych/plugin-survey-html-form 2.1.0 sha512-jM9xSaojD7+xqL7yVjn7FUmboH3QAFBAaNOLBSUNJNQpGaJmGRtjrmlPggLp24Bnjd/jkjnThFj+z88Mgr67gQ=="
  "@jspsych/plugin-survey-multi-choice 2.2.1 sha512-InbDgMkvn/SO50dpEU605Qwj3vZARdVvfXWyNvFDUzIt4G76NgDWmVZWsFVqaqocosC4OyHkc8CID2MIBEcnCg=="
  "@jspsych/plugin-video-keyboard-response 2.2.0 sha512-1ckE3rjfUfqf4AVNFr6/v23NDvfyKuy2LKRTwi15VTR+zPbPcRnmYQ6VlHlL/2zdI3fBGPayst4Twb+LHYPCOg=="
)

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
into=$repo/third_party/jspsych
case "${1:-}" in
  "") ;;
  --into) [[ $# -eq 2 ]] || { echo "usage: scripts/fetch-jspsych.sh [--into DIR]" >&2; exit 1; }; into=$2 ;;
  -h|--help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "usage: scripts/fetch-jspsych.sh [--into DIR]" >&2; exit 1 ;;
esac
registry=${NPM_REGISTRY:-https://registry.npmjs.org}
registry=${registry%/}
licence=$repo/third_party/jspsych-LICENSE.txt

read -r _ jspsych_version _ <<<"${pins[0]}"
say() { echo "fetch-jspsych: $*"; }
fail() { echo "fetch-jspsych: $*" >&2; exit 1; }

# The stamp (PINS.txt, copied into every study's experiment/jspsych/) lists the pins the folder
# was filled from, and the licence notice's digest, so that a changed notice is copied again.
stamp_text() {
  echo "# npm package, version, SHA-512 integrity of its tarball (checked by signstim's scripts/fetch-jspsych.sh)"
  printf '%s\n' "${pins[@]}"
  echo "# LICENSE.txt sha512 $(sha512sum "$licence" | cut -d' ' -f1)"
}
complete() {  # the folder holds these pins, and their files are still there
  [[ -f $into/PINS.txt && -f $into/LICENSE.txt ]] && [[ $(cat "$into/PINS.txt") == "$(stamp_text)" ]] || return 1
  local pin name
  for pin in "${pins[@]}"; do
    read -r name _ <<<"$pin"
    [[ -f $into/${name#@jspsych/}/package.json && -f $into/${name#@jspsych/}/dist/index.browser.js ]] || return 1
  done
}
[[ -f $licence ]] || fail "$licence is missing (it is part of the repository)"
if complete; then
  say "jsPsych $jspsych_version and $(( ${#pins[@]} - 1 )) plugins present in ${into#"$repo"/}"
  exit 0
fi

for tool in curl tar gzip sha512sum base64 od; do
  command -v "$tool" >/dev/null 2>&1 || fail "$tool is missing (run scripts/setup.sh, which installs it)"
done

parent=$(dirname "$into")
mkdir -p "$parent"
work=$(mktemp -d "$parent/.jspsych.tmp-XXXXXX")
chmod 755 "$work"
trap 'rm -rf "$work"' EXIT

for pin in "${pins[@]}"; do
  read -r name version integrity <<<"$pin"
  short=${name#@jspsych/}                   # jspsych, plugin-preload, ...
  tarball="$registry/$name/-/$short-$version.tgz"
  file=$work/$short.tgz
  if ! curl -fsSL --retry 2 --connect-timeout 20 --max-time 300 -o "$file" "$tarball" 2>"$work/curl.log"; then
    fail "cannot download $tarball: $(tail -n 1 "$work/curl.log")"
  fi
  # integrity is "sha512-" + the base64 of the digest; compare it as hex with sha512sum's.
  expected=$(printf '%s' "${integrity#sha512-}" | base64 -d | od -An -v -tx1 | tr -d ' \n')
  actual=$(sha512sum "$file" | cut -d' ' -f1)
  [[ $actual == "$expected" ]] || fail "$name $version: the tarball's SHA-512 is not the pinned integrity ($tarball); nothing installed"
  mkdir -p "$work/$short"
  tar -xzf "$file" -C "$work/$short" --strip-components=1 --no-same-owner 2>"$work/tar.log" ||
    fail "$name $version: cannot unpack $tarball: $(tail -n 1 "$work/tar.log")"
  rm -f "$file"
  # The tarball must be the package it claims to be, under the licence we ship for it.
  grep -q "\"name\": *\"${name//\//\\/}\"" "$work/$short/package.json" &&
    grep -q "\"version\": *\"$version\"" "$work/$short/package.json" ||
    fail "$name $version: the tarball's package.json names another package or version"
  grep -q '"license": *"MIT"' "$work/$short/package.json" ||
    fail "$name $version: its package.json no longer says \"license\": \"MIT\"; check the licence before using it"
  [[ -f $work/$short/dist/index.browser.js ]] || fail "$name $version: no dist/index.browser.js in the tarball"
done

# npm tarballs of jsPsych carry no licence file; the notice kept in the repository goes beside them.
cp "$licence" "$work/LICENSE.txt"
stamp_text >"$work/PINS.txt"
rm -f "$work/curl.log" "$work/tar.log"

# Swap the new folder in; the old one (another set of pins) is removed after.
if [[ -e $into ]]; then
  old=$parent/.jspsych.old-$$
  mv "$into" "$old"
  mv "$work" "$into"
  rm -rf "$old"
else
  mv "$work" "$into"
fi
trap - EXIT
say "installed jsPsych $jspsych_version and $(( ${#pins[@]} - 1 )) plugins (SHA-512 checked) into ${into#"$repo"/}"
