"""The friction command: torque and power loss by seed 003's constant coefficient or by
the SKF four-component model. Parses the options and calls
:func:`bearinglab.friction.bearing_friction`, which holds every rule (equivalent load,
C_0, seals, viscosity, lubrication); the report calls the same function."""

from rich.markup import escape

from ..analyses.operation import FRICTION
from ..units import label, unit_of
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, takes
from ._output import _emit_json, _number, _table

app = command_app()


@app.command("friction")
@takes(argument="designation", **FRICTION.command_options)
def friction_command(values, json_output: JsonOpt = False):
    """Friction torque and power loss: seed 003's constant coefficient or the SKF model."""
    r = FRICTION(values)
    out = r.to_dict()
    if json_output:
        _emit_json(out)
        return
    _print(r.result, out)
    _print_warnings(out["warnings"])


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
