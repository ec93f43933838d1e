"""Estimate the internal geometry of a cylindrical or tapered roller bearing from its
boundary dimensions (ISO 15, ISO 355), when no published geometry is shipped.

No public design method of roller bearings like the deep-groove rules of
:mod:`bearinglab.catalog.estimate` was found, so these are bearinglab's rules, stated here
and checked against what is published (docs/capabilities/roller_bearings.md):

* pitch diameter d_m = (d + D)/2, as for ball bearings;
* roller diameter D_we = K_r (D - d) with K_r = 0.27: the roller takes a little over half
  of the radial section (D - d)/2, the rings and their ribs the rest. Harris's 209
  cylindrical roller bearing (Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing
  Technology*, 5th ed., 2007, ch. 2: 45 x 85 x 19 mm, 14 rollers of 10 x 9.6 mm on
  65.01 mm) has 0.25; modern reinforced (E) designs carry larger rollers;
* effective length L_we = 0.6 B for cylindrical bearings (the ribs and the rollers' end
  chamfers take the rest of the ring width; Harris's 209: 0.51 B), shared by the rows of a
  double-row bearing (0.3 B each), and 0.8 C for tapered bearings (C the cup width, which
  the roller spans less its end chamfers);
* roller count Z = floor(pi d_m / (1.3 D_we)): a cage bar of 0.3 D_we between rollers
  (Harris's 209: 1.46 D_we from centre to centre, an older light design);
* the contact angle of a tapered bearing from the e its series carries in the makers'
  tables, alpha = atan(e / 1.5) (ISO 281: e = 1.5 tan(alpha)): e = 0.37 for 302 and 322,
  0.30 for 303 and 323, 0.43 for 320, 0.83 for 313 (SKF 30205 J2/Q, 32206 J2/Q, 30305 J2,
  32305 J2, 32005 X/Q, 31305 J2, as in the SKF data of the stored public script
  ``cargar_base_datos_rodamientos``, id 14438996); the cone angle follows from the on-apex
  design (:func:`bearinglab.roller_geometry.on_apex_angles`);
* the roller profile: ISO/TS 16281's logarithmic profile, the one the standard assumes
  for a profiled roller; no clearance (diametral clearance 0, axial play 0).

Checks (tests/literature/test_roller_designations_skf.py): NU205 C = 29.4 kN against the
catalogue's 32.5 kN (0.90), 30205 alpha = 13.86 deg against 13.9 deg and C = 32.1 kN
against 30.8 kN (1.04); the other 15 SKF bearings stored (25 and 30 mm bores) 0.78-1.03.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError, bore_below_outside, positive_number

#: Citation attached to every estimated value.
ROLLER_ESTIMATE_METHOD = (
    "bearinglab roller-bearing rules (docs/capabilities/roller_bearings.md): d_m = (d + D)/2, "
    "D_we = 0.27 (D - d), L_we = 0.6 B (cylindrical) or 0.8 C (tapered), "
    "Z = floor(pi d_m / (1.3 D_we))"
)
#: D_we / (D - d) [-].
ROLLER_DIAMETER_FACTOR = 0.27
#: L_we / B of cylindrical bearings and L_we / C (cup width) of tapered bearings [-].
CYLINDRICAL_LENGTH_FACTOR = 0.6
TAPERED_LENGTH_FACTOR = 0.8
#: Centre distance of neighbouring rollers over D_we [-].
ROLLER_PITCH_FACTOR = 1.3
#: e of ISO 281 (1.5 tan alpha) by tapered series, from the makers' tables (see above).
TAPERED_SERIES_E = {"302": 0.37, "303": 0.30, "313": 0.83, "320": 0.43, "322": 0.37, "323": 0.30}
TAPERED_E_SOURCE = (
    "e of the series in SKF's tables (30205 J2/Q, 32206 J2/Q: 0.37; 30305 J2, 32305 J2: "
    "0.30; 32005 X/Q: 0.43; 31305 J2: 0.83; stored public script id 14438996), "
    "alpha = atan(e / 1.5) (ISO 281 e = 1.5 tan alpha)"
)


@dataclass(frozen=True)
class EstimatedRollerGeometry:
    """Internal geometry of a roller bearing estimated from its boundary dimensions (SI).

    Parameters
    ----------
    roller_count : int
        Z [-].
    roller_diameter : float
        D_we [m].
    roller_length : float
        L_we [m].
    pitch_diameter : float
        d_m [m].
    contact_angle : float
        alpha [rad].
    method : str
        Citation of the rules [-].
    """

    roller_count: int
    roller_diameter: float
    roller_length: float
    pitch_diameter: float
    contact_angle: float
    method: str = ROLLER_ESTIMATE_METHOD

    def as_kwargs(self) -> dict:
        """The values as :class:`~bearinglab.roller_geometry.RollerBearing` keywords."""
        return {
            "roller_count": self.roller_count,
            "roller_diameter": self.roller_diameter,
            "roller_length": self.roller_length,
            "pitch_diameter": self.pitch_diameter,
            "contact_angle": self.contact_angle,
        }


def tapered_contact_angle(series: str) -> float:
    """Contact angle of a tapered series from the e its members carry, atan(e/1.5) [rad].

    Parameters
    ----------
    series : str
        ISO 355 series, e.g. ``"302"`` [-].

    Examples
    --------
    >>> round(math.degrees(tapered_contact_angle("302")), 2)
    13.86
    """
    if series not in TAPERED_SERIES_E:
        raise InputError(
            "series",
            series,
            "a tapered series with a known e: " + ", ".join(TAPERED_SERIES_E),
            "give the contact angle (contact_angle)",
        )
    return math.atan(TAPERED_SERIES_E[series] / 1.5)


def estimate_roller_geometry(
    bore: float,
    outside_diameter: float,
    width: float,
    bearing_type: str = "cylindrical_roller",
    contact_angle: float = 0.0,
) -> EstimatedRollerGeometry:
    """Estimate Z, D_we, L_we, d_m of a cylindrical or tapered roller bearing.

    See the module docstring for the rules.

    Parameters
    ----------
    bore, outside_diameter : float
        d, D [m].
    width : float
        B of a cylindrical bearing, the cup width C of a tapered bearing [m].
    bearing_type : str
        ``"cylindrical_roller"`` or ``"tapered_roller"`` [-].
    contact_angle : float
        alpha [rad] (0 for cylindrical bearings).

    Examples
    --------
    >>> g = estimate_roller_geometry(0.025, 0.052, 0.015)   # NU205
    >>> g.roller_count, round(g.roller_diameter * 1e3, 2), round(g.roller_length * 1e3, 2)
    (12, 7.29, 9.0)
    """
    if bearing_type not in ("cylindrical_roller", "tapered_roller"):
        raise InputError("bearing_type", bearing_type, "cylindrical_roller or tapered_roller")
    for name, value in (("bore", bore), ("outside_diameter", outside_diameter), ("width", width)):
        positive_number(name, value, "a positive length [m]")
    bore_below_outside(bore, outside_diameter)
    pitch = 0.5 * (bore + outside_diameter)
    diameter = ROLLER_DIAMETER_FACTOR * (outside_diameter - bore)
    factor = (
        TAPERED_LENGTH_FACTOR if bearing_type == "tapered_roller" else CYLINDRICAL_LENGTH_FACTOR
    )
    count = max(3, math.floor(math.pi * pitch / (ROLLER_PITCH_FACTOR * diameter)))
    return EstimatedRollerGeometry(
        roller_count=int(count),
        roller_diameter=diameter,
        roller_length=factor * width,
        pitch_diameter=pitch,
        contact_angle=float(contact_angle),
    )
