"""The command line's geometry: the explicit-geometry options (and the ``--geometry`` TOML
file) every command takes, their ranges in the options' units, and the BallBearing they
describe with a designation (SI inside); model errors put back in the user's terms."""

import functools
import inspect
import math
import re
import tomllib
from dataclasses import replace
from pathlib import Path
from typing import Annotated

import typer

from ..catalog import GeometryNeeded, bearing_from_designation
from ..errors import CatalogError, InputError
from ..geometry import BallBearing, Source
from ..materials import BEARING_STEEL, Material
from ._app import System
from ._inputs import OptionError, _show

# ------------------------------------------------------------------ shared geometry options
# name -> (flag, type, help, SI factor for BallBearing, BallBearing keyword or None)
_GEOMETRY_OPTIONS = {
    "system": (
        "--system",
        System | None,
        "Read the designation as GOST 3189-89 or ISO.",
        None,
        None,
    ),
    "balls": ("--balls", int | None, "Number of balls Z.", 1, "ball_count"),
    "ball_diameter_mm": (
        "--ball-diameter-mm",
        float | None,
        "Ball diameter D_w [mm].",
        1e-3,
        "ball_diameter",
    ),
    "pitch_diameter_mm": (
        "--pitch-diameter-mm",
        float | None,
        "Pitch diameter d_m [mm].",
        1e-3,
        "pitch_diameter",
    ),
    "contact_angle_deg": (
        "--contact-angle-deg",
        float | None,
        "Nominal contact angle [deg].",
        math.pi / 180,
        "contact_angle",
    ),
    "inner_groove_factor": (
        "--inner-groove-factor",
        float | None,
        "Inner groove curvature factor f_i (> 0.5).",
        1,
        "inner_groove_factor",
    ),
    "outer_groove_factor": (
        "--outer-groove-factor",
        float | None,
        "Outer groove curvature factor f_o (> 0.5).",
        1,
        "outer_groove_factor",
    ),
    "clearance_um": (
        "--clearance-um",
        float | None,
        "Diametral clearance P_d [um].",
        1e-6,
        "diametral_clearance",
    ),
    "inner_arch_angle_deg": (
        "--inner-arch-angle-deg",
        float | None,
        "Gothic-arch angle of the inner groove [deg] (0 = circular).",
        math.pi / 180,
        "inner_arch_angle",
    ),
    "outer_arch_angle_deg": (
        "--outer-arch-angle-deg",
        float | None,
        "Gothic-arch angle of the outer groove [deg] (0 = circular).",
        math.pi / 180,
        "outer_arch_angle",
    ),
    "bore_mm": ("--bore-mm", float | None, "Bore d [mm].", 1e-3, "bore"),
    "outside_diameter_mm": (
        "--outside-diameter-mm",
        float | None,
        "Outside diameter D [mm].",
        1e-3,
        "outside_diameter",
    ),
    "width_mm": ("--width-mm", float | None, "Width B [mm].", 1e-3, "width"),
    "elastic_modulus_gpa": (
        "--elastic-modulus-gpa",
        float | None,
        "Young's modulus of rings and balls [GPa].",
        1e9,
        None,
    ),
    "poisson_ratio": (
        "--poisson-ratio",
        float | None,
        "Poisson's ratio of rings and balls.",
        1,
        None,
    ),
    "density_kg_m3": (
        "--density-kg-m3",
        float | None,
        "Density of rings and balls [kg/m^3].",
        1,
        None,
    ),
    "geometry": (
        "--geometry",
        Path | None,
        (
            "TOML file with any of the geometry values "
            "(keys as the option names with underscores, e.g. ball_diameter_mm = 7.94, "
            "balls = 9; also system and name)."
        ),
        None,
        None,
    ),
}


def _geometry_parameters() -> list[inspect.Parameter]:
    return [
        inspect.Parameter(
            name,
            inspect.Parameter.KEYWORD_ONLY,
            default=None,
            annotation=Annotated[kind, typer.Option(flag, help=text)],
        )
        for name, (flag, kind, text, _, _) in _GEOMETRY_OPTIONS.items()
    ]


