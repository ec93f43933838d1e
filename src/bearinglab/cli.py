"""The ``bearinglab`` command line (typer + rich): parse, call the analyses, print.

Every command accepts a designation and/or explicit geometry (the options below, or a
TOML file), prints readable tables, and with ``--json`` one JSON object whose keys carry
their units. Bad input exits with code 2 and one line on stderr.
"""

import functools
import inspect
import json
import math
import sys
import tomllib
from dataclasses import replace
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.table import Table

from . import __version__
from .catalog import bearing_from_designation, boundary_dimensions, published_geometry
from .contact.ball_race import ball_contacts
from .designation import parse
from .errors import BearinglabError, CatalogError, DesignationError, InputError
from .geometry import BallBearing, Source
from .kinematics import FREQUENCY_NAMES, LONG_NAMES, defect_frequencies
from .materials import BEARING_STEEL, Material
from .plotting import save_figure

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  rich_markup_mode=None,
                  help="Rolling-bearing mechanics, vibration and diagnostics from published "
                       "methods. Run 'bearinglab COMMAND --help' for a command's options.")
console = Console()


class System(str, Enum):
    gost = "gost"
    iso = "iso"


class HertzMethod(str, Enum):
    exact = "exact"
    hamrock_brewe = "hamrock-brewe"


# ------------------------------------------------------------------ shared geometry options
# name -> (flag, type, help, SI factor for BallBearing, BallBearing keyword or None)
_GEOMETRY_OPTIONS = {
    "system": ("--system", System | None, "Read the designation as GOST 3189-89 or ISO.",
               None, None),
    "balls": ("--balls", int | None, "Number of balls Z.", 1, "ball_count"),
    "ball_diameter_mm": ("--ball-diameter-mm", float | None, "Ball diameter D_w [mm].",
                         1e-3, "ball_diameter"),
    "pitch_diameter_mm": ("--pitch-diameter-mm", float | None, "Pitch diameter d_m [mm].",
                          1e-3, "pitch_diameter"),
    "contact_angle_deg": ("--contact-angle-deg", float | None,
                          "Nominal contact angle [deg].", math.pi / 180, "contact_angle"),
    "inner_groove_factor": ("--inner-groove-factor", float | None,
                            "Inner groove curvature factor f_i (> 0.5).", 1, "inner_groove_factor"),
    "outer_groove_factor": ("--outer-groove-factor", float | None,
                            "Outer groove curvature factor f_o (> 0.5).", 1, "outer_groove_factor"),
    "clearance_um": ("--clearance-um", float | None, "Diametral clearance P_d [um].",
                     1e-6, "diametral_clearance"),
    "bore_mm": ("--bore-mm", float | None, "Bore d [mm].", 1e-3, "bore"),
    "outside_diameter_mm": ("--outside-diameter-mm", float | None,
                            "Outside diameter D [mm].", 1e-3, "outside_diameter"),
    "width_mm": ("--width-mm", float | None, "Width B [mm].", 1e-3, "width"),
    "elastic_modulus_gpa": ("--elastic-modulus-gpa", float | None,
                            "Young's modulus of rings and balls [GPa].", 1e9, None),
    "poisson_ratio": ("--poisson-ratio", float | None, "Poisson's ratio of rings and balls.",
                      1, None),
    "density_kg_m3": ("--density-kg-m3", float | None, "Density of rings and balls [kg/m^3].",
                      1, None),
    "geometry": ("--geometry", Path | None, ("TOML file with any of the geometry values "
                 "(keys as the option names with underscores, e.g. ball_diameter_mm)."), None, None),
}


def _geometry_parameters() -> list[inspect.Parameter]:
    return [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=None,
                              annotation=Annotated[kind, typer.Option(flag, help=text,
                                                                      show_default=False)])
            for name, (flag, kind, text, _, _) in _GEOMETRY_OPTIONS.items()]


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


