# Shell functions shared by scripts/gallery-plots and scripts/grass-convergence (sourced, not
# run). The caller sets gonio (the executable), work (a scratch folder) and scale (a factor on
# every photon count, 1 for none).

# trace MODEL RAYS [NAME [SEED]]: BRDFLight on ribs/MODEL.rib with RAYS paths (times $scale)
# and the given seed (default 0) -> $work/NAME.pm (NAME defaults to MODEL).
trace() {
    local rays
    rays=$(awk -v r="$2" -v s="$scale" 'BEGIN { printf "%d", r * s }')
    sed -E "s/\"integer rays\" [0-9]+/\"integer rays\" $rays/" "ribs/$1.rib" |
        "$gonio" render - -o "$work/${3:-$1}.pm" --seed "${4:-0}" 2>&1 | grep '^BRDFLight' >&2
}

# grid iopt|opt NAME RADIUS IN.pm: a splat grid of about one radius per cell -> $work/NAME.grd
grid() {
    local rings
    rings=$(awk -v r="$3" 'BEGIN { n = int(3.14159265 / 2 / r + 0.5); print (n < 1 ? 1 : n) }')
    "$gonio" brdf "$1" "$rings" $((4 * rings)) "$3" 0 "$4" "$work/$2.grd" 2> /dev/null |
        sed 's/^/  /' >&2
}
