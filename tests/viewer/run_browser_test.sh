#!/bin/sh
# Runs browser.test.mjs from a work folder in the build tree: npm ci installs playwright-core
# there from package-lock.json (from npm's cache when it has it), never a browser; Debian's
# chromium is the browser. Usage: run_browser_test.sh SOURCE_DIR GONIO IMAGE WORK_DIR.
# Exit 77 (ctest: skipped) when node, npm or chromium is not installed (scripts/install-deps), or
# Node.js is older than 20.
set -eu
src=$1 gonio=$2 image=$3 work=$4
for tool in node npm /usr/bin/chromium; do
    command -v "$tool" >/dev/null 2>&1 || { echo "viewer.browser: $tool is not installed" >&2; exit 77; }
done
# playwright-core 1.65 needs Node.js 20 (Debian 12's own nodejs is 18).
node_major=$(node -p 'process.versions.node.split(".")[0]')
[ "$node_major" -ge 20 ] || { echo "viewer.browser: Node.js $node_major, playwright-core needs 20" >&2; exit 77; }
mkdir -p "$work/artefacts"
cp "$src/package.json" "$src/package-lock.json" "$src/browser.test.mjs" "$work/"
cd "$work"
npm ci --prefer-offline --no-audit --no-fund
GONIO=$gonio GONIO_IMAGE=$image ARTEFACTS=$work/artefacts node --test browser.test.mjs
echo "screenshots: $work/artefacts"
