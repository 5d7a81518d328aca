#!/usr/bin/env bash
# Issue 37's comparison: for FNA's stock effects, every ShaderIndex, what hfx's GLSL (compiled
# from the HLSL source) costs against what FNA runs today, MojoShader's GLSL translated from
# fxc's binary of the same source (FNA's .fxb). Instructions of the calling thread only
# (LP_NUM_THREADS=0: llvmpipe shades there), 20 frames per variant after two to warm up, each
# frame a clear, the side's Apply (hfx's; MojoShader's CommitChanges, ProgramReady and vertex
# attributes; hfx's attributes stay bound in the mesh's VAO, as an engine keeps them) and one
# draw of hfxview's sphere (SpriteEffect: the screen rectangle) into 128x128, XNA's default
# states; the two pictures compared (largest channel difference, /255). hfx's frames are drawn
# as FNA draws (XNA 4's Apply, no Begin / End, hfx_device_sync after the application's own GL
# state; MojoShader's side begins without saving state, as FNA3D does); BEGIN_END=1 wraps hfx's
# frames in hfx_effect_begin / end instead (D3DX's save and restore: see mojo_compare.c).
#
#   [CALLGRIND=1] [BEGIN_END=1] bench/mojo_instructions.sh BUILD [Effect ...]     (all six when none given)
#
# By default the kernel's counter of user-space instructions (perf_event_open, what `perf stat -e
# instructions:u` reads) brackets the frames: a few minutes for the 97 variants, counts within a
# few in 10^4 from run to run. CALLGRIND=1 runs under callgrind instead (bench/gpu_instructions.sh's
# exact counts, whatever else the machine runs; an hour or more: llvmpipe compiles every
# variant's shaders under valgrind).
#
# BUILD must have bench/mojo_compare (configure with -DMOJOSHADER_DIR: bench/mojo/README.md);
# the effects come from the FNA mirror ($HFX_MIRROR, default /work/.mirror: FNA-XNA+FNA/repo,
# nothing of it committed). KEEP_DUMPS=DIR keeps the callgrind dumps for callgrind_annotate.
set -euo pipefail
build=$(cd "${1:?usage: mojo_instructions.sh BUILD [Effect ...]}" && pwd); shift
compare=$build/bench/mojo_compare
[ -x "$compare" ] || { echo "no $compare: configure with -DMOJOSHADER_DIR=... (skipped)"; exit 0; }
command -v valgrind > /dev/null || { echo "no valgrind (skipped)"; exit 0; }
mirror=${HFX_MIRROR:-/work/.mirror}
fna="git --git-dir=$mirror/FNA-XNA+FNA/repo"
src=$(mktemp -d)
if [ -n "${KEEP_DUMPS:-}" ]; then out=$KEEP_DUMPS; mkdir -p "$out"; rm -f "$out"/*.cg* "$out"/*.txt
else out=$(mktemp -d); fi
trap 'rm -rf "$src"; [ -n "${KEEP_DUMPS:-}" ] || rm -rf "$out"' EXIT
for f in $($fna ls-tree -r --name-only HEAD | grep 'StockEffects/\(HLSL\|FXB\)/'); do
    $fna show "HEAD:$f" > "$src/$(basename "$f")"
done
effects=("$@")
frame=xna; [ -z "${BEGIN_END:-}" ] || frame=begin-end
# a mojo_compare from before --frame takes no such option: its frames are begin-end
usage=$("$compare" --frame xna 2>&1 || true)
[[ $usage == *"[--frame"* ]] || frame=
[ ${#effects[@]} -gt 0 ] || effects=(BasicEffect AlphaTestEffect DualTextureEffect EnvironmentMapEffect SkinnedEffect SpriteEffect)
# Variants (ShaderIndex values the C# classes use) and the values docs/stock-effects.md draws with.
args_of() {
    case $1 in
    BasicEffect) echo "--vary ShaderIndex=0..31 ; " ;;
    AlphaTestEffect) echo "--vary ShaderIndex=0..7 ;  --set AlphaTest=0.5,0.6,-1,1" ;;
    DualTextureEffect) echo "--vary ShaderIndex=0..3 ; " ;;
    EnvironmentMapEffect) echo "--vary ShaderIndex=0..15 ;  --set EnvironmentMapAmount=0.6" ;;
    SkinnedEffect) echo "--vary ShaderIndex=0..17 ; " ;;
    *) echo " ; " ;;
    esac
}
for fx in "${effects[@]}"; do
    a=$(args_of "$fx"); pre=${a%%;*}; post=${a#*;}
    if [ -n "${CALLGRIND:-}" ]; then
        # shellcheck disable=SC2086
        (cd "$src" && LP_NUM_THREADS=0 valgrind --tool=callgrind --separate-threads=yes --instr-atstart=no \
            --callgrind-out-file="$out/$fx.cg" "$compare" --bench 20 ${frame:+--frame $frame} $pre "$fx.fxb" "$fx.fx" $post > "$out/$fx.txt" 2>&1) || true
        # Each dump: "desc: Trigger: Client Request: LABEL", then "summary: N": as `count LABEL N`.
        for ((i = 1; ; i++)); do [ -e "$out/$fx.cg.$i-01" ] || break
            awk '/^desc: Trigger: Client Request: / { l = $0; sub(/^desc: Trigger: Client Request: /, "", l) }
                 /^summary:/ && l != "" { print "count " l " " $2; l = "" }' "$out/$fx.cg.$i-01" >> "$out/$fx.txt"
        done
    else
        # Twice, the first to fill Mesa's shader cache: on a cold cache some first variants counted
        # up to 10x more on hfx's side.
        for run in 1 2; do
            # shellcheck disable=SC2086
            (cd "$src" && LP_NUM_THREADS=0 "$compare" --bench 20 ${frame:+--frame $frame} $pre "$fx.fxb" "$fx.fx" $post > "$out/$fx.txt" 2>&1) || true
        done
    fi
done
printf '%-22s %-7s %14s %14s %7s %5s\n' effect variant hfx mojo ratio diff
# mojo_compare's lines: "alike|DIFFER max=M over=K effect.fx index technique variant" for the
# pictures, "count effect.fx|technique|variant|side N" for the counts.
for fx in "${effects[@]}"; do
    grep -q '^count ' "$out/$fx.txt" || { echo "$fx: no counts"; sed -n 1,5p "$out/$fx.txt"; continue; }
    awk -v fx="$fx" '
        $1 == "alike" || $1 == "DIFFER" { sub("max=", "", $2); diff[$NF] = $2; next }
        $1 == "count" { split($2, k, "|"); if (!(k[3] in seen)) { seen[k[3]] = 1; order[n++] = k[3] }
            v[k[3] "|" k[4]] = $3 }
        END { for (i = 0; i < n; i++) { x = order[i]; h = v[x "|hfx"]; m = v[x "|mojo"]; th += h; tm += m
                  r = m ? h / m : 0; if (r > 0.95) above++; if (r > 1.0) over++
                  printf "%-22s %-7s %14.0f %14.0f %6.4fx %5s\n", fx, x, h, m, r, diff[x] }
              printf "%-22s %-7s %14.0f %14.0f %6.4fx  (%d variants, %d above 0.95x, %d above 1.0x)\n",
                     fx, "all", th, tm, tm ? th / tm : 0, n, above, over }' "$out/$fx.txt"
done
