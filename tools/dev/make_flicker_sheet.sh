#!/bin/bash
# Renders a flicker sequence of a scene with flame lights and assembles its frames into one contact sheet
# (docs/tools.md#flicker-contact-sheet). The sheet of the README gallery is made by running it from the
# repository root with no arguments.
# usage: tools/dev/make_flicker_sheet.sh [SCENE.json] [SHEET.png] (environment: OCHRE, FRAMES, FPS, RESOLUTION,
#        SPP, SHEET_COLUMNS)
set -euo pipefail
scene="${1:-scenes/default/default.json}"
sheet="${2:-docs/images/cave_flicker.png}"
ochre="${OCHRE:-build/bin/ochre}"
frames="${FRAMES:-24}" fps="${FPS:-24}" resolution="${RESOLUTION:-160x90}" spp="${SPP:-64}"
columns="${SHEET_COLUMNS:-6}"
rows=$(((frames + columns - 1) / columns))

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$ochre" render "$scene" -o "$work/frame.exr" --png "$work/frame.png" --frames "$frames" --fps "$fps" \
  --resolution "$resolution" --spp "$spp"
# The frames in order, left to right then top to bottom, 2 pixels apart; the sheet reduced to 80 % (the
# filtering removes noise, so the PNG of the README's sheet stays under 400 KB).
oiiotool "$work"/frame.*.png --mosaic:pad=2 "${columns}x${rows}" --resize 80% -o "$sheet"
echo "wrote $sheet: $frames frames at $fps fps, ${columns}x${rows}"
