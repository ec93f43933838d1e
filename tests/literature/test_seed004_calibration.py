"""Seed 004 (Hou et al. 2024, table 2): the calibration of the values it does not print.

The published lines themselves are cases in bearinglab.validation.seed004 (run by
test_published_cases.py): 500 N and the rise to 1000 N are strict known failures with
their reasons, 1000 N is predicted within 1 %. Here: the calibration is the closest
approach to the paper's 93.6 % that the literature ranges allow. The spin ratio falls as
each calibrated value rises, so the best set is every value at the top of its range;
moving any one of them inward must raise the 500 N spin ratio, i.e. take the line further
from the paper's.
"""

import pytest

from bearinglab.validation.seed004 import CALIBRATION, ball_line_ratio, calibrated

PAPER_RATIO_500N = 87.41 / 93.40


def _ratio(**changes):
    bearing, parameters = calibrated(**changes)
    ratio, sim = ball_line_ratio(500.0, bearing, parameters, duration=0.2, settle=0.5)
    return ratio


@pytest.mark.slow
def test_calibration_is_the_closest_approach_within_the_ranges():
    best = _ratio()
    assert PAPER_RATIO_500N < best < 0.97  # above the paper's: the ranges fall short
    inward = {
        "diametral_clearance": 15e-6,
        "cage_friction": 0.25,
        "oil_fraction": 0.03,
        "spin_drag": False,
    }
    assert set(inward) == set(CALIBRATION)
    # each step is worth 3e-3 or more of spin ratio; runs scatter by about 1e-3
    for name, value in inward.items():
        assert _ratio(**{name: value}) > best + 1e-3, name
