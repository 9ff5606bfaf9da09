#!/usr/bin/env bash
# The hero clouds' pictures in the clouds module's README, made by one command and regenerated
# with the code: headless at 640x360, the clouds at High, 96 frames at a fixed 0.05 s step:
#   hero_clouds     assets_src/scenes/hero_clouds.json from its camera (the three shipped clouds)
#   user_vdb_cloud  cumulus_noon.json with an OpenVDB cloud (clouds_example_vdb) put ahead by
#                   the sample's --cloud
# into OUT_DIR (default modules/clouds/docs/images) as PNG.
# Usage: tools/clouds/hero_pictures.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${1:-modules/clouds/docs/images}"
tools/build.sh --target sample_game clouds_example_vdb >/dev/null
mkdir -p "$out"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
common=(--headless --width 640 --height 360 --quality high --fixed-dt 0.05 --frames 96)

picture() {  # name, then the sample's arguments
  local name="$1"
  shift
  build/bin/sample_game "${common[@]}" --capture "$scratch/$name" "$@" >/dev/null
  cp "$scratch/$name/frame_0095.png" "$out/$name.png"
  echo "$out/$name.png"
}
picture hero_clouds --scene assets_src/scenes/hero_clouds.json
build/bin/clouds_example_vdb "$scratch/example.vdb" >/dev/null
picture user_vdb_cloud --scene assets_src/scenes/cumulus_noon.json --cloud "$scratch/example.vdb"
