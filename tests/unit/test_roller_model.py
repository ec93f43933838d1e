"""The roller-bearing model (issue 28): geometry, line contact, catalogue, ratings, life,
kinematics names, friction forms, plausibility. The load distribution is in
test_roller_quasistatic.py; published numbers in tests/literature/test_roller_*.py."""

import dataclasses
import math

import numpy as np
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.contact import line
from bearinglab.errors import CatalogError, InputError
from bearinglab.geometry import BallBearing
from bearinglab.kinematics import defect_frequencies
from bearinglab.operating import OperatingCondition
from bearinglab.ratings import equivalent_dynamic_load, equivalent_static_load, load_ratings
from bearinglab.roller_geometry import RollerBearing, RollerProfile, on_apex_angles


def cylindrical(**kw):
    base = dict(roller_count=14, roller_diameter=10e-3, roller_length=9.6e-3, pitch_diameter=65e-3)
    base.update(kw)
    return RollerBearing(**base)


def tapered(**kw):
    base = dict(
        roller_count=16,
        roller_diameter=6.5e-3,
        roller_length=11e-3,
        pitch_diameter=39e-3,
        contact_angle=math.radians(13.86),
        bearing_type="tapered_roller",
    )
    base.update(kw)
    return RollerBearing(**base)


# ------------------------------------------------------------------ the kinds
def test_the_kinds_are_told_apart_by_rolling_element():
    ball = BallBearing(ball_count=9, ball_diameter=8e-3, pitch_diameter=39e-3)
    roller = cylindrical()
    assert (ball.rolling_element, roller.rolling_element) == ("ball", "roller")
    assert (ball.element_count, ball.element_diameter) == (9, 8e-3)
    assert (roller.element_count, roller.element_diameter) == (14, 10e-3)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"roller_count": 2}, "roller_count"),
        ({"roller_count": 30}, "roller_count"),  # 30 rollers of 10 mm do not fit on 65 mm
        ({"roller_length": -1e-3}, "roller_length"),
        ({"contact_angle": 0.1}, "contact_angle"),  # a cylindrical bearing has none
        ({"rows": 3}, "rows"),
        ({"rows": 2}, "arrangement"),  # two rows need an arrangement
        ({"arrangement": "back_to_back", "rows": 2}, "arrangement"),  # not for cylinders
        ({"diametral_clearance": 2e-3}, "diametral_clearance"),
        ({"bore": 0.07, "outside_diameter": 0.09}, "roller_diameter"),
        ({"profile": "flat"}, "roller_profile"),
        ({"cone_angle": 0.1}, "cone_angle"),
    ],
)
def test_bad_geometry_is_an_input_error_naming_the_field(kwargs, name):
    with pytest.raises(InputError) as err:
        cylindrical(**kwargs)
    assert err.value.parameter == name


def test_tapered_angles_follow_the_on_apex_design():
    b = tapered()
    alpha_i, alpha_m, phi = on_apex_angles(b.contact_angle, b.roller_diameter, b.pitch_diameter)
    # cup = axis + phi, cone = axis - phi, tan(phi) = (D/d_m) sin(axis): the three cones meet
    assert alpha_m + phi == pytest.approx(b.contact_angle, abs=1e-14)
    assert math.tan(phi) == pytest.approx(b.roller_diameter / b.pitch_diameter * math.sin(alpha_m))
    assert b.inner_angle == pytest.approx(alpha_i) and b.roller_half_angle == pytest.approx(phi)
    assert tapered(cone_angle=0.15).inner_angle == 0.15
    with pytest.raises(InputError, match="tapered"):
        tapered(contact_angle=0.0)


def test_row_layout_puts_the_pressure_centres_outside_for_back_to_back():
    b = tapered(rows=2, arrangement="back_to_back", width=16.25e-3)
    offsets, signs = b.row_layout()
    assert offsets.tolist() == pytest.approx([-8.125e-3, 8.125e-3])
    assert signs.tolist() == [1.0, -1.0]
    assert tapered(rows=2, arrangement="face_to_face").row_layout()[1].tolist() == [-1.0, 1.0]


