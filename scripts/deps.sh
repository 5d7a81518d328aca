#!/usr/bin/env bash
# Installs the Debian packages hfx builds and tests with (as root, or through sudo).
# Quiet when everything is already there.
set -euo pipefail
pkgs=(build-essential cmake ninja-build pkg-config re2c bison glslang-dev glslang-tools libosmesa6-dev
      libgl-dev libegl-dev libgl1-mesa-dri libegl-mesa0 zlib1g-dev libpng-dev libcjson-dev libstb-dev libglfw3-dev libdevil-dev xvfb xauth valgrind spirv-tools
      mesa-vulkan-drivers libvulkan-dev vulkan-validationlayers # the Vulkan back end's tests: lavapipe, validation on
      clang-14 libclang-rt-14-dev clang-tools-14 # clang: the fuzz harnesses (libFuzzer), their sanitizer runtimes; clang-query (float_casts)
      emscripten chromium) # the web page (web/): WebAssembly build, and its tests in headless Chromium
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "hfx: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO=sudo
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
