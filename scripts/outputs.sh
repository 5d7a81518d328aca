#!/usr/bin/env bash
# What hfxc prints for a set of effects, kept as files so that two builds can be compared byte
# for byte (a refactor must not change them): for every effect, the GLSL of every pass for GLSL
# 330, GLSL ES 300 and GLSL 110 (--emit-glsl), the --reflect JSON and the --annotations JSON,
# and hfxc's messages. The seeds (../shared/seed-fx), fx/ and, when given, a corpus folder.
#
#   scripts/outputs.sh BUILD OUT [CORPUS]     write OUT/<effect>/...
#   diff -r OUT_BEFORE OUT_AFTER              the comparison
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd); out=$2; corpus=${3:-}
hfxc=$build/compiler/hfxc
mkdir -p "$out"

one() {   # one effect: $1 path, $2 name
    local fx=$1 dir=$out/$2 d
    mkdir -p "$dir"
    local -a inc=(-I "$(dirname "$fx")")
    d=$(dirname "$fx"); while [ "$d" != / ] && [ "$d" != . ] && [ ${#inc[@]} -lt 12 ]; do d=$(dirname "$d"); inc+=(-I "$d"); done
    for t in glsl330 glsles300 glsl110; do
        mkdir -p "$dir/$t"
        "$hfxc" --quiet "${inc[@]}" --target $t --emit-glsl "$dir/$t" -o "$dir/$t/out.hfxo" "$fx" >"$dir/$t/log" 2>&1
        echo "exit $?" >>"$dir/$t/log"; rm -f "$dir/$t/out.hfxo"
    done
    "$hfxc" --quiet "${inc[@]}" --reflect -o /dev/null "$fx" >"$dir/reflect.json" 2>&1
    "$hfxc" --quiet "${inc[@]}" --annotations -o /dev/null "$fx" >"$dir/annotations.json" 2>&1
    sed -i "s#$(dirname "$fx")##g" "$dir"/*/log "$dir"/*.json   # paths differ between checkouts
}

for f in "$here"/../shared/seed-fx/*.fx; do [ -f "$f" ] && one "$f" "seed/$(basename "$f")"; done
for f in "$here"/fx/*.fx; do one "$f" "fx/$(basename "$f")"; done
if [ -n "$corpus" ]; then
    (cd "$corpus" && "$here/scripts/corpus.sh" roots) | while read -r rel; do
        one "$corpus/$rel" "corpus/$(echo "$rel" | tr '/' '_')"
    done
fi
echo "outputs in $out"
