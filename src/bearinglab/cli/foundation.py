"""Commands of the foundation: info, frequencies, contact."""

import math

from rich.markup import escape

from ..analyses.foundation import CONTACT, FREQUENCIES, INFO
from ..contact.ball_race import SUMMARY as BALL_SUMMARY
from ..contact.roller_race import SUMMARY as ROLLER_SUMMARY
from ..inputs import geometry_line, geometry_rows
from ..kinematics import FREQUENCY_NAMES, LONG_NAMES, defect_frequencies
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, in_flags, takes
from ._output import _check_finite, _emit_json, _plot_and_emit, _References, _table

app = command_app()


@app.command()
@takes(argument="designation", **INFO.command_options)
def info(values, json_output: JsonOpt = False):
    """Decode a designation; show dimensions, internal geometry (with sources) and
    frequency factors."""
    r = INFO(values)
    out = r.to_dict()
    if out.get("no_geometry_reason"):  # the inputs it names, as this command's flags
        out["no_geometry_reason"] = in_flags(out["no_geometry_reason"])
    if json_output:
        _emit_json(out)
        return
    _check_finite(out)
    if r.decoded is not None:
        _print_designation(r.decoded)
    if r.bearing is None:
        dims = r.dimensions
        if dims is not None:
            console.print(
                _table(
                    "Boundary dimensions",
                    ["quantity", "value", "unit", "source"],
                    [
                        ["bore d", dims.bore * 1e3, "mm", dims.standard],
                        ["outside diameter D", dims.outside_diameter * 1e3, "mm", dims.standard],
                        ["width B", dims.width * 1e3, "mm", dims.standard],
                    ],
                )
            )
        else:
            console.print(f"bore d = {r.decoded.bore_mm:g} mm (from the designation)")
            console.print(f"[yellow]no boundary dimensions:[/yellow] {escape(r.why_no_dimensions)}")
        console.print(
            f"[yellow]no internal geometry:[/yellow] {escape(in_flags(r.why_no_geometry))}"
        )
        return
    _print_bearing(r.bearing)
    _print_warnings(out["warnings"])


def _print_designation(d) -> None:
    console.print(
        f"[bold]{escape(d.text)}[/bold] - {escape(d.description)} "
        f"[dim]({'GOST 3189-89' if d.system == 'gost' else 'ISO'} reading)[/dim]"
    )
    console.print(_table("Designation", ["part", "meaning"], [list(p) for p in d.parts]))
    equivalents = [
        f"ISO {d.iso_equivalent}" if d.iso_equivalent and d.system == "gost" else None,
        f"GOST {d.gost_equivalent}" if d.gost_equivalent and d.system == "iso" else None,
    ]
    equivalents = [e for e in equivalents if e]
    if equivalents:
        console.print("Equivalent: " + escape(", ".join(equivalents)))
    for note in d.notes:
        console.print(f"[yellow]note:[/yellow] {escape(in_flags(note))}")


def _print_bearing(b) -> None:
    refs = _References()
    rows = [
        [f"{label} {symbol}", value, "" if unit == "-" else unit, refs.cell(b, name)]
        for name, label, symbol, value, unit in geometry_rows(b)
    ]
    console.print(
        _table(
            f"Geometry (source: {b.geometry_source})", ["quantity", "value", "unit", "source"], rows
        )
    )
    refs.print()
    d = b.to_dict()
    if b.rolling_element == "roller":
        derived = [
            ["inner raceway d_i", d["inner_raceway_diameter_mm"], "mm"],
            ["outer raceway d_o", d["outer_raceway_diameter_mm"], "mm"],
            ["cone angle", d["cone_angle_deg"], "deg"],
            ["roller profile", d["roller_profile"]["kind"], ""],
            ["roller mass", d["roller_mass_g"], "g"],
        ]
    else:
        derived = [
            ["inner raceway (groove bottom) d_i", d["inner_raceway_diameter_mm"], "mm"],
            ["outer raceway (groove bottom) d_o", d["outer_raceway_diameter_mm"], "mm"],
            ["free contact angle", d["free_contact_angle_deg"], "deg"],
            ["end play P_e", d["end_play_um"], "um"],
            ["ball mass", d["ball_mass_g"], "g"],
        ]
    for key, label, unit in (
        ("inner_ring_mass_g", "inner ring mass", "g"),
        ("outer_ring_mass_g", "outer ring mass", "g"),
    ):
        if key in d:
            derived.append([label, d[key], unit])
    console.print(_table("Derived", ["quantity", "value", "unit"], derived))
    f = defect_frequencies(b, 2 * math.pi)
    element = b.rolling_element
    console.print(
        _table(
            "Frequency factors (orders of shaft speed, inner ring rotating)",
            ["frequency", "order", "meaning"],
            [
                [
                    n.upper() if n != "ball_defect" else f"{element} defect (2xBSF)",
                    f.orders[n],
                    LONG_NAMES[n].replace("ball", element),
                ]
                for n in FREQUENCY_NAMES
            ],
        )
    )


