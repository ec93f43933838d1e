"""The friction command: torque and power loss by seed 003's constant coefficient or by
the SKF four-component model. Parses the options and calls
:func:`bearinglab.friction.bearing_friction`, which holds every rule (equivalent load,
C_0, seals, viscosity, lubrication); the report calls the same function."""

from enum import Enum
from typing import Annotated

import typer
from rich.markup import escape

from ..errors import BearinglabError, CatalogError, InputError
from ..friction import SEED003_COEFFICIENTS, SKF_BEARING_TYPES, FrictionBearing
from ..units import UNITS, label, unit_of
from ._app import command_app, console
from ._geometry import (
    _geometry_warnings,
    _si_to_option_units,
    resolve_bearing,
    with_geometry,
)
from ._inputs import (
    AxialLoadOpt,
    JsonOpt,
    OptionError,
    RadialLoadOpt,
    RingSpeedOpt,
    _print_warnings,
    in_range,
    load_n,
    no_effect,
    number_list,
    speed_rad_s,
)
from ._output import _emit_json, _number, _table

app = command_app()

DesignationArg = Annotated[
    str | None,
    typer.Argument(
        help="Bearing designation or catalogue name; optional with --bore-mm and "
        "--outside-diameter-mm.",
    ),
]
#: The lubricant when neither --lubricant nor --viscosity-mm2-s is given.
DEFAULT_LUBRICANT = "iso-vg68"
#: Library parameter -> the option that holds it.
_FLAGS = {
    "shaft_speed": "--speed-rpm",
    "radial_load": "--radial-load-n",
    "axial_load": "--axial-load-n",
    "equivalent_load": "--equivalent-load-n",
    "static_load_rating": "--static-load-rating-kn",
    "viscosity": "--viscosity-mm2-s",
    "temperature": "--temperature-c",
    "lubricant": "--lubricant",
    "lubrication": "--lubrication",
    "lubricant_kind": "--oil",
    "friction_type": "--type",
    "bearing_type": "DESIGNATION",
    "series": "DESIGNATION",
    "constants": "--skf-constants",
    "seals": "--seals",
    "seal_constants": "--seal-constants",
    "seal_diameter": "--seal-diameter-mm",
    "bore": "--bore-mm",
    "outside_diameter": "--outside-diameter-mm",
    "pitch_diameter": "--pitch-diameter-mm",
}


class FrictionModel(str, Enum):
    constant = "constant"
    skf = "skf"


class Seals(str, Enum):
    none = "none"
    shields = "shields"
    contact = "contact"


class Lubrication(str, Enum):
    grease = "grease"
    oil_air = "oil-air"
    oil_jet = "oil-jet"
    low_oil_bath = "low-oil-bath"


class OilKind(str, Enum):
    mineral = "mineral"
    synthetic = "synthetic"
    transmission_fluid = "transmission-fluid"


def _mm(geometry: dict, name: str) -> float | None:
    flag = "--" + name.replace("_", "-")
    value = in_range(flag, geometry.get(name), 0.0, 1e5, "a length", low_open=True)
    return None if value is None else UNITS["mm"].to_si(value)


def _bearing(designation: str | None, geometry: dict, type_option: str | None):
    """(the bearing, its Designation or None, geometry warnings) from the options: a ball
    bearing through the catalogue's full model (with the shared geometry options), any
    other type through its ISO boundary dimensions, or --bore-mm and --outside-diameter-mm
    alone."""
    if designation is not None and not designation.strip():
        raise OptionError("DESIGNATION", designation, "a bearing designation (e.g. 6205, NU205)")
    sizes = {k: _mm(geometry, f"{k}_mm") for k in ("bore", "outside_diameter", "pitch_diameter")}
    ball_given = any(geometry.get(k) is not None for k in ("balls", "ball_diameter_mm", "geometry"))
    if designation is None and not ball_given:
        if sizes["bore"] is None or sizes["outside_diameter"] is None:
            raise OptionError(
                "DESIGNATION",
                None,
                "a designation, or --bore-mm and --outside-diameter-mm (with --type)",
            )
        try:
            return (
                FrictionBearing.from_dimensions(
                    sizes["bore"],
                    sizes["outside_diameter"],
                    bearing_type=type_option,
                    pitch_diameter=sizes["pitch_diameter"],
                ),
                None,
                [],
            )
        except InputError as exc:
            if exc.parameter == "bearing_type":
                raise OptionError(
                    "--type", type_option, exc.allowed + ", or a friction type of seed 003"
                ) from None
            raise
    try:
        bearing, des = resolve_bearing(designation, geometry)
        return bearing, des, _geometry_warnings(bearing)
    except CatalogError as first:
        if designation is None:
            raise
        system = geometry.get("system")
        try:
            return (
                FrictionBearing.from_designation(
                    designation, system.value if system is not None else None, **sizes
                ),
                None,
                [],
            )
        except InputError:
            raise
        except BearinglabError:
            raise first from None


