#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the studio's screenshots in docs/screenshots/ from the bundled sample part: the
# model with its sphere and view coverage, the template browser, and the detection preview on a
# synthetic capture with each overlay, and a detection against the capture's points in 3D.
# Needs a GUI build and xvfb-run.
#   packaging/screenshots.sh [BUILD_DIR]      (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
cli="$build_dir/app/layermod"
studio="$build_dir/ui/layermod-studio"
out=docs/screenshots
for exe in "$cli" "$studio"; do
  [[ -x $exe ]] || { echo "screenshots: $exe not found (build with -DLAYERMOD_BUILD_GUI=ON)" >&2; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Own settings, so neither the user's saved layout nor these runs leak into each other.
export XDG_CONFIG_HOME="$work/config"
mkdir -p "$out" "$work/set"

# A template set with its mesh beside it (the browser draws the part under the features), and a
# synthetic capture of the same part within the set's depth range.
cp resources/sample/bracket.ply "$work/set/"
"$cli" train --model "$work/set/bracket.ply" --obj-id 1 --name bracket \
  --camera resources/sample/camera.json --dmin 600 --dmax 1000 --even-views 15 \
  --roll -45:15:45 --out "$work/set/bracket.layermod" > /dev/null 2>&1
"$cli" synth --models resources/sample/bracket.ply --obj-ids 1 --scenes 1 --seed 5 \
  --dmin 700 --dmax 850 --camera resources/sample/camera.json --out "$work/synth" > /dev/null 2>&1

shoot() {  # shoot NAME ARGS...
  local name=$1
  shift
  xvfb-run -a -s "-screen 0 1280x800x24" "$studio" --screenshot "$out/$name.png" "$@"
  echo "wrote $out/$name.png"
}
capture=(--bop "$work/synth/test" --scene 1 --frame 0)
shoot model resources/sample/bracket.ply
shoot templates "$work/set/bracket.layermod"
shoot template-selected "$work/set/bracket.layermod" --select-template 40
shoot detection-poses "$work/set/bracket.layermod" "${capture[@]}" --overlays poses
shoot detection-regions "$work/set/bracket.layermod" "${capture[@]}" --overlays regions
shoot detection-coarse "$work/set/bracket.layermod" "${capture[@]}" --overlays coarse
shoot detection-matches "$work/set/bracket.layermod" "${capture[@]}" --overlays matches
shoot detection-3d "$work/set/bracket.layermod" "${capture[@]}" --show-detection 0
shoot detection-all "$work/set/bracket.layermod" "${capture[@]}" \
  --overlays regions,coarse,matches,poses
