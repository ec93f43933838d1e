"""Assemble a :class:`~bearinglab.geometry.BallBearing` from a designation or catalogue name.

Order of precedence for every value: the caller's ``overrides`` (``Source("user", ...)``),
then the boundary dimensions of its ISO family (``Source("catalog", "ISO 15:2017 ...")``),
then the published geometry of that bearing if the catalogue has one
(``Source("catalog", <its source>)``), then the estimate of
:mod:`bearinglab.catalog.estimate` (``Source("estimated", <method>)``).  A value nobody
gives keeps the :class:`~bearinglab.geometry.BallBearing` default, marked
``Source("default", ...)``.

The diametral clearance of a single-row deep-groove ball bearing that neither the caller
nor the published row gives is the middle of its ISO 5753-1 radial internal clearance
group (:func:`~bearinglab.catalog.lookup.radial_clearance`; ISO's radial internal
clearance is the whole radial play, P_d): the group written in the designation (suffix
C2, CN, C3, C4, C5, or P62/P63/P52/P53), CN when none is written, marked
``Source("estimated", "ISO 5753-1 group CN: mean of 5-20 um (...)")``.  GOST designations
carry a clearance-group sign in the prefix (``А125-205``: group 2); its correspondence to
the ISO groups is not verified here, so they get CN and the source says so.
Angular-contact bearings keep the clearance BallBearing derives from the contact angle.

Contact angle: the designation's (ISO suffix A, B, C, AC...; GOST design variant 36xxx,
46xxx, 66xxx), else the ISO family default (72/73/70/718/719: 40 deg, the SKF/FAG "B"
execution; QJ: 35 deg), 90 deg for thrust ball bearings, 0 for deep-groove bearings.  A
GOST angular contact bearing without a contact-angle variant (e.g. 6205 or 7206 read as
GOST) gets no default: the ISO family's 40 deg is not a GOST design, so the caller must
give the angle.  Thrust ball bearings (ISO 511-514, GOST type 8) are built only from
explicit ball_count, ball_diameter and pitch_diameter, with the catalogue's boundary
dimensions (d, D and the height T as ``width``) and assumed groove factors.
"""

from __future__ import annotations

import math
import re
from typing import Any

from ..errors import CatalogError, InputError
from ..geometry import BallBearing, Source
from .build_roller import (
    ROLLER_BUILD_TYPES,
    ROLLER_OVERRIDABLE,
    published_roller,
    roller_by_name,
    roller_from_designation,
)
from .estimate import (
    BALL_TYPES,
    ESTIMATE_METHOD,
    INNER_GROOVE_FACTOR,
    OUTER_GROOVE_FACTOR,
    estimate_internal_geometry,
)
from .families import FAMILIES
from .lookup import (
    CLEARANCE_TABLE,
    BoundaryDimensions,
    PublishedGeometry,
    _clearance_band,
    _norm,
    _parse,
    boundary_dimensions,
    published_geometries,
    published_geometry,
)
from .needed import GeometryNeeded

#: Keywords of BallBearing a caller may override.
OVERRIDABLE = (
    *PublishedGeometry.GEOMETRY_FIELDS,
    "ring_material",
    "ball_material",
    "name",
    "inner_arch_angle",
    "outer_arch_angle",
)
USER_SOURCE = Source("user", "command line or caller")
_INTERNAL = (
    "ball_count",
    "ball_diameter",
    "pitch_diameter",
    "inner_groove_factor",
    "outer_groove_factor",
)


#: What a thrust ball bearing needs from the caller: the catalogue estimates no thrust
#: geometry, so the balls and pitch circle must be given.
THRUST_NEEDS = ("ball_count", "ball_diameter", "pitch_diameter")


