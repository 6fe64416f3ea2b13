#!/bin/bash
# Renders the default cave's images of the README gallery and the tutorial (docs/tools.md#cave-gallery), from
# the repository root:
#   docs/images/cave_capture_modes.png  the five capture modes of scenes/default/ (fast preset) side by side,
#                                       each reduced to half size: torch, flash, cross-polarized, raking, infrared
#   docs/images/default.png             the torch capture with --preset final, reduced to 800x450
#                                       (skipped with --modes-only: at the preset's 128 spp it takes about 15
#                                       minutes on two cores; FINAL_SPP=32 renders it with fewer samples)
# usage: tools/dev/make_cave_gallery.sh [--modes-only]   (environment: OCHRE, the ochre executable; FINAL_SPP)
set -euo pipefail
ochre="${OCHRE:-build/bin/ochre}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

strip=()
for mode in default flash cross_polarized raking infrared; do
  "$ochre" render "scenes/default/$mode.json" -o "$work/$mode.exr" --png "$work/$mode.png"
  oiiotool "$work/$mode.png" --resize 320x180 -o "$work/$mode.small.png"
  strip+=("$work/$mode.small.png")
done
oiiotool "${strip[@]}" --mosaic:pad=4 5x1 -o docs/images/cave_capture_modes.png
echo "wrote docs/images/cave_capture_modes.png"

if [ "${1:-}" != "--modes-only" ]; then
  "$ochre" render scenes/default/default.json --preset final ${FINAL_SPP:+--spp "$FINAL_SPP"} \
    -o "$work/final.exr" --png "$work/final.png"
  oiiotool "$work/final.png" --resize 800x450 -o docs/images/default.png
  echo "wrote docs/images/default.png"
fi
