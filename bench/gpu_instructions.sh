#!/usr/bin/env bash
# bench_gpu under callgrind: instructions per frame (llvmpipe in the calling thread) for hfx with
# preshaders, without them, and hand-written GLSL, and the ratios to hand-written. Exact counts,
# whatever else the machine runs, where frame times on a shared machine are not; a proxy for
# GPU time (same driver, same pipeline, only the shaders and hfx's Apply differ).
# usage: [KEEP_DUMPS=DIR] bench/gpu_instructions.sh BUILD_DIR [effect.fx ...]   (all seed effects when none given)
# Only the main thread counts: with LP_NUM_THREADS=0 llvmpipe rasterises and shades in the calling
# thread, and the other threads (Mesa's disk shader cache compressing with zstd) run at times
# that differ from side to side, which added 2-3 M instructions to some frames. With
# --separate-threads=yes a client-request dump writes the calling thread's file only (NAME.N-01).
set -euo pipefail
build=$1; shift
# KEEP_DUMPS=DIR keeps the dumps there, for callgrind_annotate (which JIT'ed function costs what).
if [ -n "${KEEP_DUMPS:-}" ]; then out=$KEEP_DUMPS; mkdir -p "$out"; rm -f "$out"/*.cg*
else out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; fi
effects=("$@")
[ ${#effects[@]} -gt 0 ] || effects=(ambient.fx ambient_textured.fx directional.fx directional_specular.fx point.fx
    point_specular.fx spot.fx spot_specular.fx tutorial0.fx fxcomposer_empty.fx phong.fx pointlights.fx)
for fx in "${effects[@]}"; do
    LP_NUM_THREADS=0 valgrind --tool=callgrind --separate-threads=yes --instr-atstart=no --callgrind-out-file="$out/$fx.cg" \
        "$build/bench/bench_gpu" 1 "$fx" >/dev/null 2>&1
done
# The main thread's dumps, effect by effect in the order given, each in the order it was written.
dumps=()
for fx in "${effects[@]}"; do
    for ((i = 1; ; i++)); do [ -e "$out/$fx.cg.$i-01" ] || break; dumps+=("$out/$fx.cg.$i-01"); done
done
printf '%-24s %-16s %-7s %14s %14s %14s %7s %7s\n' effect technique case hfx hfx-nopre hand ratio nopre
# Each dump: "desc: Trigger: Client Request: effect|technique|case|side", then "summary: N".
awk '/^desc: Trigger: Client Request: / { label = $0; sub(/^desc: Trigger: Client Request: /, "", label) }
     /^summary:/ && label != "" { split(label, k, "|"); key = k[1] "|" k[2] "|" k[3];
        if (!(key in seen)) { seen[key] = 1; order[n++] = key }
        v[key "|" k[4]] = $2; label = "" }
     END { for (i = 0; i < n; i++) { split(order[i], k, "|"); key = order[i];
        printf "%-24s %-16s %-7s %14.0f %14.0f %14.0f %6.3fx %6.3fx\n", k[1], k[2], k[3], v[key "|hfx"],
               v[key "|nopre"], v[key "|hand"], v[key "|hfx"] / v[key "|hand"], v[key "|nopre"] / v[key "|hand"] } }' \
    "${dumps[@]}"
