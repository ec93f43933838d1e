"""Hertz point contact: exact solution, Hamrock-Brewe approximations, inverses, errors."""

import numpy as np
import pytest
from scipy import special

from bearinglab.contact import hertz
from bearinglab.errors import InputError

E_STEEL = 228.6e9
# 209 deep-groove bearing (Harris & Kotzalas' example bearing): inner contact radii [m]
RX_209, RY_209 = 5.10931e-3, 165.1e-3


def test_ellipticity_satisfies_the_exact_relation():
    ratios = np.array([1.0001, 1.5, 5.0, 21.75, 32.313, 100.0, 2000.0])
    k = hertz.ellipticity(ratios)
    m = 1 - 1 / k**2
    kk, ee = special.ellipk(m), special.ellipe(m)
    # curvature difference F(rho) = ((k^2+1)E - 2K)/((k^2-1)E) = (ratio-1)/(ratio+1)
    f_rho = ((k**2 + 1) * ee - 2 * kk) / ((k**2 - 1) * ee)
    np.testing.assert_allclose(f_rho, (ratios - 1) / (ratios + 1), rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("ratio", [1.0, 1.2, 2.0, 5.0, 10.0, 21.75, 32.3, 50.0])
def test_hamrock_brewe_close_to_exact(ratio):
    # Largest deviations of the fits over 1 <= R_y/R_x <= 50, found by us (research note in
    # docs/capabilities/hertz.md): k 3.4 %, E 1.7 %, K 2.7 %, all at R_y/R_x -> 1.
    k_exact = hertz.ellipticity(ratio)
    k_hb = hertz.ellipticity(ratio, "hamrock_brewe") if ratio > 1 else 1.0339
    assert k_hb == pytest.approx(k_exact, rel=0.035)
    kk, ee = hertz.elliptic_integrals(k_exact)
    kk_hb, ee_hb = hertz.elliptic_integrals(None, ratio, "hamrock_brewe")
    assert ee_hb == pytest.approx(ee, rel=0.018)
    assert kk_hb == pytest.approx(kk, rel=0.028)


def test_contact_results_agree_between_methods_for_a_ball_bearing():
    exact = hertz.point_contact(4321.4, RX_209, RY_209, E_STEEL)
    approx = hertz.point_contact(4321.4, RX_209, RY_209, E_STEEL, "hamrock_brewe")
    for name in ("semi_major", "semi_minor", "max_pressure", "approach"):
        assert getattr(approx, name) == pytest.approx(getattr(exact, name), rel=0.02), name


def test_209_inner_contact_values():
    # Exact Hertz for the 209 inner contact at Q = 4.37 Fr / Z (Fr = 8900 N) with
    # E = 200 GPa, nu = 0.3 (E' = 219.8 GPa): a = 2.5373 mm, b = 0.27327 mm,
    # delta = 26.81 um, p_max = 2975.8 MPa (computed independently with the Harris
    # a*, b*, delta* route, research note of 2026-11-21).
    c = hertz.point_contact(4321.4, RX_209, RY_209, 2 * 200e9 / (1 - 0.09) / 2)
    assert float(c.semi_major) == pytest.approx(2.5373e-3, rel=2e-4)
    assert float(c.semi_minor) == pytest.approx(0.27327e-3, rel=2e-4)
    assert float(c.approach) == pytest.approx(26.81e-6, rel=5e-4)
    assert float(c.max_pressure) == pytest.approx(2975.8e6, rel=2e-4)


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
    np.testing.assert_allclose(hertz.load_from_approach(delta, RX_209, RY_209, E_STEEL), q,
                               rtol=1e-12)
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


@pytest.mark.parametrize("kwargs, parameter", [
    ({"load": -1.0}, "load"),
    ({"load": np.nan}, "load"),
    ({"rx": 0.0}, "rx, ry"),
    ({"ry": -1e-3}, "rx, ry"),
    ({"effective_modulus": 0.0}, "effective_modulus"),
    ({"method": "magic"}, "method"),
])
def test_bad_input_names_the_parameter(kwargs, parameter):
    args = {"load": 100.0, "rx": RX_209, "ry": RY_209, "effective_modulus": E_STEEL, **kwargs}
    with pytest.raises(InputError) as err:
        hertz.point_contact(**args)
    assert err.value.parameter == parameter


def test_ratio_below_one_is_rejected():
    with pytest.raises(InputError):
        hertz.ellipticity(0.5)
