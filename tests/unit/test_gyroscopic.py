"""Gyroscopic moments under outer-raceway control."""

import math

import numpy as np
import pytest

from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import centrifugal_force, solve_load_distribution
from bearinglab.quasistatic.gyroscopic import gyroscopic_ball_force, outer_control_kinematics

ACBB = BallBearing(
    ball_count=12, ball_diameter=10e-3, pitch_diameter=60e-3, contact_angle=math.radians(25)
)


def test_kinematics_reduce_to_pure_rolling_at_zero_angle():
    beta, orbit, spin = outer_control_kinematics(0.0, 0.0, 0.2)
    assert beta == 0.0 and orbit == pytest.approx(0.4) and spin == pytest.approx(-2.4)


@pytest.mark.parametrize("ai, ao, g", [(0.6, 0.5, 0.15), (0.2, 0.45, 0.3), (0.0, 0.7, 0.1)])
def test_outer_control_is_harris_printed_formulas(ai, ao, g):
    """The general raceway-control form gives Harris & Kotzalas's outer-control formulas
    (Advanced Concepts, ch. 3) as printed: attitude, orbital and spin speed."""
    beta = math.atan2(math.sin(ao), math.cos(ao) + g)
    orbit = (1.0 - g * math.cos(ai)) / (1.0 + math.cos(ai - ao))
    tb = math.tan(beta)
    spin = -1.0 / (
        (
            (math.cos(ao) + tb * math.sin(ao)) / (1.0 + g * math.cos(ao))
            + (math.cos(ai) + tb * math.sin(ai)) / (1.0 - g * math.cos(ai))
        )
        * g
        * math.cos(beta)
    )
    got = outer_control_kinematics(ai, ao, g)
    assert np.allclose(got, (beta, orbit, spin), rtol=1e-13, atol=0)


def test_attitude_angle_is_below_the_outer_contact_angle():
    beta, _, _ = outer_control_kinematics(0.6, 0.5, 0.15)
    assert 0 < beta < 0.5
    assert math.tan(beta) == pytest.approx(math.sin(0.5) / (math.cos(0.5) + 0.15))


def test_force_magnitude_and_direction():
    omega, ai, ao = 20000 * math.pi / 30, 0.55, 0.40
    f = gyroscopic_ball_force(10e-3, 60e-3, 7830.0, omega, np.array([ai]), np.array([ao]))[0]
    beta, orbit, spin = outer_control_kinematics(ai, ao, 10e-3 / 60e-3)
    m_g = 7830.0 * math.pi * 10e-3**5 / 60 * abs(spin * orbit) * omega**2 * math.sin(beta)
    assert np.hypot(*f) == pytest.approx(2 * m_g / 10e-3, rel=1e-12)
    # perpendicular to the outer normal (cos a, sin a), outward and towards -z
    assert f @ np.array([math.cos(ao), math.sin(ao)]) == pytest.approx(0.0, abs=1e-12)
    assert f[0] > 0 and f[1] < 0


def test_balls_are_in_equilibrium_with_the_gyroscopic_friction():
    omega = 20000 * math.pi / 30
    r = solve_load_distribution(
        ACBB, OperatingCondition(axial_load=1000.0, shaft_speed=omega), gyroscopic=True
    )
    qi, qo = r.load[0, 0], r.load[0, 1]
    ai, ao = r.contact_angle[0]
    # one cage speed (Jones's, outer raceway control) for F_c and for M_g
    _, orbit, _ = outer_control_kinematics(ai, ao, ACBB.ball_diameter / ACBB.pitch_diameter)
    fc = 0.5 * ACBB.ball_mass * ACBB.pitch_diameter * (orbit * omega) ** 2
    assert r.ball_centrifugal_force[0] == pytest.approx(fc, rel=1e-9)
    assert fc > centrifugal_force(ACBB, omega)  # the nominal-angle value is lower
    f = gyroscopic_ball_force(
        ACBB.ball_diameter, ACBB.pitch_diameter, 7830.0, omega, np.array([ai]), np.array([ao])
    )[0]
    # inner pushes out and towards +z, outer in and towards -z; plus F_c and friction
    radial = qi * math.cos(ai) - qo * math.cos(ao) + fc + f[0]
    axial = qi * math.sin(ai) - qo * math.sin(ao) + f[1]
    assert abs(radial) < 1e-6 * qo and abs(axial) < 1e-6 * qo
    plain = solve_load_distribution(ACBB, OperatingCondition(axial_load=1000.0, shaft_speed=omega))
    # the friction pushes the ball away from the outer contact's side: the inner angle grows
    assert r.contact_angle[0, 0] > plain.contact_angle[0, 0]


def test_no_gyroscopic_effect_at_rest_or_without_contact_angle():
    rest = solve_load_distribution(ACBB, OperatingCondition(axial_load=500.0), gyroscopic=True)
    plain = solve_load_distribution(ACBB, OperatingCondition(axial_load=500.0))
    np.testing.assert_allclose(rest.displacement, plain.displacement)
    dgbb = BallBearing(
        ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3, diametral_clearance=0.0
    )
    c = OperatingCondition(radial_load=500.0, shaft_speed=1500.0)
    np.testing.assert_allclose(
        solve_load_distribution(dgbb, c, gyroscopic=True).displacement,
        solve_load_distribution(dgbb, c).displacement,
        atol=1e-12,
    )
