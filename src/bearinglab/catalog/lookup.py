"""Catalogue look-ups: boundary dimensions by ISO family and bore, published geometries.

Boundary dimensions come from the ISO dimension plans shipped in ``catalog/data``
(ISO 15 radial, ISO 355 tapered, ISO 104 thrust; values as printed in maker catalogues,
see the ``# source:`` lines of each file).  Published internal geometries
(``internal_geometry.csv``) are specific bearings documented in a paper, data-set page or
textbook; each row names its source.  Radial internal clearance groups of deep-groove ball
bearings come from ISO 5753-1 (``iso5753_radial_clearance.csv``, checked against the NTN
and NSK reprints named in the file).  Everything returned is in SI units (m, rad).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from ..errors import CatalogError, DesignationError, InputError, positive_number
from ..geometry import INTERNAL_FIELDS
from . import _data
from .families import FAMILIES, TABLE_FILES, Family, families_table

#: Designation bearing types that take ISO 15 radial dimensions by dimension series when
#: the family key is not one of :data:`~bearinglab.catalog.families.FAMILIES`.
RADIAL_TYPES = (
    "radial_ball",
    "self_aligning_ball",
    "cylindrical_roller",
    "spherical_roller",
    "needle_roller",
    "angular_contact_ball",
    "four_point_contact_ball",
)

_MM = 1e-3


@dataclass(frozen=True)
class BoundaryDimensions:
    """Boundary dimensions of one bearing size, from an ISO dimension plan.

    For radial bearings ``width`` is B; for tapered roller bearings it is the total
    width T, with the cone width B in ``cone_width`` and the cup width C in
    ``cup_width``; for thrust bearings it is the height T (also in ``height``).

    Parameters
    ----------
    bore : float
        Bore diameter d [m].
    outside_diameter : float
        Outside diameter D [m].
    width : float
        Width B (radial), total width T (tapered) or height T (thrust) [m].
    standard : str
        Standard and table the values come from [-].
    family : str or None
        ISO family key, e.g. ``"62"`` [-].
    dimension_series : str or None
        ISO two-digit dimension series, e.g. ``"02"`` [-].
    chamfer_min : float or None
        Smallest chamfer dimension r_s min [m].
    cone_width : float or None
        Cone (inner-ring) width B of a tapered roller bearing [m].
    cup_width : float or None
        Cup (outer-ring) width C of a tapered roller bearing [m].
    height : float or None
        Height T of a thrust bearing [m].

    Examples
    --------
    >>> BoundaryDimensions(0.025, 0.052, 0.015, "ISO 15:2017").to_dict()["outside_diameter_mm"]
    52.0
    """

    bore: float
    outside_diameter: float
    width: float
    standard: str
    family: str | None = None
    dimension_series: str | None = None
    chamfer_min: float | None = None
    cone_width: float | None = None
    cup_width: float | None = None
    height: float | None = None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict in millimetres (``bore_mm``...)."""
        out: dict[str, Any] = {
            "family": self.family,
            "dimension_series": self.dimension_series,
            "standard": self.standard,
        }
        for name in (
            "bore",
            "outside_diameter",
            "width",
            "chamfer_min",
            "cone_width",
            "cup_width",
            "height",
        ):
            value = getattr(self, name)
            out[f"{name}_mm"] = None if value is None else round(value / _MM, 6)
        return out


def _parse(text: str, system: str | None = None):
    from ..designation import parse  # the designation package imports nothing from here

    return parse(text, system=system)


def _as_designation(designation: Any, system: str | None = None):
    if isinstance(designation, str):
        return _parse(designation, system)
    return designation


def _bore_list(bores) -> str:
    values = sorted({float(b) for b in bores})
    return ", ".join(f"{b:g}" for b in values) if values else "none"


def _family_of(designation: Any) -> Family | None:
    series = getattr(designation, "series", None)
    if series in FAMILIES:
        return FAMILIES[series]
    dims = getattr(designation, "dimension_series", None)
    btype = getattr(designation, "bearing_type", None)
    if dims and btype in RADIAL_TYPES:
        return Family(series or f"dimension series {dims}", btype, dims, "iso15")
    return None


