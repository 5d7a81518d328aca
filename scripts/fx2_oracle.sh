#!/usr/bin/env bash
# fxc's binaries as the oracle: does hfx compiling a source draw what fxc's binary of it draws?
#   scripts/fx2_oracle.sh BUILD_DIR FOLDER [PARAMS]
# FOLDER holds fxc's binaries (.fxb, .efb, .fxo) and their .fx sources, extracted by hand (it
# fetches nothing: docs/fx2.md says how). Each binary's source is the .fx whose path ends with
# the longest run of the binary's last path components (FNA/Deferred/Fog.efb ->
# Deferred/Fog.fx, FXB/BasicEffect.fxb -> HLSL/BasicEffect.fx). Both are converted once
# (hfxc -o X.hfxo), then every pass of every technique is drawn from each by hfxview (its
# parameter binding, the same on both sides, 128x128, the sphere unless the binding picks the
# screen) and the two pictures compared channel by channel (scripts/png_diff.py).
# PARAMS (default: scripts/fx2_oracle.params) has lines "GLOB hfxview-arguments...": the
# arguments for binaries whose path below FOLDER matches GLOB (every matching line adds to
# them); `--set NAME=A..B` draws each integer from A to B (a ShaderIndex sweep).
# Prints one line per technique / pass / variant: "alike" or "DIFFER", the largest channel
# difference (0..255) and the number of pixels off by more than 2/255, then the totals.
# HFX_ORACLE_SIZE=WxH changes the size; HFX_ORACLE_KEEP=1 keeps the pictures (path printed).
set -uo pipefail
[ $# -ge 2 ] && [ $# -le 3 ] || { echo "usage: scripts/fx2_oracle.sh BUILD_DIR FOLDER [PARAMS]" >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd) folder=$(cd "$2" && pwd) params=${3:-$here/scripts/fx2_oracle.params}
export hfxc=$build/compiler/hfxc view=$build/tools/hfxview/hfxview size=${HFX_ORACLE_SIZE:-128x128}
export diff_py=$here/scripts/png_diff.py
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
    done
    if [ $sweep_i -lt 0 ]; then printf -- '-'; printf '\t%s' "${a[@]}"; echo; return; fi
    for ((v = lo; v <= hi; v++)); do
        a[sweep_i]="$name=$v"
        printf '%s' "$name=$v"; printf '\t%s' "${a[@]}"; echo
    done
}

# One picture pair: "alike|DIFFER MAX COUNT binary#technique/pass variant".
one() {
    local job=$1 rel tech name pass label
    IFS=$'\t' read -r rel tech name pass label rest <<<"$job"
    local -a extra=(); [ -n "$rest" ] && IFS=$'\t' read -ra extra <<<"$rest"
    local key; key=$(echo "$rel.$tech.$pass.$label" | tr '/=' '__')
    local d=$out/${rel//\//_}
    "$view" "$d/src.hfxo" --technique "$tech" --pass "$pass" --size "$size" "${extra[@]}" \
        -o "$out/png/$key.src.png" >"$out/log/$key.src" 2>&1
    "$view" "$d/bin.hfxo" --technique "$tech" --pass "$pass" --size "$size" "${extra[@]}" \
        -o "$out/png/$key.bin.png" >"$out/log/$key.bin" 2>&1
    local r verdict; r=$(python3 "$diff_py" "$out/png/$key.src.png" "$out/png/$key.bin.png")
    case $r in
        missing|size) verdict=FAILED r="- -" ;;
        *) [ "${r%% *}" -le 2 ] && verdict=alike || verdict=DIFFER ;;
    esac
    printf '%-6s %3s %5s %s#%s:%s/%s %s\n' "$verdict" ${r} "$rel" "$tech" "$name" "$pass" "$label"
}
export -f one

mkdir -p "$out/png" "$out/log"
jobs=$out/jobs
: >"$jobs"
effects=0 unpaired=0 broken=0
while IFS= read -r -d '' f; do
    rel=${f#"$folder"/}
    src=$(source_of "$rel")
    if [ -z "$src" ]; then echo "NOSRC  $rel: no source found"; unpaired=$((unpaired + 1)); continue; fi
    d=$out/${rel//\//_}; mkdir -p "$d"
    if ! "$hfxc" --quiet -o "$d/bin.hfxo" "$f" >"$d/bin.log" 2>&1; then
        echo "FAILED $rel: the binary does not load: $(grep -m1 error "$d/bin.log")"; broken=$((broken + 1)); continue
    fi
    if ! "$hfxc" --quiet -o "$d/src.hfxo" "$folder/$src" >"$d/src.log" 2>&1; then
        echo "FAILED $rel: $src does not compile: $(grep -m1 error "$d/src.log")"; broken=$((broken + 1)); continue
    fi
    effects=$((effects + 1))
    "$view" "$d/bin.hfxo" --list >"$d/list" 2>/dev/null
    mapfile -t vars < <(args_of "$rel" | known_only "$d/list" | variants)
    # techniques and their pass counts, from the binary (the reference)
    awk '/^technique /{t++; name[t] = $2 == "" ? "-" : $2} /^  pass /{n[t]++} END {for (i = 1; i <= t; i++) if (n[i]) print i - 1, name[i], n[i]}' "$d/list" |
    while read -r t name n; do
        for ((p = 0; p < n; p++)); do
            for v in "${vars[@]}"; do
                printf '%s\t%s\t%s\t%s\t%s\n' "$rel" "$t" "$name" "$p" "$v" >>"$jobs"
            done
        done
    done
done < <(find "$folder" -type f \( -iname '*.fxb' -o -iname '*.efb' -o -iname '*.fxo' \) -print0 | sort -z)

xargs -d '\n' -P "${HFX_ORACLE_JOBS:-2}" -I{} bash -c 'one "$@"' _ {} <"$jobs" | sort -k4 | tee "$out/table.txt"
awk -v e="$effects" -v u="$unpaired" -v b="$broken" '
    { n++ } $1 == "alike" { a++ } $1 == "DIFFER" { d++ } $1 == "FAILED" { f++ }
    END { printf "%d effects (%d without a source, %d not loaded): %d pictures compared, %d alike, %d differ, %d failed to draw\n",
                 e, u, b, n, a, d, f }' "$out/table.txt"
[ -n "${HFX_ORACLE_KEEP:-}" ] && echo "pictures and logs in $out"
exit 0
