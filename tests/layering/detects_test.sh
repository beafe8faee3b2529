#!/bin/sh
# The layering check must fail on a forbidden include: copies the tree's library folders, adds
# an include of the renderer's scene to the shading language (which may depend on base/ only),
# one of Embree to the scene builder and one of a private shading-language header to the
# renderer's shading, and expects all three reported at their file and line.
set -eu
checker=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for folder in base renderer shaderlang brdfsim spectral cli; do
    [ -d "$root/$folder" ] && cp -r "$root/$folder" "$work/$folder"
done
python3 "$checker" --root "$work" >/dev/null || { echo "the unchanged copy should pass"; exit 1; }
echo '#include "renderer/scene/frame.h"' >>"$work/shaderlang/types.h"
echo '#include <embree3/rtcore.h>' >>"$work/renderer/scene/frame.h"
echo '#include "shaderlang/runtime/program.h"' >>"$work/renderer/shading/shader_needs.h"
lines_needs=$(wc -l <"$work/renderer/shading/shader_needs.h")
lines_sl=$(wc -l <"$work/shaderlang/types.h")
lines_scene=$(wc -l <"$work/renderer/scene/frame.h")
if python3 "$checker" --root "$work" >"$work/out.txt"; then
    echo "a forbidden include passed the check"; exit 1
fi
grep -q "^shaderlang/types.h:$lines_sl: error: shaderlang/ includes \"renderer/scene/frame.h\"" "$work/out.txt" ||
    { echo "not reported at shaderlang/types.h:$lines_sl:"; cat "$work/out.txt"; exit 1; }
grep -q "^renderer/scene/frame.h:$lines_scene: error: renderer/scene/ includes <embree3/rtcore.h>" "$work/out.txt" ||
    { echo "not reported at renderer/scene/frame.h:$lines_scene:"; cat "$work/out.txt"; exit 1; }
grep -q "^renderer/shading/shader_needs.h:$lines_needs: error: .*private to shaderlang/" "$work/out.txt" ||
    { echo "not reported at renderer/shading/shader_needs.h:$lines_needs:"; cat "$work/out.txt"; exit 1; }
echo "layering.detects: all three forbidden includes reported"
