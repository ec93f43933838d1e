"""The ``life`` command: load ratings, equivalent loads and rating life (ISO 281:2007,
ISO 76:2006, or the ISO/TS 16281 reference life from the load distribution). Parses the
options and calls :func:`bearinglab.life.rating_life` once."""

from enum import Enum
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..errors import InputError
from ..units import UNITS, label, unit_of
from ._app import command_app, console
from ._geometry import (
    _geometry_line,
    _geometry_warnings,
    resolve_bearing,
    with_geometry,
)
from ._inputs import (
    AxialLoadOpt,
    DesignationArg,
    JsonOpt,
    OptionError,
    RadialLoadOpt,
    RingSpeedOpt,
    _print_warnings,
    check_loads,
    in_range,
    no_effect,
    plot_option,
    speed_rad_s,
)
from ._output import _number, _plot_and_emit, _table

app = command_app()

PlotOpt = plot_option("life against load")
#: Library parameter -> the option that holds it.
_FLAGS = {
    "shaft_speed": "--speed-rpm",
    "radial_load": "--radial-load-n",
    "axial_load": "--axial-load-n",
    "reliability_percent": "--reliability-percent",
    "viscosity": "--viscosity-mm2-s",
    "contamination": "--contamination",
    "dynamic_load_rating": "--dynamic-load-rating-kn",
    "static_load_rating": "--static-load-rating-kn",
}
#: Largest rating accepted [kN].
MAX_RATING_KN = 1e5


class LifeMethod(str, Enum):
    iso281 = "iso281"
    iso16281 = "iso16281"


def _contamination(text: str | None):
    """--contamination as a number when it reads as one, else the level's name (the library
    checks both)."""
    if text is None:
        return None
    try:
        return float(text)
    except ValueError:
        return text


@app.command("life")
@with_geometry
def life_command(
    designation: DesignationArg = None,
    speed_rpm: RingSpeedOpt = ...,
    radial_load_n: RadialLoadOpt = 0.0,
    axial_load_n: AxialLoadOpt = 0.0,
    reliability_percent: Annotated[
        float,
        typer.Option(
            "--reliability-percent",
            help="Reliability for the modified life, 90-99.95 [%] (a_1 of ISO 281 Table 12).",
        ),
    ] = 90.0,
    viscosity_mm2_s: Annotated[
        float | None,
        typer.Option(
            "--viscosity-mm2-s",
            help="Operating kinematic viscosity of the lubricant "
            "[mm^2/s]; needed for kappa, a_ISO and the modified life.",
        ),
    ] = None,
    contamination: Annotated[
        str | None,
        typer.Option(
            "--contamination",
            help="Contamination factor e_C: a number in [0, 1] or a level "
            "of ISO 281 Table 13 (extreme-cleanliness, high-cleanliness, normal-cleanliness, "
            "slight, typical, severe, very-severe); default normal-cleanliness with a "
            "viscosity.",
        ),
    ] = None,
    method: Annotated[
        LifeMethod,
        typer.Option(
            "--method",
            help="iso281: L10 = (C/P)^3; iso16281: reference life from the "
            "solved load distribution (clearance, misalignment).",
        ),
    ] = LifeMethod.iso281,
    misalignment_mrad: Annotated[
        float,
        typer.Option(
            "--misalignment-mrad",
            help="Imposed tilt of the inner ring across the radial load [mrad] (iso16281 only).",
        ),
    ] = 0.0,
    outer_rotating: Annotated[
        bool,
        typer.Option(
            "--outer-rotating",
            help="The outer ring turns (iso16281: which ring's equivalent load uses exponent 3).",
        ),
    ] = False,
    ep_additives: Annotated[
        bool,
        typer.Option(
            "--ep-additives",
            help="The lubricant has proven EP additives (ISO 281 rule for kappa < 1).",
        ),
    ] = False,
    dynamic_load_rating_kn: Annotated[
        float | None,
        typer.Option(
            "--dynamic-load-rating-kn",
            help="Basic dynamic load rating C [kN], e.g. the "
            "maker's (default: ISO 281 from the geometry); used by both methods.",
        ),
    ] = None,
    static_load_rating_kn: Annotated[
        float | None,
        typer.Option(
            "--static-load-rating-kn",
            help="Basic static load rating C0 [kN] (default: "
            "ISO 76 from the geometry); sets s0 and Cu.",
        ),
    ] = None,
    json_output: JsonOpt = False,
    plot: PlotOpt = None,
    *,
    geometry,
):
    """Load ratings C, C0, Cu, equivalent loads, basic and modified rating life."""
    from ..life import ViscosityTooLow, rating_life
    from ..operating import OperatingCondition

    omega = speed_rad_s(speed_rpm)
    check_loads(radial_load_n, axial_load_n, unloaded="an unloaded bearing has no rating life")
    in_range("--reliability-percent", reliability_percent, 90.0, 99.95, "a reliability")
    nu = in_range("--viscosity-mm2-s", viscosity_mm2_s, 0.0, 1e6, "a viscosity", low_open=True)
    tilt = in_range("--misalignment-mrad", misalignment_mrad, -20.0, 20.0, "a tilt")
    if tilt and method is not LifeMethod.iso16281:
        raise OptionError(
            "--misalignment-mrad",
            misalignment_mrad,
            "0 with --method iso281",
            "ISO 281 has no misalignment; use --method iso16281",
        )
    c, c0 = (
        in_range(flag, value, 0.0, MAX_RATING_KN, "a rating", low_open=True)
        for flag, value in (
            ("--dynamic-load-rating-kn", dynamic_load_rating_kn),
            ("--static-load-rating-kn", static_load_rating_kn),
        )
    )
    if plot is not None and not Path(plot).parent.exists():
        raise OptionError("--plot", str(plot), "a path in an existing directory")
    bearing, _ = resolve_bearing(designation, geometry)
    kn = UNITS["kn"]
    typed = {
        "shaft_speed": speed_rpm,
        "radial_load": radial_load_n,
        "axial_load": axial_load_n,
        "reliability_percent": reliability_percent,
        "viscosity": viscosity_mm2_s,
        "contamination": contamination,
        "dynamic_load_rating": dynamic_load_rating_kn,
        "static_load_rating": static_load_rating_kn,
    }
    try:
        # the tilt turns the inner ring about the axis across the (downward) radial load
        condition = OperatingCondition(
            radial_load=radial_load_n,
            axial_load=axial_load_n,
            misalignment=(UNITS["mrad"].to_si(tilt), 0.0),
            shaft_speed=omega,
        )
        result = rating_life(
            bearing,
            condition,
            reliability_percent=reliability_percent,
            viscosity=None if nu is None else UNITS["mm2_s"].to_si(nu),
            contamination=_contamination(contamination),
            method=method.value,
            rotating="outer" if outer_rotating else "inner",
            ep_additives=ep_additives,
            dynamic_load_rating=None if c is None else kn.to_si(c),
            static_load_rating=None if c0 is None else kn.to_si(c0),
        )
    except ViscosityTooLow as exc:
        raise OptionError(
            "--viscosity-mm2-s",
            viscosity_mm2_s,
            "a viscosity of at least "
            f"{UNITS['mm2_s'].from_si(exc.minimum):.3g} mm²/s at this speed and "
            "size",
            exc.hint,
        ) from None
    except InputError as exc:
        flag = _FLAGS.get(exc.parameter)
        if flag is None:
            raise
        raise OptionError(flag, typed[exc.parameter], exc.allowed, exc.hint) from None
    unused = no_effect(
        [("--outer-rotating", "rotating" in result.unused)],
        "with --method iso281 (only iso16281 tells which ring turns)",
    ) + no_effect(
        [("--ep-additives", "ep_additives" in result.unused)],
        "without --viscosity-mm2-s (the EP rule acts on a_ISO, which needs the viscosity)",
    )
    d = result.to_dict()
    # the library's warnings, less its note of the unused inputs, which is said in flags
    said = _geometry_warnings(bearing) + list(result.warnings) + unused
    out = {"designation": designation, **d, "warnings": said}
    if _plot_and_emit(out, json_output, result, plot):
        return
    _print(result, out, bearing)


