"""Unit tests of bearinglab.lubrication: film-thickness scaling laws, limits,
vectorisation, errors, entrainment speed, the seed-004 formula, and Lubricant."""

import dataclasses
import math

import numpy as np
import pytest

from bearinglab.contact import hertz
from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.kinematics import frequency_orders
from bearinglab.lubrication import ehl
from bearinglab.lubrication.lubricant import (
    ISO_VG68,
    LUBRICANTS,
    SEED004_GREASE,
    ZERO_CELSIUS,
    Lubricant,
    reynolds_viscosity,
    roelands_index,
    roelands_pressure_viscosity_coefficient,
)
from bearinglab.materials import BEARING_STEEL, SILICON_NITRIDE, effective_modulus

# A 6205-like inner contact: R_x = 3.18 mm, R_y = 104 mm, steel, VG 68-like oil.
BASE = {
    "load": 300.0,
    "entrainment_speed": 2.35,
    "rx": 3.18e-3,
    "ry": 0.104,
    "effective_modulus": 2.286e11,
    "viscosity": 0.0585,
    "pressure_viscosity_coefficient": 2.5e-8,
}
B6205 = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)


def in_mm(contact):
    """The same contact in mm, N, s: E' in N/mm^2, eta in N s/mm^2, alpha in mm^2/N."""
    return {
        "load": contact["load"],
        "entrainment_speed": contact["entrainment_speed"] * 1e3,
        "rx": contact["rx"] * 1e3,
        "ry": contact["ry"] * 1e3,
        "effective_modulus": contact["effective_modulus"] * 1e-6,
        "viscosity": contact["viscosity"] * 1e-6,
        "pressure_viscosity_coefficient": contact["pressure_viscosity_coefficient"] * 1e6,
    }


def film(kind="minimum", **changes):
    return float(ehl.hamrock_dowson_film(**{**BASE, **changes}, kind=kind))


# ---------------------------------------------------------------- scaling laws


@pytest.mark.parametrize(
    "kind, name, exponent",
    [
        ("minimum", "entrainment_speed", 0.68),
        ("minimum", "viscosity", 0.68),
        ("minimum", "pressure_viscosity_coefficient", 0.49),
        ("minimum", "load", -0.073),
        ("central", "entrainment_speed", 0.67),
        ("central", "viscosity", 0.67),
        ("central", "pressure_viscosity_coefficient", 0.53),
        ("central", "load", -0.067),
    ],
)
def test_power_laws(kind, name, exponent):
    factor = 3.7
    ratio = film(kind, **{name: BASE[name] * factor}) / film(kind)
    assert ratio == pytest.approx(factor**exponent, rel=1e-12)


@pytest.mark.parametrize(
    "kind, rx_exp, e_exp", [("minimum", 0.466, -0.117), ("central", 0.464, -0.073)]
)
def test_dimensional_exponents_of_radius_and_modulus(kind, rx_exp, e_exp):
    # h = H R_x: R_x^(1 - a_U + 2 a_W), E'^(-a_U + a_G + a_W). Scaling R_y with R_x keeps k.
    f = 2.0
    assert film(kind, rx=BASE["rx"] * f, ry=BASE["ry"] * f) / film(kind) == pytest.approx(
        f**rx_exp, rel=1e-12
    )
    assert film(kind, effective_modulus=BASE["effective_modulus"] * f) / film(
        kind
    ) == pytest.approx(f**e_exp, rel=1e-12)


def test_load_dependence_is_weak():
    # Ten times the load thins the minimum film by only 10^-0.073 = 0.845.
    assert film(load=3000.0) / film(load=300.0) == pytest.approx(0.8453, abs=1e-4)


@pytest.mark.parametrize("kind", ["minimum", "central"])
def test_unit_system_does_not_matter(kind):
    # Dimensional consistency: the same contact in mm, N, s (E' in N/mm^2, eta in N s/mm^2,
    # alpha in mm^2/N) gives the film in mm.
    h_mm = float(ehl.hamrock_dowson_film(**in_mm(BASE), kind=kind))
    assert h_mm == pytest.approx(film(kind) * 1e3, rel=1e-12)


# ---------------------------------------------------------------- limits


def test_zero_speed_gives_zero_film():
    assert film(entrainment_speed=0.0) == 0.0
    assert film("central", entrainment_speed=0.0) == 0.0


