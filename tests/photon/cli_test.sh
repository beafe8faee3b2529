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
