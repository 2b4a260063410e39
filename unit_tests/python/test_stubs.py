"""The type stubs (__init__.pyi) describe the module as it is: every public name, every member of its classes."""

import ast
import inspect
from pathlib import Path

import lrsvo

STUB = Path(lrsvo.__file__).with_name("__init__.pyi")


def stub_classes_and_functions():
    tree = ast.parse(STUB.read_text())
    names = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            members = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
            members |= {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
            names[node.name] = members
        elif isinstance(node, ast.FunctionDef):
            names[node.name] = None
    return names


def test_the_stubs_name_every_public_name_and_no_other():
    public = {name for name in dir(lrsvo) if not name.startswith("_")}
    assert set(stub_classes_and_functions()) == public


def test_the_stubs_name_every_member_of_every_class():
    for name, members in stub_classes_and_functions().items():
        cls = getattr(lrsvo, name)
        if members is None:
            assert callable(cls), name
            continue
        real = {member for member in dir(cls) if not member.startswith("_")}
        if issubclass(cls, Exception):
            real -= {member for member in dir(Exception) if not member.startswith("_")}
        assert real <= members, f"{name}: not in the stubs: {sorted(real - members)}"
        dataclass_fields = set(getattr(cls, "__dataclass_fields__", {}))
        assert members - {"__init__", "__iter__", "__next__", "__contains__"} <= real | dataclass_fields, name


def test_every_public_call_has_a_docstring():
    for name in dir(lrsvo):
        if name.startswith("_"):
            continue
        obj = getattr(lrsvo, name)
        assert inspect.getdoc(obj), name
        if isinstance(obj, type):
            for member, value in vars(obj).items():
                if not member.startswith("_") and callable(value):
                    assert inspect.getdoc(value), f"{name}.{member}"
