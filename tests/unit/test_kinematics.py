"""Kinematic frequencies: formulas, rotating ring, units, bad input."""

import math

import pytest

from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.kinematics import defect_frequencies, frequency_orders

B = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)


def test_orders_and_hz_agree():
    f = defect_frequencies(B, 1797 * math.pi / 30)
    assert f.shaft_hz == pytest.approx(29.95)
    for name, order in f.orders.items():
        assert f.hz(name) == pytest.approx(order * 29.95)
    d = f.to_dict()
    assert d["bpfo_hz"] == pytest.approx(f.hz("bpfo")) and d["bpfo_order"] == f.orders["bpfo"]
    assert d["ball_defect_hz"] == pytest.approx(2 * d["bsf_hz"])


def test_outer_ring_rotating_changes_only_the_cage():
    inner = frequency_orders(9, 7.94, 39.04, 0.2)
    outer = frequency_orders(9, 7.94, 39.04, 0.2, outer_rotating=True)
    assert outer["ftf"] == pytest.approx(1 - inner["ftf"])
    for name in ("bpfo", "bpfi", "bsf", "ball_defect"):
        assert outer[name] == pytest.approx(inner[name])


def test_thrust_limit():
    # at 90 degrees the cage turns at half the shaft speed and BPFO = BPFI = Z/2
    o = frequency_orders(12, 6.0, 40.0, math.pi / 2)
    assert o["ftf"] == pytest.approx(0.5) and o["bpfo"] == pytest.approx(o["bpfi"])


@pytest.mark.parametrize("speed", [-1.0, math.nan, math.inf])
def test_bad_speed(speed):
    with pytest.raises(InputError) as err:
        defect_frequencies(B, speed)
    assert err.value.parameter == "shaft_speed"


def test_unknown_frequency_name():
    with pytest.raises(InputError):
        defect_frequencies(B, 100.0).hz("bpfx")


def test_geometry_inputs_name_what_the_frequencies_depend_on():
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.kinematics import KINEMATIC_FIELDS, geometry_inputs

    catalogued = bearing_from_designation("6205")[0]  # Z, D_w, d_m from the catalogue
    assert geometry_inputs(catalogued) == set(KINEMATIC_FIELDS)
    estimated = bearing_from_designation("6305")[0]  # estimated from d and D
    assert estimated.sources["ball_count"].kind == "estimated"
    assert {"bore", "outside_diameter"} <= geometry_inputs(estimated)
