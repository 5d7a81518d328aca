#!/bin/sh
# fx2_roundtrip.sh BUILD [MOJOSHADER_TESTPARSE]: fxc's binaries of FNA and DigitalRune (from the
# mirrors of tests/corpus/sources.tsv's repositories, outside the repository) read, written as
# fx_2_0 by hfxc and read again: tests/compiler/effect/test_fx2_write with HFX_FX2_SAMPLES, then,
# given MojoShader's testparse (built outside the repository), MojoShader's dump of each rewrite
# against its dump of fxc's file. Run by hand; CI has neither the binaries nor MojoShader.
set -eu
build=${1:?usage: fx2_roundtrip.sh BUILD [testparse]}
testparse=${2:-}
mirror=${HFX_MIRROR:-/work/.mirror}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fna="git --git-dir=$mirror/FNA-XNA+FNA/repo"
for f in $($fna ls-tree -r --name-only HEAD | grep '\.fxb$'); do $fna show "HEAD:$f" > "$dir/$(basename "$f")"; done
dr="git --git-dir=$mirror/rds1983+DigitalRise/repo"
for f in $($dr ls-tree -r --name-only 184916d8 | grep 'EffectsSource/FNA/.*\.efb$'); do
  $dr show "184916d8:$f" > "$dir/$(echo "$f" | sed 's|.*EffectsSource/FNA/||; s|/|_|g')"
done
HFX_FX2_SAMPLES=$dir "$build/tests/compiler_effect_test_fx2_write"
[ -n "$testparse" ] || exit 0
same=0 differ=0 failed=0
for f in "$dir"/*.fxb "$dir"/*.efb; do
  "$build/compiler/hfxc" /Fo "$dir/rewrite.fxo" "$f" > /dev/null 2>&1 || continue  # the reader's to load
  "$testparse" glsl "$f" > "$dir/a.txt" 2>&1 || true
  if ! "$testparse" glsl "$dir/rewrite.fxo" > "$dir/b.txt" 2>&1; then failed=$((failed + 1)); echo "MojoShader fails: $f"; fi
  sed -i "s|$dir/rewrite.fxo|$f|" "$dir/b.txt"
  if cmp -s "$dir/a.txt" "$dir/b.txt"; then same=$((same + 1)); else differ=$((differ + 1)); echo "differs: $f"; fi
done
echo "MojoShader: $same rewrites read as fxc's file, $differ differ, $failed fail"