def _read_geometry_file(path: Path) -> dict:
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise InputError("--geometry", str(path), "an existing TOML file") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError("--geometry", str(path), "a valid TOML file", str(exc)) from None
    aliases = {"ball_count": "balls", "diametral_clearance_um": "clearance_um"}
    out = {}
    for key, value in data.items():
        key = aliases.get(key, key)
        if key in ("system", "geometry", "designation", "name"):
            continue
        if key not in _GEOMETRY_OPTIONS:
            raise InputError(f"--geometry key {key!r}", value,
                             f"one of {sorted(k for k in _GEOMETRY_OPTIONS if k != 'geometry')}")
        out[key] = value
    return out


def resolve_bearing(designation: str | None, geometry: dict):
    """Build the BallBearing from a designation and/or explicit geometry (SI inside).

    Returns (bearing, Designation or None)."""
    values = dict(geometry)
    if values.get("geometry") is not None:
        from_file = _read_geometry_file(values["geometry"])
        values = {**from_file, **{k: v for k, v in values.items() if v is not None}}
    overrides = {}
    for name, (flag, _, _, factor, keyword) in _GEOMETRY_OPTIONS.items():
        value = values.get(name)
        if keyword is None or value is None:
            continue
        if keyword == "ball_count":
            if isinstance(value, float) and not value.is_integer():
                raise InputError(flag, value, "a whole number of balls")
            overrides[keyword] = int(value)
        else:
            overrides[keyword] = float(value) * factor
    material = _material(values)
    if material is not None:
        overrides["ring_material"] = overrides["ball_material"] = material
    system = values.get("system")
    system = system.value if isinstance(system, System) else system
    if designation:
        return bearing_from_designation(designation, system=system, overrides=overrides)
    missing = [_GEOMETRY_OPTIONS[n][0] for n in ("balls", "ball_diameter_mm", "pitch_diameter_mm")
               if _GEOMETRY_OPTIONS[n][4] not in overrides]
    if missing:
        raise InputError("DESIGNATION", None, "a designation, or explicit geometry with "
                         + ", ".join(missing))
    sources = {k: Source("user", "command line") for k in overrides}
    return BallBearing(name="user geometry", sources=sources, **overrides), None


def _material(values: dict) -> Material | None:
    e, nu, rho = (values.get(n) for n in ("elastic_modulus_gpa", "poisson_ratio", "density_kg_m3"))
    if e is None and nu is None and rho is None:
        return None
    base = BEARING_STEEL
    return replace(base, name="user material",
                   elastic_modulus=base.elastic_modulus if e is None else float(e) * 1e9,
                   poisson_ratio=base.poisson_ratio if nu is None else float(nu),
                   density=base.density if rho is None else float(rho))


# ------------------------------------------------------------------ output helpers
def _tidy(value):
    """Round floats to 12 significant digits (52.00000000000001 -> 52.0) for JSON."""
    if isinstance(value, float):
        return float(f"{value:.12g}")
    if isinstance(value, dict):
        return {k: _tidy(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_tidy(v) for v in value]
    return value


def _emit_json(obj: dict) -> None:
    sys.stdout.write(json.dumps(_tidy(obj), indent=2, allow_nan=False) + "\n")


def _fmt(value, digits: int = 4) -> str:
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.{digits}g}"
    return str(value)


def _table(title: str, columns: list[str], rows: list[list]) -> Table:
    table = Table(title=title, title_justify="left", show_header=True, header_style="bold")
    for i, col in enumerate(columns):
        table.add_column(col, justify="right" if i and col not in ("source", "meaning") else "left")
    for row in rows:
        table.add_row(*(_fmt(v) for v in row))
    return table


