#!/bin/sh
# gonio spectral end to end: info of a named spectrum (D65's CIE 15 white point), the patch
# table's rows, analyze on a scene's own spectra, and bad input (an unknown name, a malformed
# file, a scene without Option "spectral") as a located error, exit 1; match (residual, the written
# cspec file's xy, an unreachable RGB as exit 1).
set -u
gonio=$1
ribs=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

out=$("$gonio" spectral info D65) || fail "info D65 exited $?"
echo "$out" | grep -q '^  xy        0.3127[0-9] 0.3290[0-9]$' || fail "D65 xy: $out"

out=$("$gonio" spectral patches --lights F11) || fail "patches exited $?"
for row in rgb bands-16 "svd-6 exact-direct" "eq. 6.9"; do
    echo "$out" | grep -q "^F11 .*$row" || fail "no $row row: $out"
done

"$gonio" spectral info NOSUCHLIGHT >"$work/out" 2>&1
[ $? -eq 1 ] || fail "an unknown name should exit 1"
grep -q 'NOSUCHLIGHT' "$work/out" || fail "the error should name it: $(cat "$work/out")"

printf '# a light\ncspec 400 700 100\n1\n2\nx\n' >"$work/bad.spd"
"$gonio" spectral info "$work/bad.spd" >"$work/out" 2>&1
[ $? -eq 1 ] || fail "a malformed file should exit 1"
grep -q "bad.spd:5: error: " "$work/out" || fail "not located at line 5: $(cat "$work/out")"
out=$("$gonio" spectral analyze "$ribs/tcs_f11.rib") || fail "analyze exited $?"
echo "$out" | grep -q '1 light(s), 8 surface colour(s)' || fail "analyze's scene: $out"
for row in rgb "bands-[0-9]" "svd-[0-9]* exact-direct" "svd-[0-9]* eq. 6.9"; do
    echo "$out" | grep -q "^distantlight 1 *$row" || fail "analyze: no $row row: $out"
done
printf 'WorldBegin\nLightSource "distantlight" 1\nSphere 1 -1 1 360\nWorldEnd\n' >"$work/rgb.rib"
"$gonio" spectral analyze "$work/rgb.rib" >"$work/out" 2>&1
[ $? -eq 1 ] || fail "analyze of an RGB scene should exit 1"
grep -q 'needs Option "spectral"' "$work/out" || fail "analyze should say why: $(cat "$work/out")"
out=$("$gonio" spectral match D65 --rgb 1 0.8 0.6 -o "$work/matched.spd") || fail "match exited $?"
echo "$out" | grep -q '^  newton steps     [0-9]*$' || fail "match: no Newton steps: $out"
residual=$(echo "$out" | sed -n 's/^  rgb residual     \([^ ]*\).*/\1/p')
awk -v r="$residual" 'BEGIN { exit !(r + 0 <= 1e-9) }' || fail "match: RGB residual $residual"
echo "$out" | grep -q '^  relative change  [0-9.]*%' || fail "match: no relative change: $out"
grep -q '^cspec 380 780 5$' "$work/matched.spd" || fail "match -o: not a cspec file"
xy=$(echo "$out" | sed -n 's/^  xy               \([0-9.]* [0-9.]*\) .*/\1/p')
"$gonio" spectral info "$work/matched.spd" | grep -q "^  xy        $xy$" ||
    fail "the written light's xy should be the printed $xy"
"$gonio" spectral match D65 --rgb -1 0.5 0.5 >"$work/out" 2>&1
[ $? -eq 1 ] || fail "an unreachable RGB should exit 1"
grep -q 'no non-negative light has this RGB' "$work/out" || fail "match should say why: $(cat "$work/out")"
echo "spectral.cli: ok"
