"""The layers hold (docs/architecture.md, issue 22).

- no import cycle among bearinglab's modules, counting every import (inside functions
  too) and the package ``__init__`` that Python runs to reach a submodule; nothing in the
  library imports ``bearinglab.cli``;
- no package imports a private module (``_name``) of another package; the parallel engine
  (``bearinglab.engine``) is on the ground floor, and work fans out to other processes
  only through it (issue 30);
- library messages name an input by its public name (``speed_rpm``), never by a
  command-line flag (``--speed-rpm``): the CLI words them its own way;
- the docstrings of the public functions and methods document every parameter of their
  signature, and document no parameter that is not there (after python-control's
  ``doc/docstrings_test.py``);
- the entry points users call are exported from ``bearinglab``.

The source is read with ``ast``; nothing here imports an analysis to find its imports.
"""

from __future__ import annotations

import ast
import functools
import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import pytest

import bearinglab

SRC = Path(bearinglab.__file__).resolve().parent.parent
PACKAGE = SRC / "bearinglab"


# ------------------------------------------------------------------ the module graph
def _modules() -> dict[str, tuple[Path, bool]]:
    """Dotted name -> (file, is a package's __init__) of every module under bearinglab."""
    found = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(SRC).with_suffix("").parts)
        is_package = parts[-1] == "__init__"
        found[".".join(parts[:-1] if is_package else parts)] = (path, is_package)
    return found


MODULES = _modules()


def _known(name: str) -> str | None:
    """The nearest module of ours that ``name`` (a module or a name in one) lives in."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


def _targets(module: str, is_package: bool, node: ast.Import | ast.ImportFrom) -> list[str]:
    """The modules of ours an import statement names (relative imports resolved; in
    ``from pkg import name`` the submodule when ``name`` is one, else ``pkg``)."""
    if isinstance(node, ast.Import):
        return [alias.name for alias in node.names]
    if node.level:
        package = module.split(".") if is_package else module.split(".")[:-1]
        package = package[: len(package) - (node.level - 1)]
        base = ".".join(package + ([node.module] if node.module else []))
    else:
        base = node.module or ""
    return [
        f"{base}.{alias.name}" if f"{base}.{alias.name}" in MODULES else base
        for alias in node.names
    ]


@functools.lru_cache(maxsize=1)
def import_graph() -> dict[str, dict[str, int]]:
    """module -> {module it imports: line of the first such import}.

    Every ``import`` counts, at module level or inside a function. Importing ``a.b.c``
    runs ``a/__init__`` and ``a/b/__init__`` first, so those count too, except the
    packages the importer itself lives in (Python has begun them already). A
    submodule's ``from . import name`` (``name`` not a submodule) is an import of its
    own package's ``__init__`` and counts.
    """
    graph: dict[str, dict[str, int]] = {}
    for module, (path, is_package) in MODULES.items():
        own = module if is_package else module.rpartition(".")[0]
        edges: dict[str, int] = {}
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            if not isinstance(node, (ast.Import, ast.ImportFrom)):
                continue
            for name in _targets(module, is_package, node):
                target = _known(name)
                if target is None or target == module:
                    continue
                edges.setdefault(target, node.lineno)
                parts = target.split(".")
                for i in range(1, len(parts)):
                    ancestor = ".".join(parts[:i])
                    if ancestor in MODULES and not f"{own}.".startswith(f"{ancestor}."):
                        edges.setdefault(ancestor, node.lineno)
        graph[module] = edges
    return graph


def strongly_connected(graph: dict[str, dict[str, int]]) -> list[list[str]]:
    """Tarjan's strongly connected components with more than one module (iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(graph[root]))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, successors = work[-1]
            for nxt in successors:
                if nxt not in index:
                    index[nxt] = low[nxt] = len(index)
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(graph[nxt])))
                    break
                if nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return found


def _where(module: str) -> str:
    return MODULES[module][0].relative_to(SRC).as_posix()