def test_ellipticity_factors_tend_to_one():
    g = (1e-11, 5000.0, 1e-5)
    bare_min = 3.63 * g[0] ** 0.68 * g[1] ** 0.49 * g[2] ** -0.073
    bare_c = 2.69 * g[0] ** 0.67 * g[1] ** 0.53 * g[2] ** -0.067
    assert float(ehl.hamrock_dowson_minimum(*g, 60.0)) == pytest.approx(bare_min, rel=1e-15)
    assert float(ehl.hamrock_dowson_central(*g, 60.0)) == pytest.approx(bare_c, rel=1e-15)
    # Circular contact (k = 1): factors 1 - e^-0.68 = 0.4934 and 1 - 0.61 e^-0.73 = 0.7060.
    assert float(ehl.hamrock_dowson_minimum(*g, 1.0)) / bare_min == pytest.approx(0.49338, 1e-4)
    assert float(ehl.hamrock_dowson_central(*g, 1.0)) / bare_c == pytest.approx(0.70604, 1e-4)


def test_film_grows_with_ellipticity():
    k = np.linspace(1.0, 12.0, 50)
    assert np.all(np.diff(ehl.hamrock_dowson_minimum(1e-11, 5000.0, 1e-5, k)) > 0)
    assert np.all(np.diff(ehl.hamrock_dowson_central(1e-11, 5000.0, 1e-5, k)) > 0)


def test_central_thicker_than_minimum_for_bearing_contacts():
    ratio = film("central") / film("minimum")
    assert 1.0 < ratio < 2.0


def test_ellipticity_methods_agree_for_ball_bearings():
    # 1.03 (R_y/R_x)^0.64 differs from the exact k by up to 3 % (at R_y = R_x) and 4 % at
    # R_y/R_x = 50, but the film depends on k only through 1 - exp(-0.68 k), which is
    # within 0.1 % for R_y/R_x >= 5 (we measured < 0.06 %).
    for method in ("exact", "hamrock_brewe"):
        h = float(ehl.hamrock_dowson_film(**BASE, kind="minimum", ellipticity_method=method))
        assert h == pytest.approx(film(), rel=1e-3)
    ratio = np.array([1.0, 5.0, 30.0])
    k = ehl.contact_ellipticity(1.0, ratio, "exact")
    assert np.allclose(k, hertz.ellipticity(ratio), rtol=1e-14)
    assert float(ehl.ellipticity_hamrock_dowson(30.0)) == pytest.approx(1.03 * 30**0.64)


# ---------------------------------------------------------------- vectorisation


def test_broadcasting_matches_scalar_calls():
    loads = np.array([50.0, 200.0, 800.0])
    speeds = np.array([[0.5], [5.0]])
    h = ehl.hamrock_dowson_film(
        loads, speeds, BASE["rx"], BASE["ry"], 2.286e11, 0.0585, 2.5e-8, "minimum"
    )
    assert h.shape == (2, 3)
    for i, u in enumerate(speeds[:, 0]):
        for j, w in enumerate(loads):
            assert h[i, j] == pytest.approx(film(load=w, entrainment_speed=u), rel=1e-14)


def test_scalar_in_scalar_out():
    assert isinstance(ehl.hamrock_dowson_film(**BASE), float)
    assert np.ndim(ehl.rolling_entrainment_speed(0.04, 0.008, 100.0)) == 0


# ---------------------------------------------------------------- errors


@pytest.mark.parametrize(
    "changes, parameter",
    [
        ({"load": 0.0}, "load"),
        ({"load": -5.0}, "load"),
        ({"load": np.nan}, "load"),
        ({"entrainment_speed": -1.0}, "entrainment_speed"),
        ({"rx": 0.0}, "rx"),
        ({"ry": 1e-3}, "ry"),
        ({"viscosity": -0.1}, "viscosity"),
        ({"pressure_viscosity_coefficient": 0.0}, "pressure_viscosity_coefficient"),
        ({"effective_modulus": -1.0}, "effective_modulus"),
    ],
)
def test_bad_inputs_are_refused(changes, parameter):
    with pytest.raises(InputError) as err:
        ehl.hamrock_dowson_film(**{**BASE, **changes})
    assert err.value.parameter == parameter


def test_bad_options_are_refused():
    with pytest.raises(InputError, match="kind"):
        ehl.hamrock_dowson_film(**BASE, kind="average")
    with pytest.raises(InputError, match="ellipticity_method"):
        ehl.hamrock_dowson_film(**BASE, ellipticity_method="guess")
    with pytest.raises(InputError, match="race"):
        ehl.film_thickness(B6205, ISO_VG68, 100.0, 100.0, "middle")
    with pytest.raises(InputError, match="ellipticity"):
        ehl.hamrock_dowson_minimum(1e-11, 5000.0, 1e-5, 0.0)
    with pytest.raises(InputError, match="ball_diameter"):
        ehl.rolling_entrainment_speed(0.01, 0.02, 100.0)


# ---------------------------------------------------------------- entrainment speed


