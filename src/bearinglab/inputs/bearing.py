"""The bearing of a request: a designation and/or explicit geometry (the inputs of
:data:`~bearinglab.inputs.table.BEARING`, in their units, or a ``geometry`` TOML file) as a
:class:`~bearinglab.geometry.BallBearing` (SI inside). The model's errors come back in the
user's terms: the input they gave (or, for a check between two values, the one of them
they gave), with its value in its unit."""

from __future__ import annotations

import math
import tomllib
from dataclasses import replace
from pathlib import Path

from ..errors import CatalogError, InputError
from .table import BALL_ONLY, BEARING, GEOMETRY_NEEDED, INPUTS, ROLLER_NEEDED, ROLLER_ONLY

#: The geometry inputs that set a BallBearing field (its name: the input's ``sets``; the
#: conversion: the input's unit), in the table's order.
_GEOMETRY = tuple(
    name
    for name in BEARING
    if INPUTS[name].fields and not str(INPUTS[name].sets).startswith("Material.")
)
#: Checks that involve other values: if the user did not give the value a check names,
#: the error names the first of these the user did give.
_PARTNERS = {
    "pitch_diameter": ("ball_diameter", "bore", "outside_diameter"),
    "ball_count": ("ball_diameter", "pitch_diameter"),
    "ball_diameter": ("pitch_diameter", "bore", "outside_diameter", "diametral_clearance"),
    "bore": ("outside_diameter",),
    "diametral_clearance": (
        "inner_groove_factor",
        "outer_groove_factor",
        "ball_diameter",
        "contact_angle",
    ),
    "width": (
        "ball_diameter",
        "outer_groove_factor",
        "inner_groove_factor",
        "pitch_diameter",
        "outside_diameter",
        "diametral_clearance",
    ),
}


def _field(name: str) -> str:
    """The model field input ``name`` sets (BallBearing's or Material's)."""
    return INPUTS[name].fields[0]


def _symbol(name: str) -> str:
    from ..units import unit_of

    unit = unit_of(name)
    return unit.symbol if unit is not None else ""


def _si(name: str, value: float) -> float:
    """A value of input ``name`` in SI (its unit's factor)."""
    from ..units import unit_of

    unit = unit_of(name)
    return value if unit is None else unit.to_si(value)


class _Given:
    """What the user gave: values in their units (inputs and the geometry file), the name
    each came under, and the BallBearing overrides in SI."""

    def __init__(self, values: dict) -> None:
        self.values: dict = {}
        self.origins: dict[str, str] = {}
        path = values.get("geometry")
        if path is not None:
            for key, (written, value) in read_geometry_file(path).items():
                self.values[key] = value
                self.origins[key] = f"geometry {written}"
        for name in BEARING:
            value = values.get(name)
            if value is not None and name not in ("geometry", "designation"):
                self.values[name] = getattr(value, "value", value)  # an Enum's value
                self.origins[name] = name
        for name, value in self.values.items():
            if name != "name":
                INPUTS[name].check(self.origin(name), value)
        self.system = self.values.get("system")
        self.overrides = self._overrides()

    def origin(self, name: str) -> str:
        return self.origins.get(name, name)

    def _overrides(self) -> dict:
        overrides: dict = {}
        for name in _GEOMETRY:
            value = self.values.get(name)
            if value is None:
                continue
            keyword, kind = _field(name), INPUTS[name].kind
            if name == "roller_profile":
                overrides[keyword] = parse_profile(value)
            elif kind == "text":
                overrides[keyword] = value
            elif kind == "integer":
                overrides[keyword] = int(value)
            else:
                overrides[keyword] = _si(name, value)
        material = _material(self.values)
        if material is not None:  # the rolling elements' key is set once the kind is known
            overrides["ring_material"] = overrides["element_material"] = material
        if isinstance(self.values.get("name"), str):
            overrides["name"] = self.values["name"]
        return overrides

    def remap(self, exc: InputError) -> InputError:
        """The model's error in the user's terms: the input they gave (or, for a check
        between two values, the one of them they gave) with its value in its unit."""
        from .values import input_for, restate

        name = input_for(exc.parameter, INPUTS)
        if name is None or name not in BEARING:
            return exc
        if name in self.values:
            return restate(exc, self.values, INPUTS).restated(
                self.origin(name),
                self.values[name],
                names=lambda p: f"`{p}`",
            )
        for partner in _PARTNERS.get(exc.parameter, ()):
            other = input_for(partner, INPUTS)
            if other not in self.values:
                continue
            own = restate(exc, {}, INPUTS)  # the model's value in the input's unit
            unit = _symbol(name)
            shown = f"{own.value:.6g}" if isinstance(own.value, (int, float)) else repr(own.value)
            shown += f" {unit}" if unit else ""
            label = exc.parameter.replace("_", " ")
            given = self.origin(other), self.values[other]
            if exc.parameter == "pitch_diameter" and partner == "ball_diameter":
                if exc.template[0].startswith("more than the ball diameter"):
                    return InputError(
                        *given,
                        f"less than the pitch diameter {shown} (not given: a catalogue or "
                        "derived value)",
                    )
            if exc.parameter == "bore" and partner == "outside_diameter":
                return InputError(
                    *given,
                    f"more than the bore {shown} (not given: a catalogue or derived value)",
                )
            return InputError(
                *given,
                f"a value with which the {label} {shown} (not given: a catalogue or derived "
                f"value) passes its check: {own.allowed}",
                own.hint,
            )
        return exc


