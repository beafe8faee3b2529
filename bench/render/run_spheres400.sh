#!/usr/bin/env bash
# The whole-render target of issue 3: wall-clock time of `gonio render spheres400.rib` (400
# plastic spheres, 640x480, 4x4 samples, gaussian 2 2), best of 3, beside gonio's process
# start-up (`gonio --help`, and the render of an empty 1x1 frame), which every render pays.
#
#   bench/render/run_spheres400.sh          (GONIO=path/to/gonio to time another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
gonio=$(realpath "${GONIO:-build/bin/gonio}")
scene=$(realpath bench/render/spheres400.rib)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf 'Format 1 1 1\nDisplay "empty.tif" "tiff" "rgba"\nWorldBegin\nWorldEnd\n' > "$work/empty.rib"

source bench/render/timing.sh
machine_line
echo "start-up, gonio --help:              $(best_of 3 "$work" "$gonio" --help) s (best of 3)"
echo "start-up + write, empty 1x1 render:  $(best_of 3 "$work" "$gonio" render "$work/empty.rib") s"
echo "spheres400.rib, gonio render:        $(best_of 3 "$work" "$gonio" render "$scene") s"
echo "spheres400.rib, --threads 1:         $(best_of 3 "$work" "$gonio" render "$scene" --threads 1) s"
