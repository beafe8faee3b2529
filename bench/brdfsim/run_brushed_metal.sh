#!/usr/bin/env bash
# Lookups on the thesis's brushed-metal case itself (Table 4.1: 300,000 photons, R = 0.5,
# anisotropic): BRDFLight renders ribs/brushed_metal.rib into a photon map, then brdfsim_bench
# times BrdfSimple, the splat grid and the baked table on it (BM_LookupBrushedMetal/0, 1, 2).
#
#   bench/brdfsim/run_brushed_metal.sh [benchmark options]    (BUILD=dir to time another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "${BUILD:-build}")
for tool in gonio brdfsim_bench; do
    [ -x "$build/bin/$tool" ] || { echo "run_brushed_metal: no $build/bin/$tool" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bin/gonio" render ribs/brushed_metal.rib -o "$work/brushed_metal.pm"
GONIO_BRUSHED_METAL_PM="$work/brushed_metal.pm" "$build/bin/brdfsim_bench" \
    --benchmark_filter=LookupBrushedMetal "$@"