def _option_error(exc: InputError, typed: dict) -> InputError:
    """A library error in the command line's terms: the option that holds the parameter,
    with the value as typed (lengths in the message in the option's unit)."""
    flag = _FLAGS.get(exc.parameter)
    if flag is None or isinstance(exc, OptionError):
        return exc
    name = flag.lstrip("-").replace("-", "_")
    allowed, hint = exc.allowed, exc.hint
    if name.endswith("_mm"):
        allowed, hint = _si_to_option_units(allowed, name), _si_to_option_units(hint, name)
    return OptionError(flag, typed.get(exc.parameter), allowed, hint)


@app.command("friction")
@with_geometry
def friction_command(
    designation: DesignationArg = None,
    speed_rpm: RingSpeedOpt = ...,
    radial_load_n: RadialLoadOpt = 0.0,
    axial_load_n: AxialLoadOpt = 0.0,
    model: Annotated[
        FrictionModel,
        typer.Option(
            "--model",
            help="constant: seed 003's M = mu P d_m / 2; skf: SKF's rolling + "
            "sliding + seal (+ drag) model.",
        ),
    ] = FrictionModel.constant,
    type_option: Annotated[
        str | None,
        typer.Option(
            "--type",
            help="Friction type (constant model: "
            + ", ".join(SEED003_COEFFICIENTS)
            + "; skf: "
            + ", ".join(SKF_BEARING_TYPES)
            + "). Default: from the designation.",
        ),
    ] = None,
    equivalent_load_n: Annotated[
        float | None,
        typer.Option(
            "--equivalent-load-n",
            help="Equivalent load P [N] (constant model; default: "
            "F_r, or ISO 281 from a ball bearing's geometry).",
        ),
    ] = None,
    static_load_rating_kn: Annotated[
        float | None,
        typer.Option(
            "--static-load-rating-kn",
            help="Basic static load rating C_0 [kN] for the SKF "
            "model with an axial load on a deep-groove bearing (default: ISO 76 from the "
            "geometry).",
        ),
    ] = None,
    lubricant: Annotated[
        str | None,
        typer.Option(
            "--lubricant",
            help="Lubricant (built-in: iso-vg68, seed004-grease) for the viscosity "
            "at --temperature-c, and grease or oil for the --lubrication default (SKF model; "
            f"default {DEFAULT_LUBRICANT} unless --viscosity-mm2-s is given).",
        ),
    ] = None,
    viscosity_mm2_s: Annotated[
        float | None,
        typer.Option(
            "--viscosity-mm2-s",
            help="Operating kinematic viscosity of the oil or the "
            "grease's base oil [mm^2/s] (instead of the lubricant's at --temperature-c).",
        ),
    ] = None,
    temperature_c: Annotated[
        float | None,
        typer.Option(
            "--temperature-c",
            help="Operating temperature of the lubricant [degC] (default: its reference).",
        ),
    ] = None,
    lubrication: Annotated[
        Lubrication | None,
        typer.Option(
            "--lubrication",
            help="Lubrication method, sets K_rs (default: grease for a "
            "grease, oil-jet for an oil, grease for a viscosity alone).",
        ),
    ] = None,
    oil: Annotated[
        OilKind, typer.Option("--oil", help="Kind of oil, sets mu_EHL.")
    ] = OilKind.mineral,
    skf_constants: Annotated[
        str | None,
        typer.Option(
            "--skf-constants",
            help="SKF geometry constants R1,R2,S1,S2 (deep groove) or "
            "R1,R2,S1,S2,R3,S3 (angular contact).",
        ),
    ] = None,
    seals: Annotated[
        Seals | None,
        typer.Option("--seals", help="Seals (default: from the designation's suffix)."),
    ] = None,
    seal_constants: Annotated[
        str | None,
        typer.Option(
            "--seal-constants",
            help="SKF seal constants K_S1,K_S2,BETA (M_seal = K_S1 "
            "d_s^BETA + K_S2 in N mm, d_s in mm).",
        ),
    ] = None,
    seal_diameter_mm: Annotated[
        float | None,
        typer.Option("--seal-diameter-mm", help="Seal counterface diameter d_s [mm]."),
    ] = None,
    json_output: JsonOpt = False,
    *,
    geometry,
):
    """Friction torque and power loss: seed 003's constant coefficient or the SKF model."""
    from ..friction import SkfGeometryConstants, bearing_friction
    from ..lubrication.lubricant import OPERATING_TEMPERATURE_RANGE, ZERO_CELSIUS

    omega = speed_rad_s(speed_rpm, zero=True)
    fr = load_n("--radial-load-n", radial_load_n)
    fa = load_n("--axial-load-n", axial_load_n)
    p = load_n("--equivalent-load-n", equivalent_load_n)
    c0 = in_range(
        "--static-load-rating-kn", static_load_rating_kn, 0.0, 1e5, "a rating", low_open=True
    )
    nu = in_range("--viscosity-mm2-s", viscosity_mm2_s, 0.0, 1e6, "a viscosity", low_open=True)
    t_low, t_high = (t - ZERO_CELSIUS for t in OPERATING_TEMPERATURE_RANGE)
    t = in_range("--temperature-c", temperature_c, t_low, t_high, "a temperature")
    ds = in_range("--seal-diameter-mm", seal_diameter_mm, 0.0, 1e5, "a diameter", low_open=True)
    c = number_list(
        "--skf-constants",
        skf_constants,
        "R1,R2,S1,S2 (deep-groove) or "
        "R1,R2,S1,S2,R3,S3 (angular contact), numbers >= 0 in SKF units",
        counts=(4, 6),
        zero=True,
    )
    ks = number_list(
        "--seal-constants",
        seal_constants,
        "K_S1,K_S2,BETA, numbers >= 0 in SKF units",
        counts=(3,),
        zero=True,
    )
    typed = {
        "shaft_speed": speed_rpm,
        "radial_load": radial_load_n,
        "axial_load": axial_load_n,
        "equivalent_load": equivalent_load_n,
        "static_load_rating": static_load_rating_kn,
        "viscosity": viscosity_mm2_s,
        "temperature": temperature_c,
        "lubricant": lubricant,
        "friction_type": type_option,
        "bearing_type": designation,
        "series": designation,
        "constants": skf_constants,
        "seal_constants": seal_constants,
        "seal_diameter": seal_diameter_mm,
        "seals": seals and seals.value,
        "bore": geometry.get("bore_mm"),
        "pitch_diameter": geometry.get("pitch_diameter_mm"),
        "outside_diameter": geometry.get("outside_diameter_mm"),
    }
    try:
        bearing, des, warnings = _bearing(designation, geometry, type_option)
        result = bearing_friction(
            bearing,
            omega,
            fr,
            fa,
            model=model.value,
            designation=des,
            friction_type=type_option,
            equivalent_load=p,
            static_load_rating=None if c0 is None else UNITS["kn"].to_si(c0),
            viscosity=None if nu is None else UNITS["mm2_s"].to_si(nu),
            lubricant=lubricant
            or (DEFAULT_LUBRICANT if nu is None and model is FrictionModel.skf else None),
            temperature=None if t is None else t + ZERO_CELSIUS,
            lubrication=lubrication and lubrication.value,
            lubricant_kind=oil.value,
            constants=None
            if c is None
            else SkfGeometryConstants(
                *c[:4], *(c[4:] or (None, None)), source="user (--skf-constants)"
            ),
            seals=seals and seals.value,
            seal_constants=ks,
            seal_diameter=None if ds is None else UNITS["mm"].to_si(ds),
        )
    except InputError as exc:
        raise _option_error(exc, typed) from None
    # the library's warnings, less its note of the unused inputs, which is said in flags
    said = warnings + list(result.warnings) + _unused(result.unused, model)
    out = {"designation": designation, **result.to_dict(), "warnings": said}
    if json_output:
        _emit_json(out)
        return
    _print(result, out)
    _print_warnings(out["warnings"])


