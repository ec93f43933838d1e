"""One JSON contract (issue 12, docs/json.md): every key of every command's ``--json``
carries its unit as a suffix of :data:`bearinglab.units.UNITS`, or is one of the
dimensionless keys of :data:`bearinglab.json_keys.DIMENSIONLESS`, inside maps' members too
(issue 22); docs/json.md lists both."""

import json
from pathlib import Path

import pytest
from conftest import README_REPORT, README_STATIC, write_pronostia

from bearinglab.cli import main
from bearinglab.json_keys import DIMENSIONLESS, MAPS
from bearinglab.units import (
    JSON_EXCEPTIONS,
    JSON_SUFFIXES,
    UNITS,
    contract_markdown,
    unit_of,
)

DOC = Path(__file__).resolve().parents[2] / "docs" / "json.md"

#: One cheap invocation of every command (tmp is replaced by a temporary folder).
COMMANDS = {
    "info": ["info", "6205"],
    "info-gost": ["info", "180205"],
    "frequencies": ["frequencies", "6205-2RS", "--speed-rpm", "1797"],
    "contact": ["contact", "6205", "--ball-load-n", "1000"],
    "static": list(README_STATIC),
    "static-orbit": [
        "static",
        "608",
        "--radial-load-n",
        "50",
        "--speed-rpm",
        "720",
        "--waviness",
        "outer:order=8,amplitude_um=0.5",
        "--orbit",
    ],
    "stiffness-map": ["stiffness-map", "6205", "--radial-load-n", "0:1000:2"],
    "ring-modes": ["ring-modes", "310", "--system", "gost", "--axial-load-n", "200"],
    "simulate": [
        "simulate",
        "6205",
        "--speed-rpm",
        "1800",
        "--radial-load-n",
        "500",
        "--defect",
        "outer:width_mm=1",
        "--duration-s",
        "0.5",
        "--sample-rate-hz",
        "10000",
        "-o",
        "tmp/sim.npz",
    ],
    "simulate-slip": [
        "simulate",
        "6205",
        "--model",
        "slip",
        "--speed-rpm",
        "1800",
        "--radial-load-n",
        "500",
        "--defect",
        "outer:width_mm=1",
        "--duration-s",
        "0.3",
        "--sample-rate-hz",
        "10000",
        "-o",
        "tmp/slip.npz",
    ],
    "noise": [
        "noise",
        "608",
        "--speed-rpm",
        "720",
        "--radial-load-n",
        "50",
        "--waviness",
        "inner:order=7,amplitude_um=0.2",
    ],
    "friction": ["friction", "6205", "--speed-rpm", "3000", "--radial-load-n", "1000"],
    "life": ["life", "6205", "--speed-rpm", "3000", "--radial-load-n", "1000"],
    "report": [*README_REPORT, "-o", "tmp/report.html"],
    "study": [
        "study",
        "frequencies",
        "--set",
        "designation=6205",
        "--set",
        "speed_rpm=1000,2000",
        "-o",
        "tmp/study",
        "--scheduler",
        "serial",
    ],
    "dataset": [
        "dataset",
        "tmp/data",
        "--records",
        "2",
        "--duration-s",
        "0.3",
        "--scheduler",
        "serial",
    ],
}
#: Fault families, one spelling everywhere (docs/json.md).
FAMILIES = {"outer_race", "inner_race", "ball", "cage"}
REAL = Path(__file__).resolve().parents[3] / "shared" / "data" / "real"


def _offending(obj, path: str = "") -> list[str]:
    """Keys that break the contract, with their path. The data-named levels of a map
    (json_keys.MAPS) are not checked, but the keys inside its members are."""
    bad = []
    if isinstance(obj, dict):
        for key, value in obj.items():
            where = f"{path}.{key}"
            if unit_of(key) is not None:
                continue  # its members carry its unit (velocity_bands_um_s.low)
            if key not in DIMENSIONLESS:
                bad.append(where)
            if key in MAPS:
                bad += _members(value, MAPS[key], where)
            else:
                bad += _offending(value, where)
    elif isinstance(obj, list):
        for item in obj:
            bad += _offending(item, f"{path}[]")
    return bad


def _members(obj, levels: int, path: str) -> list[str]:
    """The offending keys inside a map's members, below its ``levels`` data-named levels."""
    if levels == 0 or not isinstance(obj, dict):
        return _offending(obj, path)
    bad = []
    for name, value in obj.items():
        bad += _members(value, levels - 1, f"{path}.{name}")
    return bad


