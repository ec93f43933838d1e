"""Invariants of the kinematics and of Hertz contact (hypothesis)."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab.contact import hertz
from bearinglab.kinematics import frequency_orders

ratios = st.floats(min_value=0.05, max_value=0.45)  # D_w / d_m
angles = st.floats(min_value=0.0, max_value=math.radians(60))
counts = st.integers(min_value=3, max_value=40)


@given(counts, ratios, angles)
def test_ball_pass_frequencies_sum_to_ball_count(z, ratio, alpha):
    o = frequency_orders(z, ratio, 1.0, alpha)
    assert math.isclose(o["bpfo"] + o["bpfi"], z, rel_tol=1e-12)
    assert math.isclose(o["bpfo"], z * o["ftf"], rel_tol=1e-12)
    assert o["bpfi"] > o["bpfo"] and 0 < o["ftf"] < 0.5


@given(counts, ratios, angles, st.floats(min_value=1e-4, max_value=10.0))
def test_orders_are_scale_free(z, ratio, alpha, scale):
    a = frequency_orders(z, ratio, 1.0, alpha)
    b = frequency_orders(z, ratio * scale, scale, alpha)
    for name in a:
        assert math.isclose(a[name], b[name], rel_tol=1e-10)


# effective radii from 10 um to 100 m: R_y/R_x up to 1e7 (groove factors near 0.5 give
# R_y of metres against R_x of millimetres)
radii = st.floats(min_value=1e-5, max_value=1e2)
loads = st.floats(min_value=1e-3, max_value=1e5)


@settings(deadline=None)
@given(radii, radii, loads, st.floats(min_value=1.1, max_value=100.0))
def test_hertz_scaling_with_load(rx, ry, q, c):
    e = 228.6e9
    one = hertz.point_contact(q, rx, ry, e)
    more = hertz.point_contact(c * q, rx, ry, e)
    assert math.isclose(float(more.approach), c ** (2 / 3) * float(one.approach), rel_tol=1e-9)
    assert math.isclose(float(more.semi_major), c ** (1 / 3) * float(one.semi_major), rel_tol=1e-9)
    assert math.isclose(
        float(more.max_pressure), c ** (1 / 3) * float(one.max_pressure), rel_tol=1e-9
    )
    assert float(one.semi_major) >= float(one.semi_minor) > 0


@settings(deadline=None)
@given(radii, radii, loads)
def test_hertz_symmetric_in_the_two_directions(rx, ry, q):
    a = hertz.point_contact(q, rx, ry, 228.6e9)
    b = hertz.point_contact(q, ry, rx, 228.6e9)
    assert np.isclose(float(a.approach), float(b.approach), rtol=1e-9)
    assert np.isclose(float(a.max_pressure), float(b.max_pressure), rtol=1e-9)


@settings(deadline=None)
@given(st.floats(min_value=0.0, max_value=8.0))
def test_exact_ellipticity_solves_its_relation(log10_ratio):
    ratio = 10.0**log10_ratio
    k = float(hertz.ellipticity(ratio))
    assert k >= 1.0 and math.isfinite(k)
    if k == 1.0:  # the circle, to double precision
        assert ratio < 1.0 + 1e-14
    else:
        residual = math.expm1(float(hertz._log_ratio(math.log(k))) - math.log(ratio))
        assert abs(residual) < 1e-12
