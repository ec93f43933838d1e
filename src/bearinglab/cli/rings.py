"""The ``ring-modes`` command: the outer ring's natural frequencies in the loaded bearing
(seed 000, :func:`bearinglab.rings.ring_modes`), from a bearing or from the ring-level
inputs of the paper alone (ball count, ring mass, K_x or f_1, free-ring frequencies,
kappa)."""

from ..analyses.rings import DEFAULT_RING_AXIAL_LOAD, RING_MODES
from ._app import command_app, console
from ._inputs import JsonOpt, _print_warnings, check_path, plot_option, save_plot_figure, takes
from ._output import _emit_json, _table

app = command_app()
PlotOpt = plot_option("the frequencies")


@app.command("ring-modes")
@takes(argument="designation", files=RING_MODES.files, **RING_MODES.command_options)
def ring_modes_command(values, json_output: JsonOpt = False, plot=None):
    """Natural frequencies of the outer ring in the loaded bearing (seed 000).

    Give a bearing (designation or geometry), or the paper's ring-level inputs alone:
    --balls, --ring-mass-kg with --radial-stiffness-n-per-m (or --rigid-body-frequency-hz),
    --free-frequencies-hz and --ball-mass-ratio."""
    check_path("plot", plot, (".png", ".svg", ".pdf"))
    r = RING_MODES(values)
    if plot is not None:
        save_plot_figure(r.plot()[0], plot)
    d = r.to_dict()
    if json_output:
        _emit_json(d)
        return
    _print(d, r.bearing, values["axial_load_n"] or DEFAULT_RING_AXIAL_LOAD)


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
