"""The ``ring-modes`` command: the outer ring's natural frequencies in the loaded bearing
(seed 000, :func:`bearinglab.rings.ring_modes`), from a bearing or from the ring-level
inputs of the paper alone (ball count, ring mass, K_x or f_1, free-ring frequencies,
kappa)."""

import math
from enum import Enum
from typing import Annotated

import typer

from ..errors import InputError
from ..rings import ring_modes
from ._app import command_app, console
from ._geometry import (
    _geometry_warnings,
    resolve_bearing,
    with_geometry,
)
from ._inputs import (
    MAX_LOAD_N,
    DesignationArg,
    JsonOpt,
    OptionError,
    _print_warnings,
    check_path,
    in_range,
    no_effect,
    number_list,
    option_error,
    plot_option,
    save_plot_figure,
    typed,
)
from ._output import _emit_json, _table

app = command_app()
PlotOpt = plot_option("the frequencies")


class StiffnessSource(str, Enum):
    closed_form = "closed-form"
    load_distribution = "load-distribution"


#: The options that set K_x from the bearing at an axial load: (flag, parameter).
_AXIAL_OPTIONS = (("--axial-load-n", "axial_load_n"), ("--stiffness-from", "stiffness_from"))


def _modes(text: str) -> list[int]:
    try:
        if ":" in text:
            a, b = (int(v) for v in text.split(":"))
            ms = list(range(a, b + 1))
        else:
            ms = [int(v) for v in text.split(",")]
    except ValueError:
        ms = []
    if not ms or min(ms) < 1 or max(ms) > 50:
        raise OptionError("--modes", text, "FIRST:LAST or a list of mode numbers 1..50")
    return ms


def _ring_level_only(designation: str | None, geometry: dict) -> bool:
    """No designation and no ball geometry: the paper's own ring-level inputs."""
    ball_geometry = ("ball_diameter_mm", "pitch_diameter_mm", "geometry")
    return designation is None and all(geometry.get(k) is None for k in ball_geometry)


