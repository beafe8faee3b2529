#!/bin/sh
# `gonio catrib`: exit 0 on a good file, 1 on RIB errors, 2 on an unreadable file; and its
# output is RIB that catrib prints back unchanged.
set -u
gonio="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

printf 'FrameBegin 1\nWorldBegin\nSphere 1 -1 1 360 "Kd" .5\nWorldEnd\nFrameEnd\n' > "$dir/good.rib"
"$gonio" catrib "$dir/good.rib" > "$dir/once.rib" || fail "good file: exit $?"
"$gonio" catrib - < "$dir/once.rib" > "$dir/twice.rib" || fail "stdin: exit $?"
cmp -s "$dir/once.rib" "$dir/twice.rib" || fail "catrib output does not print back unchanged"

printf 'WorldBegin\nSphere 1 -1 1\nWorldEnd\n' > "$dir/bad.rib"
"$gonio" catrib "$dir/bad.rib" > /dev/null 2> "$dir/bad.err"
[ $? -eq 1 ] || fail "bad file: expected exit 1"
grep -q "bad.rib:2:1: error: Sphere expects 4 numbers, got 3" "$dir/bad.err" || fail "message"

"$gonio" catrib "$dir/missing.rib" > /dev/null 2>&1
[ $? -eq 2 ] || fail "missing file: expected exit 2"
echo "catrib exit codes ok"
