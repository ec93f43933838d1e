"""Published numbers of roller bearings that bearinglab reproduces (issue 28).

- IMS/NASA prognostics data, Rexnord ZA-2115 double-row bearing (16 rollers of 0.331 in
  per row, pitch 2.815 in, contact angle 15.17 deg; the catalogue row ``ZA-2115 (IMS)``)
  at 2000 rpm: BPFO 236.4, BPFI 296.9, BSF 139.9, FTF 14.8 Hz as printed with the data set
  by Qiu H. et al., J. Sound Vib. 289 (2006) 1066-1090 (the unrounded values 236.40,
  296.93, 139.92 and 14.775 Hz follow from the same formula), through the RollerBearing.
- Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing Technology*, 5th ed., 2007
  (ch. 7 examples; the catalogue row ``209 cylindrical (Harris)``): the 209 cylindrical
  roller bearing, 14 rollers of 10 x 9.6 mm on 65.01 mm, unprofiled, 4450 N radial with a
  roller on the load line: Q_max = 1299 N without clearance, 1959 N with 0.041 mm
  diametral clearance; C = 48.4 kN (ISO 281) and C_0 = 50.0 kN (ISO 76).
- NSK, *Rolling bearings* CAT. E728g, sec. 5.1 "Bearing internal load distribution"
  (stored copy tr.scribd.com/document/403457064): line contact, zero clearance, half the
  raceway loaded: Q_max = 4.08 F_r / (Z cos a), F_a = 1.260 F_r tan a.
- ROSS (petrobras/ross ``RollerBearingElement``, after Friswell et al., *Dynamics of
  Rotating Machines*, 2010, pp. 182-185): kyy = 1.0e9 n^0.9 l^0.8 F_s^0.1 cos(a)^1.9
  [N/m; m, N], kxx = 0.49 kyy for 8 rollers; its docstring example (8 rollers, 0.03 m,
  500 N) at alpha = 0 gives kyy = 7.32e8 N/m.
- Johnson K. L., *Contact Mechanics*, 1985, eq. 4.45: a cylinder of 20 mm diameter and
  20 mm length on a flat, 40 kN, E = 210 GPa, nu = 0.3 for both: p_0 = (w' E*/(pi R))^(1/2)
  = 2710 MPa.
- The catalogue (SKF): 30205 J2/Q e = 0.37 (contact angle atan(0.37/1.5) = 13.9 deg),
  C = 30.8 kN; NU 205 ECP C = 32.5 kN, the estimated geometries rated by ISO 281.
"""

from __future__ import annotations

import math
from functools import cache

from ..catalog import bearing_from_designation
from ..contact.line import line_contact
from ..kinematics import defect_frequencies
from ..operating import OperatingCondition
from ..ratings import load_ratings
from ..roller_geometry import RollerBearing, RollerProfile
from .case import Case

IMS = "IMS/NASA bearing data (Rexnord ZA-2115, Qiu et al. 2006) | roller bearing model"
HARRIS = "Harris & Kotzalas 2007, 209 cylindrical roller bearing"
NSK = "NSK CAT. E728g sec. 5.1 (line contact load zone)"
ROSS = "ROSS RollerBearingElement (Friswell et al. 2010)"
JOHNSON = "Johnson 1985, eq. 4.45 (line contact)"
SKF = "SKF catalogue data (stored public copy)"


@cache
def _ims():
    return defect_frequencies(
        bearing_from_designation("ZA-2115 (IMS)", rollers=True)[0], speed_rpm=2000.0
    )


def _ims_hz(name: str):
    return lambda: _ims().hz(name)


def harris_209(clearance: float = 0.0) -> RollerBearing:
    """Harris's 209 cylindrical roller bearing with a diametral clearance [m]."""
    b, _ = bearing_from_designation(
        "209 cylindrical (Harris)", rollers=True, overrides={"diametral_clearance": clearance}
    )
    return b


@cache
def _harris_qmax(clearance: float) -> float:
    from ..quasistatic import solve_load_distribution

    return solve_load_distribution(
        harris_209(clearance), OperatingCondition(radial_load=4450.0)
    ).max_roller_load


def _line_bearing(z: int, tapered: bool = False) -> RollerBearing:
    """An unprofiled roller set for the load-zone integrals (the rollers' size does not
    enter the ratios)."""
    if tapered:
        return RollerBearing(
            roller_count=z,
            roller_diameter=6.5e-3,
            roller_length=11e-3,
            pitch_diameter=0.2,
            contact_angle=math.radians(14.0),
            bearing_type="tapered_roller",
            profile=RollerProfile("flat"),
        )
    return RollerBearing(
        roller_count=z,
        roller_diameter=10e-3,
        roller_length=10e-3,
        pitch_diameter=0.2,
        profile=RollerProfile("flat"),
    )


def stribeck_ratio(z: int) -> float:
    """Q_max Z / F_r of an unprofiled cylindrical roller set without clearance [-]."""
    from ..quasistatic import solve_load_distribution

    r = solve_load_distribution(_line_bearing(z), OperatingCondition(radial_load=10e3))
    return r.max_roller_load * z / 10e3


