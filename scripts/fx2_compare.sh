#!/usr/bin/env bash
# How far hfx reads a folder of effects fxc compiled (FNA's .fxb, DigitalRune's .efb, .fxo):
#   scripts/fx2_compare.sh BUILD_DIR FOLDER
# For each file (searched recursively): whether it decodes (hfxc --disassemble: parameters,
# techniques, passes, states, expressions and every shader's bytecode), and whether it loads
# whole (hfxc -o: shaders translated to GLSL too), with the first error of each that fails.
# It fetches nothing: put the binaries in FOLDER yourself (docs/fx2.md).
set -uo pipefail
[ $# -eq 2 ] || { echo "usage: scripts/fx2_compare.sh BUILD_DIR FOLDER" >&2; exit 2; }
hfxc=$1/compiler/hfxc folder=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
total=0 decoded=0 loaded=0
while IFS= read -r -d '' f; do
  total=$((total + 1))
  if "$hfxc" --disassemble "$f" >"$tmp/list" 2>"$tmp/err"; then
    decoded=$((decoded + 1)) d=decodes
  else
    d="does not decode: $(head -n1 "$tmp/err")"
  fi
  if "$hfxc" --quiet -o "$tmp/out.hfxo" "$f" >/dev/null 2>"$tmp/err"; then
    loaded=$((loaded + 1)) l=loads
  else
    l="does not load: $(grep -m1 error "$tmp/err")"
  fi
  printf '%s\n    %s\n    %s\n' "${f#"$folder"/}" "$d" "$l"
done < <(find "$folder" -type f \( -iname '*.fxb' -o -iname '*.efb' -o -iname '*.fxo' -o -iname '*.xnb' \) -print0 | sort -z)
echo "$total files: $decoded decode, $loaded load"
