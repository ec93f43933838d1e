"""Shared test helpers."""

import json
import os

import pytest

#: The README's static example (``bearinglab static 6205 ...``), run by several tests.
README_STATIC = (
    "static",
    "6205",
    "--radial-load-n",
    "1000",
    "--axial-load-n",
    "200",
    "--speed-rpm",
    "3000",
)

#: The README's report example, before its ``-o`` (``bearinglab report 6205 ...``).
README_REPORT = ("report", "6205", "--speed-rpm", "1797", "--radial-load-n", "1000")
#: Keys of the static result's dict (``to_dict`` and ``static --json``) and of each ball's.
STATIC_KEYS = (
    "radial_displacement_um",
    "axial_displacement_um",
    "tilt_mrad",
    "max_ball_load_n",
    "stiffness_matrix_si",
    "stiffness_matrix_order",
    "radial_stiffness_n_per_um",
    "axial_stiffness_n_per_um",
    "balls",
)
STATIC_BALL_KEYS = (
    "angle_deg",
    "inner_load_n",
    "outer_load_n",
    "inner_contact_angle_deg",
    "outer_contact_angle_deg",
    "inner_max_pressure_gpa",
    "outer_max_pressure_gpa",
    "contact_points",
)


def simulate_seed004_slip(defects=(), **options):
    """``simulate`` on the slip model of seed 004's 6205 (``validation.seed004.SKF6205``: no
    clearance; default SlipParameters unless ``parameters`` is given) at 500 N radial and
    2400 rpm, with ``defects`` and ``options`` (duration, sample_rate, settle, ...) as for
    ``simulate``."""
    from bearinglab.dynamics import simulate
    from bearinglab.operating import OperatingCondition
    from bearinglab.validation.seed004 import SKF6205, SPEED

    condition = OperatingCondition(radial_load=500.0, shaft_speed=SPEED)
    return simulate(SKF6205, condition, defects, model="slip", **options)


def in_ci() -> bool:
    """True under CI (CI=true), where every optional test dependency must be installed."""
    return os.environ.get("CI", "").strip().lower() in ("true", "1", "yes")


def require(module: str):
    """``pytest.importorskip(module)``, except under CI, where a missing test dependency
    fails the test instead of skipping it silently (``.ci/run`` installs them all)."""
    if in_ci():
        import importlib

        return importlib.import_module(module)
    return pytest.importorskip(module)


def run_json(capsys, *args):
    """Run the command line with ``args`` and ``--json``: exit code 0, the parsed output."""
    from bearinglab.cli import main

    code = main([*args, "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    return json.loads(out)


def run_error(capsys, *args):
    """Run the command line with ``args``: exit code 2 and a one-line ``error: ...`` message,
    which is returned."""
    from bearinglab.cli import main

    code = main(list(args))
    out, err = capsys.readouterr()
    assert code == 2, (out, err)
    assert err.startswith("error: ") and err.count("\n") == 1, err
    return err
