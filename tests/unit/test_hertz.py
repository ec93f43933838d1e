"""Hertz point contact: exact solution, Hamrock-Brewe approximations, inverses, errors."""

from decimal import Decimal, localcontext

import numpy as np
import pytest

from bearinglab.contact import hertz
from bearinglab.contact.ball_race import ball_contacts
from bearinglab.errors import ConvergenceError, InputError
from bearinglab.geometry import BallBearing

E_STEEL = 228.6e9
# 209 deep-groove bearing (Harris & Kotzalas' example bearing): inner contact radii [m]
RX_209, RY_209 = 5.10931e-3, 165.1e-3

_PI = Decimal("3.14159265358979323846264338327950288419716939937510582097494459")


def _exact_relation_50_digits(k: float):
    """(R_y/R_x, F(rho)) of the exact Hertz relation at ellipticity k, to ~45 digits:
    K and E by the arithmetic-geometric mean in Decimal arithmetic (b_0 = sqrt(1 - m) =
    1/k exactly), independent of SciPy and of the module's own formulation."""
    with localcontext() as ctx:
        ctx.prec = 60
        k = Decimal(k)
        m = 1 - 1 / (k * k)
        a, b = Decimal(1), 1 / k
        total, power, c2 = m / 2, Decimal(1), m  # sum 2^(n-1) c_n^2, from n = 0
        while c2 > Decimal(10) ** -58 * (1 + m):
            a, b, c = (a + b) / 2, (a * b).sqrt(), (a - b) / 2
            c2, power = c * c, power * 2
            total += power / 2 * c2
        first = _PI / (2 * a)
        second = first * (1 - total)
        ratio = (k * k * second - first) / (first - second)
        f_rho = ((k * k + 1) * second - 2 * first) / ((k * k - 1) * second)
        return ratio, f_rho


@pytest.mark.parametrize("ratio", [1.0001, 1.5, 5.0, 21.75, 32.313, 100.0, 2000.0, 1e5, 1e7, 1e8])
def test_ellipticity_satisfies_the_exact_relation(ratio):
    # F(rho) = ((k^2+1)E - 2K)/((k^2-1)E) = (ratio-1)/(ratio+1) (Harris & Kotzalas eq. 6.9),
    # checked in 60-digit arithmetic: a float evaluation of it loses ~8 digits near k = 1.
    k = float(hertz.ellipticity(ratio))
    got_ratio, f_rho = _exact_relation_50_digits(k)
    assert float(got_ratio) == pytest.approx(ratio, rel=1e-12)
    want = (Decimal(ratio) - 1) / (Decimal(ratio) + 1)
    assert float(f_rho) == pytest.approx(float(want), rel=1e-10)


def test_ellipticity_is_robust_over_the_whole_range():
    # 1 <= R_y/R_x <= 1e8 (a groove factor of 0.500005 gives ~1.3e5): every value solved,
    # monotonic, and the relative residual below 1e-12; the brief's failing case included.
    ratios = np.concatenate([[1.0, 1.0 + 1e-13, 1.0 + 1e-9], np.logspace(0, 8, 801)])
    k = hertz.ellipticity(ratios)
    assert np.all(np.isfinite(k)) and np.all(np.diff(k[3:]) >= 0) and k[0] == 1.0
    above = ratios > 1.0
    residual = np.abs(np.expm1(hertz._log_ratio(np.log(k[above])) - np.log(ratios[above])))
    assert residual.max() < 1e-12
    rx, ry = BallBearing(
        ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3, inner_groove_factor=0.500005
    ).contact_radii("inner")
    c = hertz.point_contact(1000.0, rx, ry, E_STEEL)
    assert np.isfinite(float(c.approach)) and float(c.ellipticity) > 900.0  # R_y/R_x ~ 1.3e5


def test_bracketed_fallback_gives_the_same_ellipticity():
    # with no secant steps every element goes to the per-element Brent search
    target = np.log(np.array([1.0001, 3.0, 1e3, 1e8]))
    fast = hertz._solve_log_k(target)
    slow = hertz._solve_log_k(target, iterations=0)
    np.testing.assert_allclose(np.exp(slow), np.exp(fast), rtol=1e-14)


def test_failure_to_solve_is_a_convergence_error(monkeypatch):
    monkeypatch.setattr(hertz, "_log_ratio", lambda u: np.full(np.shape(u), np.nan))
    with pytest.raises(ConvergenceError, match="R_y/R_x"):
        hertz.ellipticity(50.0)


