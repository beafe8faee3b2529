#!/usr/bin/env bash
# End-to-end check of `gonio brdf ...`: each tool runs, the numbers make sense, bad input gives
# exit status 1 (data) or 2 (usage, I/O) and leaves no output file behind.
set -euo pipefail
gonio="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
expect_status() {  # expect_status CODE command...
    local want=$1; shift
    set +e; "$@" > out.txt 2> err.txt; local got=$?; set -e
    [ "$got" -eq "$want" ] || fail "$* exited $got, expected $want: $(cat err.txt)"
}

"$gonio" brdf synth lambert:0.5 -n 200000 --isotropic --stratified --seed 3 -o a.pm > /dev/null
"$gonio" brdf synth lambert:0.5 -n 200000 --isotropic --stratified --seed 3 -o b.pm > /dev/null
cmp -s a.pm b.pm || fail "synth is not deterministic"
"$gonio" brdf synth lambert:0.5 -n 1000 --isotropic --seed 4 -o c.pm > /dev/null
"$gonio" brdf merge a.pm c.pm -o m.pm > /dev/null
[ "$(head -1 m.pm)" = "201000" ] || fail "merge header: $(head -1 m.pm)"

"$gonio" brdf iopt 4 12 0.5 0 a.pm a.grd --bake 16 > /dev/null 2>&1
value=$("$gonio" brdf eval a.grd 40 0 60 120 --grid)
awk -v v="${value%% *}" 'BEGIN { exit !(v > 0.156 && v < 0.162) }' ||
    fail "Lambert 0.5 should give 0.159, got $value"
baked=$("$gonio" brdf eval a.grd 40 0 60 120)
awk -v v="${baked%% *}" 'BEGIN { exit !(v > 0.156 && v < 0.162) }' || fail "baked gave $baked"
"$gonio" brdf info a.grd | grep -q "splats per cell average" || fail "info on a .grd"
"$gonio" brdf info a.pm | grep -q "isotropic" || fail "info on a .pm"
"$gonio" brdf section 19 a.grd --theta-in 30,60 --analytic lambert:0.5 --plot s.svg > s.txt 2> /dev/null
[ "$(grep -vc '^#' s.txt)" -eq 19 ] || fail "section table rows"
grep -q "<svg" s.svg && grep -q "polyline" s.svg || fail "section plot"
"$gonio" brdf section 19 a.grd --theta-in 30 --vary phi-out --relative --plot s.png \
    --plot-size 640 360 --title "png" --label "grid" > /dev/null 2>&1
oiiotool --info s.png | grep -q "640 x  *360" || fail "section png: $(oiiotool --info s.png)"
expect_status 2 "$gonio" brdf section 5 a.grd --plot s.nosuchformat
[ ! -e s.nosuchformat ] || fail "a plot of an unknown format was left behind"
expect_status 2 "$gonio" brdf section 5 a.grd --plot t.png --plot-size 10 10
expect_status 2 "$gonio" brdf section 5 a.grd --label a --label b
"$gonio" brdf sectslow 0.5 0 5 c.pm --vary phi-out > /dev/null
"$gonio" brdf map 64 3 0.5 45 0 a.grd map.png --colormap viridis --scale-bar > /dev/null
[ -s map.png ] || fail "map image"

printf '2\n0.5 0 0.7 3.1 0.1 1 1\n0.5 0 0.7 3.1 0.1 1\n' > bad.pm
expect_status 1 "$gonio" brdf iopt 4 12 0.5 0 bad.pm bad.grd
[ ! -e bad.grd ] || fail "a .grd was left behind"
grep -q "bad.pm:3:" err.txt || fail "no line number: $(cat err.txt)"
head -c 100 a.grd > truncated.grd
expect_status 1 "$gonio" brdf eval truncated.grd 10 0 10 0
grep -q "truncated" err.txt || fail "truncated .grd message: $(cat err.txt)"
expect_status 2 "$gonio" brdf eval missing.grd 10 0 10 0
expect_status 2 "$gonio" brdf opt 4 12 0.5 0 missing.pm x.grd
expect_status 2 "$gonio" brdf opt 4 12 0.5 0 a.pm
expect_status 2 "$gonio" brdf synth blinn:3 -n 10 -o x.pm
expect_status 2 "$gonio" brdf iopt 4 12 0.5 0 a.pm x.grd --norm l3
[ ! -e x.pm ] && [ ! -e x.grd ] || fail "output left behind after a usage error"
echo "brdf cli ok"
