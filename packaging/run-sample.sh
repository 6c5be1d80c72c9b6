#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job on the bundled sample, from a fresh Debian 12 machine: install dependencies,
# build, train the sample part into an archive and inspect it, then synthesise RGB-D scenes of it
# and detect it there. Outputs go to ./out/sample.
set -euo pipefail
cd "$(dirname "$0")/.."
bash packaging/install-deps.sh
bash packaging/build.sh
mkdir -p out/sample
./build/app/layermod train --model resources/sample/bracket.ply --obj-id 1 --name bracket \
  --camera resources/sample/camera.json --dmin 500 --dmax 1500 \
  --out out/sample/bracket.layermod
./build/app/layermod inspect out/sample/bracket.layermod
./build/app/layermod render --archive out/sample/bracket.layermod --out out/sample/templates \
  --every 500
rm -rf out/sample/scenes
./build/app/layermod synth --models resources/sample/bracket.ply --obj-ids 1 --scenes 3 --seed 1 \
  --camera resources/sample/camera.json --out out/sample/scenes
./build/app/layermod detect --archive out/sample/bracket.layermod --bop out/sample/scenes/test \
  --scene 1 --frame 0 --json out/sample/detection.json --overlay out/sample/detection.png \
  --overlay-stages out/sample/stages
# The Python module of this build, importable by Debian's python3 from now on (a .pth file in
# the user's site-packages, as an editable install would do), then the Python example on the
# same scene.
site_dir="$(/usr/bin/python3 -c 'import site; print(site.getusersitepackages())')"
mkdir -p "$site_dir"
echo "$PWD/build/python" > "$site_dir/layermod-build.pth"
/usr/bin/python3 examples/python/detect_folder.py out/sample/scenes/test/000001 \
  out/sample/bracket.layermod
echo "sample done: out/sample/bracket.layermod, template renders in out/sample/templates,"
echo "detection in out/sample/detection.{json,png} and out/sample/stages;"
echo "python3 -c 'import layermod' uses this build ($site_dir/layermod-build.pth)"
