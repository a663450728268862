#!/bin/sh
# SYNTHETIC stand-ins for a lab's human-video recordings (docs/study.md, "Human-video
# versions"): ffmpeg's procedural test pattern (testsrc2), hue-shifted per clip — no person in
# them. They let a study with "humanVersions" run before the lab has recorded anything; replace
# them with the real recordings (a replaced recording renders its unit again).
#
#   scripts/synthetic-human-clips.sh FOLDER STORIES [SENTENCES [SECONDS]]
#
# writes FOLDER/story-01.mp4 ... story-NN.mp4 and, when SENTENCES > 0, likert-01.mp4 ...; e.g.
#   scripts/synthetic-human-clips.sh scenes/studies/examples/human 10
#   build/signstim study scenes/studies/examples/human-baseline.json --quick --out human-baseline
set -eu
if [ $# -lt 2 ]; then
    echo "usage: $0 FOLDER STORIES [SENTENCES [SECONDS]]" >&2
    exit 1
fi
folder=$1 stories=$2 sentences=${3:-0} seconds=${4:-8}
command -v ffmpeg >/dev/null || { echo "$0: needs ffmpeg (apt install ffmpeg)" >&2; exit 3; }
mkdir -p "$folder"
clip() {  # clip NAME HUE
    ffmpeg -v error -nostdin -y -f lavfi -i "testsrc2=size=640x480:rate=25:duration=$seconds,hue=h=$2" \
        -c:v libx264 -pix_fmt yuv420p -threads 1 "$folder/$1.mp4"
}
i=1
while [ "$i" -le "$stories" ]; do
    clip "$(printf 'story-%02d' "$i")" $((i * 37))
    i=$((i + 1))
done
i=1
while [ "$i" -le "$sentences" ]; do
    clip "$(printf 'likert-%02d' "$i")" $((i * 53))
    i=$((i + 1))
done
printf 'SYNTHETIC test patterns (ffmpeg testsrc2), not recordings of a person: written by %s.\n' "$0" \
    >"$folder/SYNTHETIC-CLIPS.txt"
echo "$folder: $stories story clip(s) and $sentences sentence clip(s), SYNTHETIC test patterns"
