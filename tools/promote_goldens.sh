#!/usr/bin/env bash
# Promotes the golden-frame test's latest actual images (build/golden_output/*.png, written by
# every run of sample_golden_frame_tests) to the committed goldens in tests/goldens/.
# Review them first (and the diffs in build/golden_failures/); state why they changed in the
# commit that promotes them.
set -euo pipefail
cd "$(dirname "$0")/.."
shopt -s nullglob
images=(build/golden_output/*.png)
if ((${#images[@]} == 0)); then
  echo "promote_goldens: no images in build/golden_output; run: ctest --preset default -R golden" >&2
  exit 1
fi
mkdir -p tests/goldens
for image in "${images[@]}"; do
  cp "$image" tests/goldens/
  echo "promoted $(basename "$image")"
done
echo "now review 'git diff --stat tests/goldens' and commit with the reason for the change"