def induced_axial_ratio(z: int) -> float:
    """F_a / (F_r tan a) of a single tapered row with half its raceway loaded (the inner
    ring's axial displacement held at 0) [-]."""
    from ..quasistatic import solve_load_distribution

    b = _line_bearing(z, tapered=True)
    r = solve_load_distribution(b, OperatingCondition(radial_load=10e3), axial_displacement=0.0)
    return r.induced_axial_force / (10e3 * math.tan(b.contact_angle))


@cache
def _ross_stiffness():
    from ..quasistatic import solve_load_distribution

    b = RollerBearing(
        roller_count=8,
        roller_diameter=10e-3,
        roller_length=0.03,
        pitch_diameter=0.08,
        profile=RollerProfile("flat"),
    )
    return solve_load_distribution(b, OperatingCondition(radial_load=500.0)).stiffness_matrix


def _johnson_p0() -> float:
    e_prime = 2.0 / (2.0 * (1.0 - 0.3**2) / 210e9)
    return float(line_contact(40e3 / 0.02, 0.01, e_prime).max_pressure) / 1e6


@cache
def _rating(name: str):
    return load_ratings(bearing_from_designation(name, rollers=True)[0])


CASES = [
    *(
        Case(
            IMS,
            f"{label} at 2000 rpm",
            value,
            "Hz",
            _ims_hz(name),
            0.05 / value,
            "printed to 0.1 Hz (the unrounded value is within 0.02 % of the printed one "
            "except FTF, 14.775 Hz printed 14.8)",
        )
        for name, label, value in (
            ("bpfo", "BPFO", 236.4),
            ("bpfi", "BPFI", 296.9),
            ("bsf", "BSF", 139.9),
            ("ftf", "FTF", 14.8),
        )
    ),
    Case(
        HARRIS,
        "Q_max at zero clearance, 4450 N",
        1299.0,
        "N",
        lambda: _harris_qmax(0.0),
        0.01,
        "printed to 4 digits; the discrete sum with a roller on the load line gives "
        "1298.8 N, 4.086 F_r/Z (issue 28 asks 1 %)",
    ),
    Case(
        HARRIS,
        "Q_max with 0.041 mm diametral clearance, 4450 N",
        1959.0,
        "N",
        lambda: _harris_qmax(0.041e-3),
        0.02,
        "depends on the roller's load-deflection constant (ISO/TS 16281's c_l here; "
        "Palmgren's is 3.4 % apart in approach); issue 28 asks 2 %",
    ),
    Case(
        HARRIS,
        "basic dynamic load rating C (ISO 281)",
        48400.0,
        "N",
        lambda: _rating("209 cylindrical (Harris)").dynamic,
        0.01,
        "printed to 3 digits (0.1 %); f_c from its closed form, not the printed table",
    ),
    Case(
        HARRIS,
        "basic static load rating C0 (ISO 76)",
        50000.0,
        "N",
        lambda: _rating("209 cylindrical (Harris)").static,
        0.01,
        "printed to 3 digits; ISO 76's closed form",
    ),
    Case(
        NSK,
        "Q_max Z / F_r, 14 rollers, zero clearance",
        4.08,
        "-",
        lambda: stribeck_ratio(14),
        0.02 / 4.08,
        "the printed integral (load exponent 1.1; 4.085 with the model's 10/9); a "
        "discrete set of Z >= 12 rollers lies within 0.02 (Z = 13: 4.093, Z = 14: 4.086)",
    ),
    Case(
        NSK,
        "F_a / (F_r tan a) at half the raceway loaded, 17 tapered rollers",
        1.260,
        "-",
        lambda: induced_axial_ratio(17),
        0.01 / 1.26,
        "the printed integral (load exponent 1.1; 1.258 with the model's 10/9); the "
        "discrete set of 17 rollers gives 1.2593 (it dips to 1.235 for Z = 12 and 1.246 "
        "for Z = 16, where rollers sit at the zone's edge: "
        "tests/literature/test_roller_load_zone_nsk.py)",
    ),
    Case(
        ROSS,
        "radial stiffness kyy, 8 rollers of 30 mm, 500 N, zero clearance",
        7.32e8,
        "N/m",
        lambda: _ross_stiffness()[1, 1],
        0.03,
        "ROSS's empirical 1e9 n^0.9 l^0.8 F^0.1 (issue 28 asks 3 %); ISO/TS 16281's c_l "
        "with the discrete set gives 0.8 % less",
    ),
    Case(
        ROSS,
        "kxx / kyy, 8 rollers",
        0.49,
        "-",
        lambda: _ross_stiffness()[0, 0] / _ross_stiffness()[1, 1],
        0.005 / 0.49,
        "printed to 2 digits",
    ),
    Case(
        JOHNSON,
        "p_0 of a 20 x 20 mm roller on a flat, 40 kN",
        2710.0,
        "MPa",
        _johnson_p0,
        0.001,
        "Hertz's closed form, printed to 4 digits (issue 28 asks 0.1 %)",
    ),
    Case(
        SKF,
        "30205 contact angle from the estimate",
        13.9,
        "deg",
        lambda: math.degrees(bearing_from_designation("30205", rollers=True)[0].contact_angle),
        0.05 / 13.9,
        "e = 0.37 printed to 2 digits: atan(0.37/1.5) = 13.86 deg; printed angle rounded "
        "to 0.1 deg",
    ),
]
