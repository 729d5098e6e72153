#!/usr/bin/env python3
"""Writes the settings lines of python/sgtllc.pyi from the built module: in each config class, one `name: type`
line per setting property (the properties the settings table makes, whose docstrings name their YAML key), in the
table's order, where the class's settings lines stood; every other line of the stub is left as it is.

    PYTHONPATH=build/python /usr/bin/python3 scripts/update-stub.py [--check]

--check writes nothing and exits 1 if the stub is not what it would write (python/tests/test_stub.py runs it).
"""
import ast
import inspect
import sys
from pathlib import Path

STUB = Path(__file__).resolve().parent.parent / "python" / "sgtllc.pyi"


def type_name(value):
    if isinstance(value, tuple):
        return "Tuple[int, ...]"
    return type(value).__name__


def settings_of(module, name):
    """(field, type) of each setting property of class `name`, in binding order (the settings table's)."""
    cls = getattr(module, name, None)
    if not inspect.isclass(cls):
        return []
    fields = []
    for field, prop in vars(cls).items():
        if isinstance(prop, property) and "(YAML " in (prop.__doc__ or ""):
            fields.append((field, type_name(getattr(cls(), field))))
    return fields


def regenerate(text, module):
    lines = text.split("\n")
    edits = []  # (first line, last line, replacement lines), 0-based and inclusive, applied bottom-up
    for node in ast.parse(text).body:
        if not isinstance(node, ast.ClassDef):
            continue
        settings = settings_of(module, node.name)
        if not settings:
            continue
        names = {field for field, _ in settings}
        indent = " " * node.body[0].col_offset
        new = [f"{indent}{field}: {kind}" for field, kind in settings]
        old = [item for item in node.body if isinstance(item, ast.AnnAssign) and item.target.id in names]
        if old:
            for k, item in enumerate(old):  # the first old line takes them all, the others go
                edits.append((item.lineno - 1, item.end_lineno - 1, new if k == 0 else []))
        else:
            edits.append((node.lineno, node.lineno - 1, new))  # insert after the class line
    for first, last, replacement in sorted(edits, key=lambda e: e[0], reverse=True):
        lines[first:last + 1] = replacement
    return "\n".join(lines)


def main():
    import sgtllc

    text = STUB.read_text()
    wanted = regenerate(text, sgtllc)
    if "--check" in sys.argv[1:]:
        if wanted != text:
            print(f"{STUB} lacks or misorders settings: run scripts/update-stub.py", file=sys.stderr)
            return 1
        return 0
    if wanted != text:
        STUB.write_text(wanted)
        print(f"updated {STUB}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
