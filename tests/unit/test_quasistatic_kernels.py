"""The compiled quasi-static kernels agree with their NumPy/Python twins, and load from
numba's on-disk cache in a new process."""

import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import _ring, solve_load_distribution, solver
from bearinglab.quasistatic.solver import _Problem

B218 = {
    "ball_count": 16,
    "ball_diameter": 22.225e-3,
    "pitch_diameter": 125.26e-3,
    "inner_groove_factor": 0.5232,
    "outer_groove_factor": 0.5232,
    "contact_angle": math.radians(40),
}
SMALL = {"ball_count": 9, "ball_diameter": 7.94e-3, "pitch_diameter": 39.04e-3}

CASES = [
    (
        SMALL | {"diametral_clearance": 15e-6},
        {"radial_load": 1000.0, "axial_load": 300.0, "shaft_speed": 10000 * math.pi / 30},
        {},
    ),
    (
        SMALL
        | {
            "diametral_clearance": 60e-6,
            "inner_arch_angle": math.radians(25),
            "outer_arch_angle": math.radians(25),
        },
        {"radial_load": 1500.0, "axial_load": 100.0},
        {},
    ),
    (
        SMALL | {"contact_angle": math.radians(25)},
        {"radial_load": 300.0, "axial_load": 900.0, "misalignment": (1e-3, -5e-4)},
        {},
    ),
    (
        B218,
        {"axial_load": 4450.0, "radial_load": 10.0, "shaft_speed": 20000 * math.pi / 30},
        {"gyroscopic": True},
    ),
    (
        B218,
        {"axial_load": 17800.0, "radial_load": 3000.0, "shaft_speed": 12000 * math.pi / 30},
        {"gyroscopic": True, "race_control": "inner"},
    ),
]


def _problem(geometry, load, options):
    b = BallBearing(**geometry)
    c = OperatingCondition(**load)
    r = solve_load_distribution(b, c, **options)
    p = _Problem(
        b,
        c,
        c.radial_load_angle,
        None,
        None,
        gyroscopic=options.get("gyroscopic", False),
        race_control=options.get("race_control", "outer"),
    )
    p.spd[6] = np.mean(r.orbital_speed)
    return r, p


@pytest.mark.parametrize("geometry, load, options", CASES)
def test_compiled_and_numpy_ball_solutions_agree(geometry, load, options):
    r, p = _problem(geometry, load, options)
    # start away from the solution and at a perturbed ring position
    u = r.displacement + np.array([1e-7, -2e-7, 3e-7, 0, 0])
    start = r.ball_centre + np.array([2e-6, -3e-6])
    fast_b, fast = p.solve_balls(start, u, 1e-8, compiled=True)
    slow_b, slow = p.solve_balls(start, u, 1e-8, compiled=False)
    carrying = np.any(slow[0][:, p.inner] > 0, axis=1)
    assert carrying.sum() >= 3
    np.testing.assert_allclose(fast_b, slow_b, rtol=0, atol=1e-12)
    np.testing.assert_allclose(fast[0], slow[0], rtol=1e-7, atol=1e-7)  # loads [N]
    np.testing.assert_allclose(fast[4], slow[4], rtol=1e-7, atol=1e-9)  # speed forces
    np.testing.assert_allclose(fast[5], slow[5], rtol=1e-7, atol=1e-6)  # ring force
    np.testing.assert_allclose(
        fast[6], slow[6], rtol=1e-5, atol=1e-6 * np.abs(slow[6]).max()
    )  # stiffness


@pytest.mark.parametrize("geometry, load, options", CASES)
def test_stiffness_is_the_derivative_of_the_ring_force(geometry, load, options):
    # the condensed stiffness, speed forces included, against central differences of the
    # ball forces on the inner ring with every ball re-solved
    r, p = _problem(geometry, load, options)
    k = np.empty((5, 5))
    for d in range(5):
        h = 1e-9 if d < 3 else 1e-8
        du = np.zeros(5)
        du[d] = h
        fp = p.solve_balls(r.ball_centre, r.displacement + du, 1e-10)[1][5]
        fm = p.solve_balls(r.ball_centre, r.displacement - du, 1e-10)[1][5]
        k[:, d] = -(fp - fm) / (2 * h)
    scale = np.abs(r.stiffness_matrix).max()
    np.testing.assert_allclose(r.stiffness_matrix, k, rtol=1e-4, atol=2e-5 * scale)


GRID = [
    (fr, fa, rpm, gyro)
    for fr in (0.0, 300.0, 2000.0)
    for fa in (0.0, 150.0, 900.0)
    for rpm in (0.0, 9000.0)
    for gyro in (False, True)
    if fr + fa > 0
]