def test_to_dict_names_the_roller():
    d = cylindrical(profile=RollerProfile("crowned", crown_radius=0.5)).to_dict()
    assert d["rolling_element"] == "roller" and d["roller_count"] == 14
    assert d["roller_diameter_mm"] == pytest.approx(10) and d["roller_length_mm"] == 9.6
    assert d["roller_profile"] == {"kind": "crowned", "crown_radius_mm": 500.0, "flat_length_mm": 0}


# ------------------------------------------------------------------ profiles and line contact
def test_profiles():
    x = np.array([0.0, 2e-3, 4.5e-3])
    flat = RollerProfile("flat").drop(x, 10e-3, 9.6e-3)
    assert flat.tolist() == [0, 0, 0]
    log = RollerProfile().drop(x, 10e-3, 9.6e-3)
    assert log[0] == 0 and 0 < log[1] < log[2]  # grows towards the ends
    # the long-roller form is flat over L_we - 2.5 D_we
    long = line.logarithmic_profile(np.array([0.0, 2e-3, 11e-3]), 10e-3, 30e-3)
    assert long[0] == long[1] == 0 and long[2] > 0
    user = RollerProfile("user", positions=(0, 5e-3), drops=(0, 10e-6)).drop(2.5e-3, 1, 1)
    assert user == pytest.approx(5e-6)
    with pytest.raises(InputError, match="roller_profile"):
        RollerProfile("user", positions=(0, 1), drops=(1,))


def test_palmgren_and_iso_approaches_agree_within_four_percent():
    """Two of Palmgren's contacts in series against ISO/TS 16281's c_l: 7.68e-5 against
    7.94e-5 Q^0.9 / l^0.8 mm."""
    for q, length in ((100.0, 5e-3), (5e3, 20e-3)):
        two = 2 * line.palmgren_approach(q, length)
        iso = line.iso16281_approach(q, length)
        assert iso / two == pytest.approx(1.034, abs=0.002)


def test_line_contact_half_width_and_pressure_balance_the_load():
    c = line.line_contact(1e6, 5e-3, 228.6e9)
    # the load per length is the pressure's integral over the width: pi b p0 / 2
    assert math.pi * c.half_width * c.max_pressure / 2 == pytest.approx(1e6)
    assert c.mean_pressure == pytest.approx(math.pi / 4 * c.max_pressure)
    with pytest.raises(InputError):
        line.line_contact(-1.0, 5e-3, 228.6e9)


def test_edge_stress_factors_of_iso16281():
    f = line.edge_stress_factors(30)
    assert f[0] == f[-1] == pytest.approx(2.3284, abs=1e-4)
    assert np.all(np.diff(f[:15]) < 0) and f[14] == pytest.approx(1.003, abs=1e-3)
    assert line.edge_stress_factors(31)[15] == 1.0  # a middle slice


# ------------------------------------------------------------------ catalogue
@pytest.mark.parametrize(
    "text, system, kind, design",
    [
        ("NU205", None, "cylindrical_roller", "NU"),
        ("N205", None, "cylindrical_roller", "N"),
        ("NJ205", None, "cylindrical_roller", "NJ"),
        ("NUP205", None, "cylindrical_roller", "NUP"),
        ("2205", "gost", "cylindrical_roller", "N"),
        ("42205", "gost", "cylindrical_roller", "NJ"),
        ("32205", "gost", "cylindrical_roller", "NU"),
        ("30205", None, "tapered_roller", ""),
        ("7205", "gost", "tapered_roller", ""),
        ("7505", "gost", "tapered_roller", ""),
    ],
)
def test_roller_designations_give_a_roller_bearing(text, system, kind, design):
    b, des = bearing_from_designation(text, system, rollers=True)
    assert isinstance(b, RollerBearing) and b.bearing_type == kind and b.design == design
    assert b.sources["roller_count"].kind == "estimated"
    assert b.sources["bore"].kind == "catalog"


def test_gost_and_iso_read_the_same_bearing():
    iso, _ = bearing_from_designation("30205", rollers=True)
    gost, _ = bearing_from_designation("7205", "gost", rollers=True)
    assert (iso.roller_count, iso.roller_diameter, iso.contact_angle) == (
        gost.roller_count,
        gost.roller_diameter,
        gost.contact_angle,
    )


