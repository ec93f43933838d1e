"""Quasi-static load distribution: closed forms, equilibrium, stiffness, contact cases."""

import math

import numpy as np
import pytest
from conftest import STATIC_BALL_KEYS, STATIC_KEYS
from scipy import optimize

from bearinglab.contact.ball_race import load_deflection_constants
from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import centrifugal_force, solve_load_distribution

GEOM = {"ball_count": 9, "ball_diameter": 7.94e-3, "pitch_diameter": 39.04e-3}


def bearing(**kw):
    return BallBearing(**{**GEOM, **kw})


def test_stribeck_zero_clearance():
    # Stribeck: Q_max = 4.37 F_r / Z for zero clearance and many balls (NSK CAT. E728g 5.1
    # eq. 4; Harris & Kotzalas ch. 7). With Z = 9 the discrete ball set gives 4.38; with
    # more balls it tends to 4.37 within the approximation's own rounding.
    for z, dw, allowed in ((9, 7.94e-3, 0.006), (20, 4e-3, 0.003)):
        b = BallBearing(
            ball_count=z, ball_diameter=dw, pitch_diameter=39.04e-3, diametral_clearance=0.0
        )
        r = solve_load_distribution(b, OperatingCondition(radial_load=2000.0))
        q_max = r.load[:, r.ring == 0].max()
        assert q_max * z / 2000.0 == pytest.approx(4.37, rel=allowed)


def test_pure_axial_matches_the_closed_form():
    # Harris & Kotzalas ch. 7: F_a = Z K_n A^1.5 sin(b) (cos(b0)/cos(b) - 1)^1.5,
    # Q = F_a / (Z sin b), with K_n the ball's series constant at the operating angle b.
    b = bearing(diametral_clearance=20e-6)
    fa = 1500.0
    r = solve_load_distribution(b, OperatingCondition(axial_load=fa))
    a, b0 = b.groove_centre_distance, b.free_contact_angle

    def residual(beta):
        k_n = load_deflection_constants(b, beta)[2]
        return (
            b.ball_count
            * k_n
            * a**1.5
            * math.sin(beta)
            * (math.cos(b0) / math.cos(beta) - 1) ** 1.5
            - fa
        )

    beta = optimize.brentq(residual, b0 + 1e-9, math.radians(80))
    assert np.allclose(r.contact_angle, beta, rtol=1e-6)
    assert np.allclose(r.load, fa / (b.ball_count * math.sin(beta)), rtol=1e-6)
    # axial displacement from the centred position: A sin(beta) + ... geometry
    assert r.axial_displacement == pytest.approx(
        a * math.sin(beta) / math.cos(beta) * math.cos(b0), rel=1e-6
    )


@pytest.mark.parametrize(
    "kwargs, cond",
    [
        ({"diametral_clearance": 15e-6}, {"radial_load": 800.0, "axial_load": 300.0}),
        (
            {"diametral_clearance": 15e-6},
            {
                "radial_load": 800.0,
                "axial_load": 300.0,
                "moment": (2.0, -1.0),
                "shaft_speed": 1500.0,
            },
        ),
        (
            {"contact_angle": math.radians(25)},
            {"radial_load": 500.0, "axial_load": 900.0, "misalignment": (1e-3, 0.0)},
        ),
        (
            {
                "diametral_clearance": 60e-6,
                "inner_arch_angle": math.radians(25),
                "outer_arch_angle": math.radians(25),
            },
            {"radial_load": 1200.0, "axial_load": 200.0, "shaft_speed": 2000.0},
        ),
    ],
)
def test_stiffness_matrix_equals_finite_differences(kwargs, cond):
    b = bearing(**kwargs)
    c = OperatingCondition(**cond)
    r = solve_load_distribution(b, c)
    from bearinglab.quasistatic.solver import _Problem

    p = _Problem(b, c, c.radial_load_angle, None, None)
    steps = np.array([1e-8, 1e-8, 1e-8, 1e-7, 1e-7])
    fd = np.zeros((5, 5))
    for i in range(5):
        cols = []
        for sgn in (1, -1):
            u = r.displacement.copy()
            u[i] += sgn * steps[i]
            _, state = p.solve_balls(r.ball_centre, u, 1e-9)
            cols.append(p.ring_force_and_stiffness(state)[0])
        fd[:, i] = -(cols[0] - cols[1]) / (2 * steps[i])
    scale = np.abs(r.stiffness_matrix).max()
    np.testing.assert_allclose(r.stiffness_matrix, fd, atol=2e-5 * scale, rtol=2e-4)


