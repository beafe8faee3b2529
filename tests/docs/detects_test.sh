#!/bin/sh
# The tested-by check must fail on a reference to a test that does not exist and on a cell
# left "?": copies docs/rib-support.md, breaks the Sphere row's cell one way and then the
# other, and expects each reported at its line.
set -eu
checker=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/docs"
doc="$work/docs/rib-support.md"
cp "$root/docs/rib-support.md" "$doc"
python3 "$checker" "$doc" --root "$root" >/dev/null || { echo "the unchanged copy should pass"; exit 1; }
line=$(grep -n '^| Sphere ' "$doc" | cut -d: -f1)
sed -i "${line}s/| [^|]*|\$/| render_golden: no_such_scene.rib |/" "$doc"
if python3 "$checker" "$doc" --root "$root" >"$work/out.txt"; then
    echo "a dangling reference passed the check"; exit 1
fi
grep -q ":$line:.*no_such_scene.rib" "$work/out.txt" ||
    { echo "the dangling reference is not reported at line $line"; cat "$work/out.txt"; exit 1; }
sed -i "${line}s/| [^|]*|\$/| ? |/" "$doc"
if python3 "$checker" "$doc" --root "$root" >"$work/out.txt"; then
    echo "a '?' cell passed the check"; exit 1
fi
grep -q ":$line:" "$work/out.txt" || { echo "the '?' cell is not reported"; cat "$work/out.txt"; exit 1; }
echo "docs_tested_by.detects: a dangling reference and a '?' cell reported"
