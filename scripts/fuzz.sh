#!/usr/bin/env bash
# Runs one libFuzzer harness of fuzz/ for a bounded time:  scripts/fuzz.sh NAME SECONDS [libFuzzer flags...]
#   NAME: compile, pp, hfxo, hfxo_repair, runtime, runtime_vk, diff, d3d9, fx2, or `all` (each in turn,
#   SECONDS each). runtime_vk needs a Vulkan device (lavapipe) and is left out of `all` without one.
# Builds build/fuzz with clang (-DHFX_FUZZ=ON: ASan + UBSan + coverage), generates the seed corpus
# from fx/, ../shared/seed-fx (when present) and the semantics tables of tests/runtime/semantics
# (compiled to .hfxo for the .hfxo harnesses), and grows build/fuzz/corpus/NAME across runs.
# Exits nonzero on any finding (crash, leak, timeout, broken promise); the input is left in
# build/fuzz/findings/. Reproduce one with: build/fuzz/fuzz/fuzz_NAME build/fuzz/findings/FILE
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: scripts/fuzz.sh NAME|all SECONDS [libFuzzer flags...]" >&2; exit 2; }
name=$1 seconds=$2
shift 2
extra=("$@")
all=(compile pp hfxo hfxo_repair runtime runtime_vk diff d3d9 fx2)
out=build/fuzz
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

build() {
  cmake -S . -B $out -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHFX_FUZZ=ON -DHFX_TESTS=OFF -DHFX_TOOLS=OFF \
    -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DHFX_WERROR=ON >/dev/null
  cmake --build $out -j "${HFX_FUZZ_JOBS:-2}" > $out/build.log 2>&1 || { cat $out/build.log; exit 1; }
}