def _check_type(des: Any, overrides: dict) -> None:
    btype = getattr(des, "bearing_type", None)
    text = getattr(des, "text", "?")
    if btype in BALL_TYPES:
        series = getattr(des, "series", None)
        fam = FAMILIES.get(series)
        if fam is not None and fam.rows != 1:
            raise CatalogError(
                f"{text!r} is a {fam.rows}-row bearing (family {series}): only "
                "single-row ball bearings have an internal-geometry model yet"
            )
        return
    if btype == "thrust_ball":
        if any("double-direction" in meaning for _, meaning in getattr(des, "parts", ())):
            raise CatalogError(
                f"{text!r} is a double-direction thrust ball bearing: only "
                "single-direction (one row) thrust ball bearings have an "
                "internal-geometry model"
            )
        missing = tuple(k for k in THRUST_NEEDS if k not in overrides)
        if missing:
            raise GeometryNeeded(
                f"{text!r} is a thrust ball bearing: no internal-geometry "
                "model estimates its balls and pitch circle",
                missing,
            )
        return
    if btype == "self_aligning_ball":
        raise CatalogError(
            f"{text!r} is a self-aligning (double-row) ball bearing: only "
            "single-row radial, angular-contact and four-point ball bearings, and "
            "thrust ball bearings with explicit geometry, have an "
            "internal-geometry model yet"
        )
    raise CatalogError(
        f"{text!r} is a {str(btype).replace('_', ' ')} bearing: only ball "
        "bearings have an internal-geometry model yet"
    )


def _by_name(text: str) -> PublishedGeometry | None:
    wanted = _norm(text)
    for geo in published_geometries():
        if _norm(geo.name) == wanted:
            return geo
    return None


def _contact_angle_default(des: Any) -> tuple[float | None, Source | None]:
    if des is None:
        return None, None
    if getattr(des, "contact_angle", None) is not None:
        return float(des.contact_angle), Source("catalog", f"designation {des.text!r}")
    btype = getattr(des, "bearing_type", None)
    if btype == "thrust_ball":
        return math.pi / 2, Source("default", "thrust ball bearing: nominal contact angle 90 deg")
    if btype == "angular_contact_ball" and getattr(des, "system", None) == "gost":
        # GOST writes the angle as the design variant (36xxx 12, 46xxx 26, 66xxx 36 deg);
        # without one the ISO family defaults (SKF/FAG 40 deg) would be a guess.
        return None, None
    fam = FAMILIES.get(getattr(des, "series", None))
    if fam is not None and fam.default_contact_angle is not None:
        return fam.default_contact_angle, Source(
            "default", f"family {fam.key} default {math.degrees(fam.default_contact_angle):g} deg"
        )
    if getattr(des, "bearing_type", None) == "radial_ball":
        return 0.0, Source("default", "deep-groove ball bearing: nominal contact angle 0")
    return None, None


#: ISO suffixes that name a radial internal clearance group (SKF combined codes P62...).
_CLEARANCE_SUFFIX = re.compile(r"C[0-5]|CN")
_COMBINED_CLEARANCE = {"P62": "C2", "P63": "C3", "P52": "C2", "P53": "C3"}


def _clearance_group_of(des: Any) -> tuple[str, str, str | None]:
    """(ISO 5753-1 group, where it comes from, the code written or None) of a designation."""
    if getattr(des, "system", None) == "gost":
        signs = [
            code
            for code, meaning in getattr(des, "prefixes", ())
            if meaning.startswith("radial clearance group")
        ]
        if signs:
            return (
                "CN",
                (
                    f"GOST clearance group {signs[-1]} in the prefix not mapped to an "
                    "ISO 5753-1 group (correspondence not verified): CN assumed"
                ),
                None,
            )
        return "CN", "no clearance group in the designation: CN (normal) assumed", None
    written = [
        (code, _COMBINED_CLEARANCE.get(code, code))
        for code, _ in getattr(des, "suffixes", ())
        if code in _COMBINED_CLEARANCE or _CLEARANCE_SUFFIX.fullmatch(code)
    ]
    if not written:
        return "CN", "no clearance group in the designation: CN (normal) assumed", None
    code, group = written[-1]
    where = f"group from the designation suffix {code}"
    if len({g for _, g in written}) > 1:
        where += f" (the last of {', '.join(c for c, _ in written)})"
    return group, where, code


