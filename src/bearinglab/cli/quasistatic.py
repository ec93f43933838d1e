"""Commands of the load-distribution issue: static, stiffness-map, ring-modes."""

import math
from enum import Enum
from pathlib import Path
from typing import Annotated

import numpy as np
import typer
from rich.markup import escape

from ..errors import InputError
from ..files import write_atomically
from ..lubrication import LUBRICANTS, ZERO_CELSIUS
from ..operating import OperatingCondition
from ..plausibility import operating_warnings
from ..plotting import stiffness_map_figure
from ..quasistatic import solve_load_distribution
from ..quasistatic.orbit import inner_ring_orbit
from ..quasistatic.study import stiffness_map as stiffness_map_study
from ..units import label
from ._app import command_app, console
from ._forms import BallErrorOpt, FormErrors, SeedOpt, Surface3dOpt, WavinessOpt
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
    PlotOpt,
    RadialLoadOpt,
    _print_warnings,
    in_range,
    load_n,
    no_effect,
    option_error,
    save_plot_figure,
    speed_rad_s,
    writing,
)
from ._output import _emit_json, _table, progress_bar

app = command_app()

MAX_CASES = 1_000_000


class RaceControl(str, Enum):
    outer = "outer"
    inner = "inner"
    hybrid = "hybrid"


RaceControlOpt = Annotated[
    RaceControl,
    typer.Option(
        "--race-control",
        help="Raceway control that sets each ball's orbital speed (centrifugal "
        "force) and spin (gyroscopic moment): outer or inner (the ball rolls without spinning on "
        "that race, Jones), or hybrid (per ball by Jones's criterion, friction shared as Harris "
        "does).",
    ),
]

#: static and stiffness-map share --gyroscopic.
GyroscopicOpt = Annotated[
    bool,
    typer.Option(
        "--gyroscopic",
        help="Include the balls' gyroscopic moments, held by friction at the controlling "
        "raceway (--race-control).",
    ),
]


def _grid(flag: str, text: str, signed: bool = False, speed: bool = False) -> np.ndarray:
    """'a:b:n' (n values from a to b), 'a,b,c' or a single value."""
    try:
        if ":" in text:
            a, b, n = text.split(":")
            values = np.linspace(float(a), float(b), int(n))
            if int(n) < 1 or int(n) > 10000:
                raise ValueError
        else:
            values = np.array([float(v) for v in text.split(",")])
    except ValueError:
        raise OptionError(
            flag, text, "START:STOP:COUNT (COUNT 1..10000), a list A,B,C or one value"
        ) from None
    for v in values:
        speed_rad_s(v, zero=True) if speed else load_n(flag, v, signed)
    return values


def _condition(radial, axial, speed_rpm, angle_deg, misalignment_mrad):
    if not math.isfinite(angle_deg):
        raise OptionError("--radial-load-angle-deg", angle_deg, "a finite angle")
    if not (math.isfinite(misalignment_mrad) and abs(misalignment_mrad) <= 20):
        raise OptionError("--misalignment-mrad", misalignment_mrad, "a tilt within +-20 mrad")
    # the tilt is about the axis perpendicular to the radial load in the radial plane
    a = math.radians(angle_deg)
    tilt = misalignment_mrad * 1e-3
    return OperatingCondition(
        radial_load=radial,
        radial_load_angle=a,
        axial_load=axial,
        misalignment=(-tilt * math.sin(a), tilt * math.cos(a)),
        shaft_speed=speed_rad_s(speed_rpm, zero=True),
    )


#: The film's lubricant when --lubricant is not given.
DEFAULT_LUBRICANT = "iso-vg68"


def _lubricant(film: bool, name: str, temperature_c: float | None):
    """The film's lubricant and temperature [K] (None, None without --film), and the
    warnings for lubricant options that then have no effect."""
    if name not in LUBRICANTS:
        raise OptionError("--lubricant", name, f"one of {', '.join(LUBRICANTS)}")
    in_range("--temperature-c", temperature_c, -60.0, 300.0, "a temperature")
    if not film:
        flags = (
            ("--lubricant", name != DEFAULT_LUBRICANT),
            ("--temperature-c", temperature_c is not None),
        )
        return None, None, no_effect(flags, "without --film (the EHL film)")
    kelvin = None if temperature_c is None else temperature_c + ZERO_CELSIUS
    return LUBRICANTS[name], kelvin, []


