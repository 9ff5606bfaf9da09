#!/usr/bin/env bash
# The hero clouds' pictures in the clouds module's README, made by one command and regenerated
# with the code: headless at 640x360, the clouds at High, 96 frames at a fixed 0.05 s step:
#   hero_clouds     assets_src/scenes/hero_clouds.json from its camera (the three shipped clouds)
#   user_vdb_cloud  cumulus_noon.json with an OpenVDB cloud (clouds_example_vdb) put ahead by
#                   the sample's --cloud
#   hero_cloud_life the towering cumulus's life (HeroCloudLifecycle): growing, grown and
#                   dissipating, each a scene whose clock reaches that age by the captured frame
#   hero_cloud_detail the towering cumulus from 700 m, its half-metre detail (Settings::
#                   heroDetail) beside its voxels smooth
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

# The life: grows 60 s, stays 60 s, dissipates 60 s; the captured frame is at 4.75 s, so a
# scene that starts the life 4.75 - AGE seconds in shows it at AGE.
life_scene() {  # age (s)
  local start
  start="$(awk -v age="$1" 'BEGIN { print 4.75 - age }')"
  cat >"$scratch/life_$1.json" <<JSON
{
  "name": "A hero cloud's life",
  "camera": {"position": [2830, 1800, 17600], "yawDegrees": 0, "pitchDegrees": 10},
  "sun": {"timeOfDayHours": 15.5, "maxElevationDegrees": 60},
  "terrain": {"gltf": "default"},
  "clouds": {
    "coverage": 0.2,
    "cloudType": 0.8,
    "heroClouds": [
      {"asset": "towering_cumulus", "positionMetres": [2830, 1300, 14170], "yawDegrees": 20,
       "lifecycle": {"startSeconds": $start, "growSeconds": 60, "matureSeconds": 60,
                     "dissipateSeconds": 60, "restSeconds": 60}}
    ]
  },
  "atmosphere": {"preset": "earth"},
  "exposure": {"mode": "auto"}
}
JSON
  echo "$scratch/life_$1.json"
}
stages=()
for age in 21 42 90 150; do
  picture "life_$age" --scene "$(life_scene "$age")" >/dev/null
  stages+=("$scratch/life_$age.png")
  cp "$out/life_$age.png" "$scratch/life_$age.png"
  rm "$out/life_$age.png"
done
python="$(sed -n 's/^CLOUDSCAPE_PLOT_PYTHON:[A-Z]*=//p' build/CMakeCache.txt)"
"${python:-python3}" tools/review/contact_sheet.py --columns 2 "$out/hero_cloud_life.png" \
  "growing (growth 0.35)=${stages[0]}" "growing (growth 0.7)=${stages[1]}" \
  "grown=${stages[2]}" "dissipating (dissipation 0.5)=${stages[3]}"
echo "$out/hero_cloud_life.png"

# The detail: the towering cumulus from its sunlit side, about 700 m off, up-rezzed and smooth.
detail_scene() {  # heroDetail
  cat >"$scratch/detail_$1.json" <<JSON
{
  "name": "A hero cloud up close",
  "camera": {"position": [2830, 2300, 15400], "yawDegrees": 0, "pitchDegrees": 10},
  "sun": {"timeOfDayHours": 15.5, "maxElevationDegrees": 60},
  "terrain": {"gltf": "default"},
  "clouds": {
    "coverage": 0.0,
    "heroClouds": [
      {"asset": "towering_cumulus", "positionMetres": [2830, 1300, 14170], "yawDegrees": 20}
    ],
    "heroDetail": "$1"
  },
  "atmosphere": {"preset": "earth"},
  "exposure": {"mode": "auto"}
}
JSON
  echo "$scratch/detail_$1.json"
}
for detail in uprezzed off; do
  picture "detail_$detail" --scene "$(detail_scene "$detail")" >/dev/null
  cp "$out/detail_$detail.png" "$scratch/detail_$detail.png"
  rm "$out/detail_$detail.png"
done
"${python:-python3}" tools/review/contact_sheet.py --columns 2 "$out/hero_cloud_detail.png" \
  "half-metre detail (heroDetail Uprezzed)=$scratch/detail_uprezzed.png" \
  "its voxels smooth (heroDetail Off)=$scratch/detail_off.png"
echo "$out/hero_cloud_detail.png"
