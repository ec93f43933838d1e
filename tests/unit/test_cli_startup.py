"""Start-up of the command line: commands are imported only when run (issue 12)."""

import ast
import importlib
import json
import subprocess
import sys
from pathlib import Path

import pytest

from bearinglab.cli._app import COMMANDS

CLI = Path(__file__).resolve().parents[2] / "src" / "bearinglab" / "cli"
#: Modules a command should not pay for unless it uses them.
HEAVY = ("scipy", "pandas", "numba", "matplotlib", "bearinglab.dynamics", "bearinglab.signal")


def _imported_after(argv: list[str], prefixes: tuple = HEAVY) -> list[str]:
    """The modules starting with ``prefixes`` (default: the heavy ones) imported by
    running ``bearinglab ARGV`` in a new process."""
    code = (
        "import sys, json, io, contextlib\n"
        "from bearinglab.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    main({argv!r})\n"
        f"print(json.dumps(sorted(m for m in sys.modules if m.startswith({prefixes!r}))))\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    return json.loads(out.strip().splitlines()[-1])


def _docstrings() -> dict[str, str]:
    """command name -> its docstring's first paragraph, read from the modules' source."""
    out = {}
    for path in CLI.glob("*.py"):
        for node in ast.parse(path.read_text()).body:
            if not isinstance(node, ast.FunctionDef):
                continue
            for deco in node.decorator_list:
                if isinstance(deco, ast.Call) and ast.unparse(deco.func) == "app.command":
                    name = deco.args[0].value if deco.args else node.name.replace("_", "-")
                    doc = ast.get_docstring(node) or ""
                    out[name] = " ".join(doc.split("\n\n")[0].split())
    return out


def test_help_imports_no_analysis():
    assert _imported_after(["--help"]) == []


def test_every_command_is_in_the_table_with_its_own_help():
    docs = _docstrings()
    assert sorted(docs) == sorted(COMMANDS)
    for name, (_, text) in COMMANDS.items():
        assert docs[name].startswith(text.rstrip(".")), name


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_table_names_the_module_that_registers_the_command(name):
    import typer

    module = importlib.import_module(f"bearinglab.cli.{COMMANDS[name][0]}")
    assert name in typer.main.get_group(module.app).commands


def test_light_commands_import_no_scipy_nor_pydantic():
    """info and contact run without SciPy (Hertz's elliptic integrals by the AGM) and
    without pydantic (typer 0.26-0.28): each was 80-150 ms of their start-up."""
    for argv in (["info", "6205"], ["contact", "6205", "--ball-load-n", "1000"]):
        assert _imported_after(argv, ("scipy", "pydantic")) == [], argv


def test_static_imports_no_pandas_nor_matplotlib():
    """static's table and JSON read the per-ball rows as plain values: pandas was 0.3 s
    of its 1.7 s (the numba kernels load from the cache and stay)."""
    argv = ["static", "6205", "--radial-load-n", "2000", "--speed-rpm", "3000"]
    for extra in ([], ["--json"]):
        assert _imported_after(argv + extra, ("pandas", "matplotlib")) == [], extra
