# SPDX-License-Identifier: MIT
# Fixtures: the bundled sample part trained small through the module, and a few RGB-D scenes of
# it synthesised by the CLI (`layermod synth`), once per test session.
import json
import os
import pathlib
import subprocess

import pytest

import layermod

SOURCE_DIR = pathlib.Path(os.environ.get("LAYERMOD_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
SAMPLE = SOURCE_DIR / "resources" / "sample"
# A small profile: 5 layers of 260 views, trained in about two seconds on two cores.
PROFILE = {"depth_min_mm": 600, "depth_max_mm": 900,
           "views": {"even_spacing_deg": 20, "roll": {"min_deg": -30, "step_deg": 15,
                                                      "max_deg": 30}}}
# That archive is coarse for speed: its right poses fit the depth less closely than a default
# archive's and verify at confidences from about 0.75, below the default acceptance of 0.8.
DETECTOR_OPTIONS = {"min_confidence": 0.5}


def cli():
    path = os.environ.get("LAYERMOD_CLI")
    if not path:
        pytest.skip("LAYERMOD_CLI not set (ctest sets it to build/app/layermod)")
    return path


@pytest.fixture(scope="session")
def work(tmp_path_factory):
    return tmp_path_factory.mktemp("layermod")


@pytest.fixture(scope="session")
def archive_path(work):
    out = work / "bracket.layermod"
    layermod.train(model=SAMPLE / "bracket.ply", obj_id=1, name="bracket",
                   camera=SAMPLE / "camera.json", profile=PROFILE, out=out)
    return out


@pytest.fixture(scope="session")
def scenes(work):
    out = work / "scenes"
    subprocess.run([cli(), "synth", "--models", str(SAMPLE / "bracket.ply"), "--obj-ids", "1",
                    "--scenes", "3", "--seed", "1", "--dmin", "650", "--dmax", "850",
                    "--camera", str(SAMPLE / "camera.json"), "--out", str(out)],
                   check=True, stdout=subprocess.DEVNULL)
    return out / "test" / "000001"


def frame_files(scene, image_id):
    name = f"{image_id:06d}.png"
    return scene / "rgb" / name, scene / "depth" / name


def ground_truth(scene, image_id):
    gt = json.loads((scene / "scene_gt.json").read_text())[str(image_id)][0]
    return gt["cam_R_m2c"], gt["cam_t_m2c"]
