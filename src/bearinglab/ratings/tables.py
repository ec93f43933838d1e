"""Coefficient tables of ISO 281:2007, ISO 76:2006 and ISO/TS 16281 for ball bearings.

The standards themselves are not stored where this project can read them; every table
below was taken from stored public copies and cross-checked (docs/capabilities/life.md
lists the copies). Where a copy disagreed with the others, or with a derivation that
reproduces the table, the note says which value was kept and why.

Stored copies named below (public repositories, read with the project's search tool):

- ``bb_core``: a Rust ball-bearing solver implementing ISO 281:2007 and ISO 16281:2025
  (file ``solver/bb/life.rs``, stored id 71231574917; ``static_rating.rs``, id 70911022923;
  its level-E test, id 71232758373, which reproduces ISO 76 Table 1 from ISO/TR 10657).
- ``dgbb-design``: a Chinese deep-groove design script (``fc_list``, stored id 4148630016).
- ``sfere``: a JavaScript rating calculator (``sfereRadiali``, id 9277541628;
  ``sfereAssiali``, id 9018672827).
- ``lehmann``: S. Lehmann's DGBB calculator, X/Y/e "from table 9 of the SKF rolling
  bearing catalogue" (id 13081227344).
- ``mecapy``: ``mecapy`` ISO 281 data module (id 61555616929).
- ``ewing``: F. Ewing, ISO_281 bearing life notebook (MIT, id 12173787189).
- ``dozersim``: ``dozersim`` ball-bearing model (id 4159169026).
- ``iso16281-py``: two versions of a Python ISO/TS 16281 implementation (ids 23542449958,
  23203886147).
- MESYS AG calculation-software manual, "Contamination factor"
  (https://www.mesys.ag/manual/contamination_factor.html), quoting ISO 281:2007.
"""

from __future__ import annotations

import numpy as np

# ---------------------------------------------------------------- ISO 281 section 6.1
#: b_m for radial deep-groove and angular-contact ball bearings (not filling-slot) and
#: thrust ball bearings (ISO 281:2007 Table 1; bb_core ``B_M_BALL``, dgbb-design, sfere).
B_M_BALL = 1.3
#: Ball diameter above which C uses 3.647 D_w^1.4 instead of D_w^1.8 [mm]
#: (3.647 = 25.4^0.4, so the two forms meet; bb_core, dgbb-design).
LARGE_BALL_MM = 25.4
LARGE_BALL_COEFFICIENT = 3.647

#: gamma = D_w cos(alpha)/D_pw of ISO 281 Table 2 (0.01 ... 0.40 in steps of 0.01).
FC_GAMMA = np.round(np.arange(1, 41) / 100.0, 2)
#: f_c of ISO 281:2007 Table 2, column "single-row radial contact and single- and
#: double-row angular contact groove ball bearings" [N/mm^1.8 with D_w in mm]. The three
#: stored copies (bb_core, dgbb-design, sfere) agree on all 40 values. The column follows
#: Lundberg-Palmgren's form with f_i = f_e = 0.52 times a constant to within the
#: table's rounding (test_life: ``test_fc_table_follows_lundberg_palmgren_shape``).
FC_RADIAL = np.array(
    [
        29.1,
        35.8,
        40.3,
        43.8,
        46.7,
        49.1,
        51.1,
        52.8,
        54.3,
        55.5,
        56.6,
        57.5,
        58.2,
        58.8,
        59.3,
        59.6,
        59.8,
        59.9,
        60.0,
        59.9,
        59.8,
        59.6,
        59.3,
        59.0,
        58.6,
        58.2,
        57.7,
        57.1,
        56.6,
        56.0,
        55.3,
        54.6,
        53.9,
        53.2,
        52.4,
        51.7,
        50.9,
        50.0,
        49.2,
        48.4,
    ]
)

#: gamma = D_w/D_pw of the thrust (alpha = 90 deg) column of ISO 281 Table 4.
FC_THRUST_GAMMA = np.round(np.arange(1, 35) / 100.0, 2)
#: f_c for thrust ball bearings, alpha = 90 deg. ONE stored copy only (sfere, which also
#: lists 165.2 at 0.35 -- evidently a misprint, dropped here). Not cross-checked: the
#: values follow 146 gamma^0.3 to about 1 % (a smooth Lundberg-Palmgren shape), which
#: catches a wrong digit but not a wrong constant. Results that use it say so.
FC_THRUST_90 = np.array(
    [
        36.7,
        45.2,
        51.1,
        55.7,
        59.5,
        62.9,
        65.8,
        68.5,
        71.0,
        73.3,
        75.4,
        77.4,
        79.3,
        81.1,
        82.7,
        84.4,
        85.9,
        87.4,
        88.8,
        90.2,
        91.5,
        92.8,
        94.1,
        95.3,
        96.4,
        97.6,
        98.7,
        99.8,
        100.8,
        101.9,
        102.9,
        103.9,
        104.8,
        105.8,
    ]
)

