#!/usr/bin/env bash
# Runs one libFuzzer harness of fuzz/ for a bounded time:  scripts/fuzz.sh NAME SECONDS [libFuzzer flags...]
#   NAME: compile, pp, hfxo, hfxo_repair, runtime, diff, fx2, or `all` (each in turn, SECONDS each).
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
all=(compile pp hfxo hfxo_repair runtime diff fx2)
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

# The same effects compiled to .hfxo (GLSL 330 + ES 300), once per run of this script.
hfxo_seeds() {
  local dir=$1 tmp=$out/seeds/fx-for-hfxo made=$out/seeds/hfxo-made
  if [ ! -d "$made" ]; then
    rm -rf "$tmp" && fx_seeds "$tmp" && mkdir -p "$made"
    for f in "$tmp"/*.fx; do
      ASAN_OPTIONS=detect_leaks=0 $out/compiler/hfxc --no-self-check -o "$made/$(basename "$f" .fx).hfxo" "$f" >/dev/null 2>&1 || true
    done
  fi
  mkdir -p "$dir" && cp "$made"/*.hfxo "$dir"/
}

run_one() {
  local n=$1 seeds=$out/seeds/$1 corpus=$out/corpus/$1
  rm -rf "$seeds" && mkdir -p "$corpus" $out/findings
  case $n in
    hfxo|hfxo_repair|runtime) hfxo_seeds "$seeds" ;;
    compile|pp|diff) fx_seeds "$seeds" ;;
    fx2) mkdir -p "$seeds" && $out/fuzz/fx2_seed "$seeds" ;;
    *) echo "fuzz.sh: unknown harness $n (${all[*]})" >&2; exit 2 ;;
  esac
  echo "== fuzz $n for ${seconds}s ($(ls "$seeds" | wc -l) seeds, $(ls "$corpus" | wc -l) in the corpus)"
  $out/fuzz/fuzz_$n -max_total_time="$seconds" -timeout=60 -rss_limit_mb=4096 -max_len=65536 \
    -dict=fuzz/hfx.dict -print_final_stats=1 -artifact_prefix=$out/findings/$n- ${extra[@]+"${extra[@]}"} "$corpus" "$seeds"
}

build
rm -rf $out/seeds/hfxo-made
if [ "$name" = all ]; then
  for n in "${all[@]}"; do run_one "$n"; done
else
  run_one "$name"
fi
