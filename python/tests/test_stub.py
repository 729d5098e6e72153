"""sgtllc.pyi names exactly what the module binds: every public function and class, and every field and method
of each class (so a field added to the bindings without its stub line fails here)."""
import ast
import inspect
from pathlib import Path

import sgtllc

STUB = Path(sgtllc.__file__).with_name("sgtllc.pyi")
HELPERS = {"ArrayLike", "Nodes"}  # type aliases of the stub itself


def stub_names():
    tree = ast.parse(STUB.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            names = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    names.add(item.name)
                elif isinstance(item, ast.AnnAssign):
                    names.add(item.target.id)
            members[node.name] = names
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
        elif isinstance(node, (ast.AnnAssign, ast.Assign)):
            target = node.target if isinstance(node, ast.AnnAssign) else node.targets[0]
            top.add(target.id)
    return top - HELPERS, members


def public(names):
    return {n for n in names if not n.startswith("_") and "[" not in n}  # bind_map adds KeysView[int] etc.


def test_stub_lists_every_binding():
    top, members = stub_names()
    assert top - {"__version__"} == public(dir(sgtllc))
    for name, stub_members in members.items():
        cls = getattr(sgtllc, name)
        if not inspect.isclass(cls) or issubclass(cls, Exception):
            continue
        bound = public(dir(cls))
        if hasattr(cls, "__members__"):  # enums: the values, not pybind11's helpers
            bound = set(cls.__members__)
        elif name.endswith(("List", "Map")):  # bound containers: the stub's base class gives their methods
            continue
        stub = stub_members - {"__init__", "__len__"}
        assert stub == bound, name


def stub_annotations():
    tree = ast.parse(STUB.read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {item.target.id: ast.unparse(item.annotation)
                              for item in node.body if isinstance(item, ast.AnnAssign)}
    return out


def python_type(value):
    if isinstance(value, tuple):
        return "Tuple[int, ...]"
    return type(value).__name__


def test_settings_have_the_stub_type_of_their_value():
    # The settings properties come from the settings table (each docstring names its YAML key); the stub must give
    # each the type of its value, so a setting added to the table without its stub line fails here.
    annotations = stub_annotations()
    checked = 0
    for name, members in annotations.items():
        cls = getattr(sgtllc, name, None)
        if not inspect.isclass(cls):
            continue
        for field, prop in vars(cls).items():
            if not isinstance(prop, property) or "(YAML " not in (prop.__doc__ or ""):
                continue
            default = getattr(cls(*([] if name != "ClassClusterConfig" else [])), field)
            assert members.get(field) == python_type(default), f"{name}.{field}: stub {members.get(field)}"
            checked += 1
    assert checked >= 120