@pytest.mark.parametrize("ratio", [1.0, 1.2, 2.0, 5.0, 10.0, 21.75, 32.3, 50.0])
def test_hamrock_brewe_close_to_exact(ratio):
    # Largest deviations of the fits over 1 <= R_y/R_x <= 50, found by us (research note in
    # docs/capabilities/hertz.md): k 3.4 %, E 1.7 %, K 2.7 %, all at R_y/R_x -> 1 (where the
    # k fit gives its 1.0339 against the exact 1).
    k_exact = hertz.ellipticity(ratio)
    k_hb = hertz.ellipticity(ratio, "hamrock_brewe")
    assert k_hb == pytest.approx(k_exact, rel=0.035)
    kk, ee = hertz.elliptic_integrals(k_exact)
    kk_hb, ee_hb = hertz.elliptic_integrals(None, ratio, "hamrock_brewe")
    assert ee_hb == pytest.approx(ee, rel=0.018)
    assert kk_hb == pytest.approx(kk, rel=0.028)


def test_hamrock_brewe_fit_at_the_circle_is_its_own_value():
    # the fit is used as a whole: k(1) = 1.0339 with E(1) = 1.5971, K(1) = 1.5277
    assert float(hertz.ellipticity(1.0, "hamrock_brewe")) == pytest.approx(1.0339, abs=1e-12)
    np.testing.assert_allclose(
        hertz.ellipticity([1.0, 4.0], "hamrock_brewe"), 1.0339 * np.array([1.0, 4.0]) ** 0.6360
    )
    kk, ee = hertz.elliptic_integrals(None, 1.0, "hamrock_brewe")
    assert (kk, ee) == pytest.approx((1.5277, 1.0003 + 0.5968))


def test_contact_results_agree_between_methods_for_a_ball_bearing():
    exact = hertz.point_contact(4321.4, RX_209, RY_209, E_STEEL)
    approx = hertz.point_contact(4321.4, RX_209, RY_209, E_STEEL, "hamrock_brewe")
    for name in ("semi_major", "semi_minor", "max_pressure", "approach"):
        assert getattr(approx, name) == pytest.approx(getattr(exact, name), rel=0.02), name


def test_209_inner_contact_against_an_independent_exact_computation():
    # Not a printed textbook value: exact Hertz for the 209 inner contact at
    # Q = 4.37 Fr / Z (Fr = 8900 N) with E = 200 GPa, nu = 0.3 (E' = 219.8 GPa), computed
    # independently of this module with the Harris a*, b*, delta* route (research note of
    # 2026-11-21): a = 2.5373 mm, b = 0.27327 mm, delta = 26.81 um, p_max = 2975.8 MPa.
    c = hertz.point_contact(4321.4, RX_209, RY_209, 2 * 200e9 / (1 - 0.09) / 2)
    assert float(c.semi_major) == pytest.approx(2.5373e-3, rel=2e-4)
    assert float(c.semi_minor) == pytest.approx(0.27327e-3, rel=2e-4)
    assert float(c.approach) == pytest.approx(26.81e-6, rel=5e-4)
    assert float(c.max_pressure) == pytest.approx(2975.8e6, rel=2e-4)


def test_point_contact_solves_the_ellipticity_once(monkeypatch):
    calls = []
    real = hertz.ellipticity
    monkeypatch.setattr(hertz, "ellipticity", lambda *a, **k: calls.append(1) or real(*a, **k))
    c = hertz.point_contact(np.array([0.0, 250.0, 1000.0]), RX_209, RY_209, E_STEEL)
    assert len(calls) == 1
    # stiffness 1.5 Q / delta equals 1.5 K delta^0.5, and is 0 at zero load
    k_c = hertz.load_deflection_constant(RX_209, RY_209, E_STEEL)
    np.testing.assert_allclose(c.stiffness, 1.5 * k_c * np.sqrt(c.approach), rtol=1e-12)
    assert c.stiffness[0] == 0.0


def test_huge_loads_stay_finite():
    c = hertz.point_contact(1e300, RX_209, RY_209, E_STEEL)
    assert np.isfinite([float(c.approach), float(c.max_pressure), float(c.stiffness)]).all()


