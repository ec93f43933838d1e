"""The result of reading a bearing designation: :class:`Designation`.

Both readers (:func:`bearinglab.designation.parse_gost` for GOST 3189-89 and
:func:`bearinglab.designation.parse_iso` for ISO 15 / maker designations) return this one
frozen dataclass, in SI units (bore in metres, contact angle in radians).  The GOST system
is the one described in seed 003 (lines 129-187: "Условные обозначения и маркировка
подшипников качения").

>>> d = Designation(text="311", system="gost", bearing_type="radial_ball", bore=0.055,
...                 bore_code="11", description="deep-groove ball bearing")
>>> d.to_dict()["bore_mm"]
55.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

#: Bearing kinds known to the designation readers.  The first ten are GOST 3189-89
#: types 0-9 in order (seed 003, lines 145-154).
BEARING_TYPES: tuple[str, ...] = (
    "radial_ball",
    "self_aligning_ball",
    "cylindrical_roller",
    "spherical_roller",
    "needle_roller",
    "spiral_roller",
    "angular_contact_ball",
    "tapered_roller",
    "thrust_ball",
    "thrust_roller",
    "four_point_contact_ball",
)

#: Allowed values of :attr:`Designation.closures`.
CLOSURES: tuple[str, ...] = ("open", "shield", "2shields", "seal", "2seals", "unknown")

#: Allowed values of :attr:`Designation.system`.
SYSTEMS: tuple[str, ...] = ("gost", "iso")


@dataclass(frozen=True)
class Designation:
    """One reading of a rolling-bearing designation.

    Parameters
    ----------
    text : str
        The designation exactly as given [-]
    system : str
        ``"gost"`` (GOST 3189-89, seed 003) or ``"iso"`` (ISO 15 and maker suffixes) [-]
    bearing_type : str
        One of :data:`BEARING_TYPES` [-]
    bore : float
        Nominal bore diameter d [m]
    bore_code : str
        The bore part as written: two-digit code, single small-bore digit or ``"/d"`` [-]
    series : str or None
        ISO family key used for catalogue lookup (``"62"``, ``"NU2"``, ``"302"``...) [-]
    dimension_series : str or None
        ISO two-digit dimension series, width (height) digit then diameter digit [-]
    diameter_series : str or None
        Diameter-series digit as written in the designation's own system [-]
    diameter_series_name : str or None
        Name of that diameter series ("light", "medium"...) [-]
    width_series : str or None
        Width-series digit in the designation's own system [-]
    width_series_name : str or None
        Name of that width series [-]
    design_variant : str or None
        GOST digits 5-6 as written, or the ISO type prefix (``"NU"``, ``"QJ"``) [-]
    design_variant_meaning : str or None
        What the design variant means, or ``"design variant NN (not decoded)"`` [-]
    precision_class : str or None
        GOST class ``"0"``, ``"6"``, ``"5"``, ``"4"``, ``"2"``, ``"T"``, ``"8"``, ``"7"``;
        ISO P6/P5/P4/P2 map to ``"6"``/``"5"``/``"4"``/``"2"`` [-]
    category : str or None
        GOST category ``"A"``, ``"B"`` or ``"C"`` (seed 003 lines 168-172) [-]
    contact_angle : float or None
        Nominal contact angle when the designation implies one [rad]
    closures : str
        One of :data:`CLOSURES` [-]
    prefixes : tuple of (str, str)
        (code, meaning) pairs written before the basic number [-]
    suffixes : tuple of (str, str)
        (code, meaning) pairs written after the basic number [-]
    parts : tuple of (str, str)
        (text, meaning) pairs in reading order: the full breakdown [-]
    iso_equivalent : str or None
        The bearing in ISO form (for an ISO reading: its normalised spelling) [-]
    gost_equivalent : str or None
        The bearing in GOST 3189-89 form (for a GOST reading: its normalised spelling) [-]
    alternatives : tuple of Designation
        Other valid readings of the same text in the other system [-]
    notes : tuple of str
        Caveats: uncertain decodings, ambiguity, inexact equivalents [-]
    description : str
        One line an engineer would write [-]
    """

    text: str
    system: str
    bearing_type: str
    bore: float
    bore_code: str
    series: str | None = None
    dimension_series: str | None = None
    diameter_series: str | None = None
    diameter_series_name: str | None = None
    width_series: str | None = None
    width_series_name: str | None = None
    design_variant: str | None = None
    design_variant_meaning: str | None = None
    precision_class: str | None = None
    category: str | None = None
    contact_angle: float | None = None
    closures: str = "open"
    prefixes: tuple[tuple[str, str], ...] = ()
    suffixes: tuple[tuple[str, str], ...] = ()
    parts: tuple[tuple[str, str], ...] = ()
    iso_equivalent: str | None = None
    gost_equivalent: str | None = None
    alternatives: tuple[Designation, ...] = ()
    notes: tuple[str, ...] = ()
    description: str = field(default="")

    def __post_init__(self) -> None:
        if self.system not in SYSTEMS:
            raise ValueError(f"system must be one of {SYSTEMS}, got {self.system!r}")
        if self.bearing_type not in BEARING_TYPES:
            raise ValueError(
                f"bearing_type must be one of BEARING_TYPES, got {self.bearing_type!r}"
            )
        if self.closures not in CLOSURES:
            raise ValueError(f"closures must be one of {CLOSURES}, got {self.closures!r}")
        if not (math.isfinite(self.bore) and self.bore > 0.0):
            raise ValueError(f"bore must be a positive length in metres, got {self.bore!r}")

    @property
    def bore_mm(self) -> float:
        """Bore diameter in millimetres (engineering unit, for display) [mm]."""
        return round(self.bore * 1000.0, 6)

    @property
    def contact_angle_deg(self) -> float | None:
        """Contact angle in degrees (engineering unit, for display) [deg]."""
        if self.contact_angle is None:
            return None
        return round(math.degrees(self.contact_angle), 6)

    def to_dict(self) -> dict[str, Any]:
        """Return a JSON-ready dict in engineering units (``bore_mm``, ``contact_angle_deg``).

        >>> d = Designation(text="608", system="iso", bearing_type="radial_ball", bore=0.008,
        ...                 bore_code="8", parts=(("60", "deep-groove ball bearing"),))
        >>> d.to_dict()["parts"]
        [{'text': '60', 'meaning': 'deep-groove ball bearing'}]
        """
        return {
            "text": self.text,
            "system": self.system,
            "bearing_type": self.bearing_type,
            "bore_mm": self.bore_mm,
            "bore_code": self.bore_code,
            "series": self.series,
            "dimension_series": self.dimension_series,
            "diameter_series": self.diameter_series,
            "diameter_series_name": self.diameter_series_name,
            "width_series": self.width_series,
            "width_series_name": self.width_series_name,
            "design_variant": self.design_variant,
            "design_variant_meaning": self.design_variant_meaning,
            "precision_class": self.precision_class,
            "category": self.category,
            "contact_angle_deg": self.contact_angle_deg,
            "closures": self.closures,
            "prefixes": [{"code": c, "meaning": m} for c, m in self.prefixes],
            "suffixes": [{"code": c, "meaning": m} for c, m in self.suffixes],
            "parts": [{"text": t, "meaning": m} for t, m in self.parts],
            "iso_equivalent": self.iso_equivalent,
            "gost_equivalent": self.gost_equivalent,
            "alternatives": [a.to_dict() for a in self.alternatives],
            "notes": list(self.notes),
            "description": self.description,
        }
