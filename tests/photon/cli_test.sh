#!/bin/sh
# BRDFLight through the command line: bad input gives a clear error and no file, and the whole
# chain (render -> brdf iopt -> brdf eval) reconstructs the Lambert plane's 1/pi.
# Usage: cli_test.sh GONIO RIBS_DIR
set -u
GONIO=$1
RIBS=$2
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
failures=0

fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}

# expect_error NAME PATTERN RIB...: the render must fail, say PATTERN, and leave no output.
expect_error() {
    name=$1
    pattern=$2
    shift 2
    printf '%s\n' "$@" > "$name.rib"
    if "$GONIO" render "$name.rib" > out.txt 2>&1; then
        fail "$name: render succeeded"
    fi
    grep -q -- "$pattern" out.txt || fail "$name: expected '$pattern' in: $(cat out.txt)"
    if ls | grep -q '\.pm'; then fail "$name: left a file: $(ls)"; fi
}

PLANE='WorldBegin
Surface "matte"
Polygon "P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0]
WorldEnd'

expect_error empty "no geometry" \
    'Option "BRDFLight" "string texturename" "empty.pm" "integer rays" 1000' \
    'WorldBegin' 'WorldEnd'
expect_error unwritable "cannot write the photon map" \
    'Option "BRDFLight" "string texturename" "no/such/dir/x.pm" "integer rays" 1000' "$PLANE"
expect_error norays "positive number of photon paths" \
    'Option "BRDFLight" "string texturename" "norays.pm" "integer rays" 0' "$PLANE"
expect_error noarea "positive side length" \
    'Option "BRDFLight" "string texturename" "noarea.pm" "float area" -0.1' "$PLANE"
expect_error angles "thetamin" \
    'Option "BRDFLight" "string texturename" "angles.pm" "float thetamin" 60 "float thetamax" 30' \
    "$PLANE"

# Leaf optics: bad parameters are located errors and no map.
LEAF_PLANE() {
    printf 'WorldBegin\nAttribute "brdflight" "string model" "leaf" %s\nPolygon "P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0]\nWorldEnd\n' "$1"
}
expect_error leafmodel 'leafmodel.rib:3:[0-9]*: error: Attribute "brdflight" "model": expected "phong" or "leaf"' \
    'Option "BRDFLight" "string texturename" "leafmodel.pm" "integer rays" 1000' \
    "$(LEAF_PLANE '' | sed 's/"leaf"/"leaves"/')"
expect_error leafeta 'leafeta.rib:3:[0-9]*: error: Attribute "brdflight" "eta": expected a refractive index' \
    'Option "BRDFLight" "string texturename" "leafeta.pm" "integer rays" 1000' \
    "$(LEAF_PLANE '"float eta" 0.5')"
expect_error leafenergy 'error: Attribute "brdflight" "transmittance": expected reflectance and transmittance' \
    'Option "BRDFLight" "string texturename" "leafenergy.pm" "integer rays" 1000' \
    "$(LEAF_PLANE '"color reflectance" [0.5 0.5 0.5] "color transmittance" [0.2 0.6 0.2]')"
expect_error leafcolours 'error: Attribute "brdflight" "reflectance": expected 1 or 3 values' \
    'Option "BRDFLight" "string texturename" "leafcolours.pm" "integer rays" 1000' \
    "$(LEAF_PLANE '"float reflectance" [0.1 0.2]')"

# Bounce tags: a leaf sheet over a matte ground, tagged; merge --bounces keeps the photons
# scattered once (the sheet's reflection), and every traced path still counts.
{
    echo 'Option "BRDFLight" "string texturename" "tagged.pm" "integer rays" 20000 "integer bounces" 1'
    LEAF_PLANE '"float transmittance" 0.4' | sed 's/^WorldEnd$//'
    echo 'Attribute "brdflight" "string model" "phong"'
    echo 'Surface "matte"'
    echo 'Polygon "P" [-9 -9 -0.5 9 -9 -0.5 9 9 -0.5 -9 9 -0.5]'
    echo 'WorldEnd'
} > tagged.rib
"$GONIO" render tagged.rib > tagged.txt 2>&1 || fail "tagged render: $(cat tagged.txt)"
head -1 tagged.pm | grep -q '^[0-9]* 20000 bounces$' || fail "tagged header: $(head -1 tagged.pm)"
awk 'NR > 1 && ($9 < 1 || $9 != int($9)) { bad = 1 } END { exit bad }' tagged.pm ||
    fail "tagged rows: a bounce count that is not a positive integer"
awk 'NR > 1 && $9 >= 2 { n++ } END { exit n > 0 ? 0 : 1 }' tagged.pm ||
    fail "tagged rows: no photon came back through the sheet from the ground"
"$GONIO" brdf merge tagged.pm --bounces 1 -o once.pm > merge.txt 2>&1 || fail "merge --bounces: $(cat merge.txt)"
once=$(awk 'NR > 1 && $9 == 1 { n++ } END { print n }' tagged.pm)
[ "$(head -1 once.pm)" = "$once 20000 bounces" ] || fail "merge --bounces header: $(head -1 once.pm), expected $once photons"
"$GONIO" brdf merge tagged.pm --bounces 2:x -o bad.pm > bad.txt 2>&1 && fail "merge --bounces 2:x succeeded"
grep -q 'expected N or N:M' bad.txt || fail "merge --bounces 2:x: $(cat bad.txt)"

# The chain on the committed Lambert plane (100,000 photons, isotropic).
"$GONIO" render "$RIBS/lambert_plane.rib" > render.txt 2>&1 || fail "render: $(cat render.txt)"
grep -q "100000 photons escaped up" render.txt || fail "summary: $(cat render.txt)"
[ -f lambert_plane.pm ] || fail "no photon map written"
ls | grep -q '\.tmp\.' && fail "temporary file left behind"
"$GONIO" brdf iopt 8 24 0.5 0 lambert_plane.pm lambert.grd > iopt.txt 2>&1 ||
    fail "iopt: $(cat iopt.txt)"
for angles in "0 0 0 0" "30 0 45 90" "45 0 45 180" "60 0 30 0" "20 0 70 270"; do
    # shellcheck disable=SC2086
    value=$("$GONIO" brdf eval lambert.grd $angles 2>&1 | awk '{print $NF}' | tail -1)
    ok=$(awk -v v="$value" 'BEGIN { print (v > 0.3183 * 0.95 && v < 0.3183 * 1.05) ? 1 : 0 }')
    [ "$ok" = 1 ] || fail "brdf eval $angles = '$value', expected 1/pi within 5%"
done

# More photon paths than the machine's memory holds: a located error, exit 1, no map.
sed 's/"integer rays" [0-9]*/"integer rays" 2000000000000/' "$RIBS/lambert_plane.rib" > huge.rib
"$GONIO" render huge.rib -o huge.pm > huge.txt 2>&1
code=$?
[ "$code" -eq 1 ] || fail "huge ray count: exit $code, expected 1: $(cat huge.txt)"
grep -q 'huge.rib:3:[0-9]*: error: BRDFLight: 2000000000000 photon paths need' huge.txt ||
    fail "huge ray count: $(cat huge.txt)"
[ ! -e huge.pm ] || fail "huge ray count: a map was written"

if [ "$failures" -gt 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "all BRDFLight command-line checks passed"