def read_geometry_file(path) -> dict:
    """Read the geometry TOML file at ``path``: input name -> (key as written, checked
    value).

    Parameters
    ----------
    path : str or os.PathLike
        The TOML file (UTF-8): keys are geometry input names (``ball_diameter_mm``, ...;
        also ``ball_count`` for ``balls``, ``diametral_clearance_um`` for ``clearance_um``),
        ``name`` and ``system`` ('gost' or 'iso').

    Returns
    -------
    dict
        Input name -> (key as written, value): numbers as float (finite), ``balls`` as int,
        ``system`` in lower case, in the units of the input names (no conversion).
    """
    name = "geometry"
    try:
        text = Path(path).read_bytes().decode("utf-8")
        data = tomllib.loads(text)
    except FileNotFoundError:
        raise InputError(name, str(path), "an existing TOML file") from None
    except IsADirectoryError:
        raise InputError(name, str(path), "a TOML file, not a directory") from None
    except PermissionError:
        raise InputError(name, str(path), "a readable TOML file", "permission denied") from None
    except OSError as exc:
        raise InputError(
            name, str(path), "a readable TOML file", exc.strerror or type(exc).__name__
        ) from None
    except UnicodeDecodeError as exc:
        raise InputError(
            name, str(path), "a UTF-8 encoded TOML file", f"byte {exc.start} is not UTF-8"
        ) from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError(name, str(path), "a valid TOML file", str(exc)) from None
    aliases = {"ball_count": "balls", "diametral_clearance_um": "clearance_um"}
    known = sorted([k for k in BEARING if k not in ("geometry", "designation")] + ["name"])
    out: dict = {}
    for written, value in data.items():
        key = aliases.get(written, written)
        where = f"geometry {written}"
        if key not in known:
            raise InputError(f"geometry key {written!r}", value, f"one of {known}")
        if key in out:
            raise InputError(
                f"geometry key {written!r}",
                value,
                f"each value once ({out[key][0]!r} gives it too)",
            )
        if key == "name":
            if not isinstance(value, str):
                raise InputError(where, value, "a text label (TOML string)")
        elif key == "system":
            if not (isinstance(value, str) and value.lower() in ("gost", "iso")):
                raise InputError(where, value, "'gost' or 'iso'")
            value = value.lower()
        elif key == "balls":
            if type(value) is not int:
                raise InputError(where, value, "an integer number of balls (e.g. balls = 9)")
        elif isinstance(value, bool) or not isinstance(value, (int, float)):
            unit = _symbol(key)
            raise InputError(
                where, value, f"a number{' in ' + unit if unit else ''} (TOML integer or float)"
            )
        elif not math.isfinite(value):
            raise InputError(where, value, "a finite number")
        else:
            value = float(value)
        out[key] = (written, value)
    return out


