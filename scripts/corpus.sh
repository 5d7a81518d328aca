#!/usr/bin/env bash
# The real-world corpus: effects from public repositories, kept outside the repository (only
# their list, tests/corpus/sources.tsv, is committed: repository, commit, path, kind).
#
#   scripts/corpus.sh extract MIRRORS DIR   copy every listed file out of git snapshots
#                                           (MIRRORS/<owner>+<name>/repo, as the search
#                                           tool's fetch leaves them) into DIR/<owner>+<name>/
#   scripts/corpus.sh run DIR [BUILD]       compile every root effect with hfxc for GLSL 330
#                                           and GLSL ES 300, validate each shader with
#                                           glslangValidator, render it with hfxview; print a
#                                           table, the failures' first lines, `N/M compiled`
#   scripts/corpus.sh techniques DIR [BUILD] every technique of every root effect drawn by
#                                           hfxview with its defaults at 128x128, each picture
#                                           classed drawn / black / blank (scripts/png_class.py),
#                                           with the parameters hfxview could not bind; prints
#                                           `N/M techniques draw something`
#   scripts/corpus.sh roots                 the root effects' paths relative to DIR, one a line
#                                           (bench/bench_corpus DIR LIST times their compile)
#   scripts/corpus.sh compare DIR [BUILD]   every technique (with a pass) of every root effect
#                                           drawn by hfxview on GL and with --vulkan (128x128,
#                                           its defaults), the pictures compared: "alike" when
#                                           99% of the pixels are within 2/255 in every channel;
#                                           prints a line per technique, the validation layer's
#                                           messages, and `alike A / drawn D`;
#                                           HFX_CORPUS_EVERY=N takes every Nth root effect only;
#                                           then the same techniques on the web page in headless
#                                           Chromium (scripts/web_corpus.js, the site of
#                                           scripts/web.sh in BUILD/web) against GL's pictures
#
# BUILD is a build folder of this checkout (default build/test). Output files go to a
# temporary folder (kept: its path is printed), PNGs under <tmp>/png for a contact sheet.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
list=$here/tests/corpus/sources.tsv