def _print(result, out: dict, bearing) -> None:
    """The result as a table of (quantity [unit], value, given or computed), ratings in kN,
    and the sources underneath."""
    title = (
        f"{bearing.name or 'bearing'}: F_r = {out['radial_load_n']:g} N, F_a = "
        f"{out['axial_load_n']:g} N, {out['speed_rpm']:g} rpm ({out['method']})"
    )
    console.print(f"[bold]{escape(title)}[/bold]")
    rows = []
    for row in result.to_pandas().itertuples(index=False):
        unit, value = unit_of(row.key), row.value
        if row.key in ("dynamic_rating_n", "static_rating_n"):
            unit, value = UNITS["kn"], UNITS["kn"].from_si(value)
        what = label(row.quantity.strip(), unit.suffix) if unit is not None else row.quantity
        if row.quantity.startswith(" "):
            what = "  " + what
        source = "given" if row.source.startswith("given") else "computed" if row.source else ""
        rows.append([what, _number(value), source])
    console.print(_table("", ["quantity", "value", "source"], rows))
    for name, key in (
        ("C", "dynamic_rating_source"),
        ("C0", "static_rating_source"),
        ("Cu", "fatigue_load_limit_source"),
    ):
        console.print(escape(f"{name}: {out[key]}"))
    console.print(escape(_geometry_line(bearing)))
    factors = ", ".join(
        f"{name} {out[key]:.4g}"
        for name, key in (("f_c", "fc"), ("f_0", "f0"), ("b_m", "rating_factor_bm"))
        if out[key] is not None
    )
    console.print(
        escape(
            f"{factors}; X {out['x_factor']:.3g}, Y {out['y_factor']:.3g}, "
            f"e {out['e_limit']:.3g}; a_1 {out['a1']:.3g} at "
            f"{out['reliability_percent']:g} %"
        ),
        style="dim",
    )
    _print_warnings(out["warnings"])
