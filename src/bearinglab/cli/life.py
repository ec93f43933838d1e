"""The ``life`` command: load ratings, equivalent loads and rating life (ISO 281:2007,
ISO 76:2006, or the ISO/TS 16281 reference life from the load distribution)."""

import math
from enum import Enum
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape

from ..errors import InputError
from ..life import rating_life
from ..life.tables import CONTAMINATION_ALIASES, CONTAMINATION_LEVELS
from ..operating import OperatingCondition
from ._app import command_app, console
from ._inputs import (
    DesignationArg,
    JsonOpt,
    OptionError,
    _geometry_line,
    _geometry_warnings,
    _print_warnings,
    check_loads,
    resolve_bearing,
    speed_rad_s,
    with_geometry,
)
from ._output import _check_finite, _emit_json, _save_plot, _table

app = command_app()

PlotOpt = Annotated[Path | None, typer.Option(
    "--plot", help="Also draw life against load to this .png, .svg or .pdf file.",
    show_default=False)]
LEVELS = ", ".join(list(CONTAMINATION_ALIASES) + list(CONTAMINATION_LEVELS))


class LifeMethod(str, Enum):
    iso281 = "iso281"
    iso16281 = "iso16281"


def _contamination(text: str | None):
    if text is None:
        return None
    try:
        value = float(text)
    except ValueError:
        key = text.strip().lower().replace("_", "-").replace(" ", "-")
        if CONTAMINATION_ALIASES.get(key, key) not in CONTAMINATION_LEVELS:
            raise OptionError("--contamination", text, f"a number in [0, 1] or one of {LEVELS}"
                              ) from None
        return text
    if not (math.isfinite(value) and 0.0 <= value <= 1.0):
        raise OptionError("--contamination", text, f"a number in [0, 1] or one of {LEVELS}")
    return value


def _check(speed_rpm, radial, axial, reliability, viscosity, misalignment, method):
    speed_rad_s(speed_rpm)
    check_loads(radial, axial, unloaded="an unloaded bearing has no rating life")
    if not (math.isfinite(reliability) and 90 <= reliability <= 99.95):
        raise OptionError("--reliability-percent", reliability, "a reliability in [90, 99.95] %")
    if viscosity is not None and not (math.isfinite(viscosity) and 0 < viscosity <= 1e6):
        raise OptionError("--viscosity-mm2-s", viscosity, "a viscosity in (0, 1e6] mm^2/s")
    if not (math.isfinite(misalignment) and abs(misalignment) <= 20):
        raise OptionError("--misalignment-mrad", misalignment, "a tilt within +-20 mrad")
    if misalignment and method is not LifeMethod.iso16281:
        raise OptionError("--misalignment-mrad", misalignment, "0 with --method iso281",
                          "ISO 281 has no misalignment; use --method iso16281")


@app.command("life")
@with_geometry
def life_command(
        designation: DesignationArg = None,
        speed_rpm: Annotated[float, typer.Option("--speed-rpm", help="Speed of the rotating "
                                                 "ring [rpm].")] = ...,
        radial_load_n: Annotated[float, typer.Option("--radial-load-n",
                                                     help="Radial load F_r [N].")] = 0.0,
        axial_load_n: Annotated[float, typer.Option("--axial-load-n",
                                                    help="Axial load F_a [N].")] = 0.0,
        reliability_percent: Annotated[float, typer.Option(
            "--reliability-percent", help="Reliability for the modified life, 90-99.95 "
            "[%] (a_1 of ISO 281 Table 12).")] = 90.0,
        viscosity_mm2_s: Annotated[float | None, typer.Option(
            "--viscosity-mm2-s", help="Operating kinematic viscosity of the lubricant "
            "[mm^2/s]; needed for kappa, a_ISO and the modified life.",
            show_default=False)] = None,
        contamination: Annotated[str | None, typer.Option(
            "--contamination", help="Contamination factor e_C: a number in [0, 1] or a level "
            "of ISO 281 Table 13 (extreme, high, normal, slight, typical, severe, "
            "very-severe); default normal with a viscosity.", show_default=False)] = None,
        method: Annotated[LifeMethod, typer.Option(
            "--method", help="iso281: L10 = (C/P)^3; iso16281: reference life from the "
            "solved load distribution (clearance, misalignment).")] = LifeMethod.iso281,
        misalignment_mrad: Annotated[float, typer.Option(
            "--misalignment-mrad", help="Imposed tilt of the inner ring across the radial "
            "load [mrad] (iso16281 only).")] = 0.0,
        outer_rotating: Annotated[bool, typer.Option(
            "--outer-rotating", help="The outer ring turns (iso16281: which ring's "
            "equivalent load uses exponent 3).")] = False,
        ep_additives: Annotated[bool, typer.Option(
            "--ep-additives", help="The lubricant has proven EP additives (ISO 281 rule for "
            "kappa < 1).")] = False,
        json_output: JsonOpt = False, plot: PlotOpt = None, *, geometry):
    """Load ratings C, C0, Cu, equivalent loads, basic and modified rating life."""
    _check(speed_rpm, radial_load_n, axial_load_n, reliability_percent, viscosity_mm2_s,
           misalignment_mrad, method)
    e_c = _contamination(contamination)
    if plot is not None and not Path(plot).parent.exists():
        raise OptionError("--plot", str(plot), "a path in an existing directory")
    bearing, _ = resolve_bearing(designation, geometry)
    tilt = misalignment_mrad * 1e-3       # about the axis across the (downward) radial load
    condition = OperatingCondition(radial_load=radial_load_n, axial_load=axial_load_n,
                                   misalignment=(tilt, 0.0), shaft_speed=speed_rpm * math.pi / 30)
    try:
        result = rating_life(bearing, condition, reliability_percent=reliability_percent,
                             viscosity=None if viscosity_mm2_s is None else viscosity_mm2_s * 1e-6,
                             contamination=e_c, method=method.value,
                             rotating="outer" if outer_rotating else "inner",
                             ep_additives=ep_additives)
    except InputError as exc:
        if exc.parameter == "viscosity":
            raise OptionError("--viscosity-mm2-s", viscosity_mm2_s,
                              "a viscosity giving kappa >= 0.1 at this speed and size",
                              str(exc).split("(", 1)[-1].rstrip(")")) from None
        if exc.parameter == "radial_load":
            raise OptionError("--radial-load-n", radial_load_n, exc.allowed) from None
        raise
    d = result.to_dict()
    warnings = _geometry_warnings(bearing) + d.pop("warnings")
    out = {"designation": designation, **d, "warnings": warnings}
    if plot is not None:
        _save_plot(result, plot)
    if json_output:
        _emit_json(out)
        return
    _check_finite(out)
    title = (f"{bearing.name or 'bearing'}: F_r = {radial_load_n:g} N, F_a = {axial_load_n:g} N, "
             f"{speed_rpm:g} rpm ({method.value})")
    table = result.to_pandas()
    console.print(_table(title, ["quantity", "value", "unit"],
                         [[q, "-" if v is None else v, u] for q, v, u in
                          table[["quantity", "value", "unit"]].itertuples(index=False)]))
    console.print(escape(_geometry_line(bearing)))
    console.print(f"[dim]f_c {d['fc']:.4g}, f_0 {d['f0']:.4g}, b_m {d['b_m']:g}; X {d['x_factor']:.3g}, "
                  f"Y {d['y_factor']:.3g}, e {d['e_limit']:.3g}; a_1 {d['a1']:.3g} at "
                  f"{reliability_percent:g} %[/dim]")
    _print_warnings(warnings)
