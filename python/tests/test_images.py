"""Image files from Python, and the checks every image argument goes through."""
import numpy as np
import pytest

import visp_photomodel as pm


def test_an_image_written_reads_back_bit_for_bit(tmp_path):
    rng = np.random.default_rng(1)
    rgba = rng.integers(0, 256, (48, 64, 4), dtype=np.uint8)
    rgba[..., 3] = 255
    pm.write_image(rgba, str(tmp_path / "a.png"))
    np.testing.assert_array_equal(pm.read_image(str(tmp_path / "a.png")), rgba)
    # BGR in, RGBA out: the channels turned, alpha opaque.
    bgr = np.ascontiguousarray(rgba[..., 2::-1])
    pm.write_image(bgr, str(tmp_path / "b.png"))
    np.testing.assert_array_equal(pm.read_image(str(tmp_path / "b.png")), rgba)


@pytest.mark.parametrize(
    "array, error, message",
    [
        (np.zeros((48, 64, 4), np.float32), TypeError, "uint8"),
        (np.zeros((48, 64), np.uint8), ValueError, "H x W x 3"),
        (np.zeros((48, 64, 2), np.uint8), ValueError, "H x W x 3"),
        (np.zeros((48, 128, 4), np.uint8)[:, ::2], ValueError, "contiguous"),
        (np.zeros((0, 64, 4), np.uint8), ValueError, "empty"),
    ],
)
def test_a_wrong_array_raises_not_crashes(tmp_path, array, error, message):
    with pytest.raises(error, match=message):
        pm.write_image(array, str(tmp_path / "x.png"))


def test_a_missing_image_raises_the_programs_message(tmp_path):
    with pytest.raises(pm.Error, match="missing.png"):
        pm.read_image(str(tmp_path / "missing.png"))