#: ISO 281 groove radii for which the f_c values hold: r_i <= 0.52 D_w, r_e <= 0.53 D_w.
FC_MAX_INNER_GROOVE_FACTOR = 0.52
FC_MAX_OUTER_GROOVE_FACTOR = 0.53

# ---------------------------------------------------------------- ISO 76
#: gamma of ISO 76:2006 Table 1 (0 ... 0.40 in steps of 0.01).
F0_GAMMA = np.round(np.arange(0, 41) / 100.0, 2)
#: f_0 of ISO 76 Table 1, radial and angular-contact groove ball bearings [N/mm^2].
#: Stored copy: sfere (it prints 15.7 at 0.06, a misprint: the derivation below and the
#: smooth steps of 0.2 give 15.9). Checked by derivation: the Hertz contact at 4200 MPa
#: with r_i = 0.52 D_w, r_e = 0.53 D_w, E = 207 GPa, nu = 0.3 and C_0 = 0.2 Z Q_max cos(a)
#: (the ISO/TR 10657 chain quoted by bb_core) reproduces all 41 values within 0.06
#: (test_life: ``test_f0_table_is_the_4200_mpa_hertz_contact``).
F0_RADIAL = np.array(
    [
        14.7,
        14.9,
        15.1,
        15.3,
        15.5,
        15.7,
        15.9,
        16.1,
        16.3,
        16.5,
        16.4,
        16.1,
        15.9,
        15.6,
        15.4,
        15.2,
        14.9,
        14.7,
        14.4,
        14.2,
        14.0,
        13.7,
        13.5,
        13.2,
        13.0,
        12.8,
        12.5,
        12.3,
        12.1,
        11.8,
        11.6,
        11.4,
        11.2,
        10.9,
        10.7,
        10.5,
        10.3,
        10.0,
        9.8,
        9.6,
        9.4,
    ]
)
#: gamma = D_w/D_pw of the thrust column of ISO 76 Table 1 (0 ... 0.35).
F0_THRUST_GAMMA = np.round(np.arange(0, 36) / 100.0, 2)
#: f_0 of thrust ball bearings [N/mm^2]. Stored copy: sfere. Checked by derivation:
#: 4200 MPa with washer groove radius 0.54 D_w reproduces all 36 values within 0.15 %.
F0_THRUST = np.array(
    [
        61.6,
        60.8,
        59.9,
        59.1,
        58.3,
        57.5,
        56.7,
        55.9,
        55.1,
        54.3,
        53.5,
        52.7,
        51.9,
        51.2,
        50.4,
        49.6,
        48.8,
        48.0,
        47.3,
        46.5,
        45.7,
        45.0,
        44.2,
        43.5,
        42.7,
        41.9,
        41.2,
        40.5,
        39.7,
        39.0,
        38.2,
        37.5,
        36.8,
        36.0,
        35.3,
        34.6,
    ]
)
#: Contact stress that defines C_0 for these ball bearings [Pa] (ISO 76; skf.com "Load
#: ratings": 4200 MPa for all ball bearings but self-aligning ones, 4600 MPa).
STATIC_CONTACT_STRESS = 4.2e9

