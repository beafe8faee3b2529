#!/usr/bin/env bash
# The start-up target of issue 21: the median wall-clock time of cheap gonio commands, which is
# nearly all process start-up (target ≤ 10 ms): `catrib` on a 2-line RIB, `shader` on
# plastic.sl, `brdf --help`, and renders of an empty 1x1 frame written as TIFF, PNG and OpenEXR.
# With hyperfine (apt-get install hyperfine) the median of 30 runs after 3 warm-ups, else of 30
# runs timed with date.
#
#   bench/render/run_startup.sh          (GONIO=path/to/gonio to time another build)
set -euo pipefail
cd "$(dirname "$0")/../.."
gonio=$(realpath "${GONIO:-build/bin/gonio}")
shader=$(realpath shaders/plastic.sl)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf 'Format 1 1 1\nWorldBegin\n' > "$work/two.rib"
for format in tif png exr; do
    printf 'Format 1 1 1\nDisplay "empty.%s" "file" "rgba"\nWorldBegin\nWorldEnd\n' "$format" \
        > "$work/empty_$format.rib"
done

# median COMMAND...: the median wall-clock time of 30 runs in milliseconds (with hyperfine also
# the mean CPU time, user + system, which a loaded machine inflates less).
median() {
    if command -v hyperfine > /dev/null; then
        (cd "$work" && hyperfine -N -w 3 -r 30 --export-json "$work/h.json" "$*" > /dev/null 2>&1)
        python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))["results"][0]
print("%.1f ms (CPU %.1f ms)" % (1000 * r["median"], 1000 * (r["user"] + r["system"])))' \
            "$work/h.json"
        return
    fi
    local times=() start end
    for ((k = 0; k < 30; ++k)); do
        start=$(date +%s%N)
        (cd "$work" && "$@" > /dev/null 2>&1)
        end=$(date +%s%N)
        times+=($(((end - start) / 1000)))
    done
    printf '%s\n' "${times[@]}" | sort -n |
        awk '{ t[NR] = $1 } END { printf "%.1f ms\n", t[int((NR + 1) / 2)] / 1000 }'
}

source bench/render/timing.sh
machine_line
echo "gonio: $gonio ($(ldd "$gonio" | wc -l) shared libraries)"
echo "catrib, 2-line RIB:        $(median "$gonio" catrib "$work/two.rib")"
echo "shader plastic.sl:         $(median "$gonio" shader "$shader")"
echo "brdf --help:               $(median "$gonio" brdf --help)"
for format in tif png exr; do
    echo "render empty 1x1, .$format:   $(median "$gonio" render "$work/empty_$format.rib")"
done