def test_contact_ellipse_over_the_groove_shoulder_is_warned():
    # criterion of the load-distribution model: |alpha| + a/(f D_w) > arccos(1 - 0.2/f)
    b = BallBearing(
        ball_count=9,
        ball_diameter=7.94e-3,
        pitch_diameter=39.04e-3,
        inner_groove_factor=0.515,
        outer_groove_factor=0.525,
    )
    assert ball_contacts(b, 1000.0).warnings == []
    loads = np.array([1000.0, 5000.0, 20000.0, 40000.0])
    r = ball_contacts(b, loads)
    f, dw = 0.515, 7.94e-3
    shoulder = np.arccos(1 - 0.2 / f)
    over = r.inner.semi_major / (f * dw) > shoulder
    assert list(over) == [False, False, True, True]
    over_shoulder = [w for w in r.to_dict()["warnings"] if "groove shoulder" in w]
    inner = [w for w in over_shoulder if w.startswith("inner")]
    assert len(inner) == 1 and "Q = 2e+04 N" in inner[0]
    # these loads also pass the 4200 MPa of ISO 76's static rating (8.3 GPa at 40 kN)
    iso76 = [w for w in r.warnings if "ISO 76" in w]
    assert iso76[0].startswith("inner contact: p_max = 8317 MPa")
    assert not any("ISO 76" in w for w in ball_contacts(b, 1000.0).warnings)
    # a thrust bearing's groove bottom lies at 90 deg: no warning at a light load
    t = BallBearing(
        ball_count=15,
        ball_diameter=6e-3,
        pitch_diameter=38e-3,
        contact_angle=np.pi / 2,
        bearing_type="thrust_ball",
    )
    assert ball_contacts(t, 100.0).warnings == []


def test_vectorised_over_loads_and_zero_load():
    loads = np.array([0.0, 10.0, 100.0, 1000.0])
    c = hertz.point_contact(loads, RX_209, RY_209, E_STEEL)
    assert c.semi_major.shape == (4,)
    assert c.semi_major[0] == 0 and c.max_pressure[0] == 0 and c.approach[0] == 0
    assert np.all(np.diff(c.approach) > 0)
    for i, q in enumerate(loads[1:], start=1):
        one = hertz.point_contact(q, RX_209, RY_209, E_STEEL)
        assert float(one.max_pressure) == pytest.approx(c.max_pressure[i], rel=1e-12)


def test_approach_and_load_are_inverse():
    q = np.array([1.0, 50.0, 3000.0])
    delta = hertz.approach(q, RX_209, RY_209, E_STEEL)
    np.testing.assert_allclose(
        hertz.load_from_approach(delta, RX_209, RY_209, E_STEEL), q, rtol=1e-12
    )
    assert hertz.load_from_approach(-1e-6, RX_209, RY_209, E_STEEL) == 0.0


def test_stiffness_is_the_derivative_of_load():
    q, dq = 1000.0, 1e-3
    d1, d2 = hertz.approach([q - dq, q + dq], RX_209, RY_209, E_STEEL)
    c = hertz.point_contact(q, RX_209, RY_209, E_STEEL)
    assert float(c.stiffness) == pytest.approx(2 * dq / (d2 - d1), rel=1e-6)


def test_series_constant_adds_approaches():
    k_i, k_o, q = 3.2e10, 3.4e10, 800.0
    k_n = hertz.series_constant(k_i, k_o)
    assert (q / k_n) ** (2 / 3) == pytest.approx((q / k_i) ** (2 / 3) + (q / k_o) ** (2 / 3))


def test_orientation_does_not_matter():
    a = hertz.point_contact(500.0, RX_209, RY_209, E_STEEL)
    b = hertz.point_contact(500.0, RY_209, RX_209, E_STEEL)
    for name in ("semi_major", "semi_minor", "max_pressure", "approach"):
        assert getattr(a, name) == pytest.approx(getattr(b, name), rel=1e-12)


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"load": -1.0}, "load"),
        ({"load": np.nan}, "load"),
        ({"rx": 0.0}, "rx, ry"),
        ({"ry": -1e-3}, "rx, ry"),
        ({"effective_modulus": 0.0}, "effective_modulus"),
        ({"method": "magic"}, "method"),
    ],
)
def test_bad_input_names_the_parameter(kwargs, parameter):
    args = {"load": 100.0, "rx": RX_209, "ry": RY_209, "effective_modulus": E_STEEL, **kwargs}
    with pytest.raises(InputError) as err:
        hertz.point_contact(**args)
    assert err.value.parameter == parameter


def test_ratio_below_one_is_rejected():
    with pytest.raises(InputError):
        hertz.ellipticity(0.5)
