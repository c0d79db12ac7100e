"""Photo-models from Python: loaded, saved, built from a views folder and from arrays (the same model as pm-make-model's)."""
import json
import math

import numpy as np
import pytest

import visp_photomodel as pm


def pose_of_yaml(path) -> np.ndarray:
    """A vpPoseVector YAML (tx, ty, tz, theta-u) as a 4 x 4 matrix: the views folder's pose files."""
    values = [float(line.split("[")[1].split("]")[0]) for line in open(path) if line.strip().startswith("- [")]
    t, u = np.array(values[:3]), np.array(values[3:])
    angle = np.linalg.norm(u)
    k = u / angle if angle > 0 else np.zeros(3)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    M = np.eye(4)
    M[:3, :3] = np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K
    M[:3, 3] = t
    return M


def test_a_model_saved_reads_back_the_same(model, tmp_path):
    model.save(str(tmp_path / "m.json"))
    back = pm.load_model(str(tmp_path / "m.json"))
    assert back.to_json() == model.to_json()
    assert model.all_around and model.has_outlines and model.viewpoints == 241
    assert model.inner.shape == (model.inner_points, 4)


def test_a_model_of_another_version_or_missing_raises(model, tmp_path):
    text = json.loads(model.to_json())
    text["version"] = 99
    (tmp_path / "v99.json").write_text(json.dumps(text))
    with pytest.raises(pm.Error, match="version"):
        pm.load_model(str(tmp_path / "v99.json"))
    with pytest.raises(pm.Error, match="missing.json"):
        pm.load_model(str(tmp_path / "missing.json"))


def test_built_from_its_views_folder_and_from_arrays_it_is_pm_make_models(rig, made_model, model):
    views = made_model / "views"
    from_folder = pm.build_model_from_folder(rig, str(views))
    arrays = []
    k = 0
    while (views / f"left_{k:02d}.png").exists():
        read = lambda stem: pm.read_image(str(views / f"{stem}_{k:02d}.png"))
        arrays.append(pm.PassView(read("left"), read("right"), pose_of_yaml(views / f"pose_fPh_{k:02d}.yaml"),
                                  read("background_left"), read("background_right"), name=f"view {k:02d}"))
        k += 1
    from_arrays = pm.build_model(rig, arrays)
    # The same pass, from files or from arrays: the same model to a micrometre (the poses' last digits differ).
    assert from_arrays.inner.shape == from_folder.inner.shape == model.inner.shape
    np.testing.assert_allclose(from_arrays.inner, from_folder.inner, atol=1e-3)
    np.testing.assert_allclose(from_arrays.outer, from_folder.outer, atol=1e-3)
    # pm-make-model's model.json holds positions to 0.01 mm and hues to 0.01 deg: equal to them.
    np.testing.assert_allclose(from_folder.inner, model.inner, atol=0.0051, rtol=0)
    np.testing.assert_allclose(from_folder.outer, model.outer, atol=0.0051, rtol=0)


def test_a_pass_that_cannot_make_a_model_raises(rig, made_model):
    view = pm.PassView(pm.read_image(str(made_model / "views" / "left_00.png")), pm.read_image(str(made_model / "views" / "right_00.png")),
                       np.eye(4), pm.read_image(str(made_model / "views" / "background_left_00.png")),
                       pm.read_image(str(made_model / "views" / "background_right_00.png")))
    with pytest.raises(pm.Error, match="views"):
        pm.build_model(rig, [view] * 3)
    with pytest.raises(ValueError, match="both or neither"):
        pm.PassView(view.left, view.right, np.eye(4), view.left)
    with pytest.raises(ValueError, match="rigid"):
        pm.PassView(view.left, view.right, np.ones((4, 4)))
    with pytest.raises(pm.Error, match="no_such_folder"):
        pm.build_model_from_folder(rig, "no_such_folder")
