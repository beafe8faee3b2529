#!/usr/bin/env bash
# Issue 21's per-sample cost, free of the machine's load: the instructions `gonio render` executes
# (valgrind --tool=callgrind, one thread) on the spheres400, spheres10k, mirror and shadows
# scenes made small (Format 320 240 for spheres400, 320 180 for the others; their samples,
# filter and shading rate unchanged). With BASE=path/to/another/gonio, each scene is counted for
# both builds and the ratio printed: how a change is judged before a wall-clock pairing.
#
#   bench/render/run_instructions.sh      (GONIO=path/to/gonio, BASE=path/to/gonio)
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! command -v valgrind > /dev/null; then
    echo "run_instructions.sh: valgrind is not installed (apt-get install valgrind); skipped" >&2
    exit 0
fi
gonio=$(realpath "${GONIO:-build/bin/gonio}")
base=${BASE:+$(realpath "$BASE")}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 bench/render/make_scenes.py "$work" > /dev/null
cp bench/render/spheres400.rib "$work/"
for scene in spheres10k mirror shadows; do
    sed -i 's/^Format .*/Format 320 180 1/' "$work/$scene.rib"
done
sed -i 's/^Format .*/Format 320 240 1/' "$work/spheres400.rib"

# instructions GONIO SCENE: what callgrind collected over the whole run.
instructions() {
    (cd "$work" && valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" render \
        "$2.rib" --threads 1 2>&1 > /dev/null) | awk '/Collected :/ { print $NF }'
}

printf '%-12s %16s %16s %7s\n' scene gonio base ratio
for scene in spheres400 spheres10k mirror shadows; do
    g=$(instructions "$gonio" "$scene")
    b=- ratio=-
    if [[ -n "$base" ]]; then
        b=$(instructions "$base" "$scene")
        ratio=$(awk -v g="$g" -v b="$b" 'BEGIN { printf "%.3f", g / b }')
    fi
    printf '%-12s %16s %16s %7s\n' "$scene" "$g" "$b" "$ratio"
done
