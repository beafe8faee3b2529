#!/bin/sh
# scripts/photon_bins.py (the cell averages docs/gallery.md reads its grass claims from) on the
# Lambert plane: every cell of the BRDF must be 1/pi within 3.5 standard errors, and the errors
# must be small enough (< 7%) that a wrong factor of the normalisation could not pass.
#   cells_test.sh GONIO RIBS_DIR SCRIPTS_DIR
set -eu
gonio=$1 ribs=$2 scripts=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed -E 's/"integer rays" [0-9]+/"integer rays" 1000000/' "$ribs/lambert_plane.rib" |
    "$gonio" render - -o "$work/lambert.pm" 2> /dev/null
python3 "$scripts/photon_bins.py" "$work/lambert.pm" 45 70 > "$work/cells.txt"
cat "$work/cells.txt"
awk 'BEGIN { pi = atan2(0, -1); cells = 0; bad = 0 }
     $2 ~ /^[0-9]+-[0-9]+$/ {
         for (k = 3; k <= 5; ++k) {
             split($k, v, "±"); cells++
             if (v[2] > 0.07 * v[1] || (v[1] - 1 / pi) ^ 2 > (3.5 * v[2]) ^ 2) {
                 print "cell " $1 " " $2 " field " k ": " $k " is not 1/pi"; bad++
             }
         }
     }
     END { if (cells != 18 || bad) { print cells " cells, " bad " bad"; exit 1 } }' "$work/cells.txt"
echo "cells ok: 18 cells of the Lambert plane are 1/pi"
