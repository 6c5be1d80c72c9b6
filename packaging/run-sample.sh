#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job on the bundled sample, from a fresh Debian 12 machine: install dependencies,
# build, train the sample part into an archive and inspect it. Outputs go to ./out/sample.
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
echo "sample done: out/sample/bracket.layermod, template renders in out/sample/templates"
