"""The type stubs (python/subdiv/__init__.pyi) name what the package has,
with the same parameters."""

import ast
import inspect
import pathlib

import subdiv


def stub_tree():
    path = pathlib.Path(subdiv.__file__).with_name("__init__.pyi")
    return ast.parse(path.read_text())


def test_every_public_name_has_a_stub():
    names = set()
    for node in stub_tree().body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    assert set(subdiv.__all__) <= names, set(subdiv.__all__) - names


def parameters(node):
    arguments = node.args
    return [a.arg for a in arguments.posonlyargs + arguments.args + arguments.kwonlyargs] + \
        ([arguments.kwarg.arg] if arguments.kwarg else [])


def test_functions_take_the_stubs_parameters():
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            runtime = inspect.signature(getattr(subdiv, node.name))
            assert parameters(node) == list(runtime.parameters), node.name
        if isinstance(node, ast.ClassDef) and node.name == "Mesh":
            init = next(n for n in node.body if isinstance(n, ast.FunctionDef) and n.name == "__init__")
            assert parameters(init) == list(inspect.signature(subdiv.Mesh.__init__).parameters)
