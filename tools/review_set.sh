#!/usr/bin/env bash
# The review set: the frames a person looks at to judge the look, made by one command and
# regenerated with the code. Renders, headless at 640x360 with the clouds at High and each view
# given 96 frames (4.8 s at a fixed 0.05 s step) to converge:
#   ground_cumulus           cumulus_noon.json at noon, from the ground looking up 20 degrees
#                            (the place and direction of clouds_look's canonical view)
#   cumulus_towards_the_sun  the same field at 16:00, looking towards the sun
#   sunset                   sunset_stratocumulus.json from its camera
#   overcast                 overcast_stratus.json from its camera
#   above_the_layer          default.json, 6.5 km up looking down on the layer
#   inside_a_cloud           default.json, inside a cumulus at 2.6 km
#   default_flight           default.json from its camera, 4.8 s into its flight (the ground
#                            ahead as a pilot sees it)
#   lake                     lake.json from its camera: the lake reflecting the cloudy sky
# into OUT_DIR (default docs/review) as PNG (tonemapped) and EXR (linear HDR, kcd/m^2), and
# the PNGs side by side into OUT_DIR/contact_sheet.png; and the look in figures (clouds_look:
# the noon cumulus' flank-to-base ratio and what each lighting term does) into OUT_DIR/look.txt.
# Usage: tools/review_set.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs/review}"
tools/build.sh --target sample_game clouds_look >/dev/null
mkdir -p "$out"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
common=(--headless --width 640 --height 360 --quality high --fixed-dt 0.05 --capture "$out")

scene_view() {  # scene file, view name: the scene's own camera
  sed "s/VIEW/$2/" tools/review/scene_view.json >"$scratch/$2.json"
  build/bin/sample_game "${common[@]}" --scene "assets_src/scenes/$1" --script "$scratch/$2.json"
}
build/bin/sample_game "${common[@]}" --scene assets_src/scenes/cumulus_noon.json \
  --script tools/review/cumulus_views.json
scene_view sunset_stratocumulus.json sunset
scene_view overcast_stratus.json overcast
scene_view default.json default_flight
scene_view lake.json lake
build/bin/sample_game "${common[@]}" --scene assets_src/scenes/default.json \
  --script tools/review/default_views.json

views=(ground_cumulus cumulus_towards_the_sun sunset overcast above_the_layer inside_a_cloud
  default_flight lake)
sheet_args=()
for view in "${views[@]}"; do sheet_args+=("${view//_/ }=$out/$view.png"); done
python="$(sed -n 's/^CLOUDSCAPE_PLOT_PYTHON:[A-Z]*=//p' build/CMakeCache.txt)"
"${python:-python3}" tools/review/contact_sheet.py "$out/contact_sheet.png" "${sheet_args[@]}"
build/bin/clouds_look 2>/dev/null >"$out/look.txt"
echo "review_set: wrote ${#views[@]} views, contact_sheet.png and look.txt into $out"