def boundary_dimensions(designation: Any, system: str | None = None) -> BoundaryDimensions:
    """Boundary dimensions of a bearing from its ISO family and bore.

    The family key (``designation.series``) picks the standard and the row: radial
    families by ISO 15 dimension series, tapered (302, 303, 320, 322, 323) from ISO 355,
    thrust ball (511-514) from ISO 104.  A radial designation whose family is unknown
    but whose dimension series is given is looked up by that series.

    Parameters
    ----------
    designation : Designation or str
        A parsed designation (anything with ``series``, ``dimension_series``,
        ``bearing_type``, ``bore`` [m]) or the text to parse [-].
    system : str or None
        ``"gost"`` or ``"iso"`` when ``designation`` is text; None lets the reader decide [-].

    Raises
    ------
    CatalogError
        If the family has no shipped table or the bore is not in it; the message names
        the family and bore and lists the bores that are there.
    """
    des = _as_designation(designation, system)
    text = getattr(des, "text", str(designation))
    fam = _family_of(des)
    bore_mm = round(float(des.bore) / _MM, 6)
    if fam is None:
        raise CatalogError(
            f"{text!r}: no boundary-dimension table for family "
            f"{getattr(des, 'series', None)!r} "
            f"({getattr(des, 'bearing_type', 'unknown type')}); the catalogue holds "
            f"ISO 15 radial, ISO 355 tapered (302, 303, 320, 322, 323) and ISO 104 "
            "thrust ball (511-514) bearings"
        )
    column, wanted, where = (
        ("dimension_series", fam.dimension_series, f"dimension series {fam.dimension_series}")
        if fam.table == "iso15"
        else ("series", fam.key, f"series {fam.key}")
    )
    rows = [r for r in _data.rows(TABLE_FILES[fam.table]) if r[column] == wanted]
    hit = [r for r in rows if abs(r["bore_mm"] - bore_mm) < 1e-6]
    if not hit:
        raise CatalogError(
            f"{text!r}: family {fam.key} ({where}, {fam.standard}) has no "
            f"bore {bore_mm:g} mm in the catalogue; bores there [mm]: "
            f"{_bore_list(r['bore_mm'] for r in rows)}"
        )
    r = hit[0]
    common = {
        "bore": float(r["bore_mm"]) * _MM,
        "outside_diameter": float(r["outside_diameter_mm"]) * _MM,
        "family": fam.key,
        "dimension_series": fam.dimension_series,
    }
    if fam.table == "iso15":
        chamfer = r["chamfer_min_mm"]
        return BoundaryDimensions(
            width=float(r["width_mm"]) * _MM,
            standard=f"{fam.standard} dimension series {fam.dimension_series} "
            f"({TABLE_FILES[fam.table]})",
            chamfer_min=None if chamfer is None else float(chamfer) * _MM,
            **common,
        )
    if fam.table == "iso355":
        return BoundaryDimensions(
            width=float(r["total_width_mm"]) * _MM,
            standard=f"{fam.standard} series {fam.key} ({TABLE_FILES[fam.table]})",
            cone_width=float(r["cone_width_mm"]) * _MM,
            cup_width=float(r["cup_width_mm"]) * _MM,
            **common,
        )
    height = float(r["height_mm"]) * _MM
    return BoundaryDimensions(
        width=height,
        height=height,
        standard=f"{fam.standard} series {fam.key} ({TABLE_FILES[fam.table]})",
        **common,
    )


# ------------------------------------------------------------------ radial internal clearance

#: Shipped ISO 5753-1 table of deep-groove ball bearings (bore in mm, clearance in um).
CLEARANCE_TABLE = "iso5753_radial_clearance.csv"
#: ISO 5753-1 radial internal clearance groups of deep-groove ball bearings, smallest first.
CLEARANCE_GROUPS = ("C2", "CN", "C3", "C4", "C5")
_GROUP_ALIASES = {"NORMAL": "CN", "N": "CN", "C0": "CN"}


def _clearance_group(group: Any) -> str:
    allowed = f"one of {', '.join(CLEARANCE_GROUPS)}"
    if not isinstance(group, str):
        raise InputError("group", group, allowed)
    key = "".join(group.split()).upper()
    key = _GROUP_ALIASES.get(key, key)
    if key not in CLEARANCE_GROUPS:
        raise InputError(
            "group",
            group,
            allowed,
            "the ISO 5753-1 groups of deep-groove ball bearings; 'Normal' and 'C0' are read as CN",
        )
    return key


def _clearance_band(bore: Any, group: Any = "CN") -> tuple[str, float, float, float, float]:
    """(group, bore over [mm], bore incl [mm], min [um], max [um]) of the ISO 5753-1 row."""
    key = _clearance_group(group)
    d_mm = round(positive_number("bore", bore, "a positive length [m]") / _MM, 6)
    rows = [r for r in _data.rows(CLEARANCE_TABLE) if r["group"] == key]
    hit = [r for r in rows if r["bore_over_mm"] < d_mm <= r["bore_incl_mm"]]
    if not hit:
        low = min(r["bore_over_mm"] for r in rows)
        high = max(r["bore_incl_mm"] for r in rows)
        hint = " (the bore is in metres: 25 mm is 0.025)" if d_mm >= 1000.0 else ""
        raise CatalogError(
            f"bore {d_mm:g} mm{hint} is outside the ISO 5753-1 table of "
            f"radial internal clearance group {key} of deep-groove ball bearings "
            f"({CLEARANCE_TABLE}): it covers bores over {low:g} incl {high:g} mm"
        )
    r = hit[0]
    return (
        key,
        float(r["bore_over_mm"]),
        float(r["bore_incl_mm"]),
        float(r["min_um"]),
        float(r["max_um"]),
    )