# One effect per row of the semantics tables: the row's globals and body in a pixel shader.
semantics_effects() {
  local dir=$1
  awk -v dir="$dir" '
    /^#/ || /^==/ || !NF { next }
    { line = $0; sub(/ => .*/, "", line); globals = ""
      if (index(line, " ;; ")) { globals = substr(line, 1, index(line, " ;; ") - 1); line = substr(line, index(line, " ;; ") + 4) }
      body = (line ~ /^[ \t]*\{/) ? line : "{ R = " line "; }"
      f = sprintf("%s/sem%04d.fx", dir, NR)
      print "float4 A; float4 B; int4 I; float4x4 M; bool T1, F1; half2 H; int N1;" > f
      print "texture T2; sampler S2 = sampler_state { Texture = <T2>; MinFilter = Point; };" > f
      print globals > f
      print "float4 PS() : COLOR0 { float4 R = 0; " body " return R; }" > f
      print "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, M); }" > f
      print "technique T { pass P { CullMode = None; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }" > f
      close(f) }' tests/runtime/semantics/*.tbl
}

fx_seeds() {
  local dir=$1
  mkdir -p "$dir"
  cp fx/*.fx "$dir"/
  if [ -d ../shared/seed-fx ]; then
    for f in ../shared/seed-fx/*.fx; do cp "$f" "$dir/seed_$(basename "$f")"; done
  fi
  semantics_effects "$dir"
}

# The same effects compiled to .hfxo (GLSL 330 + ES 300 by default; $2: hfxc's --target, e.g.
# spirv-vk for the Vulkan runtime, whose seeds leave out the ~500 semantics rows: SPIR-V takes
# glslang longer and the Vulkan harness runs a few inputs a second), once per run of this script.
hfxo_seeds() {
  local dir=$1 target=${2:-} tmp=$out/seeds/fx-for-hfxo made=$out/seeds/hfxo-made${2:+-$2}
  if [ ! -d "$made" ]; then
    rm -rf "$tmp" && fx_seeds "$tmp" && mkdir -p "$made"
    for f in "$tmp"/*.fx; do
      [ -n "$target" ] && [[ $(basename "$f") == sem[0-9]* ]] && continue
      ASAN_OPTIONS=detect_leaks=0 $out/compiler/hfxc --no-self-check ${target:+--target "$target"} \
        -o "$made/$(basename "$f" .fx).hfxo" "$f" >/dev/null 2>&1 || true
    done
  fi
  mkdir -p "$dir" && cp "$made"/*.hfxo "$dir"/
}

# D3D9 shader blobs for the bytecode reader, hand-assembled as in tests/compiler/d3d9 (ps_2_0 with
# dcl / def / texld / _sat_pp, vs_3_0 with rep / if_lt / break / relative addressing, ps_1_1 with
# coissue and the old source modifiers).
d3d9_seeds() {
  local dir=$1
  mkdir -p "$dir"
  printf '%b' '\x00\x02\xff\xff\x1f\x00\x00\x02\x00\x00\x00\x80\x00\x00\x03\xb0\x1f\x00\x00\x02\x00\x00\x00\x90\x00\x08\x0f\xa0\x51\x00\x00\x05\x01\x00\x0f\xa0\x00\x00\x80\x3f\x00\x00\x00\x3f\x00\x00\x00\x80\xac\xc5\x27\x37\x42\x00\x00\x03\x00\x00\x0f\x80\x00\x00\xe4\xb0\x00\x08\xe4\xa0\x05\x00\x00\x03\x00\x00\x37\x80\x00\x00\xe4\x80\x00\x00\x00\xa0\x01\x00\x00\x02\x00\x08\x0f\x80\x00\x00\xe4\x80\xff\xff\x00\x00' > "$dir/ps20.pso"
  printf '%b' '\x00\x03\xfe\xff\x51\x00\x00\x05\x04\x00\x0f\xa0\x00\x00\x80\x3f\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x1f\x00\x00\x02\x00\x00\x00\x80\x00\x00\x0f\x90\x1f\x00\x00\x02\x00\x00\x00\x80\x00\x00\x0f\xe0\x14\x00\x00\x03\x00\x00\x0f\xe0\x00\x00\xe4\x90\x00\x00\xe4\xa0\x26\x00\x00\x01\x00\x00\xe4\xf0\x02\x00\x00\x03\x00\x00\x0f\x80\x00\x00\xe4\x80\x04\x00\x00\xa0\x29\x00\x04\x02\x00\x00\x00\x80\x04\x00\x55\xa0\x2c\x00\x00\x00\x2b\x00\x00\x00\x27\x00\x00\x00\x2e\x00\x00\x02\x00\x00\x01\xb0\x00\x00\x00\x90\x01\x00\x00\x03\x01\x00\x0f\x80\x07\x20\xe4\xa0\x00\x00\x00\xb0\xff\xff\x00\x00' > "$dir/vs30.vso"
  printf '%b' '\x01\x01\xff\xff\x42\x00\x00\x00\x00\x00\x0f\xb0\x05\x00\x00\x00\x00\x00\x07\x81\x00\x00\xe4\xb4\x00\x00\xe4\x96\x01\x00\x00\x40\x00\x00\x18\x80\x00\x00\xff\xb2\xff\xff\x00\x00' > "$dir/ps11.pso"
}

run_one() {
  local n=$1 seeds=$out/seeds/$1 corpus=$out/corpus/$1
  if [ "$n" = runtime_vk ] && [ ! -x $out/fuzz/fuzz_runtime_vk ]; then
    echo "== fuzz runtime_vk: not built (no Vulkan headers or loader); skipped"
    return 0
  fi
  rm -rf "$seeds" && mkdir -p "$corpus" $out/findings
  case $n in
    hfxo|hfxo_repair|runtime) hfxo_seeds "$seeds" ;;
    runtime_vk) hfxo_seeds "$seeds" spirv-vk ;;
    compile|pp|diff) fx_seeds "$seeds" ;;
    d3d9) d3d9_seeds "$seeds" ;;
    fx2) mkdir -p "$seeds" && $out/fuzz/fx2_seed "$seeds" ;;
    *) echo "fuzz.sh: unknown harness $n (${all[*]})" >&2; exit 2 ;;
  esac
  echo "== fuzz $n for ${seconds}s ($(ls "$seeds" | wc -l) seeds, $(ls "$corpus" | wc -l) in the corpus)"
  $out/fuzz/fuzz_$n -max_total_time="$seconds" -timeout=60 -rss_limit_mb=4096 -max_len=65536 \
    -dict=fuzz/hfx.dict -print_final_stats=1 -artifact_prefix=$out/findings/$n- ${extra[@]+"${extra[@]}"} "$corpus" "$seeds"
}

build
rm -rf $out/seeds/hfxo-made*
if [ "$name" = all ]; then
  for n in "${all[@]}"; do run_one "$n"; done
else
  run_one "$name"
fi
