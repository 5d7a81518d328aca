#!/usr/bin/env bash
# bench_gpu under callgrind: instructions per frame (llvmpipe in the calling thread) for hfx with
# preshaders, without them, and hand-written GLSL, and the ratios to hand-written. Exact counts,
# whatever else the machine runs, where frame times on a shared machine are not; a proxy for
# GPU time (same driver, same pipeline, only the shaders and hfx's Apply differ).
# usage: bench/gpu_instructions.sh BUILD_DIR [effect.fx ...]   (all seed effects when none given)
set -euo pipefail
build=$1; shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
effects=("$@")
[ ${#effects[@]} -gt 0 ] || effects=(ambient.fx ambient_textured.fx directional.fx directional_specular.fx point.fx
    point_specular.fx spot.fx spot_specular.fx tutorial0.fx fxcomposer_empty.fx phong.fx pointlights.fx)
for fx in "${effects[@]}"; do
    LP_NUM_THREADS=0 valgrind --tool=callgrind --callgrind-out-file="$out/$fx.cg" \
        "$build/bench/bench_gpu" 1 "$fx" >/dev/null 2>&1
done
printf '%-24s %-16s %-7s %14s %14s %14s %7s %7s\n' effect technique case hfx hfx-nopre hand ratio nopre
# Each dump: "desc: Trigger: Client Request: effect|technique|case|side", then "summary: N".
awk '/^desc: Trigger: Client Request:/ { split($0, a, ": "); label = a[3] }
     /^summary:/ && label != "" { split(label, k, "|"); key = k[1] "|" k[2] "|" k[3];
        if (!(key in seen)) { seen[key] = 1; order[n++] = key }
        v[key "|" k[4]] = $2; label = "" }
     END { for (i = 0; i < n; i++) { split(order[i], k, "|"); key = order[i];
        printf "%-24s %-16s %-7s %14d %14d %14d %6.3fx %6.3fx\n", k[1], k[2], k[3], v[key "|hfx"],
               v[key "|nopre"], v[key "|hand"], v[key "|hfx"] / v[key "|hand"], v[key "|nopre"] / v[key "|hand"] } }' \
    $(ls "$out"/*.cg.* | sort -t. -k3,3n -k4,4n)
