#!/usr/bin/env bash
# Paths per second per core of the path tracer (issue 17) on cornell_pathtrace.rib (128 × 128
# pixels × 16 paths, 270,400 with the pixel filter's margin: the camera rays --stats counts;
# one path each): process CPU time (user + system) of `gonio render` on 1
# and on 2 threads, best of 3, so that a shared machine's other jobs do not count; the empty
# 1 × 1 render's CPU time (start-up) is taken off first. With PIXIE=/path/to/Pixie (bin/rndr,
# bin/sdrc) the same room is rendered by Pixie's raytrace hider at the same samples
# (cornell_pixie.rib, cornell_gi.sl: one shadow ray and one indirect ray per camera hit; Pixie
# does not shade diffuse ray hits, so it does one bounce) in the same run, and gonio's CPU time
# over Pixie's printed.
#
#   bench/render/run_cornell_pathtrace.sh      (GONIO=path/to/gonio to time another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
gonio=$(realpath "${GONIO:-build/bin/gonio}")
scene=$(realpath bench/render/cornell_pathtrace.rib)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf 'Format 1 1 1\nDisplay "empty.tif" "tiff" "rgba"\nWorldBegin\nWorldEnd\n' > "$work/empty.rib"
paths=$(cd "$work" && "$gonio" render "$scene" --stats 2>&1 | sed -n 's/.* \([0-9]*\) camera rays.*/\1/p')

# cpu_best N COMMAND...: the least CPU time (user + system, s) of N runs.
cpu_best() {
    local runs=$1 best="" t
    shift
    for ((k = 0; k < runs; ++k)); do
        (cd "$work" && /usr/bin/time -o "$work/time" -f "%U %S" "$@" > /dev/null 2>&1)
        t=$(awk '{ printf "%.3f", $1 + $2 }' "$work/time")
        best=$(awk -v t="$t" -v best="$best" 'BEGIN { if (best == "" || t < best) best = t;
                                                      printf "%.3f", best }')
    done
    echo "$best"
}

source bench/render/timing.sh
machine_line
startup=$(cpu_best 3 "$gonio" render "$work/empty.rib")
echo "start-up (empty 1x1 render): $startup s CPU"
if [[ -n "${PIXIE:-}" ]]; then
    cp bench/render/cornell_pixie.rib bench/render/cornell_gi.sl "$work/"
    (cd "$work" && "$PIXIE/bin/sdrc" cornell_gi.sl > /dev/null)
fi
for threads in 1 2; do
    cpu=$(cpu_best 3 "$gonio" render "$scene" --threads "$threads")
    line="$threads thread(s): $cpu s CPU, $(awk -v p=$paths -v c="$cpu" -v s="$startup" \
        'BEGIN { printf "%.0f", p / (c - s) }') paths per CPU-second"
    if [[ -n "${PIXIE:-}" ]]; then
        pixie=$(cpu_best 3 "$PIXIE/bin/rndr" "-t:$threads" cornell_pixie.rib)
        line+="; Pixie raytrace hider $pixie s CPU, gonio / Pixie $(awk -v g="$cpu" -v p="$pixie" \
            'BEGIN { printf "%.2f", g / p }')"
    fi
    echo "$line"
done