def test_without_rollers_the_catalogue_refuses_as_before():
    with pytest.raises(CatalogError, match="internal-geometry model"):
        bearing_from_designation("NU205")


def test_roller_overrides_and_their_sources():
    b, _ = bearing_from_designation(
        "NU205", rollers=True, overrides={"roller_count": 13, "diametral_clearance": 20e-6}
    )
    assert b.roller_count == 13 and b.sources["roller_count"].kind == "user"
    assert b.sources["roller_diameter"].kind == "estimated"
    assert b.geometry_source == "mixed"
    with pytest.raises(InputError) as err:
        bearing_from_designation("NU205", rollers=True, overrides={"ball_count": 9})
    assert err.value.parameter == "ball_count"
    with pytest.raises(InputError) as err:
        bearing_from_designation("6205", rollers=True, overrides={"roller_count": 9})
    assert err.value.parameter == "roller_count"


def test_unchecked_series_are_refused_not_estimated():
    with pytest.raises(CatalogError, match="diameter series 2 and 3"):
        bearing_from_designation("NU1005", rollers=True)
    with pytest.raises(CatalogError, match="pitch_diameter"):
        bearing_from_designation("NN3005", rollers=True)  # no ISO 15 row for it


# ------------------------------------------------------------------ ratings and life
def test_ratings_scale_with_rows_as_iso_281_says():
    one = load_ratings(tapered())
    two = load_ratings(tapered(rows=2, arrangement="back_to_back"))
    assert two.dynamic == pytest.approx(2 ** (7 / 9) * one.dynamic)
    assert two.static == pytest.approx(2 * one.static)
    assert one.to_dict()["rating_factor_bm"] == 1.1


def test_tapered_equivalent_loads_use_e_and_y_of_the_contact_angle():
    b = tapered()
    e = 1.5 * math.tan(b.contact_angle)
    y = 0.4 / math.tan(b.contact_angle)
    below = equivalent_dynamic_load(b, 1000.0, 0.9 * e * 1000.0)
    assert below[0] == 1000.0
    above = equivalent_dynamic_load(b, 1000.0, 2 * e * 1000.0)
    assert above[0] == pytest.approx(0.4 * 1000.0 + y * 2 * e * 1000.0)
    assert above[1].e == pytest.approx(e)
    pair = tapered(rows=2, arrangement="face_to_face")
    assert equivalent_dynamic_load(pair, 1000.0, 100.0)[0] == pytest.approx(
        1000 + 0.45 / math.tan(b.contact_angle) * 100
    )
    assert equivalent_static_load(b, 1000.0, 500.0) == pytest.approx(
        max(1000, 500 + 0.22 / math.tan(b.contact_angle) * 500)
    )
    assert equivalent_static_load(cylindrical(), 1000.0, 0.0) == 1000.0


def test_roller_life_uses_ten_thirds_and_the_roller_a_iso():
    from bearinglab.life import life_modification_factor, rating_life

    b = cylindrical()
    c = load_ratings(b).dynamic
    r = rating_life(b, OperatingCondition(radial_load=0.1 * c, shaft_speed=100.0))
    assert r.l10 == pytest.approx(10 ** (10 / 3))
    assert r.to_dict()["life_exponent"] == pytest.approx(10 / 3)
    # the roller bands of a_ISO meet at kappa = 0.4 and 1
    for kappa in (0.4, 1.0):
        low = life_modification_factor(kappa * (1 - 1e-9), 0.2, roller=True)
        high = life_modification_factor(kappa, 0.2, roller=True)
        assert low == pytest.approx(high, rel=1e-4)
    assert life_modification_factor(1.0, 0.2, roller=True) != life_modification_factor(1.0, 0.2)
    with pytest.raises(InputError) as err:
        rating_life(
            BallBearing(ball_count=9, ball_diameter=8e-3, pitch_diameter=39e-3),
            OperatingCondition(radial_load=100.0, shaft_speed=100.0),
            slices=10,
        )
    assert err.value.parameter == "slices"