@app.command()
@takes(argument="designation", files=FREQUENCIES.files, **FREQUENCIES.command_options)
def frequencies(values, json_output: JsonOpt = False, plot=None):
    """Kinematic defect frequencies (pure rolling) in Hz and as orders."""
    r = FREQUENCIES(values)
    f, out, warnings = r.result, r.to_dict(), list(r.warnings)
    if _plot_and_emit(out, json_output, f, plot):
        return
    bearing, speed_rpm, outer_rotating = f.bearing, values["speed_rpm"], values["outer_rotating"]
    ring = "outer" if outer_rotating else "inner"
    element = bearing.rolling_element
    console.print(
        _table(
            f"{bearing.name or 'bearing'} at {speed_rpm:g} rpm ({ring} ring "
            f"rotating, contact angle {math.degrees(f.contact_angle):g} deg)",
            ["frequency", "Hz", "order", "meaning"],
            [["shaft", f.shaft_hz, 1.0, LONG_NAMES["shaft"]]]
            + [
                [
                    n.upper() if n != "ball_defect" else f"{element.upper()} DEFECT",
                    f.hz(n),
                    f.orders[n],
                    LONG_NAMES[n].replace("ball", element),
                ]
                for n in FREQUENCY_NAMES
            ],
        )
    )
    console.print(escape(geometry_line(bearing, f.contact_angle)))
    console.print(
        f"[dim]BSF is one spin revolution; a {element} defect strikes the races at "
        "2 x BSF (some tables print that as 'ball spin').[/dim]"
    )
    _print_warnings(warnings)


@app.command()
@takes(argument="designation", files=CONTACT.files, **CONTACT.command_options)
def contact(values, json_output: JsonOpt = False, plot=None):
    """Hertz contact of one ball or roller with the inner and outer raceway."""
    r = CONTACT(values)
    result, bearing, d = r.result, r.bearing, r.to_dict()
    ball_load_n, method = values["ball_load_n"], values["hertz_method"]
    if _plot_and_emit(d, json_output, result, plot):
        return
    if bearing.rolling_element == "roller":
        _print_roller_contact(d, bearing)
        return
    console.print(
        _table(
            f"{bearing.name or 'bearing'}: Hertz contact, Q = {ball_load_n:g} N, "
            f"contact angle {d['contact_angle_deg']:g} deg ({method})",
            ["quantity", "inner", "outer", "unit"],
            _both(d, BALL_SUMMARY),
        )
    )
    console.print(escape(geometry_line(bearing, result.contact_angle)))
    console.print(
        f"ball between both races: total approach {d['total_approach_um']:.4g} um, "
        f"K_n = {d['ball_load_deflection_constant_n_per_um1_5']:.4g} N/µm^1.5"
    )
    _print_warnings(d["warnings"])


def _print_roller_contact(d: dict, bearing) -> None:
    """A roller's line contact: pressures, half-width, approach, inner and outer."""
    console.print(
        _table(
            f"{bearing.name or 'bearing'}: line contact of one roller, Q = "
            f"{d['roller_load_n']:g} N, tilt {d['tilt_mrad']:g} mrad "
            f"({len(d['slice_loads_n'])} slices)",
            ["quantity", "inner", "outer", "unit"],
            _both(d, ROLLER_SUMMARY),
        )
    )
    console.print(escape(geometry_line(bearing)))
    console.print(
        f"roller between both races: total approach {d['roller_approach_um']:.4g} um "
        f"(Palmgren's 3.84e-5 Q^0.9 / l^0.8: {d['palmgren_approach_um']:.4g} um)"
    )
    _print_warnings(d["warnings"])


def _both(d: dict, summary) -> list[list]:
    """The rows of a contacts table: each quantity of ``summary`` at both races."""
    return [[label, d["inner"][k], d["outer"][k], "" if u == "-" else u] for k, label, u in summary]