class _References:
    """Numbers each distinct reference once, so tables show "catalog [1]" and the full
    references are printed once underneath."""

    def __init__(self) -> None:
        self.refs: list[str] = []

    def cell(self, bearing: BallBearing, field: str) -> str:
        src = bearing.sources.get(field)
        if src is None:
            return "default"
        if not src.reference:
            return src.kind
        if src.reference not in self.refs:
            self.refs.append(src.reference)
        return f"{src.kind} [{self.refs.index(src.reference) + 1}]"

    def print(self) -> None:
        for i, ref in enumerate(self.refs, start=1):
            console.print(f"[dim][{i}] {ref}[/dim]")


# ------------------------------------------------------------------ commands
DesignationArg = Annotated[str | None, typer.Argument(
    help="Bearing designation (GOST 3189-89 or ISO, e.g. 6205-2RS, 180205) or catalogue "
         "name (e.g. ER-16K). Optional when the geometry is given explicitly.",
    show_default=False)]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON object instead of tables.")]
PlotOpt = Annotated[Path | None, typer.Option(
    "--plot", help="Also draw the result to this .png, .svg or .pdf file.", show_default=False)]


@app.command()
@with_geometry
def info(designation: DesignationArg = None, json_output: JsonOpt = False, *, geometry):
    """Decode a designation; show dimensions, internal geometry (with sources) and
    frequency factors."""
    decoded = None
    if designation:
        try:
            decoded = parse(designation, system=_system(geometry))
        except DesignationError:
            if published_geometry(designation) is None:  # not a catalogue name either
                raise
    try:
        bearing, from_catalog = resolve_bearing(designation, geometry)
        decoded, why_no_geometry = from_catalog or decoded, None
    except CatalogError as exc:  # e.g. roller bearings: dimensions only
        if decoded is None:
            raise
        bearing, why_no_geometry = None, str(exc)
    if json_output:
        _emit_json(_info_dict(designation, decoded, bearing, why_no_geometry))
        return
    if decoded is not None:
        _print_designation(decoded)
    if bearing is None:
        dims = boundary_dimensions(decoded)
        console.print(_table("Boundary dimensions", ["quantity", "value", "unit", "source"], [
            ["bore d", dims.bore * 1e3, "mm", dims.standard],
            ["outside diameter D", dims.outside_diameter * 1e3, "mm", dims.standard],
            ["width B", dims.width * 1e3, "mm", dims.standard]]))
        console.print(f"[yellow]no internal geometry:[/yellow] {why_no_geometry}")
        return
    _print_bearing(bearing)


def _system(geometry: dict) -> str | None:
    system = geometry.get("system")
    return system.value if isinstance(system, System) else system


def _info_dict(text, decoded, bearing, why_no_geometry) -> dict:
    out = {"designation": text, "system": decoded.system if decoded else None,
           "bearing_type": (decoded.bearing_type if decoded else bearing.bearing_type)}
    if bearing is not None:
        out.update(bearing.to_dict())
        out["designation"] = text
        f = defect_frequencies(bearing, 2 * math.pi)
        out["frequency_factors"] = {f"{n}_order": f.orders[n] for n in FREQUENCY_NAMES}
    else:
        dims = boundary_dimensions(decoded)
        out.update({"bore_mm": dims.bore * 1e3, "outside_diameter_mm": dims.outside_diameter * 1e3,
                    "width_mm": dims.width * 1e3, "ball_count": None, "ball_diameter_mm": None,
                    "pitch_diameter_mm": None,
                    "contact_angle_deg": (None if decoded.contact_angle is None
                                          else math.degrees(decoded.contact_angle)),
                    "geometry_source": None, "dimensions_standard": dims.standard,
                    "no_geometry_reason": why_no_geometry})
    if decoded is not None:
        out["decoded"] = decoded.to_dict()
    return out


