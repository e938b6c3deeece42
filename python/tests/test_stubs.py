"""The type stubs name exactly what the extension module offers (editors complete from them)."""
import ast
import os

import raycast
from raycast import _raycast


def stub_names():
    path = os.path.join(os.path.dirname(raycast.__file__), "_raycast.pyi")
    tree = ast.parse(open(path).read())
    module, scene = set(), set()
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and node.name == "Scene":
            scene = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            module.add(node.name)
        if isinstance(node, ast.AnnAssign):
            module.add(node.target.id)
    return module, scene


def test_stub_lists_every_public_name_of_the_extension():
    module, scene = stub_names()
    assert {n for n in dir(_raycast) if not n.startswith("__")} | {"__version__"} <= module
    assert {n for n in dir(_raycast.Scene) if not n.startswith("_")} <= scene
    assert scene - {"__init__"} <= set(dir(_raycast.Scene))
