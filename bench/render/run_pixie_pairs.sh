#!/usr/bin/env bash
# Issue 21's whole-render table: gonio on the 400- and 10k-sphere, mirror and shadow scenes
# (bench/render/make_scenes.py, spheres400.rib), best of 3 wall-clock seconds at 1 and 2 threads,
# beside gonio shading every sample (ShadingRate 0.0625) to show what the shading rate buys.
# With PIXIE=/path/to/Pixie (an install with bin/rndr and bin/sdrc), each scene is paired with
# Pixie's render of the same scene at its default ShadingRate 1 in the same run, and the ratio
# gonio / Pixie printed.
#
#   bench/render/run_pixie_pairs.sh [--threads "1 2"]      (GONIO=path/to/gonio, PIXIE=...)
set -euo pipefail
cd "$(dirname "$0")/../.."
gonio=$(realpath "${GONIO:-build/bin/gonio}")
threads="1 2"
[[ "${1:-}" == "--threads" ]] && threads=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/gonio" "$work/pixie"
python3 bench/render/make_scenes.py "$work/gonio"
python3 bench/render/make_scenes.py "$work/pixie" --renderer pixie
for dir in gonio pixie; do cp bench/render/spheres400.rib "$work/$dir/"; done
scenes="spheres400 spheres10k spheres10k_8x8 mirror shadows"
for scene in $scenes; do  # the same scene with every sample shaded
    sed 's/^WorldBegin/WorldBegin\n  ShadingRate 0.0625/' "$work/gonio/$scene.rib" \
        > "$work/gonio/${scene}_every_sample.rib"
done
if [[ -n "${PIXIE:-}" ]]; then
    (cd "$work/pixie" && "$PIXIE/bin/sdrc" mirror.sl > /dev/null)
fi

source bench/render/timing.sh
machine_line
printf '%-16s %7s %10s %14s %10s %8s\n' scene threads gonio every-sample pixie ratio
for scene in $scenes; do
    for t in $threads; do
        g=$(best_of 3 "$work/gonio" "$gonio" render "$scene.rib" --threads "$t")
        e=$(best_of 3 "$work/gonio" "$gonio" render "${scene}_every_sample.rib" --threads "$t")
        p=- ratio=-
        if [[ -n "${PIXIE:-}" ]]; then
            p=$(best_of 3 "$work/pixie" "$PIXIE/bin/rndr" "-t:$t" "$scene.rib")
            ratio=$(awk -v g="$g" -v p="$p" 'BEGIN { printf "%.2f", g / p }')
        fi
        printf '%-16s %7s %10s %14s %10s %8s\n' "$scene" "$t" "$g" "$e" "$p" "$ratio"
    done
done
