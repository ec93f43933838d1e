"""Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing Technology*, 5th ed., 2007
(ch. 2 and 7 examples): the 209 cylindrical roller bearing, 14 rollers of 10 x 9.6 mm on
a 65.01 mm pitch circle, unprofiled, 4450 N radial, a roller on the load line.

- Q_max = 1299 N without clearance (= 4.08 F_r/Z): 1 % (issue 28). Independent check: the
  discrete sum of the line law Q = Q_max cos(psi)^(10/9) over the rollers (computed here
  without the solver) gives 1298.8 N.
- Q_max = 1959 N with 0.041 mm diametral clearance: 2 % (issue 28; the value depends on
  the roller's load-deflection constant, ISO/TS 16281's c_l here).
- C = 48.4 kN (ISO 281) and C_0 = 50.0 kN (ISO 76): 1 % (issue 28; printed to 3 digits).
"""

import math

import numpy as np
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution
from bearinglab.ratings import load_ratings

FR = 4450.0


def harris(clearance=0.0):
    b, _ = bearing_from_designation(
        "209 cylindrical (Harris)", rollers=True, overrides={"diametral_clearance": clearance}
    )
    assert (b.roller_count, b.roller_diameter, b.roller_length) == (14, 10e-3, 9.6e-3)
    assert b.profile.kind == "flat"
    return b


def test_qmax_without_clearance():
    r = solve_load_distribution(harris(), OperatingCondition(radial_load=FR))
    psi = 2 * np.pi * np.arange(14) / 14
    c = np.clip(np.cos(psi), 0, None)
    by_hand = FR / np.sum(c ** (10 / 9) * c)
    assert r.max_roller_load == pytest.approx(by_hand, rel=1e-6)
    assert r.max_roller_load == pytest.approx(1299.0, rel=0.01)
    assert r.max_roller_load * 14 / FR == pytest.approx(4.08, abs=0.02)


def test_qmax_with_clearance():
    r = solve_load_distribution(harris(0.041e-3), OperatingCondition(radial_load=FR))
    assert r.max_roller_load == pytest.approx(1959.0, rel=0.02)
    # fewer rollers carry it
    assert np.count_nonzero(r.inner_roller_load > 1.0) < 7


def test_load_ratings():
    ratings = load_ratings(harris())
    assert ratings.dynamic == pytest.approx(48.4e3, rel=0.01)
    assert ratings.static == pytest.approx(50.0e3, rel=0.01)
    # ISO 76 by hand: 44 (1 - D/d_m) Z L D
    assert ratings.static == pytest.approx(44 * (1 - 10 / 65.01) * 14 * 9.6 * 10, rel=1e-12)
    assert math.isclose(ratings.to_dict()["rating_factor_bm"], 1.1)