def _unused(unused: tuple, model: FrictionModel) -> list[str]:
    """The options given that the model did not use (the result's ``unused``), by flag."""
    seal = model is FrictionModel.skf and "seal_diameter" in unused
    rest = [n for n in unused if n not in ("r3", "s3") and not (seal and n == "seal_diameter")]
    return (
        no_effect([(_FLAGS[n], True) for n in rest], f"with --model {model.value}")
        + no_effect([("--seal-diameter-mm", seal)], "without --seal-constants")
        + no_effect(
            [("R3,S3 of --skf-constants", "r3" in unused or "s3" in unused)],
            "for a deep-groove ball bearing (its SKF model has no centrifugal-load terms)",
        )
    )


def _print(result, out: dict) -> None:
    title = (
        f"{out['name']}: {out['speed_rpm']:g} rpm, F_r = {out['radial_load_n']:g} N, "
        f"F_a = {out['axial_load_n']:g} N ({out['model']} model)"
    )
    rows = []
    for what, key in result.quantities():
        unit = unit_of(key)
        rows.append([label(what, unit.suffix) if unit is not None else what, _number(out[key])])
    console.print(f"[bold]{escape(title)}[/bold]")
    console.print(_table("", ["quantity", "value"], rows))
    if out["model"] == "constant":
        notes = [f"P: {out['equivalent_load_source']}", f"d_m: {out['pitch_diameter_source']}"]
    else:
        k = out["geometry_constants"]
        notes = [
            f"viscosity: {out['viscosity_source']}",
            f"lubrication: {out['lubrication']} ({out['lubrication_source']}), "
            f"K_rs {out['k_rs']:g}, K_Z {out['k_z']:g}",
            "SKF constants: "
            + ", ".join(
                f"{n.upper()} {k[n]:g}"
                for n in ("r1", "r2", "s1", "s2", "r3", "s3")
                if k[n] is not None
            ),
        ]
        if "static_rating_source" in out:
            notes.append(f"C_0: {out['static_rating_source']}")
    notes.append(f"bearing type {out['bearing_type']}, seals: {out['seals']}")
    for note in notes:
        console.print(escape(note))
    for source in out["sources"]:
        console.print(f"[dim]source: {escape(source)}[/dim]")
