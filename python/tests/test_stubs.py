# SPDX-License-Identifier: MIT
"""The type stubs, python/disksim/__init__.pyi, against the module they
describe: every public name of the one is in the other, functions and
methods with the same parameters and defaults, properties as properties,
classes with the same bases and fields, the Literal names equal to the
module's tuples. The module is C, so nothing else keeps the two in step:
a name added to a method table without a line in the stub fails here."""
import ast
import inspect
import os
import types

import disksim

STUB = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "disksim",
                    "__init__.pyi")

def stub():
    with open(STUB) as f:
        return ast.parse(f.read(), STUB)


def public(names):
    return {name for name in names if not name.startswith("_")}


def top_level(tree):
    """Name -> node of what the stub's top level defines."""
    found = {}
    for node in tree.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            found[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            found[node.target.id] = node
        elif isinstance(node, ast.Assign):
            for target in node.targets:
                found[target.id] = node
    return found


def members(cls_node):
    """(methods, properties) of a stub class: name -> FunctionDef."""
    methods, properties = {}, {}
    for node in cls_node.body:
        if isinstance(node, ast.FunctionDef):
            is_property = any(isinstance(d, ast.Name) and d.id == "property"
                              for d in node.decorator_list)
            (properties if is_property else methods)[node.name] = node
    return methods, properties


def stub_class(name):
    return top_level(stub())[name]


def runtime_names(cls, kind):
    """A class's own members of one kind (its method table or its getters)."""
    return {name for name, member in vars(cls).items() if isinstance(member, kind)}


def stub_parameters(function, drop_self=False):
    """A stub def's parameters as (name, kind, repr of default) like the runtime's."""
    a = function.args
    P = inspect.Parameter
    positional = [(arg, P.POSITIONAL_ONLY) for arg in a.posonlyargs] + \
                 [(arg, P.POSITIONAL_OR_KEYWORD) for arg in a.args]
    defaults = [None] * (len(positional) - len(a.defaults)) + list(a.defaults)
    out = [(arg.arg, kind, default) for (arg, kind), default in zip(positional, defaults)]
    if a.vararg:
        out.append((a.vararg.arg, P.VAR_POSITIONAL, None))
    out += [(arg.arg, P.KEYWORD_ONLY, default) for arg, default in zip(a.kwonlyargs, a.kw_defaults)]
    if a.kwarg:
        out.append((a.kwarg.arg, P.VAR_KEYWORD, None))
    out = [(name, kind, repr(ast.literal_eval(d)) if d is not None else None)
           for name, kind, d in out]
    return out[1:] if drop_self else out


def runtime_parameters(function, drop_self=False):
    out = [(p.name, p.kind, None if p.default is p.empty else repr(p.default))
           for p in inspect.signature(function).parameters.values()]
    return out[1:] if drop_self else out


def test_the_stub_has_every_public_name_of_the_module_and_no_other():
    names = top_level(stub())
    assert public(names) == public(dir(disksim))
    assert "__version__" in names and isinstance(disksim.__version__, str)
    assert sorted(ast.literal_eval(names["__all__"].value)) == sorted(disksim.__all__)


def test_the_stub_has_every_method_and_property_of_sim_and_writer_and_no_other():
    for cls, slots_wanted in ((disksim.Sim, {"__len__", "__bool__"}), (disksim.Writer, set())):
        methods, properties = members(stub_class(cls.__name__))
        # The method table (step, run, ... and __enter__, __exit__, __reduce__),
        # the type's slots that a type checker must know of (Sim's __len__,
        # __bool__: len(s) and truth; __init__ is declared, __repr__ is
        # object's) and the getters: a property typed as a method would be
        # called by a type checker's user, and fail.
        slots = runtime_names(cls, types.WrapperDescriptorType) - {"__init__", "__repr__"}
        assert slots == slots_wanted
        assert set(methods) - {"__init__"} == runtime_names(cls, types.MethodDescriptorType) | slots
        assert set(properties) == runtime_names(cls, types.GetSetDescriptorType)
        assert public(methods) | public(properties) == public(dir(cls))


def test_functions_and_methods_have_the_modules_parameters_and_defaults():
    names = top_level(stub())
    for name, node in names.items():
        if isinstance(node, ast.FunctionDef) and name != "memory_needed":
            assert stub_parameters(node) == runtime_parameters(getattr(disksim, name)), name
    for cls in (disksim.Sim, disksim.Writer):
        methods, _ = members(names[cls.__name__])
        for name, node in methods.items():
            if name != "__init__":
                assert stub_parameters(node, drop_self=True) == \
                    runtime_parameters(getattr(cls, name), drop_self=True), name
        assert stub_parameters(methods["__init__"], drop_self=True) == runtime_parameters(cls)


def test_memory_needed_takes_sims_arguments():
    # The module declares it (n, radius, **arguments) and parses them as
    # Sim's; the stub spells them out.
    assert runtime_parameters(disksim.memory_needed)[-1][1] is inspect.Parameter.VAR_KEYWORD
    assert stub_parameters(stub_class("memory_needed")) == runtime_parameters(disksim.Sim)


def base_name(node):
    return (node.value if isinstance(node, ast.Subscript) else node).id


def test_classes_have_the_modules_bases():
    for name, node in top_level(stub()).items():
        if isinstance(node, ast.ClassDef):
            # typeshed's structseq is what a C struct sequence is to a type
            # checker; at run time it is a tuple.
            stub_bases = [base_name(b) for b in node.bases if base_name(b) != "structseq"]
            runtime = [b.__name__ for b in getattr(disksim, name).__bases__]
            assert (stub_bases or ["object"]) == runtime, name


def test_frame_and_contacts_have_the_modules_fields_in_order():
    for name in ("Frame", "Contacts"):
        node = stub_class(name)
        declared = next(n for n in node.body if isinstance(n, ast.AnnAssign)
                        and n.target.id == "__match_args__")
        fields = getattr(disksim, name).__match_args__
        assert ast.literal_eval(declared.value) == fields, name
        assert list(members(node)[1]) == list(fields), name
        assert getattr(disksim, name).n_sequence_fields == len(fields), name


def test_the_literal_names_are_the_modules_tuples():
    names = top_level(stub())
    checked = 0
    for name, node in names.items():
        # NAMES: Final[tuple[_Alias, ...]] with _Alias = Literal["a", "b"]
        annotation = getattr(node, "annotation", None)
        if not (isinstance(annotation, ast.Subscript) and annotation.value.id == "Final"
                and isinstance(annotation.slice, ast.Subscript)
                and annotation.slice.value.id == "tuple"):
            continue
        alias = annotation.slice.slice.elts[0].id
        literal = names[alias].value
        assert literal.value.id == "Literal", alias
        assert tuple(ast.literal_eval(e) for e in literal.slice.elts) == getattr(disksim, name), \
            name
        checked += 1
    # INTEGRATORS, BOUNDARIES, PLACEMENTS, BROADPHASES, MASS_RULES, GROWTH_STATES, THERMOSTATS,
    # FORMATS
    assert checked == 8


def test_the_package_says_it_is_typed():
    # PEP 561: py.typed beside the stub, and setup.py ships both.
    assert os.path.isfile(os.path.join(os.path.dirname(STUB), "py.typed"))