def test_the_graph_sees_imports_inside_functions_and_packages():
    graph = import_graph()
    # plotting imports peak_label inside draw_spectrum, from signal/peaks.py
    assert "bearinglab.signal.peaks" in graph["bearinglab.plotting"]
    assert "bearinglab.signal" in graph["bearinglab.plotting"]  # its __init__ runs first
    # a package's own __init__ is not counted for its submodules' relative imports
    assert "bearinglab.life" not in graph["bearinglab.life.life"]
    assert strongly_connected({"a": {"b": 1}, "b": {"c": 1}, "c": {"a": 1}, "d": {}}) == [
        ["a", "b", "c"]
    ]


def test_no_import_cycles():
    graph = import_graph()
    lines = []
    for component in strongly_connected(graph):
        members = set(component)
        lines.append("cycle: " + ", ".join(component))
        for module in component:
            for target, line in sorted(graph[module].items()):
                if target in members:
                    lines.append(f"  {_where(module)}:{line} imports {target}")
    assert not lines, "\n".join(lines)


def test_the_library_never_imports_the_command_line():
    wrong = [
        f"{_where(module)}:{line} imports {target}"
        for module, edges in import_graph().items()
        if not module.startswith("bearinglab.cli")
        for target, line in edges.items()
        if target == "bearinglab.cli" or target.startswith("bearinglab.cli.")
    ]
    assert not wrong, "\n".join(wrong)


def private_imports(graph: dict[str, dict[str, int]]) -> list[str]:
    """``file:line imports module`` for each import of a private module (a ``_name`` in
    its dotted path) from outside the package that holds it."""
    wrong = []
    for module, edges in graph.items():
        for target, line in edges.items():
            parts = target.split(".")
            private = next((i for i, p in enumerate(parts) if p.startswith("_")), None)
            if private is None:
                continue
            owner = ".".join(parts[:private])
            if module != owner and not module.startswith(f"{owner}."):
                wrong.append(f"{_where(module)}:{line} imports {target}")
    return wrong


def test_no_package_imports_a_private_module_of_another():
    """A ``_module`` is its package's own business (dataset imported ``study._inputs``)."""
    wrong = private_imports(import_graph())
    assert not wrong, "make the module public or move what is shared:\n" + "\n".join(wrong)


def test_the_private_import_rule_finds_one():
    graph = {
        "bearinglab.dataset.generate": {"bearinglab.study._inputs": 92},
        "bearinglab.study.runner": {"bearinglab.study._inputs": 1},
        "bearinglab.catalog.lookup": {"bearinglab.catalog._data": 21},
    }
    assert private_imports(graph) == [
        "bearinglab/dataset/generate.py:92 imports bearinglab.study._inputs"
    ]


#: What the engine may import of bearinglab: the ground floor.
ENGINE_IMPORTS = {"bearinglab.errors", "bearinglab.files"}
#: Modules that start processes of their own, and why they still do (the issue that ends
#: it): every other fan-out runs on bearinglab.engine.
OWN_PROCESSES = {
    # stiffness_map's worker processes: the map moves onto STIFFNESS and the study runner
    # (issue 30, item 1); its workers are started with SIGINT held back meanwhile
    "bearinglab.quasistatic.study": "concurrent",
}
PARALLEL = ("distributed", "dask", "concurrent", "multiprocessing")


def test_the_engine_is_on_the_ground_floor():
    graph = import_graph()
    engine = [m for m in MODULES if m == "bearinglab.engine" or m.startswith("bearinglab.engine.")]
    assert len(engine) >= 4
    wrong = [
        f"{_where(module)}:{line} imports {target}"
        for module in engine
        for target, line in graph[module].items()
        if target not in ENGINE_IMPORTS and target not in engine
    ]
    assert not wrong, "the engine imports only errors and files:\n" + "\n".join(wrong)


