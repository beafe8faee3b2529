#!/usr/bin/env bash
# The cost of the colour representations (issue 15): `gonio render` of spheres400.rib (400
# plastic spheres, 640x480, 16 spp) with Option "spectral" "basis" rgb, bands (16), svd (6
# vectors per light spectrum) and sampled (81) prepended, one thread, the four timed
# alternately, best of 3 each, and each against rgb as a ratio. Bands and svd are chosen from
# the scene's own spectra: its lights are white and its RGB colours uplifted, so this measures
# the cost of k components, not the colour error (that is `ctest -R spectral_render` and
# `gonio spectral analyze`).
#
#   bench/render/run_spectral_bases.sh      (GONIO=path/to/gonio to time another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
gonio=$(realpath "${GONIO:-build/bin/gonio}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A option=([rgb]='"rgb"' [bands]='"bands" "int bands" [16]'
                   [svd]='"svd" "int vectors" [6]' [sampled]='"sampled"')
bases="rgb bands svd sampled"
for basis in $bases; do
    { echo "Option \"spectral\" \"string basis\" ${option[$basis]}"
      cat bench/render/spheres400.rib; } > "$work/$basis.rib"
done
source bench/render/timing.sh
machine_line
declare -A best
for ((k = 0; k < 3; ++k)); do
    for basis in $bases; do
        start=$(date +%s.%N)
        (cd "$work" && "$gonio" render "$basis.rib" --threads 1 -o "$basis.exr" 2> /dev/null)
        end=$(date +%s.%N)
        best[$basis]=$(awk -v a="$start" -v b="$end" -v best="${best[$basis]:-}" \
            'BEGIN { d = b - a; if (best == "" || d < best) best = d; printf "%.3f", best }')
    done
done
for basis in $bases; do
    awk -v b="$basis" -v t="${best[$basis]}" -v r="${best[rgb]}" \
        'BEGIN { printf "spheres400, basis %-8s %7.3f s (best of 3), %.2fx rgb\n", b, t, t / r }'
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
