"""The type stubs say what the module holds: every public class, function and member of visp_photomodel and of its
lab, and nothing else."""
import ast
import pathlib

import visp_photomodel as pm

STUBS = pathlib.Path(__file__).resolve().parents[1] / "stubs" / "visp_photomodel-stubs"


def stubbed(path: pathlib.Path) -> dict:
    """{name: set of member names (empty for a function)} of a stub file's classes and functions."""
    out = {}
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef) and not n.name.startswith("_")}
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