#: (X_0, Y_0) of ISO 76 Table 2, single row: radial contact (alpha = 0) ...
X0_RADIAL, Y0_RADIAL = 0.6, 0.5
#: ... and angular contact: X_0 = 0.5, Y_0 by contact angle [deg] (bb_core
#: ``Y0_ANGULAR_TABLE_DEG``; 15, 25 and 40 deg also in dozersim). Linear in between.
X0_ANGULAR = 0.5
Y0_ANGLE_DEG = np.array([5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
Y0_ANGULAR = np.array([0.52, 0.50, 0.46, 0.42, 0.38, 0.33, 0.29, 0.26, 0.22])

# ---------------------------------------------------------------- ISO 281 Table 3
#: Relative axial load of the upper part of Table 3: F_a/(i Z D_w^2) [N/mm^2], which
#: equals f_0 F_a/C_0r cos(alpha) (C_0r = f_0 i Z D_w^2 cos alpha), so for alpha = 0 it is
#: the familiar f_0 F_a/C_0r column 0.172 ... 6.89, and the 15 deg column printed as
#: f_0 F_a/C_0r (0.178 ... 7.14) is the same grid divided by cos 15 deg (bb_core; dozersim).
#: Both are 25, 50, ... 1000 psi rounded to 3 digits (bb_core; checked in test_life).
XYE_GRID = np.array([0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89])
#: Single-row blocks of the upper part of Table 3 (F_a/F_r > e; below e: X = 1, Y = 0):
#: contact angle [deg] -> (X, Y over the grid, e over the grid). 0 deg: deep groove
#: (lehmann, bb_core, and several course scripts); 5 deg: ISO's text "use the values of
#: single-row radial contact bearings" (bb_core); 10 and 15 deg: bb_core, 15 deg also
#: dozersim and a C# spindle calculator (id 15345955012).
_DG_Y = np.array([2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00])
_DG_E = np.array([0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44])
XYE_LOW_SINGLE = {
    0.0: (0.56, _DG_Y, _DG_E),
    5.0: (0.56, _DG_Y, _DG_E),
    10.0: (
        0.46,
        np.array([1.88, 1.71, 1.52, 1.41, 1.34, 1.23, 1.10, 1.01, 1.00]),
        np.array([0.29, 0.32, 0.36, 0.38, 0.40, 0.44, 0.49, 0.54, 0.54]),
    ),
    15.0: (
        0.44,
        np.array([1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00]),
        np.array([0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56]),
    ),
}
#: Lower part of Table 3, single row, alpha >= 20 deg: angle [deg] -> (X, Y, e)
#: (bb_core ``XYE_TABLE_DEG``; 20 and 25 deg also the C# calculator, 25 and 40 deg dozersim).
XYE_HIGH_SINGLE = {
    20.0: (0.43, 1.00, 0.57),
    25.0: (0.41, 0.87, 0.68),
    30.0: (0.39, 0.76, 0.80),
    35.0: (0.37, 0.66, 0.95),
    40.0: (0.35, 0.57, 1.14),
    45.0: (0.33, 0.50, 1.34),
}

# ---------------------------------------------------------------- ISO 281 section 9
#: Reliability [%] and life modification factor a_1 (ISO 281:2007 Table 12). ewing lists
#: 90-99 and 99.95, mecapy 90-99.9; every value equals the Weibull form
#: 0.95 (ln(100/R)/ln(100/90))^(2/3) + 0.05 rounded as printed (test_life).
A1_RELIABILITY = np.array(
    [90.0, 95.0, 96.0, 97.0, 98.0, 99.0, 99.2, 99.4, 99.6, 99.8, 99.9, 99.92, 99.94, 99.95]
)
A1_FACTOR = np.array(
    [1.0, 0.64, 0.55, 0.47, 0.37, 0.25, 0.22, 0.19, 0.16, 0.12, 0.093, 0.087, 0.080, 0.077]
)

#: a_ISO of radial ball bearings (ISO 281:2007 eqs. for 0.1 <= kappa < 0.4, 0.4 <= kappa
#: < 1, 1 <= kappa <= 4): (kappa_from, c, p) in
#: a_ISO = 0.1 [1 - (2.5671 - c / kappa^p)^0.83 (e_C C_u / P)^(1/3)]^-9.3.
#: bb_core gives 0.19087 for the middle band; mecapy and one other copy print 0.019087.
#: 0.19087 is kept: with it the bands meet at kappa = 0.4 (2.2649/0.4^0.054381 =
#: 1.9987/0.4^0.19087 = 2.381), with 0.019087 they jump (test_life).
A_ISO_BANDS = ((0.1, 2.2649, 0.054381), (0.4, 1.9987, 0.19087), (1.0, 1.9987, 0.071739))
A_ISO_BASE = 2.5671
A_ISO_EXPONENT = 0.83
A_ISO_SLOPE = 9.3
A_ISO_CAP = 50.0
KAPPA_MIN, KAPPA_MAX = 0.1, 4.0
#: a_ISO of radial roller bearings (ISO 281:2007): (kappa_from, c, p) in
#: a_ISO = 0.1 [1 - (1.5859 - c / kappa^p) (e_C C_u / P)^0.4]^-9.185.
#: ewing (id 12173787189) gives the first band and the exponents 1, 0.4, 9.185; mecapy
#: (id 61555616929) all three bands but the exponent 0.4 on the bracket's first factor.
#: The exponent 1 is kept: the bands meet at kappa = 0.4 (1.3993/0.4^0.054381 =
#: 1.2348/0.4^0.19087 = 1.471) either way, and with 0.4 a roller bearing would gain more
#: from cleanliness than a ball bearing (a_ISO 50 already at e_C C_u/P = 0.2 for kappa = 4),
#: against the makers' diagrams where roller bearings need the larger load ratio.
A_ISO_ROLLER_BANDS = ((0.1, 1.3993, 0.054381), (0.4, 1.2348, 0.19087), (1.0, 1.2348, 0.071739))
A_ISO_ROLLER_BASE = 1.5859
A_ISO_ROLLER_EXPONENT = 1.0
A_ISO_ROLLER_POWER = 0.4
A_ISO_ROLLER_SLOPE = 9.185
#: ISO 281 9.3.3.4 as quoted by bb_core: with effective EP additives, kappa < 1 and
#: e_C >= 0.2, kappa = 1 may be used and a_ISO is then limited to 3.
EP_KAPPA_EC_MIN, EP_A_ISO_CAP = 0.2, 3.0

#: Rated viscosity nu_1 [mm^2/s] = c n^-p D_pw^-0.5 (n in r/min, D_pw in mm):
#: n < 1000: 45000 n^-0.83, else 4500 n^-0.5 (bb_core, mecapy).
NU1_SWITCH_RPM = 1000.0

#: Fatigue load limit of ball bearings, simplified method of ISO 281 Annex B:
#: C_u = C_0 / 22, times (100 / D_pw)^0.5 for D_pw > 100 mm (bb_core; the C# spindle
#: calculator, id 15359366876).
CU_DIVISOR = 22.0
CU_SIZE_MM = 100.0

#: Contamination factor e_C, ISO 281:2007 Table 13 (MESYS manual; mecapy; the SKF eta_c
#: table at bearing-centre.com is the same): level -> ((low, high) for D_pw < 100 mm,
#: (low, high) for D_pw >= 100 mm).
CONTAMINATION_LEVELS = {
    "extreme-cleanliness": ((1.0, 1.0), (1.0, 1.0)),
    "high-cleanliness": ((0.6, 0.8), (0.8, 0.9)),
    "normal-cleanliness": ((0.5, 0.6), (0.6, 0.8)),
    "slight-contamination": ((0.3, 0.5), (0.4, 0.6)),
    "typical-contamination": ((0.1, 0.3), (0.2, 0.4)),
    "severe-contamination": ((0.0, 0.1), (0.0, 0.1)),
    "very-severe-contamination": ((0.0, 0.0), (0.0, 0.0)),
}
#: Short names accepted for the levels (command line): the first word alone where it can
#: only mean that level.
CONTAMINATION_ALIASES = {
    "slight": "slight-contamination",
    "typical": "typical-contamination",
    "severe": "severe-contamination",
    "very-severe": "very-severe-contamination",
}
#: Short names refused since issue 22: "extreme" read as extreme contamination when it is
#: extreme cleanliness (e_C = 1). Old word -> the level's name, given in the error's hint.
CONTAMINATION_RETIRED = {
    "extreme": "extreme-cleanliness",
    "high": "high-cleanliness",
    "normal": "normal-cleanliness",
}
CONTAMINATION_SIZE_MM = 100.0

# ---------------------------------------------------------------- ISO/TS 16281
#: Q_ci = C / (0.407 i^0.7 Z cos alpha) [1 + T^(10/3)]^0.3,
#: Q_ce = C / (0.389 i^0.7 Z cos alpha) [1 + T^(-10/3)]^0.3,
#: T = 1.044 ((1-gamma)/(1+gamma))^1.72 (r_i (2 r_e - D_w) / (r_e (2 r_i - D_w)))^0.41
#: (iso16281-py, both versions; bb_core ``q_ci_n``/``q_ce_n``). 0.407 and 0.389 are
#: Z J_r(0.5)/J_1(0.5) and Z J_r(0.5)/J_2(0.5) of a zero-clearance radial load.
QC_INNER, QC_OUTER, QC_RATIO = 0.407, 0.389, 1.044
#: Exponents of the equivalent rolling-element loads Q_e = (sum Q^w / Z)^(1/w): 3 on the
#: rotating ring, 10/3 on the stationary ring (iso16281-py; bb_core).
ROTATING_EXPONENT, STATIONARY_EXPONENT = 3.0, 10.0 / 3.0
