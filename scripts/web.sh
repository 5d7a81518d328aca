#!/usr/bin/env bash
# Builds the web page (web/) into SITE: hfx's compiler and runtime as WebAssembly (emscripten,
# from the same sources: cmake/wasm.cmake, web/CMakeLists.txt), the editor bundle (npm
# packages pinned by web/package-lock.json, installed with npm ci), and the built-in effect
# list from fx/ and ../shared/seed-fx.  Usage: scripts/web.sh BUILD_DIR SITE
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/wasm}
site=${2:-out/web}
# Debian's emscripten finds its node modules (acorn) where Debian puts them, whichever node runs it.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}

if [ ! -f web/node_modules/.package-lock.json ] || [ web/package-lock.json -nt web/node_modules/.package-lock.json ]; then
  (cd web && npm ci --no-audit --no-fund --loglevel=error)
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  emcmake cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHFX_WERROR=ON -DHFX_TESTS=OFF -DHFX_TOOLS=OFF >/dev/null
fi
cmake --build "$build" -j "$(nproc)" --target hfx_web

mkdir -p "$site"
web/node_modules/.bin/esbuild web/editor.js --bundle --minify --format=iife --log-level=warning \
  --outfile="$site/editor.bundle.js"
cp web/index.html web/style.css web/app.js web/params.js "$build/web/hfx_web.js" "$site/"
node web/effects_list.js "$site/effects.js" seed=../shared/seed-fx fx=fx
echo "web page: $site/index.html"