def radial_clearance(bore: float, group: str = "CN") -> tuple[float, float]:
    """Radial internal clearance range of a deep-groove ball bearing, ISO 5753-1 [m].

    The radial internal clearance of ISO 5753-1 is the total distance one ring can move
    radially relative to the other (unmounted, zero measuring load): the whole radial
    play, i.e. the diametral clearance P_d = d_o - d_i - 2 D_w of
    :class:`~bearinglab.geometry.BallBearing` (Harris & Kotzalas), not half of it.
    Values are those of the table for deep-groove ball bearings with cylindrical bore
    (``catalog/data/iso5753_radial_clearance.csv``), nominal bore over 2.5 incl 140 mm;
    groups C4 and C5 start above 6 mm, where ISO gives them.

    Parameters
    ----------
    bore : float
        Nominal bore diameter d [m]; the row is the one with over < d <= incl.
    group : str
        ``"C2"``, ``"CN"`` (normal; ``"Normal"`` and ``"C0"`` are read as CN), ``"C3"``,
        ``"C4"`` or ``"C5"``, case-insensitive [-].

    Returns
    -------
    tuple of float
        (smallest, largest) radial internal clearance of the group [m].

    Raises
    ------
    InputError
        For a group that is not one of these five, or a bore that is not a positive length.
    CatalogError
        For a bore outside the table of that group; the message gives the range covered.

    Examples
    --------
    >>> [round(x * 1e6, 6) for x in radial_clearance(0.025)]
    [5.0, 20.0]
    >>> [round(x * 1e6, 6) for x in radial_clearance(0.025, "C3")]
    [13.0, 28.0]
    """
    _, _, _, low, high = _clearance_band(bore, group)
    return low / 1e6, high / 1e6


# ------------------------------------------------------------------ published geometries


@dataclass(frozen=True)
class PublishedGeometry:
    """Internal geometry of one specific bearing as a source published it.

    ``None`` marks a value the source does not give.

    Parameters
    ----------
    name : str
        Catalogue name of the row, e.g. ``"6205 (CWRU drive end)"`` or ``"ER-16K"`` [-].
    designation : str
        ISO designation the row stands for (``""`` if none, e.g. an inch insert bearing) [-].
    ball_count : int or None
        Number of balls Z [-].
    ball_diameter : float or None
        Ball diameter D_w [m].
    pitch_diameter : float or None
        Pitch diameter d_m [m].
    inner_groove_factor, outer_groove_factor : float or None
        Groove curvature factors f_i, f_o [-].
    contact_angle : float or None
        Nominal contact angle [rad].
    diametral_clearance : float or None
        Diametral clearance P_d [m].
    bore, outside_diameter, width : float or None
        Boundary dimensions d, D, B as published for this bearing [m].
    source : str
        Document and table or page the values come from [-].
    default : bool
        True if the row answers a look-up by designation (family + bore) [-].
    notes : str
        How the values were read (unit conversions, choices) [-].
    """

    name: str
    designation: str
    ball_count: int | None
    ball_diameter: float | None
    pitch_diameter: float | None
    inner_groove_factor: float | None
    outer_groove_factor: float | None
    contact_angle: float | None
    diametral_clearance: float | None
    bore: float | None
    outside_diameter: float | None
    width: float | None
    source: str
    default: bool = True
    notes: str = ""

    #: Fields that describe the bearing (not its bookkeeping).
    GEOMETRY_FIELDS = (*INTERNAL_FIELDS, "bore", "outside_diameter", "width")

    def published(self) -> dict[str, Any]:
        """The published (non-None) geometry values, by BallBearing keyword, in SI units."""
        return {k: getattr(self, k) for k in self.GEOMETRY_FIELDS if getattr(self, k) is not None}


def _opt(value: Any, scale: float = 1.0) -> float | None:
    return None if value is None else float(value) * scale