def test_work_fans_out_only_on_the_engine():
    """study, dataset, benchmark and trend run on bearinglab.engine: no module but the
    engine's starts processes or talks to dask (the trend imported the study's runner, the
    benchmark had a process pool of its own)."""
    wrong = []
    for module, (path, _) in MODULES.items():
        if module.startswith("bearinglab.engine"):
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and not node.level:
                names = [node.module or ""]
            else:
                continue
            for name in names:
                top = name.split(".")[0]
                if top in PARALLEL and OWN_PROCESSES.get(module) != top:
                    wrong.append(f"{_where(module)}:{node.lineno} imports {name}")
    assert not wrong, "run it on bearinglab.engine:\n" + "\n".join(wrong)


# ------------------------------------------------------------------ no flags in messages
#: Packages not scanned for flag names: cli/ words its own messages; study/ and dataset/
#: are being rewritten (issue 22) and join this test when they land.
NOT_SCANNED = ("cli",)
#: (file, what the literal is): literals that hold ``--x`` and are no flag.
NOT_FLAGS = {
    # the generator of docs/json.md, which documents the command line's --json
    ("units.py", "# The JSON contract"),
}
#: ``--name`` as a flag; CSS custom properties (``--ink:``, ``var(--ink)``) are not flags
FLAG = re.compile(r"(?<![\w-])(?<!var\()--[a-z][a-z0-9-]*+(?!:)")


