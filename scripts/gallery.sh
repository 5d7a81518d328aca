#!/usr/bin/env bash
# gallery.sh BUILD_DIR OUT_DIR: renders every effect of the project (fx/*.fx) and of the seed
# corpus (../shared/seed-fx/*.fx, when present) to OUT_DIR/*.png with hfxview, headless.
# Every technique of a file gets its own image. multilights.fx is meant to fail (its listing
# calls Phong with 4 arguments): its error is printed and the run goes on. Any other failure
# makes the script exit 1 after rendering the rest.
set -uo pipefail

if [ $# -ne 2 ]; then
  echo "usage: $0 BUILD_DIR OUT_DIR" >&2
  exit 2
fi
build=$1
out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
hfxview=$build/tools/hfxview/hfxview
if [ ! -x "$hfxview" ]; then
  echo "gallery: $hfxview not found: build the project first" >&2
  exit 2
fi
mkdir -p "$out"
seeds=$root/../shared/seed-fx

failures=0
rendered=0

# render PREFIX FILE TECHNIQUE-LIST -- hfxview options...
render() {
  local prefix=$1 file=$2 techniques=$3
  shift 4
  local name
  name=$(basename "$file" .fx)
  for t in $techniques; do
    local png=$out/${prefix}_${name}.png args=()
    if [ "$t" != "-" ]; then
      png=$out/${prefix}_${name}_${t}.png
      args=(--technique "$t")
    fi
    if "$hfxview" "$file" -o "$png" "${args[@]}" "$@" 2>"$out/.log"; then
      rendered=$((rendered + 1))
      echo "  $png"
      grep -v "warning X3206" "$out/.log" | sed 's/^/    /' || true
    else
      failures=$((failures + 1))
      echo "FAILED: $file ${t#-}" >&2
      sed 's/^/    /' "$out/.log" >&2
    fi
  done
}

# The seed that must not compile: show its diagnostic, count it as expected.
expect_failure() {
  local file=$1
  if "$hfxview" "$file" -o "$out/.unexpected.png" 2>"$out/.log"; then
    failures=$((failures + 1))
    echo "FAILED: $file rendered, but its listing has an error the compiler must report" >&2
    rm -f "$out/.unexpected.png"
  else
    echo "  $(basename "$file") fails as it must:"
    grep "error" "$out/.log" | sed 's/^/    /'
  fi
}

# Looking down at a horizontal plane, as FX Composer shows its plane.
above="--mesh plane --camera eye=0,2.4,2.2,at=0,0,0"

echo "Project effects (fx/):"
render fx "$root/fx/textured.fx" - -- --mesh quad --camera eye=0,0,3.2,at=0,0,0
render fx "$root/fx/ambient.fx" "Textured Material" -- --mesh teapot
render fx "$root/fx/directional.fx" "Textured Material" -- --mesh teapot
render fx "$root/fx/point.fx" "Textured Material" -- --mesh sphere
render fx "$root/fx/spot.fx" "Textured Material" -- $above
render fx "$root/fx/shading_models.fx" "Gouraud GouraudBlinn Phong BlinnPhong" -- --mesh sphere
render fx "$root/fx/point_lights.fx" - -- --mesh sphere
render fx "$root/fx/multipass.fx" - -- --mesh torus
render fx "$root/fx/sas_blinn.fx" - -- --mesh teapot
render fx "$root/fx/basic_lighting.fx" - -- --mesh teapot --set ShaderIndex=8 --set DiffuseColor=0.8,0.8,1,1 \
  --set DirLight0DiffuseColor=1,0.8,0.6 --set DirLight0Direction=-0.5,-0.7,-0.5 --set DirLight0SpecularColor=1,1,1
for f in "$root"/fx/*.fx; do # effects added later still show up, with default options
  case $(basename "$f") in
    textured.fx|ambient.fx|directional.fx|point.fx|spot.fx|shading_models.fx|point_lights.fx|multipass.fx|sas_blinn.fx|basic_lighting.fx) ;;
    *) render fx "$f" - -- ;;
  esac
done

if [ -d "$seeds" ]; then
  echo "Seed corpus ($seeds):"
  spot_book="--light position=0,10,0 --set anguloInterno=0.01 --set anguloExterno=0.1 --set falloff=0.8
             --set c1=1 --set c2=0 --set c3=0.001 --set rango=20 --set atenuado=true"
  render seed "$seeds/tutorial0.fx" - -- --mesh quad --camera eye=0,0,3.2,at=0,0,0
  render seed "$seeds/phong.fx" - -- --mesh sphere
  render seed "$seeds/pointlights.fx" - -- --mesh sphere
  render seed "$seeds/ambient.fx" - -- --mesh teapot
  render seed "$seeds/ambient_textured.fx" "Texturizado Material" -- --mesh teapot
  render seed "$seeds/directional.fx" "Texturizado Material" -- --mesh teapot
  render seed "$seeds/directional_specular.fx" "Texturizado Material" -- --mesh teapot --set modIluEsp=true
  render seed "$seeds/point.fx" "Texturizado Material" -- --mesh sphere --set atenuado=true
  render seed "$seeds/point_specular.fx" "Texturizado Material" -- --mesh sphere --set modIluEsp=true
  # shellcheck disable=SC2086 # the option lists are meant to split
  render seed "$seeds/spot.fx" "Texturizado Material" -- $above $spot_book
  # shellcheck disable=SC2086
  render seed "$seeds/spot_specular.fx" "Texturizado Material" -- $above $spot_book --set modIluEsp=true
  render seed "$seeds/multilights_repaired.fx" "Texturizado Material" -- --mesh teapot --blend-passes add \
    --set habiEspec=true
  render seed "$seeds/fxcomposer_empty.fx" - -- --mesh teapot
  expect_failure "$seeds/multilights.fx"
else
  echo "(no seed corpus at $seeds: skipped)"
fi

rm -f "$out/.log"
echo "$rendered images in $out"
if [ "$failures" -ne 0 ]; then
  echo "$failures unexpected failures" >&2
  exit 1
fi