# ------------------------------------------------------------------ kinematics
def test_frequency_names_read_roller_for_rollers():
    f = defect_frequencies(cylindrical(), speed_rpm=600)
    d = f.to_dict()
    assert {"roller_count", "roller_diameter_mm", "roller_defect_hz", "bsf_hz", "bpfo_hz"} <= set(d)
    assert "ball_defect_hz" not in d and "ball_count" not in d
    assert d["roller_defect_hz"] == pytest.approx(2 * d["bsf_hz"]) == f.hz("roller_defect")
    assert d["bpfo_order"] + d["bpfi_order"] == pytest.approx(14)
    assert list(f.to_pandas()["frequency"]) == ["ftf", "bpfo", "bpfi", "bsf", "roller_defect"]


# ------------------------------------------------------------------ friction
def test_skf_roller_forms():
    from bearinglab.friction.skf import skf_frictional_moment
    from bearinglab.friction.skf_constants import SkfGeometryConstants

    const = SkfGeometryConstants(1.09e-6, 0.0, 0.16, 0.0015)
    m = skf_frictional_moment("cylindrical_roller", 0.025, 0.052, 2000.0, 0.0, 300.0, 30e-6, const)
    g_rr = 1.09e-6 * 38.5**2.41 * 2000**0.31
    assert m.rolling_variable == pytest.approx(g_rr)
    assert m.sliding_variable == pytest.approx(0.0015 * 38.5 * 2000)
    tap = SkfGeometryConstants(1.76e-6, 10.9, 0.017, 2.0)
    with pytest.raises(InputError) as err:
        skf_frictional_moment("tapered_roller", 0.025, 0.052, 2000.0, 500.0, 300.0, 30e-6, tap)
    assert err.value.parameter == "axial_factor"
    m = skf_frictional_moment(
        "tapered_roller", 0.025, 0.052, 2000.0, 500.0, 300.0, 30e-6, tap, axial_factor=1.6
    )
    assert m.sliding_variable == pytest.approx(0.017 * 38.5**0.82 * (2000 + 2 * 1.6 * 500))


def test_bearing_friction_takes_a_roller_bearing():
    from bearinglab.friction import SkfGeometryConstants, bearing_friction

    b, des = bearing_from_designation("30205", rollers=True)
    const = bearing_friction(b, 300.0, 2000.0, designation=des)
    assert const.to_dict()["friction_coefficient"] == 0.002  # seed 003: tapered
    skf = bearing_friction(
        b,
        300.0,
        2000.0,
        500.0,
        model="skf",
        viscosity=30e-6,
        constants=SkfGeometryConstants(1.76e-6, 10.9, 0.017, 2.0),
    )
    assert skf.torque > 0
    assert any("Y = 1.62" in w for w in skf.warnings)
    with pytest.raises(InputError, match="not shipped"):
        bearing_friction(b, 300.0, 2000.0, model="skf", viscosity=30e-6)


# ------------------------------------------------------------------ plausibility
def test_pressure_past_4000_mpa_is_a_warning_in_the_users_terms():
    from bearinglab.plausibility import pressure_warnings
    from bearinglab.quasistatic import solve_load_distribution

    b = cylindrical(profile=RollerProfile("flat"))
    light = solve_load_distribution(b, OperatingCondition(radial_load=2000.0))
    assert light.max_pressure < 4.0e9 and pressure_warnings(b, light) == []
    # 20 kN is 0.4 C0 (no load warning), but 15 mrad against a flat profile loads the ends
    tilted = solve_load_distribution(
        b, OperatingCondition(radial_load=20e3, misalignment=(15e-3, 0.0))
    )
    words = pressure_warnings(b, tilted)
    assert tilted.max_pressure > 4.0e9
    assert len(words) == 1 and "4000 MPa" in words[0] and "tilt" in words[0]
    ball = BallBearing(ball_count=9, ball_diameter=8e-3, pitch_diameter=39e-3)
    assert pressure_warnings(ball, tilted) == []


def test_speed_warnings_speak_of_rollers():
    from bearinglab.plausibility import speed_warnings

    words = speed_warnings(cylindrical(), 30000 * math.pi / 30, radial_load=10.0)
    assert any("roller's centrifugal force" in w for w in words)


def test_replace_keeps_validation():
    with pytest.raises(InputError):
        dataclasses.replace(cylindrical(), roller_count=1)
