"""What an installed user reads, who has no source tree: the docstrings point to no file of it,
and the type stubs (python/capsubot.pyi, installed as capsubot-stubs) describe the module as it
is: the same public names, and for every function the same keyword-only parameters, in the same
order, with the same defaults, and a return type of the same kind. The module's side is read
from the signature pybind11 writes on the first line of each docstring."""

import ast
import math
import pathlib
import re

import pytest

import capsubot

STUB = pathlib.Path(__file__).resolve().parents[1] / "capsubot.pyi"


def stub_module():
    return ast.parse(STUB.read_text(), filename=str(STUB))


def stub_functions():
    return {node.name: node for node in stub_module().body if isinstance(node, ast.FunctionDef)}


def stub_names():
    names = set(stub_functions())
    for node in stub_module().body:
        if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return names


def module_functions():
    return sorted(name for name in dir(capsubot)
                  if not name.startswith("_") and callable(getattr(capsubot, name)))


def module_signature(name):
    """The function's signature as pybind11 writes it, parsed as a Python definition:
    `solve(*, A: Optional[float] = None, c: float, ...) -> dict`."""
    first_line = getattr(capsubot, name).__doc__.splitlines()[0]
    assert first_line.startswith(name + "("), first_line
    return ast.parse(f"def {first_line}: ...").body[0]


def default_value(node):
    """A default as a Python value; pybind11 writes an infinity as `inf`."""
    if isinstance(node, ast.Name) and node.id == "inf":
        return math.inf
    return ast.literal_eval(node)


def parameters(function):
    """(name, has a default, default) of each keyword-only parameter; no other kind allowed."""
    args = function.args
    assert not (args.posonlyargs or args.args or args.vararg or args.kwarg), function.name
    return [(a.arg, d is not None, None if d is None else default_value(d))
            for a, d in zip(args.kwonlyargs, args.kw_defaults)]


def outer_type(annotation):
    """dict for `dict` or `dict[str, Any]`, list for `list[...]`."""
    node = annotation.value if isinstance(annotation, ast.Subscript) else annotation
    return ast.unparse(node)


# A path into the source tree ("docs/model.md", "results/", "examples/robot.toml") or a file
# of it by name.
SOURCE_FILE = re.compile(
    r"\b(docs|results|examples|scripts|python|src|include|tests)/|\.(md|cpp|hpp)\b|README")


@pytest.mark.parametrize("name", ["capsubot"] + module_functions())
def test_docstrings_point_to_no_file_of_the_source_tree(name):
    doc = capsubot.__doc__ if name == "capsubot" else getattr(capsubot, name).__doc__
    assert [m.group(0) for m in SOURCE_FILE.finditer(doc)] == []


def test_stubs_and_module_have_the_same_public_names():
    public = {name for name in dir(capsubot) if not name.startswith("_")} | {"__version__"}
    assert stub_names() == public


@pytest.mark.parametrize("name", module_functions())
def test_each_function_has_the_modules_parameters_defaults_and_return_kind(name):
    stub = stub_functions()[name]
    module = module_signature(name)
    assert parameters(stub) == parameters(module)
    assert outer_type(stub.returns) == outer_type(module.returns)


def test_the_module_has_functions_to_check():
    # The module's thirteen functions: a parse that found none would check nothing.
    assert len(module_functions()) == 13


NAMES = re.compile(r"[A-Za-z_]\w*(?:, [A-Za-z_]\w*)*,?")


def documented_arguments(doc):
    """The names the docstring documents: each argument line is four spaces, the names
    (comma-separated; a list ending with a comma goes on on the next line), then the text, at
    column 12 or after two spaces."""
    names, lines = set(), doc.splitlines()
    for i, line in enumerate(lines):
        if not line.startswith("    ") or line.startswith("     "):
            continue
        match = NAMES.match(line, 4)
        if match is None:
            continue
        end, group = match.end(), match.group(0)
        if not (line[end:end + 2] == "  " or (end <= 11 and line[end:12].isspace()
                                              and line[12:13] not in ("", " "))
                or (group.endswith(",") and end == len(line))):
            continue
        while group.endswith(",") and i + 1 < len(lines):
            i += 1
            more = NAMES.match(lines[i], len(lines[i]) - len(lines[i].lstrip()))
            group += " " + more.group(0)
        names.update(name for name in group.rstrip(",").split(", "))
    return names


@pytest.mark.parametrize("name", module_functions())
def test_the_docstring_documents_the_arguments_of_the_signature(name):
    # Each keyword argument, and no other (the library's tables write most of those lines,
    # python/keyword_doc.hpp).
    documented = documented_arguments(getattr(capsubot, name).__doc__)
    arguments = [a for a, _, _ in parameters(module_signature(name))]
    assert [a for a in arguments if a not in documented] == []
    assert sorted(documented - set(arguments)) == []


def test_the_parse_of_argument_lines_finds_each_form():
    doc = ("f(*, a) -> dict\n\nArguments:\n    a       one\n    long_name  two\n"
           "    b, c  three\n    d, e,\n            f  four\n            not_a_name here\n")
    assert documented_arguments(doc) == {"a", "long_name", "b", "c", "d", "e", "f"}