def _print_designation(d) -> None:
    console.print(f"[bold]{d.text}[/bold] - {d.description} "
                  f"[dim]({'GOST 3189-89' if d.system == 'gost' else 'ISO'} reading)[/dim]")
    console.print(_table("Designation", ["part", "meaning"], [list(p) for p in d.parts]))
    equivalents = [f"ISO {d.iso_equivalent}" if d.iso_equivalent and d.system == "gost" else None,
                   f"GOST {d.gost_equivalent}" if d.gost_equivalent and d.system == "iso" else None]
    equivalents = [e for e in equivalents if e]
    if equivalents:
        console.print("Equivalent: " + ", ".join(equivalents))
    for note in d.notes:
        console.print(f"[yellow]note:[/yellow] {note}")


def _print_bearing(b: BallBearing) -> None:
    refs = _References()
    _source_text = refs.cell
    rows = [
        ["bore d", b.bore and b.bore * 1e3, "mm", _source_text(b, "bore")],
        ["outside diameter D", b.outside_diameter and b.outside_diameter * 1e3, "mm",
         _source_text(b, "outside_diameter")],
        ["width B", b.width and b.width * 1e3, "mm", _source_text(b, "width")],
        ["balls Z", b.ball_count, "", _source_text(b, "ball_count")],
        ["ball diameter D_w", b.ball_diameter * 1e3, "mm", _source_text(b, "ball_diameter")],
        ["pitch diameter d_m", b.pitch_diameter * 1e3, "mm", _source_text(b, "pitch_diameter")],
        ["inner groove factor f_i", b.inner_groove_factor, "", _source_text(b, "inner_groove_factor")],
        ["outer groove factor f_o", b.outer_groove_factor, "", _source_text(b, "outer_groove_factor")],
        ["contact angle (nominal)", math.degrees(b.contact_angle), "deg",
         _source_text(b, "contact_angle")],
        ["diametral clearance P_d", b.diametral_clearance * 1e6, "um",
         _source_text(b, "diametral_clearance")],
    ]
    console.print(_table(f"Geometry (source: {b.geometry_source})",
                         ["quantity", "value", "unit", "source"], rows))
    refs.print()
    d = b.to_dict()
    derived = [["inner raceway (groove bottom) d_i", d["inner_raceway_diameter_mm"], "mm"],
               ["outer raceway (groove bottom) d_o", d["outer_raceway_diameter_mm"], "mm"],
               ["free contact angle", d["free_contact_angle_deg"], "deg"],
               ["end play P_e", d["end_play_um"], "um"],
               ["ball mass", d["ball_mass_g"], "g"]]
    for key, label, unit in (("inner_ring_mass_g", "inner ring mass", "g"),
                             ("outer_ring_mass_g", "outer ring mass", "g")):
        if key in d:
            derived.append([label, d[key], unit])
    console.print(_table("Derived", ["quantity", "value", "unit"], derived))
    f = defect_frequencies(b, 2 * math.pi)
    console.print(_table("Frequency factors (orders of shaft speed, inner ring rotating)",
                         ["frequency", "order", "meaning"],
                         [[n.upper() if n != "ball_defect" else "ball defect (2xBSF)",
                           f.orders[n], LONG_NAMES[n]] for n in FREQUENCY_NAMES]))


@app.command()
@with_geometry
def frequencies(designation: DesignationArg = None,
                speed_rpm: Annotated[float, typer.Option("--speed-rpm", help="Speed of the "
                                                         "rotating ring [rpm].")] = ...,
                outer_rotating: Annotated[bool, typer.Option(
                    "--outer-rotating", help="The outer ring turns, the inner ring is fixed.")]
                = False,
                json_output: JsonOpt = False, plot: PlotOpt = None, *, geometry):
    """Kinematic defect frequencies (pure rolling) in Hz and as orders."""
    if not (math.isfinite(speed_rpm) and speed_rpm >= 0):
        raise InputError("--speed-rpm", speed_rpm, "a speed >= 0 rpm")
    bearing, _ = resolve_bearing(designation, geometry)
    f = defect_frequencies(bearing, speed_rpm * math.pi / 30, outer_rotating=outer_rotating)
    if plot is not None:
        save_figure(f.plot()[0], plot)
    if json_output:
        _emit_json({"designation": designation, **f.to_dict()})
        return
    ring = "outer" if outer_rotating else "inner"
    console.print(_table(f"{bearing.name or 'bearing'} at {speed_rpm:g} rpm ({ring} ring "
                         f"rotating, contact angle {math.degrees(f.contact_angle):g} deg)",
                         ["frequency", "Hz", "order", "meaning"],
                         [["shaft", f.shaft_hz, 1.0, LONG_NAMES["shaft"]]]
                         + [[n.upper() if n != "ball_defect" else "BALL DEFECT", f.hz(n),
                             f.orders[n], LONG_NAMES[n]] for n in FREQUENCY_NAMES]))
    console.print("[dim]BSF is one spin revolution; a ball defect strikes the races at "
                  "2 x BSF (some tables print that as 'ball spin').[/dim]")