def _docstrings(tree: ast.AST) -> set[int]:
    """ids of the docstring constants (documentation may show a command line)."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                found.add(id(body[0].value))
    return found


def test_library_messages_name_inputs_not_flags():
    wrong = []
    for path in sorted(PACKAGE.rglob("*.py")):
        relative = path.relative_to(PACKAGE).as_posix()
        if relative.split("/")[0] in NOT_SCANNED:
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        docstrings = _docstrings(tree)
        for node in ast.walk(tree):
            if not (isinstance(node, ast.Constant) and isinstance(node.value, str)):
                continue
            if id(node) in docstrings or not FLAG.search(node.value):
                continue
            if any(relative == f and node.value.startswith(s) for f, s in NOT_FLAGS):
                continue
            flags = ", ".join(FLAG.findall(node.value))
            wrong.append(f"bearinglab/{relative}:{node.lineno}: {flags}")
    assert not wrong, "name the input in snake_case, not the flag:\n" + "\n".join(wrong)


def test_the_flag_pattern():
    assert FLAG.findall("give it (command line: --speed-rpm)") == ["--speed-rpm"]
    assert not FLAG.search(":root { --ink: #1d2733; } a { color: var(--ink) }")
    assert not FLAG.search("a -- b, x--y, 2--3")


# ------------------------------------------------------------------ docstrings
#: Subpackages whose ``__all__`` is not checked: cli/ is no library API; study/ and
#: dataset/ are being rewritten (issue 22).
NOT_CHECKED = {"cli"}
#: (function, parameter) left out of its Parameters section, each with its reason (none
#: today: every public callable lists every parameter, issue 30).
UNDOCUMENTED: set[tuple[str, str]] = set()
SECTION_RULE = re.compile(r"-{3,}")
PARAMETER_LINE = re.compile(r"(\*{0,2}\w+(?:\s*,\s*\*{0,2}\w+)*)\s*(?::.*)?")


def documented_parameters(doc: str) -> set[str]:
    """The names a numpydoc ``Parameters`` section lists (``a, b : float`` gives two)."""
    lines = inspect.cleandoc(doc).splitlines()
    names: set[str] = set()
    inside = False
    for i, line in enumerate(lines):
        following = lines[i + 1] if i + 1 < len(lines) else ""
        if SECTION_RULE.fullmatch(following.strip()) and line.strip():
            inside = line.strip() == "Parameters"
            continue
        if not inside or SECTION_RULE.fullmatch(line.strip()):
            continue
        if line.startswith(">>>"):
            inside = False
            continue
        entry = PARAMETER_LINE.fullmatch(line)
        if entry and line[:1] not in ("", " ") and (":" in line or following.startswith(" ")):
            names |= {n.strip().lstrip("*") for n in entry.group(1).split(",")}
    return names


def public_callables():
    """(dotted name, function) of every function in ``bearinglab.__all__`` and the
    ``__all__`` of each public subpackage, and of every public method of the classes
    there (those defined in the class itself)."""
    packages = [bearinglab] + [
        importlib.import_module(f"bearinglab.{info.name}")
        for info in pkgutil.iter_modules(bearinglab.__path__)
        if info.ispkg and not info.name.startswith("_") and info.name not in NOT_CHECKED
    ]
    seen = set()
    for package in packages:
        for exported in getattr(package, "__all__", ()):
            obj = getattr(package, exported)
            if inspect.isfunction(obj):
                candidates = [obj]
            elif inspect.isclass(obj) and obj.__module__.startswith("bearinglab"):
                candidates = []
                for attr, value in vars(obj).items():
                    if isinstance(value, (staticmethod, classmethod)):
                        value = value.__func__
                    if not attr.startswith("_") and inspect.isfunction(value):
                        candidates.append(value)
            else:
                continue
            for f in candidates:
                key = f"{f.__module__}.{f.__qualname__}"
                if key not in seen:
                    seen.add(key)
                    yield key, f


def docstring_problems() -> list[str]:
    """What is wrong with the public docstrings: a parameter (other than self, cls,
    ``*args`` and ``**kwargs``) that the numpydoc ``Parameters`` section does not list (a
    mention in the prose does not count), or a listed name that is no parameter."""
    problems = []
    for where, f in public_callables():
        doc = inspect.getdoc(f) or ""
        parameters = inspect.signature(f).parameters.values()
        documented = documented_parameters(doc)
        for p in parameters:
            if p.name in ("self", "cls") or p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
                continue
            if p.name not in documented and (where, p.name) not in UNDOCUMENTED:
                problems.append(f"{where}: parameter {p.name} is not documented")
        names = {p.name for p in parameters}
        for name in sorted(documented - names):
            problems.append(f"{where}: documents {name}, which is not a parameter")
    return problems


def test_the_docstring_reader():
    doc = """Do it.

    Parameters
    ----------
    radial_load, axial_load : float
        Loads [N].
    tag
        A name.
    **options :
        Passed on.

    Returns
    -------
    float
        Not a parameter.

    >>> f(1)
    9
    """
    assert documented_parameters(doc) == {"radial_load", "axial_load", "tag", "options"}
    # a mention in the prose documents nothing, quoted or not
    assert not documented_parameters("The speed ``speed_rpm=1797`` [rpm].")
    assert not documented_parameters("Uses `speed_rpm` and speed.")
    # nor does a name in another section, or in a Parameters section's description lines
    other = """Do it.

    Parameters
    ----------
    speed : float
        Shaft speed [rad/s]; see also
        load : below.

    Returns
    -------
    load : float
        The load [N].
    """
    assert documented_parameters(other) == {"speed"}


def test_public_docstrings_match_their_signatures():
    callables = list(public_callables())
    assert len(callables) > 200  # the walk found the API
    problems = docstring_problems()
    assert not problems, f"{len(problems)} docstring(s) to fix:\n" + "\n".join(problems)


# ------------------------------------------------------------------ exports
@pytest.mark.parametrize(
    "name",
    [
        "analyze_file",
        "analyze_signal",
        "noise_analysis",
        "trend_records",
        "run_benchmark",
        "simulate_record",
        "bearing_friction",
        "rating_life",
        "ring_modes",
        "inner_ring_orbit",
        "stiffness_map",
    ],
)
def test_the_entry_points_users_call_are_exported(name):
    assert name in bearinglab.__all__
    assert callable(getattr(bearinglab, name))
