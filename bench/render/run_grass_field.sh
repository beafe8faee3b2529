#!/usr/bin/env bash
# The whole-render target of issue 6: wall-clock time of the grass field (ribs/grass_field.rib:
# 640x480, 4x4 samples per pixel, one point light, every sample shaded through brdf() with the
# grass BRDF's baked table), best of 3. Target: 10 s on 2 cores. The grid is made first (the
# demo's BRDFLight and iopt steps), and is not timed.
#
#   bench/render/run_grass_field.sh         (GONIO=path/to/gonio to time another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
source bench/render/timing.sh
gonio=$(realpath "${GONIO:-build/bin/gonio}")
scene=$(realpath ribs/grass_field.rib)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && "$gonio" render "$(dirname "$scene")/grass.rib" -o grass.pm 2> /dev/null)
(cd "$work" && "$gonio" brdf iopt 8 24 0.5 0 grass.pm grass.grd --bake 16 > /dev/null 2>&1)

best=$(best_of 3 "$work" "$gonio" render "$scene")
machine_line
echo "grass_field.rib (640x480, 16 spp, brdf() baked), gonio render: $best s (best of 3)"