def _catalog_message(exc) -> str:
    """A catalogue error in the user's terms: the inputs to give instead of keywords."""
    from .values import input_for

    names = [f"`{input_for(k, INPUTS)}`" for k in exc.needed if input_for(k, INPUTS) in BEARING]
    if not names:
        return str(exc)
    listed = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
    return f"{exc.reason}; give {listed}"


def _material(values: dict):
    e, nu, rho = (values.get(n) for n in ("elastic_modulus_gpa", "poisson_ratio", "density_kg_m3"))
    if e is None and nu is None and rho is None:
        return None
    from ..materials import BEARING_STEEL

    base = BEARING_STEEL
    return replace(
        base,
        name="user material",
        elastic_modulus=base.elastic_modulus if e is None else float(e) * 1e9,
        poisson_ratio=base.poisson_ratio if nu is None else float(nu),
        density=base.density if rho is None else float(rho),
    )


def bearing_from(values: dict):
    """(BallBearing or RollerBearing, Designation or None) from a request's ``values``
    (name -> value in its unit): a ``designation`` and/or the explicit geometry and material, or a
    ``geometry`` TOML file. Errors name the input given, with its value in its unit.

    Parameters
    ----------
    values : dict
        The request: input name -> value in the input's unit (``designation``, ``system``,
        ``geometry``, ``balls``, ``ball_diameter_mm``, ...; None: not given).

    Returns
    -------
    bearing : BallBearing or RollerBearing
        In SI.
    decoded : Designation or None
        The designation as read, None for an explicit geometry.
    """
    from ..catalog import GeometryNeeded, bearing_from_designation
    from ..geometry import BallBearing, Source

    designation = values.get("designation")
    if designation is not None and not str(designation).strip():
        raise InputError(
            "designation",
            designation,
            "a bearing designation (e.g. 6205-2RS, 180205) or catalogue name, or "
            "no designation and explicit geometry",
        )
    given = _Given(values)
    overrides = given.overrides
    try:
        kind = _kind(given, designation)
        if "element_material" in overrides:
            element = "roller_material" if kind == "roller" else "ball_material"
            overrides[element] = overrides.pop("element_material")
        if designation:
            return bearing_from_designation(
                designation, system=given.system, overrides=overrides, rollers=True
            )
        needed = ROLLER_NEEDED if kind == "roller" else GEOMETRY_NEEDED
        missing = [n for n in needed if _field(n) not in overrides]
        if missing:
            raise InputError(
                "designation",
                None,
                "a designation, or explicit geometry with " + ", ".join(f"`{n}`" for n in missing),
            )
        kwargs = dict(overrides)
        name = kwargs.pop("name", "user geometry")
        sources = {k: Source("user", "request") for k in kwargs}
        if kind == "roller":
            from ..roller_geometry import RollerBearing

            return RollerBearing(name=name, sources=sources, **kwargs), None
        return BallBearing(name=name, sources=sources, **kwargs), None
    except InputError as exc:
        raise given.remap(exc) from None
    except GeometryNeeded as exc:
        raise CatalogError(_catalog_message(exc)) from None


def _kind(given: _Given, designation) -> str:
    """ "ball" or "roller": the designation's (catalogue name or designation), else the
    kind the explicit geometry describes; inputs of the other kind are refused, naming the
    first of them."""
    from ..catalog import rolling_element_of

    balls = [n for n in BALL_ONLY if n in given.values]
    rollers = [n for n in ROLLER_ONLY if n in given.values]
    if designation:
        kind = rolling_element_of(str(designation), given.system)
    else:
        kind = "roller" if rollers else "ball"
    wrong = balls if kind == "roller" else rollers
    if wrong:
        name = wrong[0]
        what = (
            f"{designation} is a {kind} bearing"
            if designation
            else (f"`{(rollers if kind == 'roller' else balls)[0]}` describes a {kind} bearing")
        )
        raise InputError(
            given.origin(name),
            given.values[name],
            f"no value: it is an input of a {'ball' if kind == 'roller' else 'roller'} bearing",
            what,
        )
    return kind