def _row_to_geometry(r: dict) -> PublishedGeometry:
    angle = _opt(r["contact_angle_deg"])
    return PublishedGeometry(
        name=str(r["name"]),
        designation=str(r["designation"]),
        ball_count=None if r["ball_count"] is None else int(r["ball_count"]),
        ball_diameter=_opt(r["ball_diameter_mm"], _MM),
        pitch_diameter=_opt(r["pitch_diameter_mm"], _MM),
        inner_groove_factor=_opt(r["inner_groove_factor"]),
        outer_groove_factor=_opt(r["outer_groove_factor"]),
        contact_angle=None if angle is None else math.radians(angle),
        diametral_clearance=_opt(r["diametral_clearance_um"], 1e-6),
        bore=_opt(r["bore_mm"], _MM),
        outside_diameter=_opt(r["outside_diameter_mm"], _MM),
        width=_opt(r["width_mm"], _MM),
        source=str(r["source"]),
        default=bool(int(r["default"])),
        notes=str(r["notes"]),
    )


def published_geometries() -> list[PublishedGeometry]:
    """All shipped published geometries, in file order (SI units)."""
    return [_row_to_geometry(r) for r in _data.rows("internal_geometry.csv")]


def _norm(text: str) -> str:
    return " ".join(text.split()).casefold()


def _key(designation: Any) -> tuple[str | None, float] | None:
    series = getattr(designation, "series", None)
    bore = getattr(designation, "bore", None)
    if series is None or bore is None:
        return None
    return series, round(float(bore) / _MM, 6)


@lru_cache(maxsize=1)
def _row_keys() -> tuple[tuple[PublishedGeometry, tuple[str | None, float] | None], ...]:
    out = []
    for geo in published_geometries():
        key = None
        if geo.designation:
            try:
                key = _key(_parse(geo.designation, "iso"))
            except (DesignationError, ValueError):
                key = None
        out.append((geo, key))
    return tuple(out)


def published_geometry(
    name_or_designation: Any,
    system: str | None = None,
) -> PublishedGeometry | None:
    """The published internal geometry of a bearing, or None if none is shipped.

    First by catalogue name (case- and space-insensitive): ``"ER-16K"``,
    ``"6205 (seed 004)"``.  Otherwise the text is read as a designation and matched on
    its family and bore, ignoring closures and other suffixes: ``"6205-2RS"``, ``"6205"``
    and GOST ``"180205"`` all find ``"6205 (CWRU drive end)"``.  When several rows stand
    for one designation, the row marked ``default`` in ``internal_geometry.csv`` answers
    (the CWRU bearings for 6205 and 6203); the others (``"6205 (seed 004)"``,
    ``"106 (seed 000)"``) are found by name only.  If several default rows matched, the
    first in file order would win.

    Parameters
    ----------
    name_or_designation : str or Designation
        A catalogue name, a designation text or a parsed designation [-].
    system : str or None
        ``"gost"`` or ``"iso"`` for reading text as a designation [-].

    Examples
    --------
    >>> published_geometry("er-16k").ball_count
    9
    """
    if isinstance(name_or_designation, str):
        wanted = _norm(name_or_designation)
        for geo in published_geometries():
            if _norm(geo.name) == wanted:
                return geo
        try:
            des = _parse(name_or_designation, system)
        except (DesignationError, ValueError):
            return None
    else:
        des = name_or_designation
    key = _key(des)
    if key is None:
        return None
    for geo, row_key in _row_keys():
        if geo.default and row_key == key:
            return geo
    return None


def catalog_table(kind: str = "dimensions"):
    """The shipped catalogue data as one DataFrame, in the units of the files (mm, um, deg).

    Parameters
    ----------
    kind : str
        ``"dimensions"`` (all boundary-dimension rows of the three ISO tables, with a
        ``table`` column), ``"geometry"`` (published internal geometries) or
        ``"families"`` (family -> standard and table) [-].

    Examples
    --------
    >>> t = catalog_table()
    >>> row = t.query("table == 'iso15_radial.csv' and key == '02' and bore_mm == 25")
    >>> float(row["width_mm"].iloc[0])
    15.0
    """
    import pandas as pd

    if kind == "families":
        return families_table()
    if kind == "geometry":
        return _data.read_table("internal_geometry.csv")
    if kind != "dimensions":
        raise ValueError(f"kind must be 'dimensions', 'geometry' or 'families', got {kind!r}")
    parts = []
    for name, key_col in (
        ("iso15_radial.csv", "dimension_series"),
        ("iso355_tapered.csv", "series"),
        ("iso104_thrust.csv", "series"),
    ):
        frame = _data.read_table(name).rename(columns={key_col: "key"})
        if name == "iso355_tapered.csv":
            frame["width_mm"] = frame["total_width_mm"]
        if name == "iso104_thrust.csv":
            frame["width_mm"] = frame["height_mm"]
        frame.insert(0, "table", name)
        parts.append(frame)
    return pd.concat(parts, ignore_index=True)
