# SPDX-License-Identifier: MIT
# Bad input raises ValueError / layermod.Error naming the problem, never crashes.
import numpy as np
import pytest

import layermod
from conftest import SAMPLE, frame_files


@pytest.fixture(scope="module")
def detector(archive_path):
    return layermod.Detector([archive_path])


@pytest.fixture(scope="module")
def frame(scenes):
    color_path, depth_path = frame_files(scenes, 0)
    return layermod.load_capture(color_path, depth_path, SAMPLE / "camera.json")


def test_error_family():
    assert issubclass(layermod.IoError, layermod.Error)
    assert issubclass(layermod.FormatError, layermod.Error)
    assert issubclass(layermod.Error, Exception)


@pytest.mark.parametrize("make, message", [
    (lambda c: c.astype(np.float64), "uint8"),
    (lambda c: c[:, :, :2].copy(), "H x W x 3"),
    (lambda c: c[:, :, 0].copy(), "H x W x 3"),
    (lambda c: c[:, ::-1], "C-contiguous"),
])
def test_bad_color_arrays(detector, frame, make, message):
    color, depth, camera = frame
    with pytest.raises(ValueError, match=message):
        detector.detect(make(color), depth, camera)


@pytest.mark.parametrize("make, message", [
    (lambda d: d.astype(np.float64), "uint16"),
    (lambda d: d.astype(np.int32), "uint16"),
    (lambda d: d[:, :, None].copy(), "H x W"),
    (lambda d: np.asfortranarray(d), "C-contiguous"),
    (lambda d: d[:-2].copy(), "same size"),
])
def test_bad_depth_arrays(detector, frame, make, message):
    color, depth, camera = frame
    with pytest.raises(ValueError, match=message):
        detector.detect(color, make(depth), camera)


def test_camera_other_than_the_archives(detector, frame):
    color, depth, camera = frame
    other = layermod.Camera(600, 600, camera.cx, camera.cy, camera.width, camera.height)
    with pytest.raises(layermod.Error, match="intrinsics differ"):
        detector.detect(color, depth, other)


def test_images_of_another_size_than_the_camera(detector, frame):
    color, depth, camera = frame
    with pytest.raises(layermod.Error, match="camera is 640x480"):
        detector.detect(color[:240].copy(), depth[:240].copy(), camera)


def test_depth_needed_by_scene_patch(detector, frame):
    color, _, camera = frame
    with pytest.raises(layermod.Error, match="needs depth"):
        detector.detect(color, None, camera)


def test_bad_depth_scale(detector, frame):
    color, depth, camera = frame
    with pytest.raises(ValueError, match="depth_scale"):
        detector.detect(color, depth.astype(np.uint16), camera, depth_scale=0)


def test_bad_options(archive_path):
    with pytest.raises(layermod.FormatError, match="no_such_option"):
        layermod.Detector([archive_path], options={"no_such_option": 1})
    with pytest.raises(layermod.FormatError, match="threshold"):
        layermod.Detector([archive_path], options={"threshold": 500})
    with pytest.raises(layermod.FormatError, match="min_confidence"):
        layermod.Detector([archive_path], options={"min_confidence": 1.5})
    with pytest.raises(TypeError):
        layermod.Detector([archive_path], options="threshold=70")


def test_bad_archives(tmp_path, archive_path):
    with pytest.raises(layermod.IoError, match="missing.layermod"):
        layermod.Detector([tmp_path / "missing.layermod"])
    broken = tmp_path / "broken.layermod"
    broken.write_bytes(archive_path.read_bytes()[:1000])
    with pytest.raises(layermod.FormatError, match="broken.layermod"):
        layermod.load_archive(broken)
    with pytest.raises(TypeError, match="one str"):
        layermod.Detector(str(archive_path))
    with pytest.raises(layermod.Error, match="no archive"):
        layermod.Detector([])
    with pytest.raises(layermod.Error, match="appears twice"):
        layermod.Detector([archive_path, archive_path])


def test_bad_camera_values(tmp_path):
    with pytest.raises(layermod.Error):
        layermod.Camera(-1, 572, 319.5, 239.5, 640, 480)
    with pytest.raises(layermod.IoError, match="nope.json"):
        layermod.Camera.from_json(tmp_path / "nope.json")