@pytest.mark.parametrize("fr, fa, rpm, gyro", GRID)
def test_compiled_ring_iteration_matches_the_python_reference(monkeypatch, fr, fa, rpm, gyro):
    b = BallBearing(**SMALL, diametral_clearance=20e-6, contact_angle=math.radians(15))
    c = OperatingCondition(radial_load=fr, axial_load=fa, shaft_speed=rpm * math.pi / 30)
    fast = solve_load_distribution(b, c, gyroscopic=gyro, tolerance=1e-10)
    monkeypatch.setattr(solver, "COMPILED_RING", False)
    slow = solve_load_distribution(b, c, gyroscopic=gyro, tolerance=1e-10)
    np.testing.assert_allclose(fast.displacement, slow.displacement, rtol=0, atol=1e-12)
    np.testing.assert_allclose(fast.load, slow.load, rtol=1e-8, atol=1e-6)
    np.testing.assert_allclose(
        fast.stiffness_matrix,
        slow.stiffness_matrix,
        rtol=1e-7,
        atol=1e-8 * np.abs(slow.stiffness_matrix).max(),
    )


def test_lu_solve_matches_numpy():
    rng = np.random.default_rng(1)
    a = rng.normal(size=(5, 5))
    x, ok = _ring._lu_solve(a, np.arange(5.0))
    assert ok and np.allclose(x, np.linalg.solve(a, np.arange(5.0)))
    assert not _ring._lu_solve(np.ones((3, 3)), np.ones(3))[1]


_CACHE_PROBE = """
import json, math
from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import _ball, _ball_set, _ring, solve_load_distribution
b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)
solve_load_distribution(b, OperatingCondition(radial_load=500.0, axial_load=100.0,
                                              shaft_speed=3000.0), gyroscopic=True)
stats = {}
for module in (_ball, _ball_set, _ring):
    for name in dir(module):
        f = getattr(module, name)
        if hasattr(f, "stats") and hasattr(f, "signatures") and f.signatures:
            stats[name] = [sum(f.stats.cache_hits.values()),
                           sum(f.stats.cache_misses.values())]
print(json.dumps(stats))
"""


@pytest.mark.slow
def test_kernels_load_from_the_disk_cache_in_a_new_process(tmp_path):
    # the first process fills a fresh cache directory, the second must find everything there
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    runs = [
        json.loads(
            subprocess.run(
                [sys.executable, "-c", _CACHE_PROBE],
                env=env,
                capture_output=True,
                text=True,
                check=True,
                timeout=600,
            ).stdout.splitlines()[-1]
        )
        for _ in range(2)
    ]
    assert runs[0]["ring_newton"] == [0, 1]  # compiled and saved
    # what the second process called from Python came from the cache (the functions it
    # calls are compiled into the cached ring_newton and are not dispatched again)
    assert "ring_newton" in runs[1]
    assert all(misses == 0 and hits >= 1 for hits, misses in runs[1].values()), runs[1]


def test_stiffness_map_lines_match_the_python_reference(monkeypatch):
    # the map solves each line after its first case in one compiled call; the reference is
    # the case-by-case path with the ring iteration in Python
    from bearinglab.quasistatic.study import stiffness_map

    b = BallBearing(**SMALL, diametral_clearance=15e-6)
    radial, axial, speeds = np.linspace(0.0, 2000.0, 9), [-400.0, 0.0, 250.0], [0.0, 12000.0]
    fast = stiffness_map(b, radial, axial, speeds, workers=1)
    monkeypatch.setattr(solver, "COMPILED_RING", False)
    slow = stiffness_map(b, radial, axial, speeds, workers=1)
    assert list(fast.status) == list(slow.status)
    assert (fast.status == "ok").sum() == len(fast) - 2  # two "no load" rows
    ok = fast.status == "ok"
    for column, atol in (
        ("radial_displacement_um", 1e-6),
        ("axial_displacement_um", 1e-6),
        ("max_ball_load_n", 1e-6),
    ):
        np.testing.assert_allclose(fast[column][ok], slow[column][ok], rtol=1e-8, atol=atol)
    for column in ("radial_stiffness_n_per_um", "axial_stiffness_n_per_um"):
        np.testing.assert_allclose(fast[column][ok], slow[column][ok], rtol=1e-6, atol=1e-6)


@pytest.mark.parametrize("control", ["inner", "hybrid"])
def test_stiffness_map_passes_gyroscopic_and_race_control(control):
    from bearinglab.quasistatic.study import stiffness_map

    b = BallBearing(**SMALL, diametral_clearance=15e-6, contact_angle=math.radians(15))
    table = stiffness_map(
        b,
        [100.0, 600.0, 1200.0],
        [300.0],
        [15000.0],
        workers=1,
        gyroscopic=True,
        race_control=control,
    )
    assert (table.status == "ok").all()
    for fr, s_r in zip(table.radial_load_n, table.radial_displacement_um, strict=True):
        r = solve_load_distribution(
            b,
            OperatingCondition(
                radial_load=fr,
                axial_load=300.0,
                shaft_speed=15000 * math.pi / 30,
                radial_load_angle=-0.5 * math.pi,
            ),
            gyroscopic=True,
            race_control=control,
        )
        assert s_r == pytest.approx(r.radial_displacement * 1e6, abs=1e-6)
    with pytest.raises(InputError, match="race_control"):
        stiffness_map(b, [100.0], [0.0], [0.0], race_control="cage")
