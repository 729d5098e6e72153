"""sgtllc.pyi names exactly what the module binds: every public function and class, and every field and method
of each class (so a field added to the bindings without its stub line fails here)."""
import ast
import importlib.util
import inspect
import os
from pathlib import Path

import sgtllc

STUB = Path(sgtllc.__file__).with_name("sgtllc.pyi")
ROOT = Path(os.environ.get("SGTLLC_SOURCE_DIR", Path(__file__).resolve().parents[2]))
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



def test_settings_lines_are_those_of_the_settings_table():
    # The config classes' settings properties come from the settings table (each docstring names its YAML key);
    # scripts/update-stub.py writes their stub lines from them. A setting added to the table without running it,
    # or a type that differs, fails here.
    spec = importlib.util.spec_from_file_location("update_stub", ROOT / "scripts" / "update-stub.py")
    update_stub = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(update_stub)
    text = STUB.read_text()
    assert update_stub.regenerate(text, sgtllc) == text, "run: PYTHONPATH=build/python scripts/update-stub.py"
    assert len(update_stub.settings_of(sgtllc, "VerificationConfig")) == 30
    assert ("ground_ids", "Tuple[int, ...]") in update_stub.settings_of(sgtllc, "RegistrationConfig")