@app.command("ring-modes")
@with_geometry
def ring_modes_command(
    ctx: typer.Context,
    designation: DesignationArg = None,
    axial_load_n: Annotated[
        float, typer.Option("--axial-load-n", help="Axial load A [N], for K_x from the bearing.")
    ] = 200.0,
    modes: Annotated[
        str,
        typer.Option(
            "--modes", help="Modes FIRST:LAST or m1,m2,...; m = 1 is the rigid-body mode."
        ),
    ] = "2:6",
    ring_mass_kg: Annotated[
        float | None,
        typer.Option(
            "--ring-mass-kg",
            help="Vibrating mass of the outer ring incl. sensors [kg].",
        ),
    ] = None,
    radial_stiffness_n_per_m: Annotated[
        float | None,
        typer.Option(
            "--radial-stiffness-n-per-m",
            help="Radial bearing stiffness K_x [N/m].",
        ),
    ] = None,
    rigid_body_frequency_hz: Annotated[
        float | None,
        typer.Option(
            "--rigid-body-frequency-hz",
            help="f_1 of the ring on the ball springs [Hz] "
            "(instead of sqrt(K_x / ring mass) / 2 pi).",
        ),
    ] = None,
    free_frequencies_hz: Annotated[
        str | None,
        typer.Option(
            "--free-frequencies-hz",
            help="Measured free-ring frequencies f2,f3,... [Hz], one per flexural mode asked for.",
        ),
    ] = None,
    ball_mass_ratio: Annotated[
        float | None,
        typer.Option("--ball-mass-ratio", help="kappa = n m_b / m_k."),
    ] = None,
    contact_stiffness_ratio: Annotated[
        float | None,
        typer.Option(
            "--contact-stiffness-ratio",
            help="K1/K2 (outer over inner contact stiffness).",
        ),
    ] = None,
    stiffness_from: Annotated[
        StiffnessSource,
        typer.Option(
            "--stiffness-from",
            help="K_x from seed 000's closed form (axial load, contact "
            "angle) or from the load-distribution stiffness at the axial load.",
        ),
    ] = StiffnessSource.closed_form,
    json_output: JsonOpt = False,
    plot: PlotOpt = None,
    *,
    geometry,
):
    """Natural frequencies of the outer ring in the loaded bearing (seed 000).

    Give a bearing (designation or geometry), or the paper's ring-level inputs alone:
    --balls, --ring-mass-kg with --radial-stiffness-n-per-m (or --rigid-body-frequency-hz),
    --free-frequencies-hz and --ball-mass-ratio."""
    check_path("--plot", plot, (".png", ".svg", ".pdf"))
    ms = _modes(modes)
    flexural = [m for m in ms if m >= 2]
    free = number_list(
        "--free-frequencies-hz", free_frequencies_hz, "positive frequencies f2,f3,... [Hz]"
    )
    if free is not None:
        if len(free) != len(flexural):
            raise OptionError(
                "--free-frequencies-hz",
                free_frequencies_hz,
                f"{len(flexural)} values, one per flexural mode {flexural}",
            )
        free = dict(zip(flexural, free, strict=True))
    for flag, value in (
        ("--ring-mass-kg", ring_mass_kg),
        ("--radial-stiffness-n-per-m", radial_stiffness_n_per_m),
        ("--rigid-body-frequency-hz", rigid_body_frequency_hz),
        ("--ball-mass-ratio", ball_mass_ratio),
        ("--contact-stiffness-ratio", contact_stiffness_ratio),
    ):
        if value is not None and not (math.isfinite(value) and 0 < value < 1e15):
            raise OptionError(flag, value, "a finite value > 0")
    in_range("--axial-load-n", axial_load_n, 0.0, MAX_LOAD_N, "a load", low_open=True)
    if _ring_level_only(designation, geometry):
        bearing, ball_count = None, geometry.get("balls")
        if ball_count is None:
            raise OptionError(
                "DESIGNATION",
                None,
                "a designation, explicit geometry, or the "
                "ring-level inputs --balls, --ring-mass-kg with "
                "--radial-stiffness-n-per-m (or --rigid-body-frequency-hz), "
                "--free-frequencies-hz and --ball-mass-ratio",
            )
    else:
        (bearing, _), ball_count = resolve_bearing(designation, geometry), None
    try:
        result = ring_modes(
            bearing,
            axial_load=axial_load_n if bearing is not None else None,
            modes=ms,
            ring_mass=ring_mass_kg,
            radial_stiffness=radial_stiffness_n_per_m,
            rigid_body_frequency=rigid_body_frequency_hz,
            free_frequencies=free,
            ball_mass_ratio=ball_mass_ratio,
            contact_stiffness_ratio=contact_stiffness_ratio,
            ball_count=ball_count,
            radial_stiffness_from=stiffness_from.value.replace("-", "_"),
        )
    except InputError as exc:
        raise option_error(
            exc,
            {
                "ring_mass_kg": ring_mass_kg,
                "radial_stiffness_n_per_m": radial_stiffness_n_per_m,
                "rigid_body_frequency_hz": rigid_body_frequency_hz,
                "free_frequencies_hz": free_frequencies_hz,
                "ball_mass_ratio": ball_mass_ratio,
                "contact_stiffness_ratio": contact_stiffness_ratio,
                "balls": ball_count,
                "axial_load_n": axial_load_n,
            },
        ) from None
    if plot is not None:
        save_plot_figure(result.plot()[0], plot)
    d = result.to_dict()
    # the axial load gives K_x, from a bearing, when K_x is not given; given f1, K_x is
    # only reported (f1 fixes the contact stiffness)
    if d["axial_load_n"] is None:
        why = (
            "with --radial-stiffness-n-per-m (K_x is given)"
            if radial_stiffness_n_per_m is not None
            else "without a bearing (K_x from the axial load needs the bearing's contacts)"
        )
    elif rigid_body_frequency_hz is not None:
        why = "on the frequencies with --rigid-body-frequency-hz (only on the K_x reported)"
    else:
        why = None
    flags = [(flag, why is not None and name in typed(ctx)) for flag, name in _AXIAL_OPTIONS]
    unused = no_effect(flags, why or "")
    d["warnings"] = (_geometry_warnings(bearing) if bearing is not None else []) + d["warnings"]
    d["warnings"] += unused
    if json_output:
        _emit_json({"designation": designation, **d})
        return
    _print(d, bearing, axial_load_n)


def _print(d: dict, bearing, axial_load_n: float) -> None:
    def khz(values) -> str:
        return ", ".join(f"{f / 1e3:.4g}" for f in values) or "-"

    rows = [
        [
            m["m"],
            m["free_hz"] / 1e3 if m["m"] > 1 else None,
            khz(m["approx_hz"]),
            khz(m["refined_hz"]),
            ", ".join("-" if e is None else f"{e:.4g}" for e in m["epsilon"]) or "-",
        ]
        for m in d["modes"]
    ]
    where = f" at A = {axial_load_n:g} N" if d["axial_load_n"] is not None else ""
    name = bearing.name if bearing is not None and bearing.name else "outer ring"
    console.print(
        _table(
            f"{name}: outer-ring modes{where}",
            ["m", "free ring [kHz]", "approximate [kHz]", "refined, ball masses [kHz]", "epsilon"],
            rows,
        )
    )
    mass = "-" if d["ring_mass_kg"] is None else f"{d['ring_mass_kg']:.4g} kg"
    k_x = (
        "-"
        if d["radial_stiffness_n_per_um"] is None
        else f"{d['radial_stiffness_n_per_um']:.4g} N/µm"
    )
    console.print(
        f"ring mass {mass}, K_x {k_x}, f_1 {d['rigid_body_frequency_hz'] / 1e3:.4g} "
        f"kHz, kappa {d['ball_mass_ratio']:.3g}, K1/K2 "
        f"{d['contact_stiffness_ratio']:.3g}"
    )
    _print_warnings(d["warnings"])
