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


def write_pronostia(folder, samples, start=34779.065664, spacing=10.0, numbers=None, sep=","):
    """Write ``samples`` (records x 2 x n, in g) as PRONOSTIA snapshots ``acc_NNNNN.csv``,
    as the data set publishes them: headerless, hour, minute, second and microsecond of
    each sample at 25.6 kHz, then the horizontal and vertical accelerations (3 decimals).
    Record k starts ``start`` + k ``spacing`` seconds into the day; ``numbers`` are the
    snapshot numbers (default 1, 2, ...). Returns the folder."""
    from pathlib import Path

    import numpy as np

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    samples = np.asarray(samples, dtype=float)
    numbers = range(1, len(samples) + 1) if numbers is None else numbers
    for k, (number, x) in enumerate(zip(numbers, samples, strict=True)):
        t = (start + k * spacing + np.arange(x.shape[-1]) / 25600.0) % 86400.0
        hour, rest = np.divmod(t, 3600.0)
        minute, rest = np.divmod(rest, 60.0)
        second, micro = np.divmod(rest, 1.0)
        lines = [
            f"{h:.0f}{sep}{m:.0f}{sep}{s:.0f}{sep}{u * 1e6:.5g}{sep}{a:.3f}{sep}{b:.3f}"
            for h, m, s, u, a, b in zip(hour, minute, second, micro, x[0], x[1], strict=True)
        ]
        (folder / f"acc_{number:05d}.csv").write_text("\n".join(lines) + "\n")
    return folder
