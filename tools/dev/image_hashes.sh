#!/usr/bin/env bash
# Renders every scene of scenes/ and tests/regression/ small and quick, and prints one SHA-256 per output
# image (EXR pixels and headers, display PNG). Run it on two builds to show that a change leaves every image
# bit-identical: diff the two listings.
# Usage: tools/dev/image_hashes.sh BUILD_DIR WORK_DIR > hashes.txt
#   BUILD_DIR: a build tree (BUILD_DIR/bin/ochre); WORK_DIR: a scratch folder for the images.
# Scenes render at 4 samples per pixel and at most 96 pixels across (each scene's own aspect), 2 threads.
set -euo pipefail
build=$(cd "$1" && pwd)
work=$2
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$work"
cd "$source_dir"
for scene in $(find scenes tests/regression -name '*.json' | sort); do
  # Only whole scenes (a camera or shapes at the top level), not included material or light files.
  grep -qE '^\s*"(camera|shapes)"' "$scene" || continue
  name=$(echo "$scene" | tr '/' '_' | sed 's/\.json$//')
  if ! "$build/bin/ochre" render "$scene" --spp 4 --threads 2 -q -o "$work/$name.exr" --png "$work/$name.png" \
      --resolution 96x54 > "$work/$name.log" 2>&1; then
    echo "FAILED $scene (exit $?): $(tail -1 "$work/$name.log")"
    continue
  fi
  for f in "$work/$name.exr" "$work/$name.png"; do
    [ -f "$f" ] && echo "$(sha256sum < "$f" | cut -c1-16) $scene $(basename "$f" | sed 's/.*\.//')"
  done
done