def balls_only(bearing, values: dict, why: str) -> None:
    """Refuse the roller ``bearing`` for a model of ball bearings only (``why``: whose model
    it is), naming the input in ``values`` (the request) that made it a roller bearing.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing built from the request; nothing happens unless it has rollers.
    values : dict
        The request (input name -> value in its unit), to name the input that made it a
        roller bearing (``designation`` if given, else ``rollers``).
    why : str
        Whose model takes ball bearings only, for the error (e.g. "the slip model").
    """
    if bearing.rolling_element != "roller":
        return
    name = "designation" if values.get("designation") else "rollers"
    raise InputError(name, values.get(name), f"a ball bearing: {why}")


def parse_profile(text):
    """A `roller_profile` text as a RollerProfile: flat, logarithmic,
    crowned:crown_radius_mm=R[,flat_length_mm=F] or user:positions_mm=A/B/C,drops_um=A/B/C.

    >>> parse_profile("crowned:crown_radius_mm=500").crown_radius
    0.5
    """
    from ..roller_geometry import PROFILE_KINDS, RollerProfile

    if not isinstance(text, str):
        return text
    kind, _, rest = text.strip().partition(":")
    kind = kind.strip().lower()
    allowed = (
        "flat, logarithmic, crowned:crown_radius_mm=R[,flat_length_mm=F] or "
        "user:positions_mm=A/B/C,drops_um=A/B/C"
    )
    if kind not in PROFILE_KINDS:
        raise InputError("roller_profile", text, allowed)
    keys: dict = {}
    for item in filter(None, (p.strip() for p in rest.split(","))):
        key, eq, value = item.partition("=")
        try:
            numbers = [float(v) for v in value.split("/")]
        except ValueError:
            numbers = []
        if not eq or not numbers or key.strip() in keys:
            raise InputError("roller_profile", text, allowed)
        keys[key.strip()] = numbers
    scales = {"crown_radius_mm": 1e-3, "flat_length_mm": 1e-3}
    wanted = {
        "flat": (),
        "logarithmic": (),
        "crowned": ("crown_radius_mm", "flat_length_mm"),
        "user": ("positions_mm", "drops_um"),
    }[kind]
    for key in keys:
        if key not in wanted:
            raise InputError("roller_profile", text, allowed, f"{key} is not a key of {kind}")
    if kind == "crowned":
        if "crown_radius_mm" not in keys:
            raise InputError("roller_profile", text, allowed, "crowned needs crown_radius_mm")
        flat = keys.get("flat_length_mm", [0.0])[0] * scales["flat_length_mm"]
        return RollerProfile(
            "crowned", crown_radius=keys["crown_radius_mm"][0] * 1e-3, flat_length=flat
        )
    if kind == "user":
        if set(keys) != {"positions_mm", "drops_um"}:
            raise InputError("roller_profile", text, allowed, "user needs positions and drops")
        return RollerProfile(
            "user",
            positions=tuple(v * 1e-3 for v in keys["positions_mm"]),
            drops=tuple(v * 1e-6 for v in keys["drops_um"]),
        )
    return RollerProfile(kind)


def bearing_warnings(bearing, decoded=None) -> list[str]:
    """Caveats about the ``bearing`` used: a designation (``decoded``, the Designation
    read, or None) that also reads in the other system
    (GOST 3189-89 / ISO: the reading used is said), an estimated ball count of an
    angular-contact bearing (a lower bound), balls of a thrust bearing reaching past its
    outside diameter.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing used.
    decoded : Designation or None
        The designation it was read from, None for an explicit geometry.

    Returns
    -------
    list of str
        The caveats, one sentence each (empty when there is none).
    """
    out = []
    if decoded is not None:
        out += [n for n in decoded.notes if n.startswith("also reads as")]
    src = bearing.sources.get("ball_count")
    if (
        src is not None
        and src.kind == "estimated"
        and bearing.bearing_type in ("angular_contact_ball", "four_point_contact_ball")
    ):
        out.append(
            f"ball count Z = {bearing.ball_count} is estimated with the Conrad "
            "filling-angle rule: for an angular-contact bearing that is a lower bound "
            "(they carry more balls); give `balls`"
        )
    big_d = bearing.outside_diameter
    if bearing.rolling_element == "ball" and bearing.is_thrust and big_d is not None:
        reach = bearing.pitch_diameter + bearing.ball_diameter
        if reach > big_d:
            out.append(
                f"the balls reach to a diameter of {reach * 1e3:.4g} mm, beyond the "
                f"outside diameter {big_d * 1e3:.4g} mm: check `pitch_diameter_mm` and "
                "`ball_diameter_mm`"
            )
    return out


