"""Catalogue data against the documents it was taken from.

1. Boundary dimensions of >= 15 bearings across families against a named maker catalogue
   (the ISO 15 / 355 / 104 dimension plans as printed).  "KOYO" is the KOYO general
   catalogue CAT. NO. B2001RUS (2008); page numbers are the catalogue's own.
2. The published internal geometries against the numbers their sources print, including
   the frequencies those sources compute from them.
3. The estimate of :mod:`bearinglab.catalog.estimate` against the published bearings.
"""

import math

import pytest

from bearinglab.catalog import (
    bearing_from_designation,
    boundary_dimensions,
    estimate_internal_geometry,
    published_geometry,
)
from bearinglab.kinematics import frequency_orders

IN = 25.4e-3  # m per inch
MM = 1e-3

# ------------------------------------------------------- 1. boundary dimensions

RADIAL = [
    # designation, d, D, B [mm], where printed
    ("6205", 25, 52, 15),  # KOYO p. 9; SKF 6205: 25 x 52 x 15
    ("6310", 50, 110, 27),  # KOYO p. 11
    ("6006", 30, 55, 13),  # KOYO p. 9
    ("16006", 30, 55, 9),  # KOYO p. 9
    ("61904", 20, 37, 9),  # KOYO p. 8 (as 6904)
    ("6203", 17, 40, 12),  # KOYO p. 8
    ("6403", 17, 62, 17),  # KOYO p. 8
    ("608", 8, 22, 7),  # KOYO p. 42; DIN 625-1 table in the BOLTS library
    ("623", 3, 10, 4),  # KOYO p. 38
    ("625", 5, 16, 5),  # KOYO p. 40; DIN 625-1 (BOLTS)
    ("626", 6, 19, 6),  # KOYO p. 40; DIN 625-1 (BOLTS)
    ("627", 7, 22, 7),  # KOYO p. 40; DIN 625-1 (BOLTS)
    ("629", 9, 26, 8),  # KOYO p. 42; DIN 625-1 (BOLTS)
    ("2205", 25, 52, 18),  # KOYO self-aligning ball bearings p. 134
    ("1310", 50, 110, 27),  # KOYO p. 134
    ("2320", 100, 215, 73),  # KOYO p. 137
    ("7208", 40, 80, 18),  # dimension series 02, as 6208 (KOYO p. 10)
    ("NU2210", 50, 90, 23),  # KOYO cylindrical roller bearings p. 156
    ("NU2320", 100, 215, 73),  # KOYO p. 166
    ("NU420", 100, 250, 58),  # KOYO p. 166 (dimension series 04 at d = 100 mm)
    ("22310", 50, 110, 40),  # KOYO spherical roller bearings p. 296 (22310RHR)
    ("23020", 100, 150, 37),  # KOYO p. 298 (23020RH)
    ("23220", 100, 180, 60.3),  # KOYO p. 298 (23220RH)
]


@pytest.mark.parametrize("text,d,big_d,b", RADIAL, ids=[r[0] for r in RADIAL])
def test_radial_boundary_dimensions(text, d, big_d, b):
    dims = boundary_dimensions(text)
    assert (dims.bore, dims.outside_diameter, dims.width) == pytest.approx(
        (d * MM, big_d * MM, b * MM), abs=1e-9
    )
    assert dims.standard.startswith("ISO 15:2017")


def test_chamfers_as_printed():
    # KOYO p. 9-11: r_s min of 6205 = 1, 6310 = 2, 6000 = 0.3 mm
    for text, r in (("6205", 1.0), ("6310", 2.0), ("6000", 0.3)):
        assert boundary_dimensions(text).chamfer_min == pytest.approx(r * MM)


TAPERED = [
    # designation, d, D, T, B, C [mm], where printed
    ("30205", 25, 52, 16.25, 15, 13),  # KOYO p. 198 (30205JR); MBP-bearings table
    ("30304", 20, 52, 16.25, 15, 13),  # Timken metric TS table (B 15, C 13); NACHI table
    ("32210", 50, 90, 24.75, 23, 19),  # KOYO p. 204 (32210JR)
    ("32320", 100, 215, 77.5, 73, 60),  # KOYO p. 216 (32320JR)
    ("32008", 40, 68, 19, 19, 14.5),  # KOYO p. 202 (32008JR)
]


@pytest.mark.parametrize("text,d,big_d,t,b,c", TAPERED, ids=[r[0] for r in TAPERED])
def test_tapered_boundary_dimensions(text, d, big_d, t, b, c):
    dims = boundary_dimensions(text)
    assert (
        dims.bore,
        dims.outside_diameter,
        dims.width,
        dims.cone_width,
        dims.cup_width,
    ) == pytest.approx((d * MM, big_d * MM, t * MM, b * MM, c * MM), abs=1e-9)
    assert dims.standard.startswith("ISO 355")


THRUST = [
    # designation, d, D, T [mm]: Schaeffler thrust ball bearing tables (BOLTS bearings.blt)
    ("51205", 25, 47, 15),
    ("51110", 50, 70, 14),
    ("51305", 25, 52, 18),
    ("51420", 100, 210, 85),
]