def test_four_point_contact_under_radial_load_and_two_point_under_axial():
    b = bearing(
        diametral_clearance=40e-6,
        inner_arch_angle=math.radians(25),
        outer_arch_angle=math.radians(25),
    )
    radial = solve_load_distribution(b, OperatingCondition(radial_load=2000.0))
    bottom = np.argmax(radial.load.sum(axis=1))
    assert radial.contact_points[bottom] == 4  # seed 001 fig. 5a
    axial = solve_load_distribution(b, OperatingCondition(axial_load=2000.0))
    assert np.all(axial.contact_points == 2)  # seed 001 fig. 1


def test_centrifugal_force_balance_at_speed():
    b = bearing(contact_angle=math.radians(40))
    omega = 20000 * math.pi / 30
    r = solve_load_distribution(b, OperatingCondition(axial_load=500.0, shaft_speed=omega))
    qi, qo = r.load[:, r.ring == 0][:, 0], r.load[:, r.ring == 1][:, 0]
    ai, ao = r.contact_angle[:, r.ring == 0][:, 0], r.contact_angle[:, r.ring == 1][:, 0]
    # F_c at Jones's orbital speed under outer raceway control, at the ball's own angles:
    # omega_m / omega = (1 - g cos a_i) / (1 + cos(a_i - a_o)) (Harris & Kotzalas)
    g = b.ball_diameter / b.pitch_diameter
    wm = omega * (1 - g * np.cos(ai)) / (1 + np.cos(ai - ao))
    fc = 0.5 * b.ball_mass * b.pitch_diameter * wm**2
    np.testing.assert_allclose(r.ball_centrifugal_force, fc, rtol=1e-9)
    np.testing.assert_allclose(r.orbital_speed, wm, rtol=1e-9)
    # with equal angles it is seed 001's pure-rolling F_c; here a_o < a_i makes it larger
    assert np.all(fc > centrifugal_force(b, omega))
    # seed 001 eq. 3: Q_o cos(a_o) = Q_i cos(a_i) + F_c, Q_o sin(a_o) = Q_i sin(a_i) = F_a/Z
    np.testing.assert_allclose(qo * np.cos(ao) - qi * np.cos(ai), fc, rtol=1e-6)
    np.testing.assert_allclose(qi * np.sin(ai), 500.0 / 9, rtol=1e-6)
    assert np.all(ao < ai)


def test_preload_without_external_load():
    b = bearing(diametral_clearance=-5e-6)
    r = solve_load_distribution(b, OperatingCondition())
    assert np.allclose(r.displacement, 0.0, atol=1e-12)
    assert np.all(r.load > 0) and r.radial_stiffness > 0
    assert any("preloaded" in w for w in r.warnings)


def test_a_larger_ball_carries_more():
    b = bearing(diametral_clearance=10e-6)
    errors = np.zeros(9)
    errors[0] = 2e-6
    even = solve_load_distribution(b, OperatingCondition(radial_load=1000.0))
    odd = solve_load_distribution(
        b, OperatingCondition(radial_load=1000.0), ball_diameter_errors=errors
    )
    assert odd.load[0, 0] > even.load[0, 0]


def test_overload_runs_over_the_shoulder_and_is_reported():
    r = solve_load_distribution(
        bearing(diametral_clearance=15e-6), OperatingCondition(axial_load=20000.0)
    )
    assert np.all(r.truncated[r.load > 0])
    assert any("shoulder" in w for w in r.warnings)
    ok = solve_load_distribution(
        bearing(diametral_clearance=15e-6), OperatingCondition(axial_load=500.0)
    )
    assert not ok.warnings and not np.any(ok.truncated)


def test_result_dict_has_the_documented_keys():
    r = solve_load_distribution(
        bearing(diametral_clearance=15e-6), OperatingCondition(radial_load=700.0, axial_load=100.0)
    )
    d = r.to_dict()
    for key in STATIC_KEYS:
        assert key in d
    ball = d["balls"][0]
    for key in STATIC_BALL_KEYS:
        assert key in ball
    assert np.array(d["stiffness_matrix_si"]).shape == (5, 5)
    assert d["equilibrium_residual_n"] < 1e-6 * 700


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"radial_load": -1.0}, "radial_load"),
        ({"axial_load": math.nan}, "axial_load"),
        ({"shaft_speed": -5.0}, "shaft_speed"),
        ({"misalignment": (0.5, 0.0)}, "misalignment"),
        ({"moment": (1.0,)}, "moment"),
    ],
)
def test_bad_operating_condition(kwargs, parameter):
    with pytest.raises(InputError) as err:
        OperatingCondition(**kwargs)
    assert err.value.parameter == parameter


