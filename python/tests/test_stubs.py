"""The type stubs say what the module holds: every public class, function and member of visp_photomodel and of its
lab, and nothing else; and what the module returns is of the types they say."""
import ast
import pathlib
import typing

import numpy as np
import numpy.typing as npt

import visp_photomodel as pm

STUBS = pathlib.Path(__file__).resolve().parents[1] / "stubs" / "visp_photomodel-stubs"


def stubbed(path: pathlib.Path) -> dict:
    """{name: set of member names (empty for a function)} of a stub file's classes and functions."""
    out = {}
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef) and not n.name.startswith("_")}
            out[node.name] |= {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}  # an enumeration's values
        elif isinstance(node, ast.FunctionDef):
            out[node.name] = set()
    return out


def held(module) -> dict:
    out = {}
    for name in dir(module):
        obj = getattr(module, name)
        if name.startswith("_") or type(obj).__name__ == "module":
            continue
        if isinstance(obj, type):
            out[name] = {m for m in vars(obj) if not m.startswith("_")}
        elif callable(obj):
            out[name] = set()
    return out


def test_the_stubs_hold_what_the_module_holds():
    for module, stub in ((pm, STUBS / "__init__.pyi"), (pm.lab, STUBS / "lab.pyi")):
        want, got = held(module), stubbed(stub)
        assert set(got) == set(want), f"{stub.name}: {set(got) ^ set(want)}"
        for name, members in want.items():
            assert got[name] == members, f"{stub.name}, {name}: {got[name] ^ members}"


def properties(path: pathlib.Path, cls: str) -> dict:
    """{property: its annotation's source} of class cls in a stub file."""
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.ClassDef) and node.name == cls:
            return {n.name: ast.unparse(n.returns) for n in node.body if isinstance(n, ast.FunctionDef)
                    and any(isinstance(d, ast.Name) and d.id == "property" for d in n.decorator_list)}
    raise KeyError(cls)


NAMES = {"Any": typing.Any, "Dict": typing.Dict, "List": typing.List, "Optional": typing.Optional, "Sequence": typing.Sequence,
         "Tuple": typing.Tuple, "np": np, "npt": npt, "Pose": npt.NDArray[np.float64], "Image": npt.NDArray[np.uint8],
         **{n: getattr(pm, n) for n in dir(pm) if isinstance(getattr(pm, n), type)}}


def conforms(value, t) -> bool:
    """value is of the annotation t (as far as a stub says: tuples by length, arrays by dtype)."""
    origin, args = typing.get_origin(t), typing.get_args(t)
    if t is type(None):
        return value is None
    if origin is typing.Union:
        return any(conforms(value, a) for a in args)
    if origin is tuple:
        return isinstance(value, tuple) and len(value) == len(args) and all(conforms(v, a) for v, a in zip(value, args))
    if origin is list:
        return isinstance(value, list) and all(conforms(v, args[0]) for v in value)
    if origin is dict:
        return isinstance(value, dict) and all(conforms(k, args[0]) and conforms(v, args[1]) for k, v in value.items())
    if origin is np.ndarray:
        dtype = typing.get_args(args[1])[0] if len(args) > 1 else None
        return isinstance(value, np.ndarray) and (dtype is None or value.dtype == dtype)
    if t is float:
        return isinstance(value, float)
    if t in (int, bool, str):
        return type(value) is t
    return isinstance(value, t)


def test_what_the_module_returns_is_of_the_types_the_stubs_say(rig, model):
    left, right = pm.lab.Scene("C12", seed=1).render(rig, np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.5], [0, 0, 0, 1.0]]), 0)
    tracker = pm.Tracker(rig, model)
    result = tracker.track(left, right)
    view = pm.PassView(left, right, np.eye(4))
    checked = 0
    for cls, obj in (("StereoRig", rig), ("Camera", rig.left), ("PhotoModel", model), ("TrackResult", result), ("Tracker", tracker),
                     ("PassView", view), ("TrackState", result.state)):
        for name, ann in properties(STUBS / "__init__.pyi", cls).items():
            t = eval(ann, dict(NAMES))
            value = getattr(obj, name)
            assert conforms(value, t), f"{cls}.{name}: {type(value).__name__} {value!r:.60}, the stub says {ann}"
            checked += 1
    assert checked > 30
    assert conforms(result.sigma, typing.Optional[typing.Tuple[float, float, float, float, float, float]])
    assert not conforms([1.0] * 6, typing.Tuple[float, float, float, float, float, float])  # the check can fail
