#!/usr/bin/env bash
# The corpus through FNA's loader: every root effect (scripts/corpus.sh roots) compiled by hfxc
# (.hfxo, as `corpus.sh run` counts it), compiled to fx_2_0 (/T fx_2_0, every pass's D3D9
# bytecode), parsed and compiled by MojoShader (its effect framework and GLSL), and every
# technique drawn by MojoShader from hfx's bytecode against hfx from the source
# (bench/mojo/mojo_compare: hfxview's scene, 128x128, alike within 2/255 in every pixel).
#
#   scripts/mojo_corpus.sh DIR [BUILD]
#
# BUILD (default build/test) must have been configured with -DMOJOSHADER_DIR (MojoShader built
# outside the repository, bench/mojo/README.md); without mojo_compare the script says so and
# exits 0. Prints one line per effect (hfx fx2 mojo alike/techniques effect; mojo: ok, FAIL
# when MojoShader refuses the effect, CRASH when it crashes reading it), the techniques that
# differ or fail, the first errors of the fx_2_0 failures, and the counts. Outputs (logs,
# the pictures of each difference) stay in a temporary folder whose path is printed.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:?usage: mojo_corpus.sh CORPUS_DIR [BUILD]}
build=$(cd "${2:-$here/build/test}" && pwd)
hfxc=$build/compiler/hfxc
compare=$build/bench/mojo_compare
[ -x "$hfxc" ] || { echo "no hfxc in $build (build first)" >&2; exit 2; }
[ -x "$compare" ] || { echo "no mojo_compare in $build: configure with -DMOJOSHADER_DIR=... (skipped)"; exit 0; }
out=$(mktemp -d /tmp/hfx-mojo-XXXXXX)
mkdir -p "$out/log" "$out/fxo" "$out/png"

# Include folders: every folder above the effect inside its repository (as corpus.sh).
include_dirs() {
    local d; d=$(dirname "$1")
    while [ "$d" != . ] && [ "${d#*/}" != "$d" ]; do d=$(dirname "$d"); printf -- "-I\n%s\n" "$d"; done
}

# One effect: "hfx fx2 mojo alike/techniques effect"; its technique lines in log/NAME.cmp.
one() {
    local fx=$1 out=$2 hfxc=$3 compare=$4 name h=FAIL f=- m=- a=0 n=0
    name=$(echo "$fx" | tr '/' '_')
    local -a inc; mapfile -t inc < <(include_dirs "$fx")
    "$hfxc" --quiet "${inc[@]}" -o "$out/fxo/$name.hfxo" "$fx" > "$out/log/$name.hfx" 2>&1 && h=ok
    if [ $h = ok ]; then
        f=FAIL
        "$hfxc" /T fx_2_0 "${inc[@]}" /Fo "$out/fxo/$name.fxo" "$fx" > "$out/log/$name.fx2" 2>&1 && f=ok
    fi
    if [ $f = ok ]; then
        mkdir -p "$out/png/$name"
        "$compare" --out "$out/png/$name" "$out/fxo/$name.fxo" "$fx" --size 128x128 "${inc[@]}" \
            > "$out/log/$name.cmp" 2>&1
        case $? in 0|1) m=ok ;; 3) m=FAIL ;; 4) m=hfx? ;; *) m=CRASH ;; esac
        a=$(grep -c '^alike' "$out/log/$name.cmp"); n=$(grep -c '^\(alike\|DIFFER\|FAIL\)' "$out/log/$name.cmp")
        rmdir "$out/png/$name" 2>/dev/null
    fi
    printf "%-4s %-4s %-4s %3s/%-3s %s\n" $h $f $m "$a" "$n" "$fx"
}
export -f one include_dirs

printf "%-4s %-4s %-4s %7s %s\n" hfx fx2 mojo alike effect
(cd "$dir" && "$here/scripts/corpus.sh" roots |
    xargs -d '\n' -P "$(nproc)" -I{} bash -c 'one "$@"' _ {} "$out" "$hfxc" "$compare") | sort -k5 | tee "$out/table.txt"
echo
echo "techniques that differ or fail:"
cat "$out"/log/*.cmp 2>/dev/null | grep '^\(DIFFER\|FAIL\|MOJO-FAIL\)' | sort -k4 | tee "$out/differ.txt"
echo
echo "MojoShader crashed loading (the effect's line CRASH):"
awk '$3 == "CRASH" { print "  " $5 }' "$out/table.txt"
echo
echo "first errors of the fx_2_0 failures (by message, most frequent first):"
cat "$out"/log/*.fx2 2>/dev/null | grep -o "error X[0-9]*: .*" | sed "s/'[^']*'/'_'/g; s/[0-9][0-9]*/N/g" |
    sort | uniq -c | sort -rn | head -20
t=$out/table.txt
skipped=$(cat "$out"/log/*.cmp 2>/dev/null | grep -c '^SKIP')
echo
echo "outputs in $out"
echo "$skipped techniques not compared: a pass without a vertex shader (FNA draws it with the one bound before)"
awk '{ e++; if ($1 == "ok") h++; if ($2 == "ok") f++; if ($3 == "ok") m++;
       if ($3 == "ok") { split($4, x, "/"); a += x[1]; n += x[2]; if (x[1] == x[2]) all++ } }
     END { printf "%d effects: %d compile (hfx), %d to fx_2_0, %d parsed by MojoShader (%d with every technique alike); techniques drawn alike: %d/%d\n",
           e, h, f, m, all, a, n }' "$t"
