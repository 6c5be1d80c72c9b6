# SPDX-License-Identifier: MIT
# layermod.train: the CLI's options, progress reports, cancellation from the callback, errors.
import pytest

import layermod
from conftest import PROFILE, SAMPLE

TINY = {"depth_min_mm": 700, "depth_max_mm": 800,
        "views": {"even_spacing_deg": 40, "roll": {"min_deg": 0, "step_deg": 15, "max_deg": 0}}}


def test_progress_reaches_the_total_and_the_archive_matches_the_profile(tmp_path):
    reports = []
    out = tmp_path / "tiny.layermod"
    archive = layermod.train(model=SAMPLE / "bracket.ply", obj_id=7,
                             camera=layermod.Camera.from_json(SAMPLE / "camera.json"),
                             profile=TINY, out=out, threads=2,
                             progress=lambda done, total, stage: reports.append((done, total)))
    assert out.is_file()
    assert reports and reports[-1][0] == reports[-1][1] == archive.template_count
    objects = archive.objects
    assert objects[0]["obj_id"] == 7 and objects[0]["name"] == "bracket"
    assert layermod.load_archive(out).info() == archive.info()
    assert archive.camera == layermod.Camera.from_json(SAMPLE / "camera.json")


def test_profile_file_and_dict_agree(tmp_path):
    import json
    profile_file = tmp_path / "profile.json"
    profile_file.write_text(json.dumps(TINY))
    from_file = layermod.train(model=SAMPLE / "bracket.ply", camera=SAMPLE / "camera.json",
                               profile=profile_file)
    from_dict = layermod.train(model=SAMPLE / "bracket.ply", camera=SAMPLE / "camera.json",
                               profile=TINY)
    assert from_file.template_count == from_dict.template_count
    assert from_file.objects[0]["layer_depths_mm"] == from_dict.objects[0]["layer_depths_mm"]


def test_an_exception_in_the_callback_cancels_and_is_raised(tmp_path):
    out = tmp_path / "never.layermod"

    def stop(done, total, stage):
        if done >= 5:
            raise KeyboardInterrupt("stop")

    with pytest.raises(KeyboardInterrupt, match="stop"):
        layermod.train(model=SAMPLE / "bracket.ply", camera=SAMPLE / "camera.json",
                       profile=PROFILE, out=out, progress=stop)
    assert not out.exists()


def test_bad_training_input(tmp_path):
    camera = SAMPLE / "camera.json"
    with pytest.raises(layermod.IoError, match="missing.ply"):
        layermod.train(model=tmp_path / "missing.ply", camera=camera)
    with pytest.raises(layermod.FormatError, match="depth_min"):
        layermod.train(model=SAMPLE / "bracket.ply", camera=camera, profile={"depth_min_mm": -5})
    with pytest.raises(layermod.Error, match="units"):
        layermod.train(model=SAMPLE / "bracket.ply", camera=camera, units="inch")
