"""Commands of the foundation: info, frequencies, contact."""

import math

from rich.markup import escape

from ..analyses.mechanics import FREQUENCIES
from ..catalog import boundary_dimensions, published_geometry
from ..designation import parse
from ..errors import CatalogError, DesignationError
from ..geometry import BallBearing
from ..inputs import BEARING, Input, bearing_from, bearing_warnings, geometry_line
from ..kinematics import FREQUENCY_NAMES, LONG_NAMES, defect_frequencies
from ._app import command_app, console
from ._inputs import JsonOpt, PlotOpt, _print_warnings, in_flags, takes
from ._output import _check_finite, _emit_json, _plot_and_emit, _References, _table

app = command_app()


@app.command()
@takes(*BEARING, argument="designation")
def info(values, json_output: JsonOpt = False):
    """Decode a designation; show dimensions, internal geometry (with sources) and
    frequency factors."""
    designation = values["designation"]
    decoded = None
    try:
        bearing, from_catalog = bearing_from(values)
    except CatalogError as exc:  # roller bearings, sizes not in the catalogue...
        bearing, from_catalog, why_no_geometry = None, None, in_flags(str(exc))
    else:
        why_no_geometry = None
    if designation:
        try:
            decoded = from_catalog or parse(designation, system=values["system"])
        except DesignationError:
            if published_geometry(designation) is None:  # not a catalogue name either
                raise
    if bearing is None and decoded is None:
        raise CatalogError(why_no_geometry)
    dims = why_no_dims = None
    if bearing is None:
        try:
            dims = boundary_dimensions(decoded)
        except CatalogError as exc:
            why_no_dims = str(exc)
    warnings = [] if bearing is None else bearing_warnings(bearing)
    out = _info_dict(designation, decoded, bearing, dims, why_no_geometry, why_no_dims, warnings)
    if json_output:
        _emit_json(out)
        return
    _check_finite(out)
    if decoded is not None:
        _print_designation(decoded)
    if bearing is None:
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
            console.print(f"bore d = {decoded.bore_mm:g} mm (from the designation)")
            console.print(f"[yellow]no boundary dimensions:[/yellow] {escape(why_no_dims)}")
        console.print(f"[yellow]no internal geometry:[/yellow] {escape(why_no_geometry)}")
        return
    _print_bearing(bearing)
    _print_warnings(warnings)


def _info_dict(text, decoded, bearing, dims, why_no_geometry, why_no_dims, warnings) -> dict:
    out = {
        "designation": text,
        "system": decoded.system if decoded else None,
        "bearing_type": (decoded.bearing_type if decoded else bearing.bearing_type),
    }
    if bearing is not None:
        out.update(bearing.to_dict())
        out["designation"] = text
        f = defect_frequencies(bearing, 2 * math.pi)
        out["frequency_factors"] = {f"{n}_order": f.orders[n] for n in FREQUENCY_NAMES}
    else:
        out.update(
            {
                "bore_mm": decoded.bore_mm,
                "outside_diameter_mm": None if dims is None else dims.outside_diameter * 1e3,
                "width_mm": None if dims is None else dims.width * 1e3,
                "ball_count": None,
                "ball_diameter_mm": None,
                "pitch_diameter_mm": None,
                "contact_angle_deg": decoded.contact_angle_deg,
                "geometry_source": None,
                "dimensions": None if dims is None else dims.to_dict(),
                "dimensions_standard": None if dims is None else dims.standard,
                "no_dimensions_reason": why_no_dims,
                "no_geometry_reason": why_no_geometry,
            }
        )
        if dims is not None:
            out["bore_mm"] = dims.bore * 1e3
    out["warnings"] = warnings
    if decoded is not None:
        out["decoded"] = decoded.to_dict()
    return out


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


def _print_bearing(b: BallBearing) -> None:
    refs = _References()
    _source_text = refs.cell
    rows = [
        ["bore d", b.bore and b.bore * 1e3, "mm", _source_text(b, "bore")],
        [
            "outside diameter D",
            b.outside_diameter and b.outside_diameter * 1e3,
            "mm",
            _source_text(b, "outside_diameter"),
        ],
        ["width B", b.width and b.width * 1e3, "mm", _source_text(b, "width")],
        ["balls Z", b.ball_count, "", _source_text(b, "ball_count")],
        ["ball diameter D_w", b.ball_diameter * 1e3, "mm", _source_text(b, "ball_diameter")],
        ["pitch diameter d_m", b.pitch_diameter * 1e3, "mm", _source_text(b, "pitch_diameter")],
        [
            "inner groove factor f_i",
            b.inner_groove_factor,
            "",
            _source_text(b, "inner_groove_factor"),
        ],
        [
            "outer groove factor f_o",
            b.outer_groove_factor,
            "",
            _source_text(b, "outer_groove_factor"),
        ],
        [
            "contact angle (nominal)",
            math.degrees(b.contact_angle),
            "deg",
            _source_text(b, "contact_angle"),
        ],
        [
            "diametral clearance P_d",
            b.diametral_clearance * 1e6,
            "um",
            _source_text(b, "diametral_clearance"),
        ],
    ]
    console.print(
        _table(
            f"Geometry (source: {b.geometry_source})", ["quantity", "value", "unit", "source"], rows
        )
    )
    refs.print()
    d = b.to_dict()
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
    console.print(
        _table(
            "Frequency factors (orders of shaft speed, inner ring rotating)",
            ["frequency", "order", "meaning"],
            [
                [
                    n.upper() if n != "ball_defect" else "ball defect (2xBSF)",
                    f.orders[n],
                    LONG_NAMES[n],
                ]
                for n in FREQUENCY_NAMES
            ],
        )
    )