def with_geometry(func):
    """Give a command the shared geometry options; it receives them as ``geometry`` (dict)."""
    sig = inspect.signature(func)
    own = [p for p in sig.parameters.values() if p.name != "geometry"]
    params = own + _geometry_parameters()

    @functools.wraps(func)
    def wrapper(**kwargs):
        geometry = {name: kwargs.pop(name) for name in _GEOMETRY_OPTIONS}
        return func(geometry=geometry, **kwargs)

    wrapper.__signature__ = sig.replace(parameters=params)
    wrapper.__annotations__ = {p.name: p.annotation for p in params}
    del wrapper.__wrapped__
    return wrapper


#: Range checks of the command line, in the options' units (the models check the rest):
#: option name -> (low, high, low included, high included, what).
_RANGES = {
    **{
        name: (0.0, 1e5, False, True, "a length in (0, 100000] mm")
        for name in (
            "ball_diameter_mm",
            "pitch_diameter_mm",
            "bore_mm",
            "outside_diameter_mm",
            "width_mm",
        )
    },
    "elastic_modulus_gpa": (0.0, 1e4, False, True, "a modulus in (0, 10000] GPa"),
    "poisson_ratio": (0.0, 0.5, True, False, "a value in [0, 0.5)"),
    "density_kg_m3": (0.0, 1e5, False, True, "a density in (0, 100000] kg/m^3"),
}
#: BallBearing / Material keyword -> option name, to put errors in the user's terms.
_KEYWORD_OPTION = {spec[4]: name for name, spec in _GEOMETRY_OPTIONS.items() if spec[4]}
_KEYWORD_OPTION.update(
    {
        "elastic_modulus": "elastic_modulus_gpa",
        "density": "density_kg_m3",
        "poisson_ratio": "poisson_ratio",
    }
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
_UNITS = {"_mm": "mm", "_um": "um", "_deg": "deg", "_gpa": "GPa", "_kg_m3": "kg/m^3"}


def _unit(name: str) -> str:
    return next((u for suffix, u in _UNITS.items() if name.endswith(suffix)), "")


def _si_to_option_units(text: str, name: str) -> str:
    """Rewrite lengths in metres ("[-0.000397, 0.000635] m", "0.00794 m", "[m]") in the
    units of option ``name`` (mm or um)."""
    unit = _unit(name)
    factor = _GEOMETRY_OPTIONS[name][3] if name in _GEOMETRY_OPTIONS else None
    if unit not in ("mm", "um") or not factor:
        return text
    number = r"-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?"

    def one(m):
        return f"{float(m.group(1)) / factor:.6g}"

    text = re.sub(
        rf"\[({number}), ({number})\] m\b",
        lambda m: f"[{float(m.group(1)) / factor:.6g}, {float(m.group(2)) / factor:.6g}] {unit}",
        text,
    )
    text = re.sub(rf"({number}) m\b", lambda m: f"{one(m)} {unit}", text)
    return text.replace("[m]", f"[{unit}]")


class _Inputs:
    """What the user gave: option values as typed (command line and --geometry file), where
    each came from, and the BallBearing overrides in SI units."""

    def __init__(self, geometry: dict) -> None:
        self.values: dict = {}
        self.origins: dict[str, str] = {}
        path = geometry.get("geometry")
        if path is not None:
            for key, (written, value) in _read_geometry_file(path).items():
                self.values[key] = value
                self.origins[key] = f"--geometry {written}"
        for name, value in geometry.items():
            if value is not None and name != "geometry":
                self.values[name] = value.value if isinstance(value, System) else value
                self.origins[name] = _GEOMETRY_OPTIONS[name][0]
        self.system = self.values.get("system")
        self._check_ranges()
        self.overrides = self._overrides()

    def flag(self, name: str) -> str:
        return self.origins.get(name, _GEOMETRY_OPTIONS[name][0])

    def _check_ranges(self) -> None:
        for name, value in self.values.items():
            if not isinstance(value, float):
                continue
            if not math.isfinite(value):
                raise OptionError(self.flag(name), value, "a finite number")
            if name in _RANGES:
                low, high, low_in, high_in, what = _RANGES[name]
                if not (
                    (low <= value if low_in else low < value)
                    and (value <= high if high_in else value < high)
                ):
                    raise OptionError(self.flag(name), value, what)

    def _overrides(self) -> dict:
        overrides: dict = {}
        for name, (_, _, _, factor, keyword) in _GEOMETRY_OPTIONS.items():
            value = self.values.get(name)
            if keyword is None or value is None:
                continue
            overrides[keyword] = int(value) if keyword == "ball_count" else float(value) * factor
        material = _material(self.values)
        if material is not None:
            overrides["ring_material"] = overrides["ball_material"] = material
        if isinstance(self.values.get("name"), str):
            overrides["name"] = self.values["name"]
        return overrides

    def remap(self, exc: InputError) -> InputError:
        """The model's error in the user's terms: the option they typed (or, for a check
        between two values, the one of them they gave) with its value in its units."""
        if isinstance(exc, OptionError):
            return exc
        name = _KEYWORD_OPTION.get(exc.parameter)
        if name is None:
            return exc
        if name in self.values:
            return OptionError(
                self.flag(name),
                self.values[name],
                _si_to_option_units(exc.allowed, name),
                _si_to_option_units(exc.hint, name),
            )
        for partner in _PARTNERS.get(exc.parameter, ()):
            other = _KEYWORD_OPTION[partner]
            if other not in self.values:
                continue
            unit = _unit(name)
            factor = _GEOMETRY_OPTIONS[name][3]
            own = (
                f"{exc.value / factor:.6g}"
                if isinstance(exc.value, (int, float)) and factor
                else _show(exc.value)
            )
            label = exc.parameter.replace("_", " ")
            if (
                exc.parameter == "pitch_diameter"
                and partner == "ball_diameter"
                and exc.allowed.startswith("more than the ball diameter")
            ):
                return OptionError(
                    self.flag(other),
                    self.values[other],
                    f"less than the pitch diameter {own} {unit} (not given: "
                    "a catalogue or derived value)",
                )
            if exc.parameter == "bore" and partner == "outside_diameter":
                return OptionError(
                    self.flag(other),
                    self.values[other],
                    f"more than the bore {own} {unit} (not given: a catalogue or derived value)",
                )
            return OptionError(
                self.flag(other),
                self.values[other],
                f"a value with which the {label} {own}{' ' + unit if unit else ''} (not given: "
                f"a catalogue or derived value) passes its check: "
                f"{_si_to_option_units(exc.allowed, name)}",
                _si_to_option_units(exc.hint, name),
            )
        return exc


def _read_geometry_file(path: Path) -> dict:
    """Read a --geometry TOML file: option name -> (key as written, checked value)."""
    flag = "--geometry"
    try:
        text = Path(path).read_bytes().decode("utf-8")
        data = tomllib.loads(text)
    except FileNotFoundError:
        raise OptionError(flag, str(path), "an existing TOML file") from None
    except IsADirectoryError:
        raise OptionError(flag, str(path), "a TOML file, not a directory") from None
    except PermissionError:
        raise OptionError(flag, str(path), "a readable TOML file", "permission denied") from None
    except OSError as exc:
        raise OptionError(
            flag, str(path), "a readable TOML file", exc.strerror or type(exc).__name__
        ) from None
    except UnicodeDecodeError as exc:
        raise OptionError(
            flag, str(path), "a UTF-8 encoded TOML file", f"byte {exc.start} is not UTF-8"
        ) from None
    except tomllib.TOMLDecodeError as exc:
        raise OptionError(flag, str(path), "a valid TOML file", str(exc)) from None
    aliases = {"ball_count": "balls", "diametral_clearance_um": "clearance_um"}
    known = sorted([k for k in _GEOMETRY_OPTIONS if k != "geometry"] + ["name"])
    out = {}
    for written, value in data.items():
        key = aliases.get(written, written)
        if key not in known:
            raise OptionError(f"--geometry key {written!r}", value, f"one of {known}")
        if key in out:
            raise OptionError(
                f"--geometry key {written!r}",
                value,
                f"each value once ({out[key][0]!r} gives it too)",
            )
        where = f"--geometry {written}"
        if key == "name":
            if not isinstance(value, str):
                raise OptionError(where, value, "a text label (TOML string)")
        elif key == "system":
            if not (isinstance(value, str) and value.lower() in ("gost", "iso")):
                raise OptionError(where, value, "'gost' or 'iso'")
            value = value.lower()
        elif key == "balls":
            if type(value) is not int:
                raise OptionError(where, value, "an integer number of balls (e.g. balls = 9)")
        elif isinstance(value, bool) or not isinstance(value, (int, float)):
            raise OptionError(
                where,
                value,
                f"a number{' in ' + _unit(key) if _unit(key) else ''} (TOML integer or float)",
            )
        elif not math.isfinite(value):
            raise OptionError(where, value, "a finite number")
        else:
            value = float(value)
        out[key] = (written, value)
    return out


def _catalog_message(exc: CatalogError) -> str:
    """A catalogue error in the user's terms: the options to give instead of keywords."""
    if isinstance(exc, GeometryNeeded):
        flags = [
            _GEOMETRY_OPTIONS[_KEYWORD_OPTION[k]][0] for k in exc.needed if k in _KEYWORD_OPTION
        ]
        if flags:
            listed = flags[0] if len(flags) == 1 else ", ".join(flags[:-1]) + " and " + flags[-1]
            return f"{exc.reason}; give {listed}"
    return str(exc)


def _resolve(designation: str | None, inputs: _Inputs):
    """(BallBearing, Designation or None) from a designation and/or explicit geometry."""
    overrides = inputs.overrides
    try:
        if designation:
            return bearing_from_designation(designation, system=inputs.system, overrides=overrides)
        missing = [
            _GEOMETRY_OPTIONS[n][0]
            for n in ("balls", "ball_diameter_mm", "pitch_diameter_mm")
            if _GEOMETRY_OPTIONS[n][4] not in overrides
        ]
        if missing:
            raise InputError(
                "DESIGNATION",
                None,
                "a designation, or explicit geometry with " + ", ".join(missing),
            )
        kwargs = dict(overrides)
        name = kwargs.pop("name", "user geometry")
        sources = {k: Source("user", "command line") for k in kwargs}
        return BallBearing(name=name, sources=sources, **kwargs), None
    except InputError as exc:
        raise inputs.remap(exc) from None
    except GeometryNeeded as exc:
        raise CatalogError(_catalog_message(exc)) from None


def _check_designation_text(designation: str | None) -> None:
    if designation is not None and not designation.strip():
        raise OptionError(
            "DESIGNATION",
            designation,
            "a bearing designation (e.g. 6205-2RS, 180205) or catalogue name, or "
            "no designation and explicit geometry",
        )


def resolve_bearing(designation: str | None, geometry: dict):
    """Build the BallBearing from a designation and/or explicit geometry (SI inside).

    Returns (bearing, Designation or None).  Errors name the option the user typed, with
    its value in that option's units."""
    _check_designation_text(designation)
    return _resolve(designation, _Inputs(geometry))


def _material(values: dict) -> Material | None:
    e, nu, rho = (values.get(n) for n in ("elastic_modulus_gpa", "poisson_ratio", "density_kg_m3"))
    if e is None and nu is None and rho is None:
        return None
    base = BEARING_STEEL
    return replace(
        base,
        name="user material",
        elastic_modulus=base.elastic_modulus if e is None else float(e) * 1e9,
        poisson_ratio=base.poisson_ratio if nu is None else float(nu),
        density=base.density if rho is None else float(rho),
    )


def _geometry_warnings(bearing: BallBearing) -> list[str]:
    """Caveats about the geometry used: an estimated ball count of an angular-contact
    bearing (a lower bound), balls of a thrust bearing reaching past its outside diameter."""
    out = []
    src = bearing.sources.get("ball_count")
    if (
        src is not None
        and src.kind == "estimated"
        and bearing.bearing_type in ("angular_contact_ball", "four_point_contact_ball")
    ):
        out.append(
            f"ball count Z = {bearing.ball_count} is estimated with the Conrad "
            "filling-angle rule: for an angular-contact bearing that is a lower bound "
            "(they carry more balls); give --balls"
        )
    big_d = bearing.outside_diameter
    if bearing.is_thrust and big_d is not None:
        reach = bearing.pitch_diameter + bearing.ball_diameter
        if reach > big_d:
            out.append(
                f"the balls reach to a diameter of {reach * 1e3:.4g} mm, beyond the "
                f"outside diameter {big_d * 1e3:.4g} mm: check --pitch-diameter-mm and "
                "--ball-diameter-mm"
            )
    return out


def _geometry_line(bearing: BallBearing, contact_angle: float | None = None) -> str:
    alpha = bearing.contact_angle if contact_angle is None else contact_angle
    return (
        f"geometry ({bearing.geometry_source}): Z = {bearing.ball_count}, "
        f"D_w = {bearing.ball_diameter * 1e3:.4g} mm, d_m = {bearing.pitch_diameter * 1e3:.4g} "
        f"mm, contact angle {math.degrees(alpha):.4g} deg"
    )
