#!/usr/bin/env bash
# The main job on a fresh Debian machine: installs what it needs, builds hfx, and renders the
# gallery (the project's fx/ and the seed corpus in ../shared/seed-fx) to out/*.png, headless,
# and the web page into out/web/ (open out/web/index.html in a browser).
set -euo pipefail
cd "$(dirname "$0")"
scripts/deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release -j "$(nproc)"
scripts/gallery.sh build/release out
scripts/web.sh build/release/wasm out/web
