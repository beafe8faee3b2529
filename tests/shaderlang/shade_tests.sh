#!/bin/sh
# Value tests through `gonio shade` and `gonio shader`: each case runs a small shader and
# compares the printed values with the expected text. Usage: shade_tests.sh GONIO SHADERS_DIR
set -u
gonio="$1"
shaders="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0

# expect NAME EXPECTED_OUTPUT -- gonio arguments...
expect() {
    name="$1"; want="$2"; shift 3
    got=$("$gonio" "$@" 2>&1)
    if [ "$got" != "$want" ]; then
        printf 'FAIL %s\n  want: %s\n  got:  %s\n' "$name" "$want" "$got"
        failures=$((failures + 1))
    fi
}

cat > "$dir/grid.sl" <<'SL'
surface grid(float Kd = 0.5; color tint = 1;) { Ci = color(u, v, 0.5) * Kd * tint; }
SL
expect grid-default "Ci[0,0] = 0.25 0.5 0.5
Ci[1,0] = 0.75 0.5 0.5" -- shade "$dir/grid.sl" --res 2x1 -p Kd=1 --print Ci
expect grid-param "Kd = 0.25" -- shade "$dir/grid.sl" -p Kd=0.25 --print Kd
expect grid-colour-param "Ci[1,1] = 0.75 0 0.5" -- shade "$dir/grid.sl" --res 2x2 -p Kd=1 \
    -p tint=1,0,1 --print Ci --at 1,1
expect grid-bad-param "gonio shade: parameter 'Kd' (float) expects numbers, got 'x'" -- \
    shade "$dir/grid.sl" -p Kd=x

cat > "$dir/uv.sl" <<'SL'
surface uv() {
    float a = 7, b = 2;
    float q = a / b, r = a - b * floor(a / b);
    float m = max(a, b);
    Ci = color(q, r, m);
}
SL
expect arithmetic "Ci[0,0] = 3.5 1 7" -- shade "$dir/uv.sl" --print Ci

cat > "$dir/loops.sl" <<'SL'
surface loops() {
    float i, n = 0;
    for (i = 0; i < 8; i += 1) { if (i >= u * 4) break; n += 1; }
    Ci = n;
}
SL
expect divergent-loop "Ci[0,0] = 1 1 1
Ci[1,0] = 2 2 2
Ci[2,0] = 3 3 3
Ci[3,0] = 4 4 4" -- shade "$dir/loops.sl" --res 4x1 --print Ci

# matte Kd=0.5, Ka=0 under a distant light along the view axis: Ci = 0.5 (N.L = 1).
expect matte-distant "Ci[0,0] = 0.5 0.5 0.5" -- shade "$shaders/matte.sl" -p Ka=0 -p Kd=0.5 \
    --light "$shaders/distantlight.sl from=0,0,0 to=0,0,1" --print Ci

cat > "$dir/err.sl" <<SL
surface err() {
    Ci = "P";
}
SL
expect type-error "$dir/err.sl:2:10: error: in the assignment to 'Ci': cannot convert string to color" -- \
    shader "$dir/err.sl"
"$gonio" shader "$dir/err.sl" >/dev/null 2>&1
[ $? -eq 1 ] || { echo "FAIL shader exit status on errors"; failures=$((failures + 1)); }
"$gonio" shader "$dir/missing.sl" >/dev/null 2>&1
[ $? -eq 2 ] || { echo "FAIL shader exit status on a missing file"; failures=$((failures + 1)); }

cat > "$dir/warn.sl" <<'SL'
surface warn() {
    float z = 0;
    Ci = 1 / (u - u);
}
SL
expect div-zero-once "$dir/warn.sl:3: warning: division by zero (the result is 0)
Ci[0,0] = 0 0 0" -- shade "$dir/warn.sl" --res 1x1 --print Ci

expect describe "surface \"grid\"
    uniform float Kd = 0.5
    uniform color tint = [1 1 1]" -- shader "$dir/grid.sl"

if [ "$failures" -gt 0 ]; then
    echo "$failures shade test(s) failed"
    exit 1
fi
echo "all shade tests passed"
