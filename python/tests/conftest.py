"""Fixtures of the Python tests (ctest runs them: python_tests, with PYTHONPATH, PM_APPS_DIR and PM_DATA_DIR set)."""
import os
import pathlib
import subprocess

import pytest

import visp_photomodel as pm


def apps_dir() -> pathlib.Path:
    """The build tree's programs (pm-make-model, pm-track): the C++ side of the comparisons."""
    d = os.environ.get("PM_APPS_DIR")
    if not d:
        pytest.skip("PM_APPS_DIR is not set (ctest sets it)")
    return pathlib.Path(d)


def run_app(name: str, *args: str) -> None:
    subprocess.run([str(apps_dir() / name), *args], check=True, stdout=subprocess.DEVNULL)


@pytest.fixture(scope="session")
def rig():
    return pm.load_rig(pm.data_path("rig/pa10_stereo.json"))


@pytest.fixture(scope="session")
def made_model(tmp_path_factory):
    """The crab's all-around model as pm-make-model makes it (model.json and its views folder)."""
    out = tmp_path_factory.mktemp("model")
    run_app("pm-make-model", "--target", "C12", "--out", str(out / "c12"), "--quiet")
    return out / "c12"


@pytest.fixture(scope="session")
def model(made_model):
    return pm.load_model(str(made_model / "model.json"))