def _table_clearance(des: Any, text: str) -> tuple[float | None, Source]:
    """Mean ISO 5753-1 clearance of a deep-groove bearing's group, or None and why not.

    The row is chosen by the designation's nominal bore (a published row's measured or
    inch-converted bore could fall across a band edge).  A group written in the
    designation that the table cannot give is an error; the implied CN outside the table
    leaves the BallBearing default.
    """
    group, where, code = _clearance_group_of(des)
    try:
        key, over, incl, low, high = _clearance_band(float(des.bore), group)
    except (CatalogError, InputError) as exc:
        if code is not None:
            raise CatalogError(
                f"{text!r}: radial internal clearance {code}: {exc}; give "
                "diametral_clearance as an override"
            ) from exc
        return None, Source(
            "default",
            f"not published, and no ISO 5753-1 value ({exc}): "
            "BallBearing derives it from the contact angle (zero "
            "for a radial bearing)",
        )
    bore_mm = round(float(des.bore) * 1e3, 6)
    return (low + high) / 2e6, Source(
        "estimated",
        f"ISO 5753-1 group {key}: mean of {low:g}-{high:g} um (deep-groove ball "
        f"bearing, bore {bore_mm:g} mm over {over:g} incl {incl:g} mm; {where}; "
        f"{CLEARANCE_TABLE})",
    )


def rolling_element_of(text: str, system: str | None = None) -> str:
    """Whether the bearing ``text`` names (a catalogue name or a designation, read as
    :func:`bearing_from_designation` reads it with ``rollers=True``) has balls or rollers:
    "ball" or "roller". A designation that does not read raises the reader's error;
    ``system`` ("iso", "gost" or None to guess) is the designation system to read it in.

    Parameters
    ----------
    text : str
        A catalogue name or a designation (e.g. ``NU205``, ``6205``, ``7205``).
    system : str or None
        ``"iso"`` or ``"gost"`` to read a designation in that system; None guesses.

    Examples
    --------
    >>> rolling_element_of("NU205"), rolling_element_of("6205"), rolling_element_of("7205", "gost")
    ('roller', 'ball', 'roller')
    """
    if roller_by_name(text) is not None:
        return "roller"
    if _by_name(text) is not None:
        return "ball"
    des = _parse(text, system)
    return "roller" if getattr(des, "bearing_type", None) in ROLLER_BUILD_TYPES else "ball"