extract() {
    local mirrors=$1 dir=$2
    tail -n +2 "$list" | while IFS=$'\t' read -r repo commit path kind; do
        local git=$mirrors/${repo/\//+}/repo
        [ -d "$git/.git" ] && git=$git/.git
        mkdir -p "$dir/${repo/\//+}/$(dirname "$path")"
        git --git-dir="$git" show "$commit:$path" > "$dir/${repo/\//+}/$path" 2>/dev/null ||
            echo "missing: $repo $commit $path" >&2
    done
}

# Include folders for an effect: every folder above it inside its repository, since games load
# effects from their working folder (`#include "DATA\Shader\Blur.inc"` in a game's DATA/Shader).
include_dirs() {
    local d; d=$(dirname "$1")
    while [ "$d" != . ] && [ "${d#*/}" != "$d" ]; do d=$(dirname "$d"); printf -- "-I\n%s\n" "$d"; done
}

# One effect: "compile330 compileES validate render" as ok / FAIL / - columns.
one() {
    local fx=$1 out=$2 hfxc=$3 view=$4 name c330=FAIL ces=FAIL val=- ren=-
    name=$(echo "$fx" | tr '/' '_')
    mkdir -p "$out/glsl/$name.330" "$out/glsl/$name.es"
    local -a inc; mapfile -t inc < <(include_dirs "$fx")
    "$hfxc" --quiet "${inc[@]}" --target glsl330 --emit-glsl "$out/glsl/$name.330" "$fx" >"$out/log/$name.330" 2>&1 && c330=ok
    "$hfxc" --quiet "${inc[@]}" --target glsles300 --emit-glsl "$out/glsl/$name.es" "$fx" >"$out/log/$name.es" 2>&1 && ces=ok
    if [ $c330 = ok ] && [ $ces = ok ]; then
        val=ok
        for s in "$out/glsl/$name".*/*; do
            [ -f "$s" ] || continue
            glslangValidator "$s" >>"$out/log/$name.val" 2>&1 || val=FAIL
        done
    fi
    if [ -n "$view" ] && [ $c330 = ok ]; then
        timeout 60 "$view" "${inc[@]}" "$fx" -o "$out/png/$name.png" --size 128x128 >"$out/log/$name.view" 2>&1 && ren=ok || ren=FAIL
    fi
    printf "%-6s %-6s %-8s %-6s %s\n" "$c330" "$ces" "$val" "$ren" "$fx"
}

# The share of pixels of two PNGs within 2/255 in every channel (RGB as stored, through
# ImageMagick's `convert FILE -alpha off ppm:-`: without -alpha off it flattens the picture
# over white, which hides the colour of transparent pixels), as a fraction; -1 when their
# sizes differ or one cannot be read.
alike_share() {
    python3 - "$1" "$2" <<'PY'
import subprocess, sys
def load(path):
    data = subprocess.run(["convert", path, "-alpha", "off", "ppm:-"], capture_output=True, check=True).stdout
    magic, w, h, _, px = data.split(maxsplit=4)
    return int(w), int(h), px
try:
    (w, h, a), (w2, h2, b) = load(sys.argv[1]), load(sys.argv[2])
except Exception:
    print(-1); sys.exit()
if (w, h) != (w2, h2): print(-1); sys.exit()
n = w * h
near = sum(1 for i in range(n) if all(abs(a[3 * i + c] - b[3 * i + c]) <= 2 for c in range(3)))
print(f"{near / n:.4f}")
PY
}

# One effect's techniques: "GL VK alike share messages effect#technique" per technique with a pass.
compare_one() {
    local fx=$1 out=$2 view=$3 name t
    name=$(echo "$fx" | tr '/' '_')
    local -a inc; mapfile -t inc < <(include_dirs "$fx")
    for t in $("$view" "${inc[@]}" "$fx" --list 2>/dev/null |
               awk '/^technique /{n++} /^  pass/ && !seen[n]++ {print n - 1}'); do
        local png=$out/png/$name.$t gl=FAIL vk=FAIL same=- share=- msgs
        timeout 120 "$view" "${inc[@]}" "$fx" --technique "$t" --size 128x128 -o "$png.gl.png" \
            >"$out/log/$name.$t.gl" 2>&1 && gl=ok
        timeout 120 "$view" "${inc[@]}" "$fx" --technique "$t" --size 128x128 --vulkan -o "$png.vk.png" \
            >"$out/log/$name.$t.vk" 2>&1 && vk=ok
        msgs=$(grep -c "^vulkan validation:" "$out/log/$name.$t.vk")
        if [ -f "$png.gl.png" ] && [ -f "$png.vk.png" ]; then
            share=$(alike_share "$png.gl.png" "$png.vk.png")
            same=$(awk -v s="$share" 'BEGIN { print (s >= 0.99 ? "alike" : "DIFFER") }')
        fi
        printf "%-4s %-4s %-6s %-6s %-3s %s#%s\n" "$gl" "$vk" "$same" "$share" "$msgs" "$fx" "$t"
    done
}

compare() {
    local dir=$1 build=${2:-$here/build/test}
    local view=$build/tools/hfxview/hfxview
    [ -x "$view" ] || { echo "no hfxview in $build (build first)" >&2; exit 2; }
    local out; out=$(mktemp -d /tmp/hfx-compare-XXXXXX)
    mkdir -p "$out/log" "$out/png"
    export -f compare_one include_dirs alike_share
    printf "%-4s %-4s %-6s %-6s %-3s %s\n" GL VK same share msg "effect#technique"
    local every=${HFX_CORPUS_EVERY:-1} # a sample: every Nth root effect (a full run takes hours on lavapipe)
    (cd "$dir" && roots | awk -v n="$every" '(NR - 1) % n == 0' |
        xargs -d '\n' -P "$(nproc)" -I{} bash -c 'compare_one "$@"' _ {} "$out" "$view") |
        sort -k6 | tee "$out/table.txt"
    echo
    echo "validation messages, by VUID or message id (most frequent first):"
    cat "$out"/log/*.vk 2>/dev/null | grep "^vulkan validation:" | grep -o "VUID-[A-Za-z0-9_-]*\|UNASSIGNED-[A-Za-z0-9_-]*\|Undefined-Value-[A-Za-z0-9_-]*" |
        sort | uniq -c | sort -rn | head -15
    echo
    echo "Vulkan failures (first error line, most frequent first):"
    grep -h "error" "$out"/log/*.vk 2>/dev/null | grep -v "^vulkan validation:" | sed "s/^[^:]*: //; s/'[^']*'/'_'/g" |
        sort | uniq -c | sort -rn | head -10
    awk -v out="$out" '
        { techniques++ }
        $1 == "ok" { gl++ }
        $1 == "ok" && $2 == "ok" { both++ }
        $1 == "ok" && $3 == "alike" && $2 == "ok" { alike++ }
        $5 > 0 { noisy++; messages += $5 }
        END {
            printf "\noutputs in %s\n", out
            printf "%d techniques; GL drew %d, Vulkan drew %d of those\n", techniques, gl, both
            printf "%d techniques with validation messages (%d messages)\n", noisy, messages
            printf "alike %d / drawn %d (%.1f%%)\n", alike, gl, gl ? 100 * alike / gl : 0
        }' "$out/table.txt"
    compare_web "$dir" "$build" "$out"
}

# The same techniques on the web page (scripts/web_corpus.js, headless Chromium, the site
# $build/web that scripts/web.sh builds), each against GL's picture: "WEB alike share effect#t".
# Skipped (with why) without Chromium, the site or playwright-core.
compare_web() {
    local dir=$1 build=$2 out=$3
    [ -x /usr/bin/chromium ] || { echo "web page: skipped (no /usr/bin/chromium)"; return 0; }
    [ -f "$build/web/index.html" ] || { echo "web page: skipped (no site in $build/web: scripts/web.sh)"; return 0; }
    [ -d "$here/web/node_modules/playwright-core" ] || { echo "web page: skipped (npm ci in web/)"; return 0; }
    # the effect#technique column to the end of the line: paths may hold spaces
    awk '$1 == "ok" { sub(/^[^ ]+ +[^ ]+ +[^ ]+ +[^ ]+ +[^ ]+ +/, ""); print }' "$out/table.txt" > "$out/web-list.txt"
    node "$here/scripts/web_corpus.js" --site "$build/web" --corpus "$dir" --list "$out/web-list.txt" \
        --out "$out/png" > "$out/web-log.txt" 2>&1
    export -f alike_share
    while IFS=$'\t' read -r state line rest; do
        local name png share=- same=-
        name=$(echo "${line%#*}" | tr '/' '_') png=$out/png/$name.${line##*#}
        if [ "$state" = ok ]; then
            share=$(alike_share "$png.gl.png" "$png.web.png")
            same=$(awk -v s="$share" 'BEGIN { print (s >= 0.99 ? "alike" : "DIFFER") }')
        fi
        printf "%-4s %-6s %-6s %s %s\n" "$state" "$same" "$share" "$line" "$rest"
    done < <(grep -E "^(ok|FAIL)"$'\t' "$out/web-log.txt") | tee "$out/web-table.txt"
    awk '{ n++ } $1 == "ok" { drew++ } $2 == "alike" { alike++ }
         END { printf "web page: drew %d of the %d techniques GL drew; alike %d / %d (%.1f%%)\n",
               drew, n, alike, n, n ? 100 * alike / n : 0 }' "$out/web-table.txt"
}

# Every technique of one effect (one hfxview run, --technique all): lines
# "class effect#index technique | the parameters hfxview could not bind".
techs() {
    local fx=$1 out=$2 view=$3 here=$4 name i t cls unbound
    name=$(echo "$fx" | tr '/' '_')
    local -a inc; mapfile -t inc < <(include_dirs "$fx")
    timeout 300 "$view" "${inc[@]}" "$fx" --technique all -o "$out/png/$name.png" --size 128x128 \
        >"$out/log/$name.list" 2>"$out/log/$name.view"
    unbound=$(grep -o 'not bound, left at.*' "$out/log/$name.view" | cut -d: -f2- | head -1)
    while read -r i t; do
        cls=$(python3 "$here/scripts/png_class.py" "$out/png/$name.$i.png" | cut -d' ' -f1)
        printf "%-7s %s#%d %s |%s\n" "$cls" "$fx" "$i" "$t" "$unbound"
    done < <(sed -n 's/^technique //p' "$out/log/$name.list")
}

techniques() {
    local dir=$1 build=${2:-$here/build/test}
    local view=$build/tools/hfxview/hfxview
    [ -x "$view" ] || { echo "no hfxview in $build (build first)" >&2; exit 2; }
    local out; out=$(mktemp -d /tmp/hfx-techniques-XXXXXX)
    mkdir -p "$out/log" "$out/png"
    export -f techs include_dirs
    (cd "$dir" && roots | xargs -d '\n' -P "$(nproc)" -I{} bash -c 'techs "$@"' _ {} "$out" "$view" "$here") |
        sort -k2 > "$out/techniques.txt"
    local total drawn
    total=$(wc -l < "$out/techniques.txt")
    drawn=$(grep -c '^drawn' "$out/techniques.txt")
    awk '{print $1}' "$out/techniques.txt" | sort | uniq -c
    echo "outputs in $out (techniques.txt, png/)"
    echo "$drawn/$total techniques draw something"
}

roots() {
    tail -n +2 "$list" | awk -F'\t' '$4 == "root" { gsub("/", "+", $1); print $1 "/" $3 }'
}

run() {
    local dir=$1 build=${2:-$here/build/test}
    local hfxc=$build/compiler/hfxc view=$build/tools/hfxview/hfxview
    [ -x "$hfxc" ] || { echo "no hfxc in $build (build first)" >&2; exit 2; }
    [ -x "$view" ] || view=
    local out; out=$(mktemp -d /tmp/hfx-corpus-XXXXXX)
    mkdir -p "$out/log" "$out/png" "$out/glsl"
    export -f one include_dirs
    printf "%-6s %-6s %-8s %-6s %s\n" "330" "ES300" "validate" "render" "effect"
    (cd "$dir" && roots |
        xargs -d '\n' -P "$(nproc)" -I{} bash -c 'one "$@"' _ {} "$out" "$hfxc" "$view") | sort -k5 | tee "$out/table.txt"
    local total ok
    total=$(wc -l < "$out/table.txt")
    ok=$(awk '$1 == "ok" && $2 == "ok" && $3 == "ok"' "$out/table.txt" | wc -l)
    echo
    echo "first errors of the failures (by message, most frequent first):"
    cat "$out"/log/*.330 "$out"/log/*.es 2>/dev/null | grep -o "error X[0-9]*: .*" | sed "s/'[^']*'/'_'/g" |
        sort | uniq -c | sort -rn | head -25
    echo
    echo "outputs in $out"
    echo "$ok/$total compiled (GLSL 330 and ES 300) and validated"
}

case "${1:-}" in
extract) extract "$2" "$3" ;;
run) run "$2" "${3:-}" ;;
compare) compare "$2" "${3:-}" ;;
techniques) techniques "$2" "${3:-}" ;;
roots) roots ;;
*) sed -n '2,28p' "$0"; exit 2 ;;
esac
