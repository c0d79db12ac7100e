"""Rigs and camera files from Python: read, written, read back; bad files raise Error."""
import numpy as np
import pytest

import visp_photomodel as pm


def test_the_shipped_rig_reads_as_the_programs_read_it(rig):
    assert (rig.left.width, rig.left.height) == (640, 480)
    assert rig.baseline_mm == pytest.approx(323.0, abs=1e-6)
    # The left camera sits half the baseline to the left of the hand's origin.
    assert rig.left.hMc[0, 3] == pytest.approx(-0.1615, abs=1e-9)
    assert rig.left.hMc.shape == (4, 4)


def test_a_rig_written_reads_back_the_same(rig, tmp_path):
    path = tmp_path / "copy.json"
    rig.save(str(path))
    back = pm.load_rig(str(path))
    for a, b in ((rig.left, back.left), (rig.right, back.right)):
        assert (a.width, a.height) == (b.width, b.height)
        assert (a.px, a.py, a.u0, a.v0) == pytest.approx((b.px, b.py, b.u0, b.v0), abs=1e-9)
        np.testing.assert_allclose(a.hMc, b.hMc, atol=1e-9)


def test_a_camera_file_written_reads_back_the_same(rig, tmp_path):
    path = tmp_path / "left.yml"
    pm.write_camera_file(rig.left, str(path))
    cam = pm.read_camera_file(str(path), width=640, height=480)
    assert (cam.px, cam.py, cam.u0, cam.v0) == pytest.approx((rig.left.px, rig.left.py, rig.left.u0, rig.left.v0), abs=1e-9)
    with pytest.raises(pm.Error, match="640x480 images"):
        pm.read_camera_file(str(path), width=320, height=240)


def test_a_missing_or_broken_rig_raises_the_programs_message(tmp_path):
    with pytest.raises(pm.Error, match="nothing.json"):
        pm.load_rig(str(tmp_path / "nothing.json"))
    bad = tmp_path / "bad.json"
    bad.write_text("{ not json")
    with pytest.raises(pm.Error):
        pm.load_rig(str(bad))
    assert issubclass(pm.Error, RuntimeError)
