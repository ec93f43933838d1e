"""The ``life`` command: load ratings, equivalent loads and rating life (ISO 281:2007,
ISO 76:2006, or the ISO/TS 16281 reference life from the load distribution). Parses the
options and calls :func:`bearinglab.life.rating_life` once."""

from rich.markup import escape

from ..analyses.operation import LIFE
from ..inputs import geometry_line
from ..units import UNITS, label, unit_of
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, check_path, plot_option, takes
from ._output import _number, _plot_and_emit, _table

app = command_app()

PlotOpt = plot_option("life against load")


@app.command("life")
@takes(argument="designation", files=LIFE.files, **LIFE.command_options)
def life_command(values, json_output: JsonOpt = False, plot=None):
    """Load ratings C, C0, Cu, equivalent loads, basic and modified rating life."""
    check_path("plot", plot)
    r = LIFE(values)
    out = r.to_dict()
    if _plot_and_emit(out, json_output, r.result, plot):
        return
    _print(r.result, out, r.bearing)


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
    console.print(escape(geometry_line(bearing)))
    factors = ", ".join(
        f"{name} {out[key]:.4g}"
        for name, key in (("f_c", "fc"), ("f_0", "f0"), ("b_m", "rating_factor_bm"))
        if out[key] is not None
    )
    console.print(
        escape(
            f"{factors}; X {out['x_factor']:.3g}, Y {out['y_factor']:.3g}, "
            f"e {'-' if out['e_limit'] is None else format(out['e_limit'], '.3g')}; "
            f"a_1 {out['a1']:.3g} at "
            f"{out['reliability_percent']:g} %"
        ),
        style="dim",
    )
    _print_warnings(out["warnings"])
