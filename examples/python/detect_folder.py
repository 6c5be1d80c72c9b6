#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Loads archives once and detects in every frame of a folder, printing poses and times.

    detect_folder.py FOLDER ARCHIVE... [--options JSON]

FOLDER is a BOP scene (rgb/, depth/, scene_camera.json; the camera is the dataset's camera.json
two levels up) or a folder of NAME_color.png / NAME_depth.png pairs (16-bit mm) with a
camera.json. The same as examples/cpp/detect_folder.cpp.
"""
import argparse
import json
import pathlib
import sys
import time

import layermod


def list_frames(folder):
    """(camera.json, [(name, colour, depth, depth_scale)]) of a BOP scene or a folder of pairs."""
    scene_camera = folder / "scene_camera.json"
    if scene_camera.is_file():
        entries = json.loads(scene_camera.read_text())
        frames = [(name, folder / "rgb" / f"{int(name):06d}.png",
                   folder / "depth" / f"{int(name):06d}.png", entry.get("depth_scale", 1.0))
                  for name, entry in sorted(entries.items(), key=lambda item: int(item[0]))]
        return folder.parent.parent / "camera.json", frames
    frames = [(path.name[:-len("_color.png")], path,
               path.with_name(path.name.replace("_color.png", "_depth.png")), 1.0)
              for path in sorted(folder.glob("*_color.png"))]
    return folder / "camera.json", frames


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=pathlib.Path)
    parser.add_argument("archives", nargs="+")
    parser.add_argument("--options", default="{}", help="detector options as JSON")
    args = parser.parse_args()
    try:
        detector = layermod.Detector(args.archives, options=json.loads(args.options))
        camera_file, frames = list_frames(args.folder)
        if not frames:
            sys.exit(f"{args.folder}: no frames (expected a BOP scene or *_color.png)")
        for name, color_path, depth_path, depth_scale in frames:
            color, depth, camera = layermod.load_capture(color_path, depth_path, camera_file,
                                                         depth_scale)
            start = time.perf_counter()
            result = detector.detect(color, depth, camera)
            wall_ms = (time.perf_counter() - start) * 1000.0
            print(f"frame {name}: {len(result)} detection(s), {wall_ms:.1f} ms "
                  f"(detector stages {result.timings['total_ms']:.1f} ms)")
            for d in result:
                R = " ".join(f"{v:.4f}" for v in d.R.ravel())
                print(f"  obj {d.obj_id} {d.name} score {d.score:.1f}% "
                      f"t = ({d.t[0]:.1f}, {d.t[1]:.1f}, {d.t[2]:.1f}) mm R = [{R}] "
                      f"layer {d.layer_mm:.0f} mm")
    except layermod.Error as error:
        sys.exit(f"error: {error}")


if __name__ == "__main__":
    main()