def bearing_from_designation(
    text: str,
    system: str | None = None,
    overrides: dict | None = None,
    *,
    rollers: bool = False,
) -> tuple[BallBearing, Any]:
    """Build a BallBearing (or a RollerBearing) from a designation (ISO or GOST) or a
    catalogue name.

    With ``rollers=True``, cylindrical and tapered roller bearings (NU205, NJ205, NUP205,
    N205, NN3020, 30205, 32205; GOST 2205, 42205, 92205, 7205, 7505 ...) and the published
    roller rows (``"209 cylindrical (Harris)"``, ``"ZA-2115 (IMS)"``) give a
    :class:`~bearinglab.roller_geometry.RollerBearing`
    (:func:`bearinglab.catalog.build_roller.roller_from_designation`), whose overrides are
    RollerBearing keywords. Without it they are refused as before (a CatalogError), which
    the command line relies on until it is wired for roller bearings (issue 28).

    ``text`` may be a catalogue name of a published bearing (``"ER-16K"``,
    ``"6205 (seed 004)"``) or a designation (``"6205-2RS"``, ``"180205"``).  Internal
    geometry comes from the published row if there is one, missing values from the
    estimate; boundary dimensions from the published row or the ISO tables.  A
    single-row deep-groove bearing (``bearing_type`` ``"radial_ball"``) whose clearance
    neither the overrides nor the published row give gets the mean of its ISO 5753-1
    radial internal clearance group -- the radial internal clearance of ISO 5753-1 is the
    total radial play, i.e. the diametral clearance P_d -- taken from the designation
    (``"6205 C3"``, ``"6205-2RS/C4"``), CN if none is written (and for GOST
    designations, whose clearance-group sign is not mapped); this holds also when an
    override gives only the contact angle.  Angular-contact bearings keep the clearance
    BallBearing derives from their contact angle.  The ``sources`` dict of the result says
    where every value came from.

    Parameters
    ----------
    text : str
        Catalogue name or designation [-].
    system : str or None
        ``"gost"`` or ``"iso"``; None lets the designation reader decide [-].
    overrides : dict or None
        BallBearing (or RollerBearing) keyword -> value in SI units (m, rad), taking
        precedence over the catalogue and the estimate [-].
    rollers : bool
        Build roller bearings too (see above) [-].

    Returns
    -------
    tuple
        (BallBearing, the parsed Designation or None for a name with no designation) [-].

    Raises
    ------
    CatalogError
        For roller bearings without ``rollers`` (and with it, for spherical, needle and
        thrust roller bearings), self-aligning or double-row ball bearings (no
        internal-geometry model yet), or when the designation names a clearance group the
        ISO 5753-1 table has no
        value for at that bore (C1; C4 or C5 below 6 mm; bores over 140 mm).
    GeometryNeeded
        (a CatalogError) When neither the catalogue nor the overrides give enough to
        build the bearing: a thrust ball bearing without ball_count, ball_diameter and
        pitch_diameter overrides; a GOST angular contact bearing without a contact-angle
        design variant (6205, 7206 read as GOST) and no contact_angle override; a size the
        estimate cannot reach.  ``needed`` names the overrides to give.
    InputError
        For an unknown override keyword or values the BallBearing refuses.
    """
    overrides = dict(overrides or {})
    for key in overrides:
        if key not in OVERRIDABLE and key not in ROLLER_OVERRIDABLE:
            raise InputError(
                "overrides",
                key,
                f"one of {', '.join(OVERRIDABLE)} (ball bearings) or "
                f"{', '.join(ROLLER_OVERRIDABLE)} (roller bearings)",
            )
    roller_row = roller_by_name(text) if rollers else None
    if roller_row is not None:
        des = _parse(roller_row.designation, "iso") if roller_row.designation else None
        return roller_from_designation(text, des, roller_row, overrides)
    named = _by_name(text)
    row = named
    des = None
    if named is not None:
        if named.designation:
            des = _parse(named.designation, "iso")
    else:
        des = _parse(text, system)
        if rollers and getattr(des, "bearing_type", None) in ROLLER_BUILD_TYPES:
            return roller_from_designation(text, des, published_roller(des), overrides)
        _check_type(des, overrides)
        row = published_geometry(des)
    for key in overrides:
        if key not in OVERRIDABLE:
            raise InputError(
                key,
                overrides[key],
                "an input of a ball bearing (" + ", ".join(OVERRIDABLE) + ")",
                "the designation is a ball bearing",
            )

    values: dict[str, Any] = {}
    sources: dict[str, Source] = {}

    def put(name: str, value: Any, source: Source) -> None:
        if name not in values and value is not None:
            values[name] = value
            sources[name] = source

    for name, value in overrides.items():
        put(name, value, USER_SOURCE)

    dims: BoundaryDimensions | None = None
    dims_error: CatalogError | None = None
    if des is not None:
        try:
            dims = boundary_dimensions(des)
        except CatalogError as exc:
            dims_error = exc
    if dims is not None:  # the standard's exact sizes before a row's rounded (inch) ones
        dim_source = Source("catalog", dims.standard)
        put("bore", dims.bore, dim_source)
        put("outside_diameter", dims.outside_diameter, dim_source)
        put("width", dims.width, dim_source)
    if row is not None:
        for name, value in row.published().items():
            put(name, value, Source("catalog", row.source))

    angle, angle_source = _contact_angle_default(des)
    if angle is not None and angle_source is not None:
        put("contact_angle", angle, angle_source)
    if (
        "contact_angle" not in values
        and getattr(des, "system", None) == "gost"
        and getattr(des, "bearing_type", None) == "angular_contact_ball"
    ):
        raise GeometryNeeded(
            f"{text!r} read as GOST 3189-89 is an angular contact ball bearing "
            "without a contact-angle design variant (36xxx = 12, 46xxx = 26, "
            "66xxx = 36 deg), so its contact angle is not known",
            ("contact_angle",),
        )

    clearance_default = Source(
        "default",
        "not published: BallBearing derives it from the contact angle (zero for a radial bearing)",
    )
    if (
        "diametral_clearance" not in values
        and des is not None
        and getattr(des, "bearing_type", None) == "radial_ball"
        and getattr(FAMILIES.get(getattr(des, "series", None)), "rows", 1) == 1
    ):
        clearance, clearance_source = _table_clearance(des, text)
        if clearance is not None:
            put("diametral_clearance", clearance, clearance_source)
        else:
            clearance_default = clearance_source

    missing = [k for k in _INTERNAL if k not in values]
    if missing and any(k in missing for k in ("ball_count", "ball_diameter", "pitch_diameter")):
        if dims is None or "bore" not in values or "outside_diameter" not in values:
            reason = (
                str(dims_error)
                if dims_error is not None
                else "no ISO family and bore to estimate from"
            )
            raise GeometryNeeded(
                f"{text!r}: cannot estimate the internal geometry ({reason})",
                tuple(k for k in missing if k in THRUST_NEEDS),
            )
        btype = getattr(des, "bearing_type", "radial_ball")
        est = estimate_internal_geometry(
            values["bore"],
            values["outside_diameter"],
            dims.dimension_series or "",
            btype,
            values.get("contact_angle"),
        )
        for name, value in est.as_kwargs().items():
            put(name, value, Source("estimated", ESTIMATE_METHOD))
    if getattr(des, "bearing_type", None) == "thrust_ball":
        assumed = Source(
            "default",
            f"deep-groove values f_i = {INNER_GROOVE_FACTOR}, "
            f"f_o = {OUTER_GROOVE_FACTOR} assumed for a thrust ball "
            "bearing (not estimated)",
        )
        put("inner_groove_factor", INNER_GROOVE_FACTOR, assumed)
        put("outer_groove_factor", OUTER_GROOVE_FACTOR, assumed)
    put("inner_groove_factor", INNER_GROOVE_FACTOR, Source("estimated", ESTIMATE_METHOD))
    put("outer_groove_factor", OUTER_GROOVE_FACTOR, Source("estimated", ESTIMATE_METHOD))
    if "contact_angle" not in values:
        sources["contact_angle"] = Source("default", "nominal contact angle 0")
    if "diametral_clearance" not in values:
        sources["diametral_clearance"] = clearance_default
    for name in ("ring_material", "ball_material"):
        if name not in values:
            sources[name] = Source("default", "AISI 52100 bearing steel")
    name = values.pop("name", None) or (
        named.name if named is not None else getattr(des, "text", text)
    )
    btype = getattr(des, "bearing_type", None) or "radial_ball"
    if btype == "four_point_contact_ball":
        _four_point_grooves(values, sources)
    bearing = BallBearing(**values, name=name, bearing_type=btype, sources=sources)
    return bearing, des


