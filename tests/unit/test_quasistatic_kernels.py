"""The compiled ball-equilibrium kernel agrees with its NumPy twin."""

import math

import numpy as np
import pytest

from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import _kernels, solve_load_distribution
from bearinglab.quasistatic.solver import _Problem

pytestmark = pytest.mark.skipif(_kernels.solve_balls_numba is None, reason="numba missing")

CASES = [
    ({"diametral_clearance": 15e-6}, {"radial_load": 1000.0, "axial_load": 300.0,
                                           "shaft_speed": 10000 * math.pi / 30}),
    ({"diametral_clearance": 60e-6, "inner_arch_angle": math.radians(25),
          "outer_arch_angle": math.radians(25)}, {"radial_load": 1500.0, "axial_load": 100.0}),
    ({"contact_angle": math.radians(25)}, {"radial_load": 300.0, "axial_load": 900.0,
                                                "misalignment": (1e-3, -5e-4)}),
]


@pytest.mark.parametrize("geometry, load", CASES)
def test_compiled_and_numpy_ball_solutions_agree(geometry, load):
    b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3, **geometry)
    c = OperatingCondition(**load)
    r = solve_load_distribution(b, c)
    p = _Problem(b, c, c.radial_load_angle, None, None)
    # start away from the solution and at a perturbed ring position
    u = r.displacement + np.array([1e-7, -2e-7, 3e-7, 0, 0])
    start = r.ball_centre + np.array([2e-6, -3e-6])
    fast = p.solve_balls(start, u, 1e-8, compiled=True)
    slow = p.solve_balls(start, u, 1e-8, compiled=False)
    # balls that touch the inner ring are solved exactly by both; a ball on the outer race
    # alone is accepted within 10 % of its own force (it cannot load the inner ring)
    carrying = np.any(slow[1][0][:, p.inner] > 0, axis=1)
    assert carrying.sum() >= 3
    np.testing.assert_allclose(fast[0][carrying], slow[0][carrying], rtol=0, atol=1e-12)
    np.testing.assert_allclose(fast[1][0][carrying], slow[1][0][carrying], rtol=1e-7,
                               atol=1e-7)                                    # loads [N]
    np.testing.assert_allclose(fast[1][4][carrying], slow[1][4][carrying], rtol=1e-6,
                               atol=1.0)                                     # S [N/m]
    np.testing.assert_array_equal(np.any(fast[1][0][:, p.inner] > 0, axis=1), carrying)


def test_whole_solve_is_the_same_with_either_kernel(monkeypatch):
    b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3,
                    diametral_clearance=20e-6)
    c = OperatingCondition(radial_load=800.0, axial_load=-250.0, shaft_speed=3000.0)
    fast = solve_load_distribution(b, c)
    monkeypatch.setattr(_kernels, "solve_balls_numba", None)
    slow = solve_load_distribution(b, c)
    np.testing.assert_allclose(fast.displacement, slow.displacement, atol=1e-12)
    np.testing.assert_allclose(fast.stiffness_matrix, slow.stiffness_matrix, rtol=1e-6,
                               atol=1e-6 * np.abs(slow.stiffness_matrix).max())
