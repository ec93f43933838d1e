"""Every command is one request of the registry (issue 30): its options are its entry's
inputs, each input is declared once, and a request is closed (a key it does not know is
refused with the closest one named)."""

import ast
import inspect
from pathlib import Path

import pytest
import typer

from bearinglab.cli._app import COMMANDS, _LazyCommands
from bearinglab.errors import InputError
from bearinglab.inputs import INPUTS
from bearinglab.registry import registry

SRC = Path(__file__).resolve().parents[2] / "src" / "bearinglab"
#: Options a command has besides its request: how it presents the result.
PRESENTATION = {"json_output"}


def test_every_command_has_an_entry():
    missing = [name for name in COMMANDS if name not in registry()]
    assert missing == []


def _options(command: str) -> set[str]:
    click = _LazyCommands()[command]
    return {p.name for p in click.params}


@pytest.mark.parametrize("command", list(COMMANDS))
def test_a_commands_options_are_its_entrys_inputs(command):
    entry = registry().get(command)
    if entry is None:
        pytest.fail(f"{command} has no registry entry")
    options = _options(command) - PRESENTATION - set(entry.files)
    assert options == set(entry.command_options), command


@pytest.mark.parametrize("command", list(COMMANDS))
def test_a_misspelt_input_is_refused_naming_the_closest(command):
    entry = registry().get(command)
    if entry is None:
        pytest.fail(f"{command} has no registry entry")
    name = next(iter(entry.options), None)
    if name is None:  # a command without inputs refuses any key
        with pytest.raises(InputError) as info:
            entry({"speed_rpm": 1000.0})
        assert info.value.parameter == "speed_rpm"
        return
    typo = name[:-2] + name[-1] + name[-2]  # two letters swapped
    with pytest.raises(InputError) as info:
        entry({typo: entry.options[name].default})
    assert info.value.parameter == typo
    assert f"did you mean `{name}`?" in info.value.hint


def test_the_issues_misspelt_reliability_is_not_ignored():
    """`reliabilty_percent=99` used to be ignored silently, giving a_1 = 1.0."""
    life = registry()["life"]
    request = {"designation": "6205", "speed_rpm": 1500.0, "radial_load_n": 1000.0}
    with pytest.raises(InputError) as info:
        life({**request, "reliabilty_percent": 99.0})
    assert "`reliability_percent`" in info.value.hint
    assert life({**request, "reliability_percent": 99.0}).to_dict()["a1"] < 1.0


def test_a_required_input_must_be_given():
    with pytest.raises(InputError) as info:
        registry()["contact"]({"designation": "6205"})
    assert info.value.parameter == "ball_load_n" and info.value.value is None


def _declarations() -> dict[str, list[str]]:
    """Input name -> where an Input(...) is declared for it (a reading of another input,
    ``INPUTS[name].with_(...)``, is not a declaration)."""
    found: dict[str, list[str]] = {}
    for path in sorted(SRC.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            pairs = []
            if isinstance(node, ast.Dict):
                pairs = [
                    (k.value, v)
                    for k, v in zip(node.keys, node.values, strict=True)
                    if isinstance(k, ast.Constant)
                ]
            elif isinstance(node, ast.Call):
                pairs = [(kw.arg, kw.value) for kw in node.keywords if kw.arg]
            for key, value in pairs:
                if (
                    isinstance(key, str)
                    and isinstance(value, ast.Call)
                    and getattr(value.func, "id", None) in ("Input", "_n")
                ):
                    found.setdefault(key, []).append(f"{path.relative_to(SRC)}:{value.lineno}")
    return found


def test_no_input_is_declared_twice():
    twice = {k: v for k, v in _declarations().items() if len(v) > 1}
    assert twice == {}


def test_the_table_s_inputs_are_declared_in_the_table_only():
    elsewhere = {
        k: v
        for k, v in _declarations().items()
        if k in INPUTS and any(not w.startswith("inputs/table.py") for w in v)
    }
    assert elsewhere == {}


def test_an_input_name_means_one_thing():
    """The names that meant two things now name one (issue 30): the life and Hertz methods
    and the friction and dynamic models have their own names, the old flag kept as an
    alias of each."""
    entries = registry()
    assert "method" not in entries["life"].options and "life_method" in entries["life"].options
    assert "method" not in entries["contact"].options
    assert "model" not in entries["friction"].options
    assert "model" not in entries["simulate"].options
    for command, name in (
        ("life", "life_method"),
        ("contact", "hertz_method"),
        ("friction", "friction_model"),
        ("simulate", "dynamic_model"),
    ):
        assert entries[command].options[name].aliases, (command, name)


def test_the_registry_is_not_imported_by_the_help():
    source = inspect.getsource(typer)  # noqa: F841 - typer is the app's only import
    assert "registry" not in (SRC / "cli" / "_app.py").read_text(encoding="utf-8")
