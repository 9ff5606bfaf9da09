#!/usr/bin/env bash
# The review set: the frames a person looks at to judge the look, made by one command and
# regenerated with the code. Renders, headless at 640x360 with the clouds at High and each view
# given 96 frames (4.8 s at a fixed 0.05 s step) to converge:
#   noon            cumulus_noon.json from its camera (fair-weather cumulus, high sun)
#   sunset          sunset_stratocumulus.json from its camera
#   above_the_layer default.json, 6.5 km up looking down on the layer
#   inside_a_cloud  default.json, inside a cumulus at 2.6 km
# into OUT_DIR (default docs/review) as PNG (tonemapped) and EXR (linear HDR, kcd/m^2).
# Usage: tools/review_set.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs/review}"
tools/build.sh --target sample_game >/dev/null
mkdir -p "$out"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
common=(--headless --width 640 --height 360 --quality high --fixed-dt 0.05 --capture "$out")

scene_view() {  # scene file, view name
  sed "s/VIEW/$2/" tools/review/scene_view.json >"$scratch/$2.json"
  build/bin/sample_game "${common[@]}" --scene "assets_src/scenes/$1" --script "$scratch/$2.json"
}
scene_view cumulus_noon.json noon
scene_view sunset_stratocumulus.json sunset
build/bin/sample_game "${common[@]}" --scene assets_src/scenes/default.json \
  --script tools/review/default_views.json
echo "review_set: wrote $(ls "$out"/*.png | wc -l) views into $out"