def geometry_line(bearing, contact_angle: float | None = None) -> str:
    """One line: where the geometry of ``bearing`` comes from and its main values (the
    ``contact_angle`` given [rad], else the nominal one).

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing shown.
    contact_angle : float or None
        The contact angle to show [rad] (e.g. the operating one); None: the bearing's
        nominal contact angle.
    """
    alpha = bearing.contact_angle if contact_angle is None else contact_angle
    if bearing.rolling_element == "roller":
        size = (
            f"D_we = {bearing.roller_diameter * 1e3:.4g} mm, "
            f"L_we = {bearing.roller_length * 1e3:.4g} mm"
        )
    else:
        size = f"D_w = {bearing.ball_diameter * 1e3:.4g} mm"
    return (
        f"geometry ({bearing.geometry_source}): Z = {bearing.element_count}, {size}, "
        f"d_m = {bearing.pitch_diameter * 1e3:.4g} mm, contact angle "
        f"{math.degrees(alpha):.4g} deg"
    )


#: The geometry a table shows: field, label, symbol, SI -> shown factor, unit.
_SHOWN_BOUNDARY = (
    ("bore", "bore", "d", 1e3, "mm"),
    ("outside_diameter", "outside diameter", "D", 1e3, "mm"),
    ("width", "width", "B", 1e3, "mm"),
)
_SHOWN = {
    "ball": (
        ("ball_count", "number of balls", "Z", 1, "-"),
        ("ball_diameter", "ball diameter", "D_w", 1e3, "mm"),
        ("pitch_diameter", "pitch diameter", "d_m", 1e3, "mm"),
        ("contact_angle", "nominal contact angle", "alpha", 180 / math.pi, "deg"),
        ("inner_groove_factor", "inner groove factor", "f_i", 1, "-"),
        ("outer_groove_factor", "outer groove factor", "f_o", 1, "-"),
        ("diametral_clearance", "diametral clearance", "P_d", 1e6, "um"),
    ),
    "roller": (
        ("roller_count", "number of rollers (per row)", "Z", 1, "-"),
        ("rows", "rows", "i", 1, "-"),
        ("roller_diameter", "roller diameter", "D_we", 1e3, "mm"),
        ("roller_length", "roller effective length", "L_we", 1e3, "mm"),
        ("pitch_diameter", "pitch diameter", "d_m", 1e3, "mm"),
        ("contact_angle", "contact angle (outer raceway)", "alpha", 180 / math.pi, "deg"),
        ("diametral_clearance", "diametral clearance", "P_d", 1e6, "um"),
        ("axial_clearance", "axial clearance", "P_a", 1e6, "um"),
    ),
}


def geometry_rows(bearing) -> list[tuple]:
    """The geometry of a ball or roller ``bearing`` as a table shows it: (field, label,
    symbol, value in the unit, unit) per value, None where it is not known; the command
    line's ``info`` and the report's identity section draw the same rows.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing.

    Examples
    --------
    >>> from bearinglab.catalog import bearing_from_designation
    >>> geometry_rows(bearing_from_designation("6205")[0])[3][1:]
    ('number of balls', 'Z', 9, '-')
    """
    rows = []
    for name, label, symbol, factor, unit in _SHOWN_BOUNDARY + _SHOWN[bearing.rolling_element]:
        value = getattr(bearing, name)
        shown = value if value is None or isinstance(value, int) else float(value) * factor
        rows.append((name, label, symbol, shown, unit))
    return rows


def given_fields(values: dict) -> dict[str, str]:
    """The geometry inputs given in ``values`` (a geometry file counts as the whole
    bearing, ``system`` reads the designation): input -> the BallBearing field it sets.

    Parameters
    ----------
    values : dict
        The request: input name -> value in its unit (None: not given).
    """
    return {
        name: _field(name) if INPUTS[name].fields else name
        for name in BEARING
        if values.get(name) is not None and name not in ("designation", "system", "geometry")
    }
