#!/usr/bin/env bash
# The settings panel's picture in the README (docs/images/settings_panel.png), made by one
# command and regenerated with the code: the default scene headless at 640x360 with the HUD
# drawn (--hud-headless), a script pressing F2 at the second frame, the fifth frame captured.
# Usage: tools/panel_picture.sh [OUT_PNG]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs/images/settings_panel.png}"
tools/build.sh --target sample_game >/dev/null
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
cat >"$scratch/f2.json" <<'JSON'
{"events": [{"frame": 1, "press": ["F2"]}, {"frame": 4, "capture": "panel"},
            {"frame": 4, "exit": true}]}
JSON
build/bin/sample_game --headless --hud-headless --width 640 --height 360 --fixed-dt 0.05 \
  --script "$scratch/f2.json" --capture "$scratch" >/dev/null
mkdir -p "$(dirname "$out")"
cp "$scratch/panel.png" "$out"
echo "$out"
