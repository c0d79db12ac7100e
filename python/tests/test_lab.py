"""The lab from Python: a stereo pair of a toy at a pose, the servo loop frame by frame."""
import numpy as np
import pytest

import visp_photomodel as pm


def test_a_rendered_pair_shows_the_toy_where_it_is(rig):
    scene = pm.lab.Scene("C12")
    near, far = np.eye(4), np.eye(4)
    near[2, 3], far[2, 3] = 0.4, 0.7
    empty_left = None
    for hMo in (near, far):
        left, right = scene.render(rig, hMo)
        assert left.shape == (480, 640, 4) and left.dtype == np.uint8 and right.shape == left.shape
        assert (left[..., 3] == 255).all()
        assert not np.array_equal(left, right)  # two cameras 323 mm apart
        empty_left = left if empty_left is None else empty_left
    # Nearer, the toy covers more of the image: the pairs differ.
    assert not np.array_equal(empty_left, scene.render(rig, far)[0])
    with pytest.raises(pm.Error, match="C99"):
        pm.lab.Scene("C99")


def test_the_servo_loop_runs_frame_by_frame_and_never_servoes_on_a_wrong_pose(rig):
    loop = pm.lab.ServoLoop("C12", rig, pm.data_path("trajectories/table2.csv"), steps=1, seed=1, ga_seed=1)
    assert loop.duration > 1 and loop.model.all_around
    frames = [loop.step() for _ in range(45)]
    assert [f.t for f in frames] == pytest.approx([k / 30 for k in range(45)])
    assert not any(f.servoed_on_wrong_pose for f in frames)
    last = frames[-1]
    assert last.result.state == pm.TrackState.TRACKING and last.servoing
    assert last.estimate_error_mm < 3 and last.estimate_error_deg < 1.5
    assert len(last.joints) == 7  # the PA-10
    left, right = loop.images()
    assert left.shape == (480, 640, 4)
    with pytest.raises(pm.Error, match="trajectory|no_such"):
        pm.lab.ServoLoop("C12", rig, "no_such.csv")