@pytest.mark.parametrize("text,d,big_d,t", THRUST, ids=[r[0] for r in THRUST])
def test_thrust_boundary_dimensions(text, d, big_d, t):
    dims = boundary_dimensions(text)
    assert (dims.bore, dims.outside_diameter, dims.height) == pytest.approx(
        (d * MM, big_d * MM, t * MM), abs=1e-9
    )


def test_gost_designations_find_the_same_sizes():
    # GOST 3189-89 180205 (two seals) and 310 are ISO 6205-2RS and 6310
    assert boundary_dimensions("180205") == boundary_dimensions("6205")
    assert boundary_dimensions("310", system="gost") == boundary_dimensions("6310")


# ------------------------------------------------- 2. published internal geometry


# CWRU Bearing Data Center, JEM SKF bearings, inches: (d, D, B, ball, pitch); the defect
# frequencies in orders of shaft speed (BPFI, BPFO, cage, rolling element), each with the
# agreement we ask of it. The page's numbers carry 4-5 digits: 1e-4 unless noted.
CWRU = [
    (
        "6205 (CWRU drive end)",
        (0.9843, 2.0472, 0.5906, 0.3126, 1.537),
        {
            "bpfi": (5.4152, 1e-4),
            "bpfo": (3.5848, 1e-4),
            "ftf": (0.39828, 1e-4),
            "ball_defect": (4.7135, 1e-4),
        },
    ),
    # 6203-2RS: rolling element 3.98767 from the inch values against 3.9874 printed: the
    # page's calculator used slightly different dimensions; 3e-4 is the disagreement
    (
        "6203 (CWRU fan end)",
        (0.6693, 1.5748, 0.4724, 0.2656, 1.122),
        {
            "bpfi": (4.9469, 1e-4),
            "bpfo": (3.0530, 2e-4),
            "ftf": (0.3817, 1e-4),
            "ball_defect": (3.9874, 3e-4),
        },
    ),
]


@pytest.mark.parametrize("name,inches,orders", CWRU, ids=[row[0] for row in CWRU])
def test_cwru_bearings_as_printed(name, inches, orders):
    g = published_geometry(name)
    assert (
        g.bore,
        g.outside_diameter,
        g.width,
        g.ball_diameter,
        g.pitch_diameter,
    ) == pytest.approx(tuple(v * IN for v in inches), rel=1e-6)
    o = frequency_orders(g.ball_count, g.ball_diameter, g.pitch_diameter, g.contact_angle)
    for key, (printed, tolerance) in orders.items():
        assert float(o[key]) == pytest.approx(printed, abs=tolerance), key


def test_er16k_from_seed_003():
    # Seed 003 Table 1: inner race 30.59, outer race 46.47, pitch 38.51, ball 7.94 mm, Z = 9,
    # radial clearance 0.045 mm; 1750 rpm gives a ball-defect line of 135.5 Hz and an outer
    # race line of 104.19 Hz.
    g = published_geometry("ER-16K")
    assert (g.ball_count, g.ball_diameter, g.pitch_diameter) == pytest.approx(
        (9, 7.94 * MM, 38.51 * MM)
    )
    # recorded as P_d = 2 c_r: the paper's 0.045 mm is one-sided (see the row's notes)
    assert g.diametral_clearance / 2 == pytest.approx(0.045 * MM)
    # the printed race diameters are nominal: they differ by exactly 2 D_w
    assert (46.47 - 30.59) / 2 == pytest.approx(7.94)
    shaft = 1750 / 60
    o = frequency_orders(g.ball_count, g.ball_diameter, g.pitch_diameter)
    # 135.45 Hz from the table values; printed to one decimal as 135.5 (rounded half up)
    assert float(o["ball_defect"]) * shaft == pytest.approx(135.5, abs=0.06)
    assert float(o["bpfo"]) * shaft == pytest.approx(104.19, abs=0.005)


def test_skf_6205_of_seed_004():
    # Seed 004 Table 1: d 25, D 52, d_m 39, d_b 8 mm, 9 balls, contact angle 0; at 2400 rpm
    # the kinematic ball defect frequency of eq. (25) is 93.40 Hz.
    g = published_geometry("6205 (seed 004)")
    assert (
        g.bore,
        g.outside_diameter,
        g.pitch_diameter,
        g.ball_diameter,
        g.ball_count,
    ) == pytest.approx((25 * MM, 52 * MM, 39 * MM, 8 * MM, 9))
    assert g.contact_angle == 0.0 and g.diametral_clearance is None and not g.default
    bsf = float(frequency_orders(g.ball_count, g.ball_diameter, g.pitch_diameter)["bsf"])
    assert bsf * 2400 / 60 == pytest.approx(93.40, abs=0.005)
    # the printed raceway diameters 30.6 / 46.3 mm imply an interference of 0.3 mm with an
    # 8 mm ball, which is why the row leaves the clearance empty
    assert 46.3 - 30.6 - 2 * 8 == pytest.approx(-0.3)


