"""Inner-ring orbit over the ball-set angle, and the EHL film in the load distribution."""

import math

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.lubrication import ISO_VG68
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution
from bearinglab.quasistatic.orbit import inner_ring_orbit

B608 = BallBearing(
    ball_count=7, ball_diameter=3.969e-3, pitch_diameter=15e-3, diametral_clearance=10e-6
)


def test_uniform_orbit_repeats_every_ball_spacing():
    o = inner_ring_orbit(B608, OperatingCondition(radial_load=50.0), points=8)
    assert o.x[0] == pytest.approx(o.x[-1], abs=1e-12)
    assert o.y[0] == pytest.approx(o.y[-1], abs=1e-12)
    assert 0 < o.peak_to_peak < 1e-6  # a sub-micrometre ball-pass wobble


def test_ball_size_errors_make_a_larger_orbit_over_a_revolution():
    errors = np.array([1.5e-6, -1.0e-6, 0.5e-6, 0.0, -1.5e-6, 1.0e-6, -0.5e-6])
    even = inner_ring_orbit(B608, OperatingCondition(radial_load=50.0), points=4)
    odd = inner_ring_orbit(
        B608, OperatingCondition(radial_load=50.0), ball_diameter_errors=errors, points=4
    )
    assert len(odd.x) == 4 * 7 + 1
    assert odd.peak_to_peak > 3 * even.peak_to_peak


def test_orbit_bad_input():
    with pytest.raises(InputError):
        inner_ring_orbit(B608, OperatingCondition(radial_load=50.0), points=1)
    with pytest.raises(InputError):
        inner_ring_orbit(B608, OperatingCondition(radial_load=50.0), span="forever")


def test_film_is_consistent_with_the_final_loads():
    from bearinglab.lubrication import film_thickness

    b = BallBearing(
        ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3, diametral_clearance=15e-6
    )
    c = OperatingCondition(radial_load=1000.0, shaft_speed=6000 * math.pi / 30)
    r = solve_load_distribution(b, c, lubricant=ISO_VG68)
    # recompute the film from the reported loads and contact angles: it matches
    loaded = r.load[:, 0] > 1.0
    h = film_thickness(
        b,
        ISO_VG68,
        r.load[loaded, 0],
        c.shaft_speed,
        "inner",
        contact_angle=np.abs(r.contact_angle[loaded, 0]),
    )
    np.testing.assert_allclose(r.film[loaded, 0], h, rtol=1e-6, atol=2e-9)
    assert 0.1e-6 < r.film.max() < 3e-6


def test_no_film_at_rest():
    b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)
    r = solve_load_distribution(b, OperatingCondition(radial_load=500.0), lubricant=ISO_VG68)
    assert np.all(r.film == 0)


def test_a_film_takes_up_play():
    # seed 001 eq. 2: centre distance = R_e + R_n - D_w + delta_e + delta_n - h_e - h_n. Under
    # a radial load (contacts along the radius) a film h on both contacts of every ball is
    # the same as 2h less play per ball, i.e. a diametral clearance smaller by 4h
    c = OperatingCondition(radial_load=2000.0)
    geometry = {"ball_count": 9, "ball_diameter": 7.94e-3, "pitch_diameter": 39.04e-3}
    wet = solve_load_distribution(
        BallBearing(**geometry, diametral_clearance=15e-6), c, film=0.5e-6
    )
    tight = solve_load_distribution(BallBearing(**geometry, diametral_clearance=13e-6), c)
    assert wet.radial_displacement == pytest.approx(tight.radial_displacement, rel=1e-6)
    np.testing.assert_allclose(wet.load, tight.load, rtol=1e-6, atol=1e-6)
    b = BallBearing(**geometry, diametral_clearance=15e-6)
    axial = OperatingCondition(axial_load=500.0, shaft_speed=6000 * math.pi / 30)
    assert (
        solve_load_distribution(b, axial, lubricant=ISO_VG68).axial_displacement
        < solve_load_distribution(b, axial).axial_displacement
    )
