#!/usr/bin/env bash
# Total `gonio render` time of the 45 conformance scenes (../shared/conformance, issue 3's
# target: less than Aqsis's 9.6 s): the wall-clock sum of the per-scene times its `run` script
# prints (each counts only the render process, not the image comparison), and the CPU time of
# the renders, and the time the renders spend past process start-up (the sum of the frame times
# `gonio render --stats` prints: scene building, rendering and writing the image; the rest of
# each process is mostly loading OpenImageIO's shared libraries). Skipped when the suite is
# absent.
#
#   bench/render/run_conformance_time.sh    (GONIO=path/to/gonio to time another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
gonio=$(realpath "${GONIO:-build/bin/gonio}")
suite=../shared/conformance/run
if [[ ! -x "$suite" ]]; then
    echo "conformance suite not found at $suite: skipped"
    exit 0
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# /usr/bin/time adds each render's CPU time (user + system) to cpu.txt: on a shared machine the
# wall-clock total counts other people's work too.
"$suite" --render "sh -c \"exec /usr/bin/time -f '%U %S' -a -o $out/cpu.txt \
    $gonio render --stats {rib} 2>> $out/stats.txt\"" \
    --out "$out/run" | tee "$out/log" | tail -1
awk '$2 ~ /^rc=/ { t += $3; n += 1 } END { printf "%d scenes, total wall time %.2f s\n", n, t }' \
    "$out/log"
awk '{ cpu += $1 + $2 } END { printf "total CPU time (user + system) %.2f s\n", cpu }' \
    "$out/cpu.txt"
awk '/^frame [0-9]+:/ { sub(/ s,$/, "", $4); t += $4; n += 1 }
     END { printf "%d frames, total frame time (past start-up) %.2f s\n", n, t }' "$out/stats.txt"