@app.command()
@with_geometry
def contact(designation: DesignationArg = None,
            ball_load_n: Annotated[float, typer.Option("--ball-load-n",
                                                       help="Normal load on one ball [N].")] = ...,
            method: Annotated[HertzMethod, typer.Option(
                "--method", help="Ellipticity and elliptic integrals: exact or Hamrock-Brewe.")]
            = HertzMethod.exact,
            json_output: JsonOpt = False, plot: PlotOpt = None, *, geometry):
    """Hertz contact of one ball with the inner and outer raceway."""
    if not (math.isfinite(ball_load_n) and ball_load_n > 0):
        raise InputError("--ball-load-n", ball_load_n, "a load > 0 N")
    bearing, _ = resolve_bearing(designation, geometry)
    result = ball_contacts(bearing, ball_load_n, method=method.value.replace("-", "_"))
    if plot is not None:
        save_figure(result.plot()[0], plot)
    if json_output:
        _emit_json({"designation": designation, **result.to_dict()})
        return
    d = result.to_dict()
    rows = []
    for key, label, unit in (("semi_major_mm", "semi-major axis a", "mm"),
                             ("semi_minor_mm", "semi-minor axis b", "mm"),
                             ("ellipticity", "ellipticity k = a/b", ""),
                             ("max_pressure_gpa", "max pressure p_max", "GPa"),
                             ("mean_pressure_gpa", "mean pressure", "GPa"),
                             ("approach_um", "approach delta", "um"),
                             ("stiffness_n_per_um", "stiffness dQ/d(delta)", "N/um")):
        rows.append([label, d["inner"][key], d["outer"][key], unit])
    console.print(_table(f"Hertz contact, Q = {ball_load_n:g} N, contact angle "
                         f"{d['contact_angle_deg']:g} deg ({method.value})",
                         ["quantity", "inner", "outer", "unit"], rows))
    console.print(f"ball between both races: total approach {d['total_approach_um']:.4g} um, "
                  f"K_n = {d['ball_load_deflection_constant_n_per_m1_5']:.4g} N/m^1.5")


def _version(value: bool):
    if value:
        print(f"bearinglab {__version__}")
        raise typer.Exit()


@app.callback()
def _main(version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True,
                                                help="Show the version and exit.")] = False):
    """Rolling-bearing mechanics, vibration and diagnostics from published methods."""


def main(argv: list[str] | None = None) -> int:
    """Entry point: run the app; user errors become one line on stderr and exit code 2."""
    try:
        result = app(args=argv, standalone_mode=False)
    except typer.Exit as exc:
        return exc.exit_code
    except typer.Abort:
        sys.stderr.write("aborted\n")
        return 1
    except BearinglabError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 2
    except typer.TyperException as exc:  # usage errors: unknown option, bad type, missing
        text = exc.format_message() if hasattr(exc, "format_message") else str(exc)
        sys.stderr.write("error: " + " ".join(text.split()) + "\n")
        return 2
    return result if isinstance(result, int) else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