def test_entrainment_speed_formula_and_symmetry():
    dm, dw, w = 39e-3, 8e-3, 2400 * math.pi / 30
    gamma = dw / dm
    expected = dm / 4 * (1 - gamma**2) * w
    assert float(ehl.rolling_entrainment_speed(dm, dw, w)) == pytest.approx(expected)
    # Only the relative speed of the rings matters.
    assert float(ehl.rolling_entrainment_speed(dm, dw, 0.0, w)) == pytest.approx(expected)
    assert float(ehl.rolling_entrainment_speed(dm, dw, 3 * w, 2 * w)) == pytest.approx(expected)


def test_entrainment_speed_equals_race_speed_relative_to_cage():
    # Cross-check with the kinematics module: inner race surface speed relative to the cage
    # (omega - omega_cage) d_m (1 - gamma)/2 and outer (omega_cage) d_m (1 + gamma)/2.
    alpha, w = math.radians(15.0), 300.0
    o = frequency_orders(9, 7.94e-3, 39.04e-3, alpha)
    gamma = 7.94e-3 * math.cos(alpha) / 39.04e-3
    inner = (1 - o["ftf"]) * w * 39.04e-3 * (1 - gamma) / 2
    outer = o["ftf"] * w * 39.04e-3 * (1 + gamma) / 2
    u = float(ehl.entrainment_speed(B6205, w, alpha))
    assert u == pytest.approx(inner, rel=1e-12)
    assert u == pytest.approx(outer, rel=1e-12)


# ---------------------------------------------------------------- film_thickness


def test_film_thickness_composes_the_pieces():
    w, q, t = 3000 * math.pi / 30, 400.0, ZERO_CELSIUS + 60.0
    for race in ("inner", "outer"):
        rx, ry = B6205.contact_radii(race)
        expected = ehl.hamrock_dowson_film(
            q,
            ehl.entrainment_speed(B6205, w),
            rx,
            ry,
            effective_modulus(BEARING_STEEL, BEARING_STEEL),
            ISO_VG68.viscosity(t),
            ISO_VG68.pressure_viscosity_coefficient,
            "minimum",
        )
        got = ehl.film_thickness(B6205, ISO_VG68, q, w, race, temperature=t, kind="minimum")
        assert float(got) == pytest.approx(float(expected), rel=1e-14)


def test_film_thickness_trends():
    w = 3000 * math.pi / 30
    inner = ehl.film_thickness(B6205, ISO_VG68, 400.0, w, "inner")
    outer = ehl.film_thickness(B6205, ISO_VG68, 400.0, w, "outer")
    hot = ehl.film_thickness(B6205, ISO_VG68, 400.0, w, "inner", temperature=ZERO_CELSIUS + 80)
    minimum = ehl.film_thickness(B6205, ISO_VG68, 400.0, w, "inner", kind="minimum")
    assert outer > inner  # larger R_x (conformity of the outer race)
    assert hot < inner  # thinner oil at 80 degC than at 40 degC
    assert minimum < inner
    # A ceramic ball (stiffer) gives a slightly thinner film: E'^-0.073 for the central one.
    hybrid = dataclasses.replace(B6205, ball_material=SILICON_NITRIDE)
    assert ehl.film_thickness(hybrid, ISO_VG68, 400.0, w, "inner") < inner


def test_film_thickness_is_vectorised_over_load_and_speed():
    loads = np.array([100.0, 300.0, 900.0])
    h = ehl.film_thickness(B6205, SEED004_GREASE, loads, 250.0, "inner")
    assert h.shape == (3,) and np.all(np.diff(h) < 0)
    h2 = ehl.film_thickness(B6205, SEED004_GREASE, 300.0, np.array([100.0, 200.0]), "outer")
    assert float(h2[1] / h2[0]) == pytest.approx(2**0.67, rel=1e-12)


# ---------------------------------------------------------------- seed 004, eq. (6)
#: Seed 004's contact: BASE's with its lubricant, in SI units.
SEED004_CONTACT = {**BASE, "viscosity": 0.04, "pressure_viscosity_coefficient": 1.48e-8}


def test_seed004_film_as_printed_and_corrected():
    printed = float(ehl.seed004_film_thickness(**SEED004_CONTACT))
    fixed = float(ehl.seed004_film_thickness(**SEED004_CONTACT, radius_exponent=0.466))
    hd = float(ehl.hamrock_dowson_film(**SEED004_CONTACT, kind="minimum"))
    # With p = 0.466 the seed's formula is Hamrock-Dowson's minimum with 3.06 for 3.63 and
    # both ellipticity factors ~1 here (R_y/R_x = 33): 3.06/3.63 = 0.843.
    assert fixed / hd == pytest.approx(3.06 / 3.63, rel=3e-3)
    # As printed (p = 0.956) in SI it is R_x^0.49 = 0.059 times that.
    assert printed / fixed == pytest.approx(3.18e-3**0.49, rel=1e-12)


