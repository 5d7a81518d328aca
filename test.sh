#!/usr/bin/env bash
# The whole test suite on a fresh Debian machine: installs what it needs, builds with
# -Werror, runs every test with ctest, then builds and runs it all again under ASan + UBSan, then
# the thread tests under ThreadSanitizer, then each fuzz harness for a short bounded time.
set -euo pipefail
cd "$(dirname "$0")"
scripts/deps.sh
jobs=$(nproc)

echo "== build (Release, -Werror)"
cmake -S . -B build/test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHFX_WERROR=ON >/dev/null
cmake --build build/test -j "$jobs"
echo "== tests"
ctest --test-dir build/test --output-on-failure -j "$jobs"

echo "== build (ASan + UBSan)"
cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=Debug -DHFX_WERROR=ON -DHFX_SANITIZE=ON >/dev/null
cmake --build build/asan -j "$jobs"
echo "== tests under ASan + UBSan"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0 \
  ctest --test-dir build/asan --output-on-failure -j "$jobs"

echo "== thread tests under ThreadSanitizer"
cmake -S . -B build/tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHFX_WERROR=ON -DHFX_TSAN=ON -DHFX_TOOLS=OFF >/dev/null
cmake --build build/tsan -j "$jobs" --target compiler_effect_test_build_threads compiler_glsl_test_spirv_threads runtime_test_threads
TSAN_OPTIONS="halt_on_error=1 suppressions=$PWD/tests/tsan.supp" \
  ctest --test-dir build/tsan --output-on-failure -R 'threads'

echo "== fuzz harnesses (clang, libFuzzer; ${HFX_FUZZ_SECONDS:-30} s each)"
scripts/fuzz.sh all "${HFX_FUZZ_SECONDS:-30}"
