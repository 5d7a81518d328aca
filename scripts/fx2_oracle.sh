#!/usr/bin/env bash
# fxc's binaries as the oracle: does hfx compiling a source draw what fxc's binary of it draws?
#   scripts/fx2_oracle.sh BUILD_DIR FOLDER [PARAMS]
# FOLDER holds fxc's binaries (.fxb, .efb, .fxo) and their .fx sources, extracted by hand (it
# fetches nothing: docs/fx2.md says how). Each binary's source is the .fx whose path ends with
# the longest run of the binary's last path components (FNA/Deferred/Fog.efb ->
# Deferred/Fog.fx, FXB/BasicEffect.fxb -> HLSL/BasicEffect.fx). Both are converted once
# (hfxc -o X.hfxo), then every pass of every technique is drawn alone from each by one hfxview
# per side and variant (--technique all --pass each; its parameter binding, the same on both
# sides, 128x128, the sphere unless the binding or PARAMS picks another mesh) and the pictures
# compared channel by channel (scripts/png_diff.py). Effects run two at a time
# (HFX_ORACLE_JOBS). PARAMS (default: fx2_oracle.params beside this script) has lines
# "GLOB hfxview-arguments...": the arguments for binaries whose path below FOLDER matches GLOB
# (every matching line adds to them; a --set of a parameter the effect lacks is dropped);
# `--set NAME=A..B[,REST]` draws each integer from A to B (a ShaderIndex sweep; several sweeps:
# every combination).
# Prints one line per technique / pass / variant: "alike" or "DIFFER", the largest channel
# difference (0..255) and the number of pixels off by more than 2/255, then the totals.
# HFX_ORACLE_SIZE=WxH changes the size; HFX_ORACLE_KEEP=1 keeps the pictures (path printed).
set -uo pipefail
[ $# -ge 2 ] && [ $# -le 3 ] || { echo "usage: scripts/fx2_oracle.sh BUILD_DIR FOLDER [PARAMS]" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd) folder=$(cd "$2" && pwd) params=${3:-$here/fx2_oracle.params}
export hfxc=$build/compiler/hfxc view=$build/tools/hfxview/hfxview size=${HFX_ORACLE_SIZE:-128x128}
export diff_py=$here/png_diff.py
[ -x "$hfxc" ] && [ -x "$view" ] || { echo "no hfxc / hfxview in $build (build first)" >&2; exit 2; }
export out; out=$(mktemp -d /tmp/hfx-oracle-XXXXXX)
[ -n "${HFX_ORACLE_KEEP:-}" ] || trap 'rm -rf "$out"' EXIT

# The source of a binary (path below FOLDER): the longest suffix of its path, stem .fx, that
# names exactly one source.
source_of() {
    local rel=${1%.*} suffix n
    local -a parts; IFS=/ read -ra parts <<<"$rel"
    for ((n = ${#parts[@]}; n >= 1; n--)); do
        suffix=$(IFS=/; echo "${parts[*]: -n}")
        mapfile -t hits < <(cd "$folder" && find . -type f -name '*.fx' | sed 's|^\./||' |
                            awk -v s="$suffix.fx" '$0 == s || substr($0, length($0) - length(s)) == "/" s')
        [ ${#hits[@]} -eq 1 ] && { echo "${hits[0]}"; return; }
    done
}

# The hfxview arguments PARAMS gives a binary, one a line.
args_of() {
    [ -f "$params" ] || return 0
    local glob rest
    while read -r glob rest; do
        [ -z "$glob" ] || [ "${glob#\#}" != "$glob" ] && continue
        # shellcheck disable=SC2053
        [[ $1 == $glob ]] && printf '%s\n' $rest
    done <"$params"
}

# The arguments without the `--set NAME=...` pairs whose NAME (before any [ or .) is not a
# parameter of the effect (FILE: its --list), so one PARAMS line can serve many effects.
known_only() {
    awk -v list="$1" 'BEGIN { while ((getline l < list) > 0) if (l ~ /^parameter /) { split(l, w, " ");
                                  sub(/\[.*/, "", w[2]); known[w[2]] = 1 } }
        $0 == "--set" { set = 1; next }
        set { set = 0; n = $0; sub(/[=\[.].*/, "", n); if (!(n in known)) next; print "--set" }
        { print }'
}

# Every variant: the arguments with each --set NAME=A..B[,REST] sweep expanded (several sweeps:
# every combination), one variant a line (arguments separated by tabs), with a label
# ("ShaderIndex=3", "SourceEncoding=2,6,0,0;TargetEncoding=1" or "-").
variants() {
    local -a a; mapfile -t a
    expand "" "${a[@]}"
}

# expand LABEL ARGS...: the first unexpanded sweep in ARGS replaced by each of its values.
expand() {
    local label=$1 i v; shift
    local -a a=("$@")
    for ((i = 1; i < ${#a[@]}; i++)); do
        [ "${a[i-1]}" = --set ] && [[ ${a[i]} =~ ^([^=]+)=(-?[0-9]+)\.\.(-?[0-9]+)(,.*)?$ ]] || continue
        local name=${BASH_REMATCH[1]} lo=${BASH_REMATCH[2]} hi=${BASH_REMATCH[3]} rest=${BASH_REMATCH[4]}
        for ((v = lo; v <= hi; v++)); do
            a[i]="$name=$v$rest"
            expand "${label:+$label;}$name=$v$rest" "${a[@]}"
        done
        return
    done
    printf '%s' "${label:--}"; printf '\t%s' "${a[@]}"; echo
}

# One effect: both converted, then for each variant each side drawn once by hfxview
# (--technique all --pass each: every pass alone into OUT.T.P.png), the pairs compared. Prints
# "alike|DIFFER|FAILED MAX COUNT binary#T:technique/P variant" per pass, or one FAILED line.
one() {
    local rel=$1 src=$2 d=$out/${1//\//_} v
    mkdir -p "$d"
    if ! "$hfxc" --quiet -o "$d/bin.hfxo" "$folder/$rel" >"$d/bin.log" 2>&1; then
        echo "FAILED - - $rel: the binary does not load: $(grep -m1 error "$d/bin.log")"; return
    fi
    if ! "$hfxc" --quiet -o "$d/src.hfxo" "$folder/$src" >"$d/src.log" 2>&1; then
        echo "FAILED - - $rel: $src does not compile: $(grep -m1 error "$d/src.log")"; return
    fi
    "$view" "$d/bin.hfxo" --list >"$d/list" 2>/dev/null
    local n=0
    while IFS= read -r v; do
        local label rest; IFS=$'\t' read -r label rest <<<"$v"
        local -a extra=(); [ -n "$rest" ] && IFS=$'\t' read -ra extra <<<"$rest"
        n=$((n + 1))
        for side in src bin; do
            "$view" "$d/$side.hfxo" --technique all --pass each --size "$size" "${extra[@]}" \
                -o "$d/$side.$n.png" >"$d/$side.$n.out" 2>"$d/$side.$n.log"
        done
        # the binary's passes (the reference): "pass T P NAME" after "technique T NAME"
        local -a keys=() names=() pngs=()
        while read -r kind t p name; do
            [ "$kind" = pass ] || continue
            keys+=("$t") names+=("$name/$p")
            pngs+=("$d/src.$n.$t.$p.png" "$d/bin.$n.$t.$p.png")
        done < <(awk '$1 == "technique" { print "technique", $2, $3 } $1 == "pass" { print }' "$d/bin.$n.out" |
                 while read -r kind t p name; do
                     if [ "$kind" = technique ]; then tn=${p:--}; else echo "pass $t $p $tn"; fi
                 done)
        [ ${#pngs[@]} -gt 0 ] || { echo "FAILED - - $rel: no pass drawn ($label): $(head -c 200 "$d/bin.$n.log")"; continue; }
        local i=0 r verdict
        while read -r r; do
            case $r in
                missing|size) verdict=FAILED r="- -" ;;
                *) [ "${r%% *}" -le 2 ] && verdict=alike || verdict=DIFFER ;;
            esac
            printf '%-6s %3s %5s %s#%s %s\n' "$verdict" ${r} "$rel" "${keys[i]}:${names[i]}" "$label"
            i=$((i + 1))
        done < <(python3 "$diff_py" "${pngs[@]}")
    done < <(args_of "$rel" | known_only "$d/list" | variants)
}
export -f one args_of known_only variants expand
export folder params

mkdir -p "$out"
jobs=$out/jobs
: >"$jobs"
unpaired=0
while IFS= read -r -d '' f; do
    rel=${f#"$folder"/}
    src=$(source_of "$rel")
    if [ -z "$src" ]; then echo "NOSRC  $rel: no source found"; unpaired=$((unpaired + 1)); continue; fi
    printf '%s\t%s\n' "$rel" "$src" >>"$jobs"
done < <(find "$folder" -type f \( -iname '*.fxb' -o -iname '*.efb' -o -iname '*.fxo' \) -print0 | sort -z)

xargs -d '\n' -P "${HFX_ORACLE_JOBS:-2}" -I{} bash -c 'IFS=$'"'\t'"' read -r rel src <<<"$1"; one "$rel" "$src"' _ {} <"$jobs" |
    sort -k4 | tee "$out/table.txt"
awk -v e="$(wc -l <"$jobs")" -v u="$unpaired" '
    $1 == "FAILED" && /: the binary does not load|does not compile/ { broken++; next }
    $1 == "FAILED" && /: no pass drawn/ { undrawn++; next }
    { n++ } $1 == "alike" { a++ } $1 == "DIFFER" { d++ } $1 == "FAILED" { f++ }
    END { printf "%d binaries with a source (%d without, %d not loaded or compiled): %d passes compared, %d alike, %d differ, %d not drawn (%d variants drew nothing)\n",
                 e, u, broken, n, a, d, f, undrawn }' "$out/table.txt"
[ -n "${HFX_ORACLE_KEEP:-}" ] && echo "pictures and logs in $out"
exit 0