def test_bad_ball_errors():
    with pytest.raises(InputError):
        solve_load_distribution(
            bearing(), OperatingCondition(radial_load=10.0), ball_diameter_errors=np.zeros(3)
        )


def test_inner_ring_expansion_thin_ring_limit_and_effect():
    from bearinglab.quasistatic import inner_ring_expansion

    # a ring whose bore is almost its raceway is a thin ring: u = rho omega^2 R^3 / E
    thin = bearing(bore=31.0e-3, outside_diameter=52e-3, width=15e-3)
    omega = 30000 * math.pi / 30
    r = 0.5 * thin.inner_raceway_diameter
    assert inner_ring_expansion(thin, omega) == pytest.approx(
        7830 * omega**2 * r**3 / 208e9, rel=0.05
    )
    b = bearing(diametral_clearance=20e-6, bore=25e-3, outside_diameter=52e-3, width=15e-3)
    c = OperatingCondition(radial_load=300.0, shaft_speed=omega)
    hot = solve_load_distribution(b, c, ring_expansion=True)
    cold = solve_load_distribution(b, c)
    shrink = 2 * inner_ring_expansion(b, omega)
    assert hot.bearing.diametral_clearance == pytest.approx(20e-6 - shrink)
    assert hot.radial_displacement < cold.radial_displacement
    with pytest.raises(InputError, match="bore"):
        solve_load_distribution(bearing(), c, ring_expansion=True)


def test_angular_contact_low_shoulder_is_checked_on_its_side():
    acbb = bearing(contact_angle=math.radians(40))
    seated = solve_load_distribution(acbb, OperatingCondition(axial_load=2000.0))
    reversed_load = solve_load_distribution(acbb, OperatingCondition(axial_load=-2000.0))
    assert not seated.warnings  # thrust side: high shoulder
    assert any("shoulder" in w for w in reversed_load.warnings)  # the low side runs over
    assert acbb.shoulder_angle("inner", 1) > acbb.shoulder_angle("inner", -1)


def test_overload_is_told_against_the_static_rating():
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.errors import ConvergenceError

    b, _ = bearing_from_designation("6205")
    with pytest.raises(
        ConvergenceError,
        match=r"cannot carry this load: F_r = 1e\+06 N.*"
        r"P0 = 1e\+06 N, 127 times the static rating C0 = 78\d\d(\.\d+)? N"
        r" \(ISO 76; s0 = 0.00789\)",
    ) as info:
        solve_load_distribution(b, OperatingCondition(radial_load=1e6))
    assert "residual" not in str(info.value)
    # a load the bearing carries is solved as before
    solve_load_distribution(b, OperatingCondition(radial_load=3e4))


def test_unknown_race_control_is_refused():
    with pytest.raises(InputError, match="race_control = 'middle'.*'outer' or 'inner' or 'hybrid'"):
        solve_load_distribution(
            bearing(), OperatingCondition(radial_load=100.0), race_control="middle"
        )


def test_hybrid_control_follows_jones_criterion():
    # a heavily thrust-loaded 40 deg bearing at speed: the outer contact carries more, its
    # spin-resisting moment wins and every ball is outer-raceway controlled; the answer is
    # then that of race_control="outer"
    b = bearing(contact_angle=math.radians(40))
    c = OperatingCondition(axial_load=3000.0, shaft_speed=15000 * math.pi / 30)
    hybrid = solve_load_distribution(b, c, race_control="hybrid", gyroscopic=True)
    outer = solve_load_distribution(b, c, race_control="outer", gyroscopic=True)
    assert np.all(hybrid.outer_controlled)
    np.testing.assert_allclose(hybrid.displacement, outer.displacement, atol=1e-13)
    inner = solve_load_distribution(b, c, race_control="inner", gyroscopic=True)
    assert not np.any(inner.outer_controlled)
    # inner raceway control: Jones's orbital speed with tan(beta) = sin a_i/(cos a_i - g)
    from bearinglab.quasistatic.gyroscopic import raceway_control_kinematics

    ai, ao = inner.contact_angle[0]
    orbit = raceway_control_kinematics(ai, ao, b.ball_diameter / b.pitch_diameter, "inner")[1]
    assert inner.orbital_speed[0] == pytest.approx(orbit * c.shaft_speed, rel=1e-12)
    assert inner.cage_speed != pytest.approx(outer.cage_speed, rel=1e-4)
    d = inner.to_dict()
    assert d["race_control"] == "inner" and d["cage_speed_rpm"] > 0
    assert {
        "orbital_speed_rpm",
        "centrifugal_force_n",
        "gyroscopic_moment_n_mm",
        "outer_raceway_control",
    } <= set(d["balls"][0])
