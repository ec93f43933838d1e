"""The bearing of a request: a designation and/or explicit geometry (the inputs of
:data:`~bearinglab.inputs.table.BEARING`, in their units, or a ``geometry`` TOML file) as a
:class:`~bearinglab.geometry.BallBearing` (SI inside). The model's errors come back in the
user's terms: the input they gave (or, for a check between two values, the one of them
they gave), with its value in its unit."""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import replace
from pathlib import Path

from ..errors import CatalogError, InputError
from .table import BEARING, GEOMETRY_NEEDED, INPUTS

#: input -> (BallBearing keyword, SI value of one unit of the input)
_KEYWORDS = {
    "balls": ("ball_count", 1),
    "ball_diameter_mm": ("ball_diameter", 1e-3),
    "pitch_diameter_mm": ("pitch_diameter", 1e-3),
    "contact_angle_deg": ("contact_angle", math.pi / 180),
    "inner_groove_factor": ("inner_groove_factor", 1),
    "outer_groove_factor": ("outer_groove_factor", 1),
    "clearance_um": ("diametral_clearance", 1e-6),
    "inner_arch_angle_deg": ("inner_arch_angle", math.pi / 180),
    "outer_arch_angle_deg": ("outer_arch_angle", math.pi / 180),
    "bore_mm": ("bore", 1e-3),
    "outside_diameter_mm": ("outside_diameter", 1e-3),
    "width_mm": ("width", 1e-3),
}
#: BallBearing / Material keyword -> input, to put errors in the user's terms.
_KEYWORD_INPUT = {keyword: name for name, (keyword, _) in _KEYWORDS.items()}
_KEYWORD_INPUT.update(
    elastic_modulus="elastic_modulus_gpa", density="density_kg_m3", poisson_ratio="poisson_ratio"
)
_FACTORS = {name: factor for name, (_, factor) in _KEYWORDS.items()}
_FACTORS.update(elastic_modulus_gpa=1e9, density_kg_m3=1, poisson_ratio=1)
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
_SYMBOLS = {"_mm": "mm", "_um": "um", "_deg": "deg", "_gpa": "GPa", "_kg_m3": "kg/m^3"}


def _unit(name: str) -> str:
    return next((u for suffix, u in _SYMBOLS.items() if name.endswith(suffix)), "")


def _in_units(text: str, name: str) -> str:
    """The model's lengths in metres ("[-0.000397, 0.000635] m", "0.00794 m", "[m]") in
    the unit of input ``name`` (mm or um)."""
    unit = _unit(name)
    factor = _FACTORS.get(name)
    if unit not in ("mm", "um") or not factor:
        return text
    number = r"-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?"

    def one(m) -> str:
        return f"{float(m.group(1)) / factor:.6g}"

    text = re.sub(
        rf"\[({number}), ({number})\] m\b",
        lambda m: f"[{one(m)}, {float(m.group(2)) / factor:.6g}] {unit}",
        text,
    )
    text = re.sub(rf"({number}) m\b", lambda m: f"{one(m)} {unit}", text)
    return text.replace("[m]", f"[{unit}]")


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
        for name, (keyword, factor) in _KEYWORDS.items():
            value = self.values.get(name)
            if value is not None:
                overrides[keyword] = int(value) if keyword == "ball_count" else value * factor
        material = _material(self.values)
        if material is not None:
            overrides["ring_material"] = overrides["ball_material"] = material
        if isinstance(self.values.get("name"), str):
            overrides["name"] = self.values["name"]
        return overrides

    def remap(self, exc: InputError) -> InputError:
        """The model's error in the user's terms: the input they gave (or, for a check
        between two values, the one of them they gave) with its value in its unit."""
        name = _KEYWORD_INPUT.get(exc.parameter)
        if name is None:
            return exc
        if name in self.values:
            return InputError(
                self.origin(name),
                self.values[name],
                _in_units(exc.allowed, name),
                _in_units(exc.hint, name),
            )
        for partner in _PARTNERS.get(exc.parameter, ()):
            other = _KEYWORD_INPUT[partner]
            if other not in self.values:
                continue
            unit = _unit(name)
            factor = _FACTORS[name]
            own = (
                f"{exc.value / factor:.6g}"
                if isinstance(exc.value, (int, float)) and factor
                else repr(exc.value)
            )
            label = exc.parameter.replace("_", " ")
            given = self.origin(other), self.values[other]
            if (
                exc.parameter == "pitch_diameter"
                and partner == "ball_diameter"
                and exc.allowed.startswith("more than the ball diameter")
            ):
                return InputError(
                    *given,
                    f"less than the pitch diameter {own} {unit} (not given: "
                    "a catalogue or derived value)",
                )
            if exc.parameter == "bore" and partner == "outside_diameter":
                return InputError(
                    *given,
                    f"more than the bore {own} {unit} (not given: a catalogue or derived value)",
                )
            return InputError(
                *given,
                f"a value with which the {label} {own}{' ' + unit if unit else ''} (not given: "
                f"a catalogue or derived value) passes its check: {_in_units(exc.allowed, name)}",
                _in_units(exc.hint, name),
            )
        return exc