def test_the_walk_enters_maps():
    """A key without a unit inside a map's member is found; the member's name is not."""
    sample = {"families": {"outer_race": {"slip": 0.0, "width": 1.0}}, "scores": {"x y": 1}}
    assert _offending(sample) == [".families.outer_race.width"]
    assert _offending({"confusion": {"raw": {"ball": {"no fault detected": 0}}}}) == []
    assert _offending({"confusion": {"raw": {"ball": {"c": {"width": 1}}}}}) == [
        ".confusion.raw.ball.c.width"
    ]


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    """Each command's JSON, run once for all the checks."""
    import contextlib
    import io

    tmp = tmp_path_factory.mktemp("json")
    out = {}
    for name, argv in COMMANDS.items():
        argv = [a.replace("tmp/", f"{tmp}/") for a in argv]
        buffer = io.StringIO()
        with contextlib.redirect_stdout(buffer):
            code = main([*argv, "--json"])
        assert code == 0, name
        out[name] = json.loads(buffer.getvalue())
    later = {
        "analyze": ["analyze", str(tmp / "sim.npz"), "--designation", "6205", "--speed-rpm", "1800"]
    }
    # a short PRONOSTIA-like series whose last records ring: an alarm, its diagnosis, zones
    import numpy as np

    x = 0.3 * np.random.default_rng(0).standard_normal((48, 2, 2560))
    x[40:] *= 4.0
    later["trend"] = [
        "trend",
        str(write_pronostia(tmp / "run", x)),
        "--settle-records",
        "0",
        "--baseline-records",
        "30",
        "--persistence-s",
        "30",
        "--unit",
        "g",
        "--machine",
        "class1",
        "--balls",
        "13",
        "--ball-diameter-mm",
        "3.5",
        "--pitch-diameter-mm",
        "25.6",
        "--speed-rpm",
        "1800",
    ]
    if (REAL / "labels.csv").exists():  # a labelled folder of one real record
        import shutil

        folder = tmp / "bench"
        folder.mkdir()
        shutil.copy(REAL / "cwru" / "12k_DE" / "130.mat", folder / "130.mat")
        lines = (REAL / "labels.csv").read_text(encoding="utf-8").splitlines()
        row = next(line for line in lines if line.startswith("cwru/12k_DE/130.mat"))
        (folder / "labels.csv").write_text(
            lines[0] + "\n" + row.replace("cwru/12k_DE/130.mat", "130.mat") + "\n", encoding="utf-8"
        )
        later["benchmark"] = ["benchmark", str(folder)]
    for name, argv in later.items():
        buffer = io.StringIO()
        with contextlib.redirect_stdout(buffer):
            assert main([*argv, "--json"]) == 0, name
        out[name] = json.loads(buffer.getvalue())
    return out


@pytest.mark.parametrize("name", [*COMMANDS, "analyze", "benchmark", "trend"])
def test_every_key_carries_its_unit_or_is_dimensionless(outputs, name):
    if name not in outputs:
        pytest.skip("the shared recordings are not here")
    assert _offending(outputs[name]) == []


def _off_rule(obj, path: str = "") -> list[str]:
    """Keys whose unit is one the rules keep out of JSON (docs/json.md: N·m, N/m, m, Pa,
    ...) and that are not a declared exception."""
    bad = []
    if isinstance(obj, dict):
        for key, value in obj.items():
            unit = unit_of(key)
            if unit is not None and unit.suffix not in JSON_SUFFIXES:
                if key not in JSON_EXCEPTIONS:
                    bad.append(f"{path}.{key} [{unit.symbol}]")
            elif unit is None:
                bad += _off_rule(value, f"{path}.{key}")
    elif isinstance(obj, list):
        for item in obj:
            bad += _off_rule(item, f"{path}[]")
    return bad


@pytest.mark.parametrize("name", [*COMMANDS, "analyze", "benchmark", "trend"])
def test_every_unit_is_one_the_rules_allow_in_json(outputs, name):
    if name not in outputs:
        pytest.skip("the shared recordings are not here")
    assert _off_rule(outputs[name]) == []


def test_the_json_units_rule():
    """The suffixes kept out of JSON are those of SI where the rules ask for an engineering
    unit; every exception gives its reason; the check finds a key in N·m."""
    assert set(JSON_SUFFIXES) <= set(UNITS)
    for suffix in ("m", "n_m", "n_per_m", "pa", "kn", "nm", "rad_s", "kg_m"):
        assert suffix not in JSON_SUFFIXES, suffix
    assert all(reason.strip() for reason in JSON_EXCEPTIONS.values())
    assert _off_rule({"balls": [{"gyroscopic_moment_n_m": 0.0}], "tilt_mrad": [0.0]}) == [
        ".balls[].gyroscopic_moment_n_m [N·m]"
    ]
    assert _off_rule({"velocity_bands_um_s": {"low": 1.0}, "torque_n_mm": 1.0}) == []


def _families_named(obj) -> set:
    """Every fault family a diagnosis JSON names (scores, families, faults, verdicts)."""
    named = set()
    if isinstance(obj, dict):
        for key, value in obj.items():
            if key in ("scores", "families", "significance") and isinstance(value, dict):
                named |= set(value)
            elif key in ("faults",) and isinstance(value, list):
                named |= {v for v in value if isinstance(v, str)}
            elif key in ("likely_fault", "primary_fault", "expected") and isinstance(value, str):
                named |= set(value.removeprefix("compound: ").split(" + "))
            else:
                named |= _families_named(value)
    elif isinstance(obj, list):
        for item in obj:
            named |= _families_named(item)
    return named


@pytest.mark.parametrize("name", ["simulate", "analyze", "benchmark", "trend"])
def test_one_spelling_of_the_fault_families(outputs, name):
    if name not in outputs:
        pytest.skip("the shared recordings are not here")
    named = _families_named(outputs[name])
    assert named and named <= FAMILIES, named


def test_the_doc_is_generated_from_the_unit_table():
    """docs/json.md is `python -m bearinglab.units` (regenerate with that command)."""
    assert DOC.read_text(encoding="utf-8") == contract_markdown()
