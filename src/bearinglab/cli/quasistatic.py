"""Commands of the load-distribution issue: static, stiffness-map, ring-modes."""

from pathlib import Path

import numpy as np
from rich.markup import escape

from ..analyses.mechanics import STATIC
from ..analyses.stiffness import STIFFNESS_MAP
from ..files import write_atomically
from ..inputs import geometry_line
from ..inputs.specs import form_errors_text
from ..units import label
from ._app import command_app, console
from ._inputs import (
    JsonOpt,
    OptionError,
    _print_warnings,
    check_path,
    save_plot_figure,
    takes,
    writing,
)
from ._output import _emit_json, _table, progress_bar

app = command_app()


@app.command()
@takes(argument="designation", files=STATIC.files, **STATIC.command_options)
def static(values, json_output: JsonOpt = False, plot=None, orbit_plot=None, stiffness_csv=None):
    """Quasi-static load distribution: per-ball (per-roller) loads and contact angles, ring
    displacements and the 5x5 stiffness matrix; with form errors (waviness, ball-size
    errors, 3-D surfaces) at the instant the shaft angle is 0, and with --orbit the
    inner-ring centre orbit."""
    for name, path in (("plot", plot), ("orbit_plot", orbit_plot)):
        check_path(name, path, (".png", ".svg", ".pdf"))
    check_path("stiffness_csv", stiffness_csv, (".csv",))
    values["orbit"] = values["orbit"] or orbit_plot is not None
    r = STATIC(values)
    result, o, d = r.distribution, r.orbit, r.to_dict()
    if plot is not None:
        save_plot_figure(r.plot()[0], plot)
    if orbit_plot is not None:
        save_plot_figure(o.plot_both()[0], orbit_plot, "--orbit-plot")
    if stiffness_csv is not None:
        _write_csv(result.stiffness_frame(), stiffness_csv, index=True, flag="--stiffness-csv")
    if json_output:
        _emit_json(d)
        return
    roller = r.bearing.rolling_element == "roller"
    elements = d["rollers" if roller else "balls"]
    # column -> header with its unit (Greek symbols keep the table within 80 columns)
    headers = {
        "roller" if roller else "ball": "roller" if roller else "ball",
        "angle_deg": label("ψ", "deg"),
        "inner_load_n": label("Q_i", "n"),
        "outer_load_n": label("Q_o", "n"),
        "inner_contact_angle_deg": label("α_i", "deg"),
        "outer_contact_angle_deg": label("α_o", "deg"),
        "inner_max_pressure_gpa": label("p_i", "gpa"),
        "outer_max_pressure_gpa": label("p_o", "gpa"),
        "contact_points": "points",
        "end_load_ratio": "end load",
    }
    cols = {c: h for c, h in headers.items() if c in elements[0]}
    console.print(
        _table(
            f"{r.bearing.name or 'bearing'}: F_r = {d['radial_load_n']:g} N, "
            f"F_a = {d['axial_load_n']:g} N, {d['speed_rpm']:g} rpm"
            + (f", {d['slices']} slices per roller" if roller else "")
            + (", with EHL film" if values["film"] else "")
            + (
                f", gyroscopic ({d['race_control']} raceway control)"
                if values["gyroscopic"]
                else ""
            ),
            list(cols.values()),
            [[element[c] for c in cols] for element in elements],
        )
    )
    console.print(escape(geometry_line(r.bearing)))
    if r.imperfections is not None:
        console.print(
            escape(
                f"form errors: {form_errors_text(r.imperfections)} (the load "
                "distribution at shaft angle 0, ball 0 under the load)"
            )
        )
    console.print(
        _table(
            "Inner ring",
            ["quantity", "value", "unit"],
            [
                ["radial displacement S_r", _clean(d["radial_displacement_um"]), "µm"],
                ["axial displacement S_a", _clean(d["axial_displacement_um"]), "µm"],
                ["tilt about x, y", ", ".join(f"{_clean(t):.4g}" for t in d["tilt_mrad"]), "mrad"],
                [
                    "max roller load" if roller else "max ball load",
                    d[f"max_{'roller' if roller else 'ball'}_load_n"],
                    "N",
                ],
                ["radial stiffness C_r", d["radial_stiffness_n_per_um"], "N/µm"],
                ["axial stiffness C_a", d["axial_stiffness_n_per_um"], "N/µm"],
            ]
            + (
                [
                    ["orbit peak to peak", d["orbit_peak_to_peak_um"], "µm"],
                    ["orbit", o.describe(), ""],
                ]
                if o is not None
                else []
            ),
        )
    )
    k = result.stiffness_matrix_shown()
    console.print(
        _table(
            "Stiffness matrix (rows x, y, z: N/µm and N/mrad; tilt rows: N·m/µm and N·m/mrad)",
            ["", *d["stiffness_matrix_order"]],
            [
                [name, *(k[i] * np.array([1e-6] * 3 + [1e-3] * 2))]
                for i, name in enumerate(d["stiffness_matrix_order"])
            ],
        )
    )
    _print_warnings(d["warnings"])