def read_geometry_file(path) -> dict:
    """Read the geometry TOML file at ``path``: input name -> (key as written, checked
    value)."""
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
            unit = _unit(key)
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
    names = [f"`{_KEYWORD_INPUT[k]}`" for k in exc.needed if k in _KEYWORD_INPUT]
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
    """(BallBearing, Designation or None) from a request's ``values`` (name -> value in
    its unit): a ``designation`` and/or the explicit geometry and material, or a
    ``geometry`` TOML file. Errors name the input given, with its value in its unit."""
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
        if designation:
            return bearing_from_designation(designation, system=given.system, overrides=overrides)
        missing = [n for n in GEOMETRY_NEEDED if _KEYWORDS[n][0] not in overrides]
        if missing:
            raise InputError(
                "designation",
                None,
                "a designation, or explicit geometry with " + ", ".join(f"`{n}`" for n in missing),
            )
        kwargs = dict(overrides)
        name = kwargs.pop("name", "user geometry")
        sources = {k: Source("user", "request") for k in kwargs}
        return BallBearing(name=name, sources=sources, **kwargs), None
    except InputError as exc:
        raise given.remap(exc) from None
    except GeometryNeeded as exc:
        raise CatalogError(_catalog_message(exc)) from None


def bearing_warnings(bearing, decoded=None) -> list[str]:
    """Caveats about the ``bearing`` used: a designation (``decoded``, the Designation
    read, or None) that also reads in the other system
    (GOST 3189-89 / ISO: the reading used is said), an estimated ball count of an
    angular-contact bearing (a lower bound), balls of a thrust bearing reaching past its
    outside diameter."""
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
    if bearing.is_thrust and big_d is not None:
        reach = bearing.pitch_diameter + bearing.ball_diameter
        if reach > big_d:
            out.append(
                f"the balls reach to a diameter of {reach * 1e3:.4g} mm, beyond the "
                f"outside diameter {big_d * 1e3:.4g} mm: check pitch_diameter_mm and "
                "ball_diameter_mm"
            )
    return out


def geometry_line(bearing, contact_angle: float | None = None) -> str:
    """One line: where the geometry of ``bearing`` comes from and its main values (the
    ``contact_angle`` given [rad], else the nominal one)."""
    alpha = bearing.contact_angle if contact_angle is None else contact_angle
    return (
        f"geometry ({bearing.geometry_source}): Z = {bearing.ball_count}, "
        f"D_w = {bearing.ball_diameter * 1e3:.4g} mm, d_m = {bearing.pitch_diameter * 1e3:.4g} "
        f"mm, contact angle {math.degrees(alpha):.4g} deg"
    )


def given_fields(values: dict) -> dict[str, str]:
    """The geometry inputs given in ``values`` (a geometry file counts as the whole
    bearing, ``system`` reads the designation): input -> the BallBearing field it sets."""
    return {
        name: _KEYWORDS.get(name, (name,))[0]
        for name in BEARING
        if values.get(name) is not None and name not in ("designation", "system", "geometry")
    }