@app.command()
@with_geometry
def static(
    designation: DesignationArg = None,
    radial_load_n: RadialLoadOpt = 0.0,
    axial_load_n: AxialLoadOpt = 0.0,
    speed_rpm: Annotated[float, typer.Option("--speed-rpm", help="Inner-ring speed [rpm].")] = 0.0,
    radial_load_angle_deg: Annotated[
        float,
        typer.Option(
            "--radial-load-angle-deg",
            help="Direction of the radial load from +x towards +y [deg]; -90 = downwards.",
        ),
    ] = -90.0,
    misalignment_mrad: Annotated[
        float,
        typer.Option(
            "--misalignment-mrad",
            help="Imposed tilt of the inner ring about the axis across the radial load [mrad].",
        ),
    ] = 0.0,
    film: Annotated[
        bool,
        typer.Option(
            "--film/--no-film", help="Subtract the Hamrock-Dowson film from the approaches."
        ),
    ] = False,
    lubricant: Annotated[
        str, typer.Option("--lubricant", help="Lubricant for the film: " + ", ".join(LUBRICANTS))
    ] = DEFAULT_LUBRICANT,
    temperature_c: Annotated[
        float | None,
        typer.Option(
            "--temperature-c",
            help="Lubricant temperature [degC] (default: its reference).",
        ),
    ] = None,
    gyroscopic: GyroscopicOpt = False,
    race_control: RaceControlOpt = RaceControl.outer,
    ring_expansion: Annotated[
        bool,
        typer.Option(
            "--ring-expansion",
            help="Reduce the clearance by the inner ring's centrifugal expansion.",
        ),
    ] = False,
    orbit: Annotated[
        bool,
        typer.Option(
            "--orbit",
            help="Also the inner-ring centre orbit: over one ball spacing "
            "(uniform balls), or, with form errors, in time over one cage revolution "
            "(seed 003 eqs. 14-18; needs --speed-rpm > 0).",
        ),
    ] = False,
    orbit_points: Annotated[
        int | None,
        typer.Option(
            "--orbit-points",
            help="Orbit positions: per ball spacing (default 24) or "
            "instants in time (default 64 per shaft revolution).",
        ),
    ] = None,
    orbit_plot: Annotated[
        Path | None,
        typer.Option(
            "--orbit-plot",
            help="Draw the orbit, the displacements and the ball centres "
            "to this .png, .svg or .pdf file (implies --orbit).",
        ),
    ] = None,
    waviness: WavinessOpt = None,
    ball_size_error_um: BallErrorOpt = None,
    surface3d: Surface3dOpt = None,
    seed: SeedOpt = None,
    stiffness_csv: Annotated[
        Path | None,
        typer.Option(
            "--stiffness-csv",
            help="Write the 5x5 stiffness matrix (SI) to this CSV.",
        ),
    ] = None,
    json_output: JsonOpt = False,
    plot: PlotOpt = None,
    *,
    geometry,
):
    """Quasi-static load distribution: per-ball loads and contact angles, ring
    displacements and the 5x5 stiffness matrix; with form errors (waviness, ball-size
    errors, 3-D surfaces) at the instant the shaft angle is 0, and with --orbit the
    inner-ring centre orbit."""
    fr = load_n("--radial-load-n", radial_load_n)
    fa = load_n("--axial-load-n", axial_load_n, signed=True)
    _check_output(
        ("--plot", plot), ("--stiffness-csv", stiffness_csv), ("--orbit-plot", orbit_plot)
    )
    for flag, path in (("--plot", plot), ("--orbit-plot", orbit_plot)):
        if path is not None and path.suffix.lower() not in (".png", ".svg", ".pdf"):
            raise OptionError(flag, str(path), "a file name ending in .png, .svg or .pdf")
    orbit = orbit or orbit_plot is not None
    in_range("--orbit-points", orbit_points, 2, 100_000, "an integer")
    condition = _condition(fr, fa, speed_rpm, radial_load_angle_deg, misalignment_mrad)
    oil, temperature, unused = _lubricant(film, lubricant, temperature_c)
    if condition.shaft_speed == 0:  # each of these acts through the balls' speed
        flags = (
            ("--gyroscopic", gyroscopic),
            ("--ring-expansion", ring_expansion),
            ("--film", film),
        )
        unused += no_effect(flags, "at --speed-rpm 0 (no rolling speed)")
    forms = FormErrors(waviness, ball_size_error_um, surface3d)
    if orbit and forms.given and condition.shaft_speed <= 0:
        raise OptionError(
            "--speed-rpm",
            speed_rpm,
            "a speed > 0 rpm with --orbit and form errors (the orbit then runs in time)",
        )
    bearing, _ = resolve_bearing(designation, geometry)
    try:
        plausibility = operating_warnings(bearing, condition)
    except InputError as exc:
        raise option_error(
            exc,
            {"radial_load_n": radial_load_n, "axial_load_n": axial_load_n, "speed_rpm": speed_rpm},
        ) from None
    imperfections = forms.build(bearing, seed)
    options = {
        "lubricant": oil,
        "temperature": temperature,
        "gyroscopic": gyroscopic,
        "race_control": race_control.value,
        "ring_expansion": ring_expansion,
    }
    errors = (
        None
        if imperfections is None  # the form errors at t = 0, ball 0 under the load
        else imperfections.diameter_errors_at_rest(bearing, condition.radial_load_angle)
    )
    result = solve_load_distribution(bearing, condition, ball_diameter_errors=errors, **options)
    d = result.to_dict()
    d["warnings"] = _geometry_warnings(bearing) + plausibility + unused + d["warnings"]
    out = {"designation": designation, **d}
    if imperfections is not None:
        out["imperfections"] = imperfections.to_dict()
        out["seed"] = 0 if seed is None else seed
        out["effective_diameter_error_um"] = (errors * 1e6).tolist()
    o = None
    if orbit:
        o = inner_ring_orbit(
            bearing, condition, imperfections=imperfections, points=orbit_points, **options
        )
        out["orbit_kind"] = "time" if o.time is not None else "ball_set"
        out["orbit"] = o.to_dict()
        out["orbit_peak_to_peak_um"] = o.peak_to_peak * 1e6
    if plot is not None:
        save_plot_figure(result.plot()[0], plot)
    if orbit_plot is not None:
        _plot_orbit(o, orbit_plot)
    if stiffness_csv is not None:
        _write_csv(result.stiffness_frame(), stiffness_csv, index=True, flag="--stiffness-csv")
    if json_output:
        _emit_json(out)
        return
    balls = out["balls"]  # the JSON's per-ball rows (LoadDistribution.ball_rows)
    # column -> header with its unit (Greek symbols keep the table within 80 columns)
    cols = {
        "ball": "ball",
        "angle_deg": label("ψ", "deg"),
        "inner_load_n": label("Q_i", "n"),
        "outer_load_n": label("Q_o", "n"),
        "inner_contact_angle_deg": label("α_i", "deg"),
        "outer_contact_angle_deg": label("α_o", "deg"),
        "inner_max_pressure_gpa": label("p_i", "gpa"),
        "outer_max_pressure_gpa": label("p_o", "gpa"),
        "contact_points": "points",
    }
    console.print(
        _table(
            f"{bearing.name or 'bearing'}: F_r = {fr:g} N, F_a = {fa:g} N, "
            f"{speed_rpm:g} rpm"
            + (", with EHL film" if film else "")
            + (f", gyroscopic ({race_control.value} raceway control)" if gyroscopic else ""),
            list(cols.values()),
            [[ball[c] for c in cols] for ball in balls],
        )
    )
    console.print(escape(_geometry_line(bearing)))
    if imperfections is not None:
        from ._forms import form_errors_text

        console.print(
            escape(
                f"form errors: {form_errors_text(imperfections)} (the load "
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
                ["max ball load", d["max_ball_load_n"], "N"],
                ["radial stiffness C_r", d["radial_stiffness_n_per_um"], "N/µm"],
                ["axial stiffness C_a", d["axial_stiffness_n_per_um"], "N/µm"],
            ]
            + (
                [
                    ["orbit peak to peak", out["orbit_peak_to_peak_um"], "µm"],
                    ["orbit", _orbit_text(o), ""],
                ]
                if orbit
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


def _orbit_text(o) -> str:
    if o.time is None:
        return (
            f"{o.x.size} positions over "
            f"{np.degrees(o.ball_phase[-1] - o.ball_phase[0]):.4g} deg of the ball set"
        )
    return f"{o.time.size} instants over {o.time.size * (o.time[1] - o.time[0]):.4g} s"


def _plot_orbit(o, path: Path) -> None:
    """Orbit (left), inner-ring displacements and ball-centre radii against time or the
    ball-set angle (right)."""
    from ..plotting import _pyplot

    plt = _pyplot()
    fig = plt.figure(figsize=(12, 5.5))
    grid = fig.add_gridspec(2, 2, width_ratios=(1, 1.4))
    o.plot(ax=fig.add_subplot(grid[:, 0]))
    right = fig.add_subplot(grid[0, 1])
    o.plot_history(axes=[right, fig.add_subplot(grid[1, 1], sharex=right)])
    fig.tight_layout()
    save_plot_figure(fig, path, "--orbit-plot")


@app.command("stiffness-map")
@with_geometry
def stiffness_map(
    designation: DesignationArg = None,
    radial_load_n: Annotated[
        str,
        typer.Option(
            "--radial-load-n", help="Radial loads: START:STOP:COUNT, A,B,C or one value [N]."
        ),
    ] = "0:2000:21",
    axial_load_n: Annotated[
        str, typer.Option("--axial-load-n", help="Axial loads [N], same forms.")
    ] = "0",
    speed_rpm: Annotated[str, typer.Option("--speed-rpm", help="Speeds [rpm], same forms.")] = "0",
    workers: Annotated[
        int,
        typer.Option(
            "--workers", help="Worker processes (default: all cores).", show_default=False
        ),
    ] = 0,
    gyroscopic: GyroscopicOpt = False,
    race_control: RaceControlOpt = RaceControl.outer,
    output: Annotated[
        Path | None,
        typer.Option("-o", "--output", help="Write the table to this CSV file."),
    ] = None,
    json_output: JsonOpt = False,
    plot: PlotOpt = None,
    *,
    geometry,
):
    """Radial and axial stiffness (and displacements) over a grid of loads and speeds."""
    radial = _grid("--radial-load-n", radial_load_n)
    axial = _grid("--axial-load-n", axial_load_n, signed=True)
    speeds = _grid("--speed-rpm", speed_rpm, speed=True)
    if not 0 <= workers <= 64:
        raise OptionError("--workers", workers, "0 (all cores) to 64")
    if len(radial) * len(axial) * len(speeds) > MAX_CASES:
        raise OptionError(
            "--radial-load-n",
            radial_load_n,
            f"a grid of at most {MAX_CASES:g} cases in all (radial x axial x speed counts)",
        )
    _check_output(("--plot", plot), ("--output", output))
    bearing, _ = resolve_bearing(designation, geometry)
    total = len(radial) * len(axial) * len(speeds)
    done = [0]

    def advance(n: int) -> None:
        done[0] += n
        update(done[0] / total, f"solving {done[0]} of {total} cases")

    with progress_bar(f"solving {total} cases", enabled=not json_output) as update:
        table = stiffness_map_study(
            bearing,
            radial,
            axial,
            speeds,
            workers=workers or None,
            progress=advance,
            gyroscopic=gyroscopic,
            race_control=race_control.value,
        )
    rows = table.to_dict(orient="records")
    solved = table[table["status"] == "ok"]
    if plot is not None and not len(solved):  # before anything is written
        raise OptionError(
            "--plot",
            str(plot),
            "a map with at least one solved case to draw",
            "no case of the map solved, status: " + ", ".join(sorted(set(table["status"]))),
        )
    if output is not None:
        _write_csv(table, output)
    if plot is not None:
        save_plot_figure(stiffness_map_figure(solved)[0], plot)
    if json_output:
        _emit_json(
            {
                "designation": designation,
                "cases": total,
                "solved": len(solved),
                "rows": [
                    {
                        k: (None if isinstance(v, float) and not math.isfinite(v) else v)
                        for k, v in row.items()
                    }
                    for row in rows
                ],
            }
        )
        return
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


def _check_output(*flags) -> None:
    """Refuse output paths in missing directories before any solving."""
    for flag, path in flags:
        if path is not None and not Path(path).parent.exists():
            raise OptionError(flag, str(path), "a path in an existing directory")


def _write_csv(table, path: Path, index: bool = False, flag: str = "--output") -> None:
    """Write atomically: a temporary file in the same directory, then rename."""
    if path.parent and not path.parent.exists():
        raise OptionError(flag, str(path), "a path in an existing directory")
    with writing(flag, path):
        write_atomically(path, lambda tmp: table.to_csv(tmp, index=index))