def _four_point_grooves(values: dict, sources: dict) -> None:
    """Gothic-arch grooves of a four-point bearing (QJ, GOST 176000): both rings get the
    arch angle alpha_T that gives the nominal contact angle alpha_0 with the clearance,
    cos(alpha_T) = cos(alpha_0) + P_d / (2 A) (seed 001 eq. 2 with g = P_d, A = (f_i + f_o
    - 1) D_w); without a clearance the bearing is taken to touch at all four points
    (P_d = 0, alpha_T = alpha_0), an estimate."""
    alpha = values.get("contact_angle")
    if alpha is None or "inner_arch_angle" in values:
        return
    if "diametral_clearance" not in values:
        values["diametral_clearance"] = 0.0
        sources["diametral_clearance"] = Source(
            "estimated", "four-point bearing taken to touch at all four points (P_d = 0)"
        )
    a = (values["inner_groove_factor"] + values["outer_groove_factor"] - 1.0) * values[
        "ball_diameter"
    ]
    arch = math.acos(
        max(-1.0, min(1.0, math.cos(alpha) + values["diametral_clearance"] / (2.0 * a)))
    )
    source = Source(
        "estimated",
        "gothic arch giving the nominal contact angle with the clearance (seed 001 eq. 2)",
    )
    for name in ("inner_arch_angle", "outer_arch_angle"):
        values[name] = arch
        sources[name] = source
