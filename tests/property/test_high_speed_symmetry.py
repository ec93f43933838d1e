"""Symmetric loading gives symmetric solutions at every speed up to the model's limit,
n d_m = 3e6 mm/min (hypothesis)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import MAX_SPEED_FACTOR, solve_load_distribution, speed_limit

BEARINGS = [
    # Harris's 218 and a small spindle bearing (7005-like) and a 6205-size one
    {
        "ball_count": 16,
        "ball_diameter": 22.225e-3,
        "pitch_diameter": 125.26e-3,
        "inner_groove_factor": 0.5232,
        "outer_groove_factor": 0.5232,
    },
    {
        "ball_count": 14,
        "ball_diameter": 5.556e-3,
        "pitch_diameter": 36.0e-3,
        "inner_groove_factor": 0.52,
        "outer_groove_factor": 0.53,
    },
    {"ball_count": 9, "ball_diameter": 7.94e-3, "pitch_diameter": 39.04e-3},
]


@settings(max_examples=60, deadline=None)
@given(
    geometry=st.sampled_from(BEARINGS),
    angle=st.floats(15.0, 40.0),
    thrust_per_ball=st.floats(5.0, 800.0),
    speed_fraction=st.floats(0.0, 1.0),
    gyroscopic=st.booleans(),
    control=st.sampled_from(["outer", "hybrid"]),
    sign=st.sampled_from([1.0, -1.0]),
)
def test_pure_thrust_gives_identical_balls_and_no_radial_motion(
    geometry, angle, thrust_per_ball, speed_fraction, gyroscopic, control, sign
):
    b = BallBearing(**geometry, contact_angle=math.radians(angle))
    omega = speed_fraction * speed_limit(b)
    fa = sign * thrust_per_ball * b.ball_count
    r = solve_load_distribution(
        b,
        OperatingCondition(axial_load=fa, shaft_speed=omega),
        gyroscopic=gyroscopic,
        race_control=control,
    )
    q = r.load.sum(axis=1)
    assert np.ptp(r.load, axis=0).max() <= 1e-6 * q.max()
    assert np.all(r.load[:, r.ring == 0].sum(axis=1) > 0)  # every ball on both races
    assert np.hypot(*r.displacement[:2]) < 1e-9
    assert np.ptp(r.contact_angle, axis=0).max() < 1e-7
    # the axial reaction balances the load; both contacts lean with the load
    assert r.reaction[2] == pytest.approx(-fa, rel=1e-7)
    assert np.all(np.sign(r.contact_angle) == sign)


def test_speed_beyond_the_limit_is_refused_in_the_users_terms():
    b = BallBearing(**BEARINGS[2])
    top = speed_limit(b)
    assert top * 30 / math.pi * b.pitch_diameter * 1e3 == pytest.approx(MAX_SPEED_FACTOR)
    with pytest.raises(InputError, match=r"shaft_speed.*rpm.*n d_m <= 3e\+06 mm/min"):
        solve_load_distribution(
            b, OperatingCondition(axial_load=500.0, shaft_speed=1e6 * math.pi / 30)
        )
    # just below the limit it answers
    solve_load_distribution(b, OperatingCondition(axial_load=500.0, shaft_speed=0.999 * top))