def _clean(value: float, floor: float = 1e-9) -> float:
    """Solver round-off (|value| < floor in the shown unit) as 0, not 3.5e-14."""
    return 0.0 if abs(value) < floor else value


@app.command("stiffness-map")
@takes(argument="designation", files=STIFFNESS_MAP.files, **STIFFNESS_MAP.command_options)
def stiffness_map(values, json_output: JsonOpt = False, output=None, plot=None):
    """Radial and axial stiffness (and displacements) over a grid of loads and speeds."""
    check_path("plot", plot, (".png", ".svg", ".pdf"))
    check_path("output", output)
    with progress_bar("solving cases", enabled=not json_output) as update:
        r = STIFFNESS_MAP(
            values, progress=lambda done, total: update(done / total, f"solving {done} of {total}")
        )
    table, solved = r.table, r.solved
    total = len(table)
    figure = None if plot is None else r.plot()[0]  # before anything is written
    if output is not None:
        _write_csv(table, output)
    if figure is not None:
        save_plot_figure(figure, plot)
    if json_output:
        _emit_json(r.to_dict())
        return
    bearing, warnings = r.bearing, list(r.warnings)
    headers = {
        "radial_load_n": label("F_r", "n"),
        "axial_load_n": label("F_a", "n"),
        "speed_rpm": label("n", "rpm"),
        "radial_displacement_um": label("S_r", "um"),
        "axial_displacement_um": label("S_a", "um"),
        "radial_stiffness_n_per_um": label("C_r", "n_per_um"),
        "axial_stiffness_n_per_um": label("C_a", "n_per_um"),
    }
    shown = [c for c in headers if c in table]
    shown_rows = solved[shown]
    if len(shown_rows) > 40:  # a readable sample; the whole grid is in the CSV / JSON
        shown_rows = shown_rows.iloc[np.linspace(0, len(shown_rows) - 1, 40).astype(int)]
    console.print(
        _table(
            f"{bearing.name or 'bearing'}: stiffness over {total} cases"
            + (f" (40 of {len(solved)} shown)" if len(solved) > 40 else ""),
            [headers[c] for c in shown],
            shown_rows.to_numpy().tolist(),
        )
    )
    failed = total - len(solved) - int((table["status"] == "no load").sum())
    if failed:
        console.print(
            f"[yellow]{failed} case(s) did not converge (see the CSV/JSON status)[/yellow]"
        )
    _print_warnings(warnings)


def _write_csv(table, path: Path, index: bool = False, flag: str = "--output") -> None:
    """Write atomically: a temporary file in the same directory, then rename."""
    if path.parent and not path.parent.exists():
        raise OptionError(flag, str(path), "a path in an existing directory")
    with writing(flag, path):
        write_atomically(path, lambda tmp: table.to_csv(tmp, index=index))