def test_seed004_printed_exponent_is_not_dimensionally_consistent():
    si = SEED004_CONTACT
    mm = in_mm(si)
    fixed = [float(ehl.seed004_film_thickness(**a, radius_exponent=0.466)) for a in (si, mm)]
    assert fixed[1] == pytest.approx(fixed[0] * 1e3, rel=1e-12)
    printed = [float(ehl.seed004_film_thickness(**a)) for a in (si, mm)]
    assert printed[1] / (printed[0] * 1e3) == pytest.approx(1e3**0.49, rel=1e-12)


# ---------------------------------------------------------------- Lubricant


def test_lubricant_viscosity_temperature_law():
    oil = Lubricant("oil", 0.05, 313.15, 2e-8, 870.0, temperature_coefficient=0.03)
    assert oil.viscosity() == 0.05
    assert float(oil.viscosity(333.15)) == pytest.approx(0.05 * math.exp(-0.6))
    t = np.array([293.15, 313.15, 353.15])
    assert np.allclose(oil.viscosity(t), 0.05 * np.exp(-0.03 * (t - 313.15)))
    assert float(oil.kinematic_viscosity(313.15)) == pytest.approx(0.05 / 870.0)
    assert float(reynolds_viscosity(0.05, 0.0, 400.0, 313.15)) == 0.05


def test_lubricant_without_temperature_coefficient():
    oil = Lubricant("oil", 0.05, 313.15, 2e-8, 870.0)
    assert float(oil.viscosity(313.15)) == 0.05
    with pytest.raises(InputError, match="temperature_coefficient"):
        oil.viscosity(323.15)


@pytest.mark.parametrize(
    "changes, parameter",
    [
        ({"name": ""}, "name"),
        ({"dynamic_viscosity": 0.0}, "dynamic_viscosity"),
        ({"dynamic_viscosity": math.inf}, "dynamic_viscosity"),
        ({"reference_temperature": 40.0}, "reference_temperature"),
        ({"pressure_viscosity_coefficient": 0.0}, "pressure_viscosity_coefficient"),
        ({"pressure_viscosity_coefficient": 22.0}, "pressure_viscosity_coefficient"),
        ({"density": -850.0}, "density"),
        ({"temperature_coefficient": -0.01}, "temperature_coefficient"),
        ({"limiting_shear_coefficient": 1.5}, "limiting_shear_coefficient"),
        ({"roelands_index": 0.0}, "roelands_index"),
    ],
)
def test_lubricant_validation(changes, parameter):
    args = {
        "name": "oil",
        "dynamic_viscosity": 0.05,
        "reference_temperature": 313.15,
        "pressure_viscosity_coefficient": 2e-8,
        "density": 870.0,
    }
    with pytest.raises(InputError) as err:
        Lubricant(**{**args, **changes})
    assert err.value.parameter == parameter


def test_celsius_given_for_kelvin_is_caught():
    with pytest.raises(InputError, match="kelvin"):
        ISO_VG68.viscosity(40.0)


def test_lubricant_is_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        ISO_VG68.density = 900.0


def test_roelands_relation():
    # alpha = Z (ln eta_0 + 9.67) / 1.96e8 and its inverse.
    alpha = roelands_pressure_viscosity_coefficient(0.04, 0.45)
    assert float(alpha) == pytest.approx(0.45 * (math.log(0.04) + 9.67) / 1.96e8, rel=1e-15)
    assert float(roelands_index(0.04, alpha)) == pytest.approx(0.45, rel=1e-14)
    with pytest.raises(InputError, match="viscosity"):
        roelands_pressure_viscosity_coefficient(1e-5, 0.6)  # below eta_inf = 6.31e-5 Pa s


def test_seed004_grease():
    g = SEED004_GREASE
    assert (g.dynamic_viscosity, g.density, g.roelands_index) == (0.04, 850.0, 0.45)
    assert (g.temperature_coefficient, g.limiting_shear_coefficient) == (0.027, 0.0434)
    assert g.reference_temperature == pytest.approx(293.15)
    assert g.pressure_viscosity_coefficient == pytest.approx(1.4811e-8, rel=1e-4)


def test_iso_vg68():
    oil = LUBRICANTS["iso-vg68"]
    assert oil is ISO_VG68
    assert oil.reference_temperature == pytest.approx(313.15)
    assert float(oil.kinematic_viscosity(313.15)) == pytest.approx(68e-6, rel=1e-12)
    # beta was fitted to nu_100 = 8.5 mm^2/s with the density held constant.
    assert float(oil.kinematic_viscosity(373.15)) == pytest.approx(8.5e-6, rel=1e-12)
    assert oil.pressure_viscosity_coefficient == 2.5e-8
    d = oil.to_dict()
    assert d["reference_temperature_c"] == pytest.approx(40.0)
    assert d["pressure_viscosity_coefficient_per_gpa"] == pytest.approx(25.0)
    assert set(LUBRICANTS) == {"seed004-grease", "iso-vg68"}