def test_harris_209():
    # Harris & Kotzalas: 209 deep-groove ball bearing, D = 12.7 mm, d_m = 65 mm, Z = 9,
    # f_i = f_o = 0.52, P_d = 0.015 mm.
    b, _ = bearing_from_designation("209 (Harris)")
    assert (
        b.ball_count,
        b.ball_diameter,
        b.pitch_diameter,
        b.inner_groove_factor,
        b.outer_groove_factor,
        b.diametral_clearance,
    ) == pytest.approx((9, 12.7 * MM, 65 * MM, 0.52, 0.52, 0.015 * MM))
    assert (
        b.outer_raceway_diameter - b.inner_raceway_diameter - 2 * b.ball_diameter
        == pytest.approx(0.015 * MM)
    )
    assert (b.bore, b.outside_diameter, b.width) == pytest.approx((45 * MM, 85 * MM, 19 * MM))


def test_seed_000_ball_counts():
    # Balmont & Varlamov, sec. 2: bearing type 106 has n = 14 balls, type 310 n = 8
    assert published_geometry("106 (seed 000)").ball_count == 14
    assert published_geometry("310 (seed 000)").ball_count == 8
    assert published_geometry("310").name == "310 (seed 000)"
    assert published_geometry("106") is None  # name only: see the row's notes


def test_test_rig_bearings():
    # NPTEL 112103024 Example 15.2: ER-10K, 8 balls, 0.3125 in ball, 1.319 in pitch;
    # XJTU-SY LDK UER204: 8 balls of 7.92 mm on 34.55 mm.
    er10 = published_geometry("ER-10K")
    assert (er10.ball_count, er10.ball_diameter, er10.pitch_diameter) == pytest.approx(
        (8, 0.3125 * IN, 1.319 * IN)
    )
    uer = published_geometry("uer204 (xjtu-sy)")
    assert (uer.ball_count, uer.ball_diameter, uer.pitch_diameter) == pytest.approx(
        (8, 7.92 * MM, 34.55 * MM)
    )


# ---------------------------------------------- 3. the estimate against them

ESTIMATE_CASES = [
    # name, d, D [mm], dimension series, published (Z, D_w, d_m) [mm]
    ("6205 (CWRU drive end)", 25, 52, "02", (9, 0.3126 * 25.4, 1.537 * 25.4)),
    ("6205 (seed 004)", 25, 52, "02", (9, 8.0, 39.0)),
    ("6203 (CWRU fan end)", 17, 40, "02", (8, 0.2656 * 25.4, 1.122 * 25.4)),
    ("209 (Harris)", 45, 85, "02", (9, 12.7, 65.0)),
    # ER-16K's boundary dimensions are not in seed 003; its races and ball are those of a
    # 205-size bearing, so it is compared with the 25 x 52 mm estimate
    ("ER-16K vs 205 size", 25, 52, "02", (9, 7.94, 38.51)),
    ("310 (seed 000)", 50, 110, "03", (8, None, None)),
    pytest.param(
        "106 (seed 000)",
        30,
        55,
        "10",
        (14, None, None),
        marks=pytest.mark.xfail(
            strict=True,
            reason="the estimate gives 11 balls for 30 x 55 mm; Balmont & Varlamov's "
            "106 has 14, presumably smaller balls than the design rules give",
        ),
    ),
]


@pytest.mark.parametrize("name,d,big_d,series,published", ESTIMATE_CASES)
def test_estimate_against_published_bearings(name, d, big_d, series, published):
    z, dw, dm = published
    g = estimate_internal_geometry(d * MM, big_d * MM, series)
    # tolerances found honest over these bearings: the ball count exact within one ball,
    # D_w within 5 % (observed at most 2.3 %), d_m within 3 % (observed at most 1.2 %)
    assert abs(g.ball_count - z) <= 1
    if dw is not None:
        assert g.ball_diameter == pytest.approx(dw * MM, rel=0.05)
        assert g.pitch_diameter == pytest.approx(dm * MM, rel=0.03)


def test_estimate_gets_the_ball_count_exactly_where_it_is_published():
    for d, big_d, series, z in (
        (25, 52, "02", 9),
        (17, 40, "02", 8),
        (45, 85, "02", 9),
        (50, 110, "03", 8),
    ):
        assert estimate_internal_geometry(d * MM, big_d * MM, series).ball_count == z


def test_estimated_defect_orders_of_the_cwru_6205():
    # What a user without the CWRU page would get: BPFO 3.58 from the estimate against the
    # printed 3.5848 (0.3 % apart), BPFI 5.41 against 5.4152.
    g = estimate_internal_geometry(25 * MM, 52 * MM, "02")
    o = frequency_orders(g.ball_count, g.ball_diameter, g.pitch_diameter)
    assert float(o["bpfo"]) == pytest.approx(3.5848, rel=0.01)
    assert float(o["bpfi"]) == pytest.approx(5.4152, rel=0.01)
    assert math.degrees(g.fill_angle) == pytest.approx(194.0)
