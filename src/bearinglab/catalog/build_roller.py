"""Assemble a :class:`~bearinglab.roller_geometry.RollerBearing` from a designation or a
catalogue name (:func:`bearinglab.catalog.bearing_from_designation` calls this for
cylindrical and tapered roller bearings, ISO or GOST: NU205, N205, NJ205, NUP205, NN3020,
30205, 32205, GOST 2205, 42205, 7205, 7505 ...).

Order of precedence for every value, as for ball bearings: the caller's overrides
(``Source("user")``), the ISO 15 / ISO 355 boundary dimensions (``Source("catalog")``), the
published geometry of that bearing (``roller_geometry.csv``, ``Source("catalog", <its
source>)``), the estimate of :mod:`bearinglab.catalog.estimate_roller`
(``Source("estimated", <rule>)``); what nobody gives keeps the RollerBearing default,
marked ``Source("default", ...)``: no clearance (roller-bearing clearance groups are not
shipped), ISO/TS 16281's logarithmic profile.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import CatalogError, InputError, bore_below_outside
from ..geometry import Source
from ..roller_geometry import RollerBearing, RollerProfile
from . import _data
from .estimate_roller import (
    ROLLER_ESTIMATE_METHOD,
    TAPERED_E_SOURCE,
    TAPERED_SERIES_E,
    estimate_roller_geometry,
    tapered_contact_angle,
)
from .families import FAMILIES
from .lookup import BoundaryDimensions, _norm, _parse, boundary_dimensions
from .needed import GeometryNeeded

_MM = 1e-3
#: Designation types built as a RollerBearing from a designation.
ROLLER_BUILD_TYPES = ("cylindrical_roller", "tapered_roller")
#: RollerBearing keywords a caller may override.
ROLLER_OVERRIDABLE = (
    "roller_count",
    "roller_diameter",
    "roller_length",
    "pitch_diameter",
    "contact_angle",
    "cone_angle",
    "rows",
    "arrangement",
    "row_spacing",
    "diametral_clearance",
    "axial_clearance",
    "profile",
    "flange_angle",
    "roller_end_radius",
    "bore",
    "outside_diameter",
    "width",
    "ring_material",
    "roller_material",
    "name",
)
USER_SOURCE = Source("user", "command line or caller")
#: Diameter series of cylindrical roller bearings whose estimate is checked against makers'
#: ratings (docs/capabilities/roller_bearings.md: NU10 came out 1.6 times, NU4 1.14 times
#: the catalogue's C, so those are refused rather than estimated).
CHECKED_DIAMETER_SERIES = ("2", "3")
_ESTIMATED = ("roller_count", "roller_diameter", "roller_length", "pitch_diameter")


@dataclass(frozen=True)
class PublishedRollerGeometry:
    """Internal geometry of one specific roller bearing as a source published it (SI;
    None: not published).

    Parameters
    ----------
    name : str
        Catalogue name [-].
    designation : str
        ISO designation the row stands for ("" if none) [-].
    bearing_type : str
        cylindrical_roller, tapered_roller or spherical_roller [-].
    values : dict
        RollerBearing keyword -> value [SI].
    source : str
        Document and table [-].
    default : bool
        True if the row answers a look-up by designation [-].
    notes : str
        How the values were read [-].
    """

    name: str
    designation: str
    bearing_type: str
    values: dict
    source: str
    default: bool
    notes: str


def published_roller_geometries() -> list[PublishedRollerGeometry]:
    """All shipped published roller geometries (``roller_geometry.csv``), in file order."""
    out = []
    for r in _data.rows("roller_geometry.csv"):
        values: dict[str, Any] = {}
        for key, column, scale in (
            ("roller_count", "roller_count", None),
            ("roller_diameter", "roller_diameter_mm", _MM),
            ("roller_length", "roller_length_mm", _MM),
            ("pitch_diameter", "pitch_diameter_mm", _MM),
            ("contact_angle", "contact_angle_deg", math.pi / 180.0),
            ("rows", "rows", None),
            ("diametral_clearance", "diametral_clearance_um", 1e-6),
            ("bore", "bore_mm", _MM),
            ("outside_diameter", "outside_diameter_mm", _MM),
            ("width", "width_mm", _MM),
        ):
            if r[column] is None:
                continue
            values[key] = int(r[column]) if scale is None else float(r[column]) * scale
        if r["profile"]:
            values["profile"] = RollerProfile(r["profile"])
        out.append(
            PublishedRollerGeometry(
                name=str(r["name"]),
                designation=str(r["designation"]),
                bearing_type=str(r["bearing_type"]),
                values=values,
                source=str(r["source"]),
                default=bool(int(r["default"])),
                notes=str(r["notes"]),
            )
        )
    return out


def roller_by_name(text: str) -> PublishedRollerGeometry | None:
    """The published roller geometry named ``text`` (case- and space-insensitive), or None.

    Parameters
    ----------
    text : str
        Catalogue name, e.g. ``"ZA-2115 (IMS)"`` [-].

    Examples
    --------
    >>> roller_by_name("za-2115 (ims)").values["roller_count"]
    16
    """
    wanted = _norm(text)
    for geo in published_roller_geometries():
        if _norm(geo.name) == wanted:
            return geo
    return None


def _published_for(des) -> PublishedRollerGeometry | None:
    series, bore = getattr(des, "series", None), getattr(des, "bore", None)
    if series is None or bore is None:
        return None
    for geo in published_roller_geometries():
        if not (geo.default and geo.designation):
            continue
        other = _parse(geo.designation, "iso")
        if other.series == series and abs(other.bore - bore) < 1e-9:
            return geo
    return None


def _design(des) -> str:
    series = getattr(des, "series", None) or ""
    if getattr(des, "bearing_type", "") == "cylindrical_roller":
        return series.rstrip("0123456789")
    return ""


def check_roller_overrides(overrides: dict) -> None:
    """Refuse a BallBearing keyword among the overrides of a roller bearing.

    Parameters
    ----------
    overrides : dict
        Keyword -> value [SI].
    """
    for key in overrides:
        if key not in ROLLER_OVERRIDABLE:
            raise InputError(
                key,
                overrides[key],
                "an input of a roller bearing (" + ", ".join(ROLLER_OVERRIDABLE) + ")",
                "the designation is a roller bearing",
            )


def roller_from_designation(
    text: str, des, row: PublishedRollerGeometry | None, overrides: dict
) -> tuple[RollerBearing, Any]:
    """Build the RollerBearing of a roller designation (``des``, or None for a catalogue
    name with no designation) and its published row.

    Parameters
    ----------
    text : str
        What was asked for [-].
    des : Designation or None
        The parsed designation [-].
    row : PublishedRollerGeometry or None
        Published geometry of the bearing [-].
    overrides : dict
        RollerBearing keyword -> value, SI [-].

    Returns
    -------
    tuple
        (RollerBearing, the Designation or None).
    """
    check_roller_overrides(overrides)
    values: dict[str, Any] = {}
    sources: dict[str, Source] = {}

    def put(name: str, value, source: Source) -> None:
        if name not in values and value is not None:
            values[name] = value
            sources[name] = source

    for name, value in overrides.items():
        put(name, value, USER_SOURCE)
    btype = row.bearing_type if row is not None else des.bearing_type
    dims: BoundaryDimensions | None = None
    dims_error: CatalogError | None = None
    if des is not None:
        try:
            dims = boundary_dimensions(des)
        except CatalogError as exc:
            dims_error = exc
    if dims is not None:
        dim_source = Source("catalog", dims.standard)
        put("bore", dims.bore, dim_source)
        put("outside_diameter", dims.outside_diameter, dim_source)
        put("width", dims.width, dim_source)
    if row is not None:
        for name, value in row.values.items():
            put(name, value, Source("catalog", row.source))
    _check_sizes(values, sources)
    fam = FAMILIES.get(getattr(des, "series", None))
    if fam is not None and fam.rows == 2:
        put("rows", 2, Source("catalog", f"family {fam.key}: two rows"))
        put("arrangement", "tandem", Source("catalog", f"family {fam.key}: two rows alike"))
    if btype == "tapered_roller":
        if getattr(des, "contact_angle", None) is not None:
            put(
                "contact_angle",
                float(des.contact_angle),
                Source("catalog", f"designation {text!r}"),
            )
        series = getattr(des, "series", None)
        if "contact_angle" not in values:
            if series not in TAPERED_SERIES_E:
                raise _needed(
                    f"{text!r}: the contact angle of tapered series {series!r} is not known",
                    ("contact_angle",),
                )
            put(
                "contact_angle",
                tapered_contact_angle(series),
                Source("estimated", TAPERED_E_SOURCE),
            )
    if (
        btype == "spherical_roller"
        and "roller_length" not in values
        and "roller_diameter" in values
    ):
        put(
            "roller_length",
            values["roller_diameter"],
            Source("default", "not published: the roller diameter (kinematics do not use it)"),
        )
    missing = [k for k in _ESTIMATED if k not in values]
    if missing:
        if dims is None:
            reason = str(dims_error) if dims_error is not None else "no ISO family and bore"
            raise _needed(f"{text!r}: cannot estimate the internal geometry ({reason})", missing)
        series = dims.dimension_series or ""
        if btype == "cylindrical_roller" and series[-1:] not in CHECKED_DIAMETER_SERIES:
            raise _needed(
                f"{text!r}: the estimate of cylindrical roller bearings is checked for "
                "diameter series 2 and 3 only (NU2, NU22, NU3, NU23: ISO 281 ratings 0.78-1.03 "
                f"times the catalogue's); dimension series {series} is not",
                missing,
            )
        width = dims.cup_width if btype == "tapered_roller" else dims.width
        if btype == "tapered_roller" and width is None:
            width = dims.width
        est = estimate_roller_geometry(
            values.get("bore", dims.bore),
            values.get("outside_diameter", dims.outside_diameter),
            width,
            btype,
            values.get("contact_angle", 0.0),
        )
        rows = int(values.get("rows", 1))
        for name, value in est.as_kwargs().items():
            if name == "contact_angle":
                continue
            if name == "roller_length" and rows > 1:
                value = value / rows  # the rows share the ring width
            put(name, value, Source("estimated", ROLLER_ESTIMATE_METHOD))
    put(
        "profile",
        RollerProfile("logarithmic"),
        Source("default", "ISO/TS 16281 logarithmic profile assumed (profile not published)"),
    )
    if "diametral_clearance" not in values:
        sources["diametral_clearance"] = Source(
            "default", "no clearance assumed (roller-bearing clearance groups are not shipped)"
        )
    if "contact_angle" not in values:
        sources["contact_angle"] = Source("default", "cylindrical rollers: contact angle 0")
    for name in ("ring_material", "roller_material"):
        if name not in values:
            sources[name] = Source("default", "AISI 52100 bearing steel")
    if int(values.get("rows", 1)) == 2 and "arrangement" not in values:
        # a double-row spherical roller bearing's contact lines meet at its centre (the
        # self-aligning point), as a face-to-face pair's; others: two rows alike
        arrangement = "face_to_face" if btype == "spherical_roller" else "tandem"
        put("arrangement", arrangement, Source("default", f"two rows: {arrangement}"))
    name = values.pop("name", None) or (row.name if row is not None and des is None else text)
    bearing = RollerBearing(
        **values,
        name=name,
        bearing_type=btype,
        design=_design(des),
        sources=sources,
    )
    return bearing, des


def _check_sizes(values: dict, sources: dict) -> None:
    """d < D and d < d_m < D, blaming a value the user gave rather than the catalogue's."""
    d, big_d = values.get("bore"), values.get("outside_diameter")
    if d is None or big_d is None:
        return
    given_outside = sources["outside_diameter"].kind == "user" and sources["bore"].kind != "user"
    bore_below_outside(d, big_d, "outside_diameter" if given_outside else "bore")
    dm = values.get("pitch_diameter")
    if dm is not None and not d < dm < big_d:
        raise InputError(
            "pitch_diameter",
            dm,
            "between the bore {d} and the outside diameter {D}",
            unit="m",
            numbers={"d": d, "D": big_d},
        )


def _needed(reason: str, needed) -> CatalogError:
    return GeometryNeeded(reason, tuple(needed))


def published_roller(des) -> PublishedRollerGeometry | None:
    """The default published roller geometry of a designation (family and bore), or None.

    Parameters
    ----------
    des : Designation
        The parsed designation [-].
    """
    return _published_for(des)