@app.command()
@takes(argument="designation", defaults={"speed_rpm": ...}, **FREQUENCIES.command_options)
def frequencies(values, json_output: JsonOpt = False, plot: PlotOpt = None):
    """Kinematic defect frequencies (pure rolling) in Hz and as orders."""
    r = FREQUENCIES.run(values)
    f, out, warnings = r.result, r.to_dict(), list(r.warnings)
    if _plot_and_emit(out, json_output, f, plot):
        return
    bearing, speed_rpm, outer_rotating = f.bearing, values["speed_rpm"], values["outer_rotating"]
    ring = "outer" if outer_rotating else "inner"
    console.print(
        _table(
            f"{bearing.name or 'bearing'} at {speed_rpm:g} rpm ({ring} ring "
            f"rotating, contact angle {math.degrees(f.contact_angle):g} deg)",
            ["frequency", "Hz", "order", "meaning"],
            [["shaft", f.shaft_hz, 1.0, LONG_NAMES["shaft"]]]
            + [
                [
                    n.upper() if n != "ball_defect" else "BALL DEFECT",
                    f.hz(n),
                    f.orders[n],
                    LONG_NAMES[n],
                ]
                for n in FREQUENCY_NAMES
            ],
        )
    )
    console.print(escape(geometry_line(bearing, f.contact_angle)))
    console.print(
        "[dim]BSF is one spin revolution; a ball defect strikes the races at "
        "2 x BSF (some tables print that as 'ball spin').[/dim]"
    )
    _print_warnings(warnings)


@app.command()
@takes(
    *BEARING,
    argument="designation",
    ball_load_n=Input(
        "number",
        ...,
        "Normal load on one ball [N].",
        low=0.0,
        high=1e7,
        low_open=True,
        what="a load",
    ),
    method=Input(
        "text",
        "exact",
        "Ellipticity and elliptic integrals: exact or Hamrock-Brewe.",
        choices=("exact", "hamrock-brewe"),
    ),
)
def contact(values, json_output: JsonOpt = False, plot: PlotOpt = None):
    """Hertz contact of one ball with the inner and outer raceway."""
    designation, ball_load_n, method = (values[k] for k in ("designation", "ball_load_n", "method"))
    bearing, decoded = bearing_from(values)
    from ..contact.ball_race import ball_contacts  # scipy.special: only this command

    result = ball_contacts(bearing, ball_load_n, method=method.replace("-", "_"))
    d = result.to_dict()
    d["warnings"] = bearing_warnings(bearing, decoded) + d["warnings"]
    out = {"designation": designation, **d}
    if _plot_and_emit(out, json_output, result, plot):
        return
    rows = []
    for key, label, unit in (
        ("semi_major_mm", "semi-major axis a", "mm"),
        ("semi_minor_mm", "semi-minor axis b", "mm"),
        ("ellipticity", "ellipticity k = a/b", ""),
        ("max_pressure_gpa", "max pressure p_max", "GPa"),
        ("mean_pressure_gpa", "mean pressure", "GPa"),
        ("approach_um", "approach delta", "um"),
        ("stiffness_n_per_um", "stiffness dQ/d(delta)", "N/um"),
    ):
        rows.append([label, d["inner"][key], d["outer"][key], unit])
    console.print(
        _table(
            f"{bearing.name or 'bearing'}: Hertz contact, Q = {ball_load_n:g} N, "
            f"contact angle {d['contact_angle_deg']:g} deg ({method})",
            ["quantity", "inner", "outer", "unit"],
            rows,
        )
    )
    console.print(escape(geometry_line(bearing, result.contact_angle)))
    console.print(
        f"ball between both races: total approach {d['total_approach_um']:.4g} um, "
        f"K_n = {d['ball_load_deflection_constant_n_per_um1_5']:.4g} N/µm^1.5"
    )
    _print_warnings(d["warnings"])
