#!/usr/bin/env bash
# The main job on a fresh Debian machine: installs what it needs, builds hfx, and renders the
# gallery (the project's fx/ and the seed corpus in ../shared/seed-fx) to out/*.png, headless.
set -euo pipefail
cd "$(dirname "$0")"
scripts/deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release -j "$(nproc)"
exec scripts/gallery.sh build/release out
