#!/bin/sh
# gonio spectral end to end: info of a named spectrum (D65's CIE 15 white point), the patch
# table's rows, analyze on a scene's own spectra, and bad input (an unknown name, a malformed
# file, a scene without Option "spectral") as a located error, exit 1; renders with bands;
# diff; match (residual, the written cspec file's xy, an unreachable RGB as exit 1).
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
for row in rgb "bands-[0-9]" "svd-[0-9]* exact-direct" "svd-[0-9]* rendered" "svd-[0-9]* eq. 6.9"; do
    echo "$out" | grep -q "^distantlight 1 *$row" || fail "analyze: no $row row: $out"
done
printf 'WorldBegin\nLightSource "distantlight" 1\nSphere 1 -1 1 360\nWorldEnd\n' >"$work/rgb.rib"
"$gonio" spectral analyze "$work/rgb.rib" >"$work/out" 2>&1
[ $? -eq 1 ] || fail "analyze of an RGB scene should exit 1"
grep -q 'needs Option "spectral"' "$work/out" || fail "analyze should say why: $(cat "$work/out")"
# Bands in a render: the scene is read twice, so a file renders and standard input is refused;
# a band is no wavelength, so Display "spectral" is refused.
sed 's/"string basis" "sampled"/"string basis" "bands" "int bands" [12]/; /"spectral"$/d' \
    "$ribs/tcs_f11.rib" >"$work/bands.rib"
(cd "$work" && "$gonio" render bands.rib -o bands.png) || fail "render with bands exited $?"
[ -s "$work/bands.png" ] || fail "render with bands wrote no image"
"$gonio" render - <"$work/bands.rib" >"$work/out" 2>&1
[ $? -eq 1 ] || fail "bands from standard input should exit 1"
grep -q 'standard input only once' "$work/out" || fail "stdin and bands: $(cat "$work/out")"
sed 's/"string basis" "sampled"/"string basis" "bands"/' "$ribs/tcs_f11.rib" >"$work/bands_exr.rib"
(cd "$work" && "$gonio" render bands_exr.rib) >"$work/out" 2>&1
[ $? -ne 0 ] || fail "Display spectral under bands should fail"
grep -q 'bands_exr.rib:7:1: error: .*"spectral" needs' "$work/out" || fail "$(cat "$work/out")"
# diff: a render against itself is 0 everywhere; the rgb render of TCS under F11 is not; the map
# is written; a size mismatch and an 8-bit file are errors.
sed 's/"string basis" "sampled"/"string basis" "rgb"/; /"spectral"$/d' "$ribs/tcs_f11.rib" \
    >"$work/rgb_tcs.rib"
sed '/"spectral"$/d' "$ribs/tcs_f11.rib" >"$work/sampled_tcs.rib"
(cd "$work" && "$gonio" render rgb_tcs.rib -o rgb.exr && "$gonio" render sampled_tcs.rib \
    -o sampled.exr) 2>/dev/null || fail "renders for diff"
out=$("$gonio" spectral diff "$work/sampled.exr" "$work/sampled.exr" --light F11) ||
    fail "diff exited $?"
echo "$out" | grep -q 'mean 0.000, 99th percentile 0.000, max 0.000' || fail "self-diff: $out"
out=$("$gonio" spectral diff "$work/sampled.exr" "$work/rgb.exr" --light F11 -o "$work/map.png") ||
    fail "diff exited $?"
mean=$(echo "$out" | sed 's/.*mean \([0-9.]*\),.*/\1/')
awk -v m="$mean" 'BEGIN { exit !(m > 1) }' || fail "rgb against sampled should differ: $out"
[ -s "$work/map.png" ] || fail "no map written"
# svd in a render: 9 vectors hold the 8 patches' products with F11 and F11 itself, so the
# direct light is exact; 3 vectors are not.
for k in 9 3; do
    sed "s/\"string basis\" \"sampled\"/\"string basis\" \"svd\" \"int vectors\" [$k]/; /\"spectral\"$/d" \
        "$ribs/tcs_f11.rib" >"$work/svd$k.rib"
    (cd "$work" && "$gonio" render "svd$k.rib" -o "svd$k.exr") || fail "render with svd $k exited $?"
    out=$("$gonio" spectral diff "$work/sampled.exr" "$work/svd$k.exr" --light F11) ||
        fail "diff of svd $k exited $?"
    max=$(echo "$out" | sed 's/.*max \([0-9.]*\).*/\1/')
    awk -v m="$max" -v k="$k" 'BEGIN { exit !(k == 9 ? m < 0.01 : m > 0.1) }' ||
        fail "svd-$k against sampled: $out"
done
"$gonio" spectral diff "$work/sampled.exr" "$work/bands.png" >"$work/out" 2>&1
[ $? -eq 1 ] || fail "diff of an 8-bit file should exit 1"
grep -q 'bands.png: ' "$work/out" || fail "diff should name the file: $(cat "$work/out")"
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
# --like: a metamer of F11 made from D65 has F11's chromaticity.
"$gonio" spectral match D65 --like F11 --brightness as-given -o "$work/metamer.spd" >/dev/null ||
    fail "match --like exited $?"
f11=$("$gonio" spectral info F11 | grep '^  xy ')
[ "$("$gonio" spectral info "$work/metamer.spd" | grep '^  xy ')" = "$f11" ] ||
    fail "the metamer's xy should be F11's $f11"
echo "spectral.cli: ok"
