# SPDX-License-Identifier: MIT
# Detection through the module: poses near the synthetic ground truth, identical to the CLI's
# `detect --json` on the same frame, the same with 16-bit or float depth and from two threads.
import json
import subprocess
import threading

import numpy as np
import pytest

import layermod
from conftest import DETECTOR_OPTIONS, SAMPLE, cli, frame_files, ground_truth


@pytest.fixture(scope="module")
def detector(archive_path):
    return layermod.Detector([archive_path], options=DETECTOR_OPTIONS)


def load(scene, image_id):
    color_path, depth_path = frame_files(scene, image_id)
    return layermod.load_capture(color_path, depth_path, SAMPLE / "camera.json")


@pytest.mark.parametrize("image_id", [0, 1, 2])
def test_finds_the_part_near_its_true_pose(detector, scenes, image_id):
    color, depth, camera = load(scenes, image_id)
    result = detector.detect(color, depth, camera)
    assert len(result) >= 1
    best = result.detections[0]
    assert (best.obj_id, best.name) == (1, "bracket")
    R_true, t_true = ground_truth(scenes, image_id)
    assert np.linalg.norm(best.t - np.array(t_true)) < 15.0
    assert best.R.shape == (3, 3) and best.R.dtype == np.float64
    np.testing.assert_allclose(best.R @ best.R.T, np.eye(3), atol=1e-9)
    assert 0 < best.score <= 100 and best.layer_mm > 0
    assert 0.5 <= best.confidence <= 1.0  # reported: at least the min_confidence asked for
    assert set(result.timings) == {"prepare_ms", "regions_ms", "coarse_ms", "match_ms",
                                   "pose_ms", "total_ms"}
    assert result.timings["total_ms"] > 0


@pytest.mark.parametrize("image_id", [0, 2])
def test_poses_equal_those_of_the_cli(detector, archive_path, scenes, image_id, tmp_path):
    out = tmp_path / "detection.json"
    subprocess.run([cli(), "detect", "--archive", str(archive_path), "--bop", str(scenes.parent),
                    "--scene", "1", "--frame", str(image_id), "--json", str(out),
                    "--min-confidence", str(DETECTOR_OPTIONS["min_confidence"])], check=True,
                   stdout=subprocess.DEVNULL)
    expected = json.loads(out.read_text())["detections"]
    result = detector.detect(*load(scenes, image_id))
    assert len(result) == len(expected) >= 1
    for got, want in zip(result, expected):
        assert got.obj_id == want["obj_id"] and got.template_id == want["template_id"]
        assert got.score == pytest.approx(want["score"], abs=1e-4)
        np.testing.assert_allclose(got.R.ravel(), want["cam_R_m2c"], atol=1e-9)
        np.testing.assert_allclose(got.t, want["cam_t_m2c"], atol=1e-6)
        assert got.layer_mm == want["layer_mm"]
        assert got.outline_agreement == pytest.approx(
            want["verification"]["outline_agreement"], abs=1e-9)
    # The module's own JSON is the CLI's format.
    assert json.loads(result.to_json())["detections"][0]["cam_t_m2c"] == pytest.approx(
        expected[0]["cam_t_m2c"], abs=1e-6)


def test_uint16_depth_gives_the_same_poses_as_float(detector, scenes):
    color, depth, camera = load(scenes, 1)
    as_float = detector.detect(color, depth, camera)
    as_u16 = detector.detect(color, depth.astype(np.uint16), camera)
    doubled = detector.detect(color, (depth * 2).astype(np.uint16), camera, depth_scale=0.5)
    for other in (as_u16, doubled):
        assert len(other) == len(as_float)
        np.testing.assert_allclose(other[0].t, as_float[0].t, atol=1e-6)


def test_two_threads_share_one_detector(detector, scenes):
    frames = [load(scenes, i) for i in (0, 1, 2)]
    alone = [detector.detect(*f)[0].t for f in frames]
    results = {}

    def run(name):
        results[name] = [detector.detect(*f)[0].t for f in frames for _ in range(2)]

    threads = [threading.Thread(target=run, args=(n,)) for n in ("a", "b")]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for name in ("a", "b"):
        for i, t in enumerate(results[name]):
            np.testing.assert_array_equal(t, alone[i // 2])


def test_options_use_the_cli_names(archive_path, scenes):
    # Confidence is left out (0): the counts below are about the LineMOD threshold alone.
    detector = layermod.Detector([layermod.load_archive(archive_path)],
                                 options={"threshold": 99.5, "instances": 2, "min_confidence": 0})
    assert detector.options["threshold"] == 99.5 and detector.options["instances"] == 2
    assert detector.options["mode"] == "scene-patch"
    strict = detector.detect(*load(scenes, 0))
    loose = detector.with_options({"threshold": 70, "min_confidence": 0}).detect(*load(scenes, 0))
    assert len(strict) < len(loose)
    colour_only = detector.with_options({"mode": "color-only"})
    color, _, camera = load(scenes, 0)
    assert colour_only.detect(color, None, camera).mode == "color-only"


def test_info_is_what_inspect_json_prints(archive_path):
    info = layermod.load_archive(archive_path).info()
    inspected = json.loads(subprocess.run([cli(), "inspect", "--json", str(archive_path)],
                                          check=True, capture_output=True, text=True).stdout)
    assert info == inspected
    assert info["objects"][0]["name"] == "bracket"
    assert len(info["objects"][0]["layers"]) == 5
    assert info["format_version"] == layermod.ARCHIVE_FORMAT_VERSION == 3
    assert info["objects"][0]["normal_frame"] == "viewing_ray"
