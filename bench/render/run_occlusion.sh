#!/usr/bin/env bash
# The cost of occlusion() (issue 17): wall-clock and CPU time of `gonio render occlusion.rib`
# (an ambient-occlusion light over a plane and 25 spheres, 320x240, 2x2 samples) at 64 and at
# 256 occlusion samples, and with no occlusion light (the rest of the frame), best of 3.
#
#   bench/render/run_occlusion.sh          (GONIO=path/to/gonio to time another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
gonio=$(realpath "${GONIO:-build/bin/gonio}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# best_of N RIB: the shortest wall-clock and user+system CPU seconds of N renders.
best_of() {
    local runs=$1 rib=$2 best="" cpu="" start end times
    for ((k = 0; k < runs; ++k)); do
        start=$(date +%s.%N)
        times=$( { /usr/bin/time -f "%U %S" "$gonio" render "$rib" --stats > /dev/null; } 2>&1 |
                 tail -1)
        end=$(date +%s.%N)
        read -r best cpu < <(awk -v a="$start" -v b="$end" -v best="$best" -v cpu="$cpu" \
            -v t="$times" 'BEGIN { split(t, u, " "); d = b - a; c = u[1] + u[2];
                                   if (best == "" || d < best) { best = d; cpu = c }
                                   printf "%.2f %.2f\n", best, cpu }')
    done
    echo "$best s wall, $cpu s CPU"
}

echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for samples in 64 256; do
    sed "s/GONIO_SAMPLES/$samples/" bench/render/occlusion.rib > "$work/occlusion_$samples.rib"
    echo "occlusion.rib, $samples samples: $(cd "$work" && best_of 3 "occlusion_$samples.rib")"
done
grep -v occlusionlight bench/render/occlusion.rib > "$work/none.rib"
echo "occlusion.rib, no occlusion light: $(cd "$work" && best_of 3 none.rib)"
