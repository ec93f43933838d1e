"""The ``noise`` command (issue 5): sound pressure of a bearing with form errors, and the
ISO 15242 vibration velocity bands.

``noise`` runs :func:`bearinglab.noise.bearing_noise` (seed 003 part 4: the quasi-static
inner-ring and ball-centre orbit of a bearing with waviness, ball-size errors and 3-D
surfaces, radiated by the inner ring as a vibrating cylinder and the balls as pulsating
spheres), matches the lines of the sound-pressure spectrum to the bearing's frequencies
(:func:`bearinglab.signal.match_peaks`) and computes the RMS radial vibration velocity in
the ISO 15242 bands (:func:`bearinglab.signal.velocity_bands`) from the orbit, or from the
rigid dynamic model when the orbit's sampling cannot resolve the bands (docs/capabilities/
noise.md, "The noise command").
"""

import math
from enum import Enum
from pathlib import Path
from typing import Annotated

import numpy as np
import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

from ..errors import InputError
from ..kinematics import defect_frequencies
from ..noise import FieldPoint, bearing_noise, velocity_from_positions
from ..operating import OperatingCondition
from ..signal import iso15242_bands, velocity_bands
from ..signal.bands import MIN_PERIODS
from ..signal.lines import spectrum_lines
from ._app import command_app, console
from ._forms import (
    BallErrorOpt,
    FormErrors,
    SeedOpt,
    Surface3dOpt,
    WavinessOpt,
    form_errors_text,
)
from ._inputs import (
    MAX_LOAD_N,
    DesignationArg,
    JsonOpt,
    OptionError,
    _geometry_line,
    _geometry_warnings,
    _print_warnings,
    check_path,
    positive,
    resolve_bearing,
    save_plot_figure,
    speed_rad_s,
    with_geometry,
)
from ._output import _emit_json, _table, peak_rows, peaks_json

app = command_app()

#: Sample rate of the velocity-band record over the top band edge (the usual analyser
#: ratio: 25.6 kHz for the 10 kHz edge).
BANDS_RATE_FACTOR = 2.56
#: Lines of the pressure spectrum kept, and the highest harmonic matched.
PEAK_COUNT = 16
PEAK_HARMONICS = 10
#: Least prominence of a pressure line, in medians of the spectrum. The record is one
#: cage revolution by default, so every bin is a multiple of the cage frequency and the
#: quasi-static orbit's kinks (a ball entering or leaving the load zone) spread the
#: ball-pass harmonics evenly: they stand about 1.5 medians above the rest.
PEAK_PROMINENCE = 1.0
#: The orbit rolls purely (kinematic cage and spin speeds), so the pressure lines are
#: matched without the slip allowance of measured spectra: within 2 % or one bin.
MAX_POINTS = 200_000


class BandsFrom(str, Enum):
    auto = "auto"
    orbit = "orbit"
    rigid = "rigid"


@app.command("noise")
@with_geometry
def noise_command(
        designation: DesignationArg = None,
        speed_rpm: Annotated[float, typer.Option("--speed-rpm",
                                                 help="Shaft (inner-ring) speed [rpm].")] = ...,
        radial_load_n: Annotated[float, typer.Option(
            "--radial-load-n", help="Radial load F_r on the shaft, downwards [N] (> 0).")] = ...,
        waviness: WavinessOpt = None, ball_size_error_um: BallErrorOpt = None,
        surface3d: Surface3dOpt = None, seed: SeedOpt = None,
        distance_mm: Annotated[float, typer.Option(
            "--distance-mm", help="Distance of the field point from the bearing centre [mm] "
            "(seed 003's point A: 10 mm).")] = 10.0,
        angle_deg: Annotated[float, typer.Option(
            "--angle-deg", help="Direction of the field point in the radial plane, from +x "
            "towards +y [deg] (90 = straight up, against the load).")] = 90.0,
        duration_s: Annotated[float | None, typer.Option(
            "--duration-s", help="Length of the orbit record [s] (default: one cage "
            "revolution, so each ball carries its size error round once).",
            show_default=False)] = None,
        points: Annotated[int | None, typer.Option(
            "--points", help="Instants of the orbit (default: 8192 per second, at least "
            "256). More points resolve higher frequencies; the mean SPL hardly changes.",
            show_default=False)] = None,
        bands_from: Annotated[BandsFrom, typer.Option(
            "--bands-from", help="Source of the ISO 15242 velocity bands: auto (the orbit "
            "if it is sampled above twice the top band edge for long enough, else the "
            "rigid dynamic model), orbit (a second, finer orbit if needed) or rigid.")]
        = BandsFrom.auto,
        bands_at_speed: Annotated[bool, typer.Option(
            "--bands-at-speed", help="Scale the ISO 15242 band edges with the speed from "
            "their 1800 rpm values (ISO 15242-4's rule); default: the 1800 rpm bands "
            "50-300, 300-1800, 1800-10000 Hz.")] = False,
        json_output: JsonOpt = False,
        plot: Annotated[Path | None, typer.Option(
            "--plot", help="Draw the pressure and SPL over time, the pressure spectrum and "
            "the directivity to this .png, .svg or .pdf file.", show_default=False)] = None,
        *, geometry):
    """Noise of a running ball bearing with waviness, ball-size errors and random
    surfaces (seed 003 part 4, seed 002): SPL at a point, pressure spectrum lines, and the
    ISO 15242 vibration velocity bands."""
    shaft_speed = speed_rad_s(speed_rpm)
    if not (math.isfinite(radial_load_n) and 0 < radial_load_n <= MAX_LOAD_N):
        raise OptionError("--radial-load-n", radial_load_n,
                          f"a load in (0, {MAX_LOAD_N:g}] N (the orbit needs a load)")
    positive("--distance-mm", distance_mm, "a distance > 0 mm")
    if not math.isfinite(angle_deg):
        raise OptionError("--angle-deg", angle_deg, "a finite angle [deg]")
    positive("--duration-s", duration_s, "a duration > 0 s")
    if points is not None and not 16 <= points <= MAX_POINTS:
        raise OptionError("--points", points, f"an integer in [16, {MAX_POINTS}]")
    if seed is not None and seed < 0:
        raise OptionError("--seed", seed, "an integer >= 0")
    check_path("--plot", plot, (".png", ".svg", ".pdf"))
    forms = FormErrors(waviness, ball_size_error_um, surface3d)
    bearing, _ = resolve_bearing(designation, geometry)
    _check_point(bearing, distance_mm)
    imperfections = forms.build(bearing, seed)
    condition = OperatingCondition(radial_load=radial_load_n, shaft_speed=shaft_speed)
    kin = defect_frequencies(bearing, shaft_speed)
    if duration_s is not None and points is None and duration_s * 8192 > MAX_POINTS:
        raise OptionError("--duration-s", duration_s, f"at most {MAX_POINTS / 8192:g} s with "
                          "the default sampling (or give --points)")
    err = Console(stderr=True)
    with Progress(TextColumn("{task.description}"), BarColumn(),
                  TextColumn("{task.percentage:>3.0f}%"), TimeElapsedColumn(), console=err,
                  transient=True, disable=json_output or not err.is_terminal) as progress:
        task = progress.add_task("orbit and sound pressure", total=1.0)
        try:
            noise = bearing_noise(bearing, condition, imperfections, duration=duration_s,
                                  points=points,
                                  point=FieldPoint(distance_mm * 1e-3, math.radians(angle_deg)))
        except InputError as exc:
            raise _noise_error(exc) from None
        progress.update(task, completed=0.6, description="velocity bands")
        vb, band_info = _bands(bearing, condition, imperfections, noise.orbit,
                               speed_rpm if bands_at_speed else None, bands_from,
                               lambda f: progress.update(task, completed=0.6 + 0.3 * f))
        progress.update(task, completed=0.9, description="pressure spectrum")
        sound = noise.sound
        top = PEAK_HARMONICS + 0.5
        max_frequency = min(0.5 * sound.sample_rate,
                            top * max(kin.hz("bpfo"), kin.hz("bpfi")))
        spec, peaks = spectrum_lines(sound.pressure("total"), sound.sample_rate, kin,
                                     max_frequency, count=PEAK_COUNT, harmonics=PEAK_HARMONICS,
                                     prominence=PEAK_PROMINENCE, slip_tolerance=0.0)
        if plot is not None:
            progress.update(task, description="plot (directivity)")
            _plot(noise, spec, peaks, kin, max_frequency, plot)
        progress.update(task, completed=1.0)
    summary = noise.to_dict()
    levels = {k: summary.pop(k) for k in ("spl_mean_db", "spl_max_db", "spl_db")}
    parts = {k: summary.pop(k) for k in list(summary) if k.startswith("spl_")}
    warnings = _geometry_warnings(bearing) + _warnings(bearing, distance_mm, imperfections)
    out = {"designation": designation, "speed_rpm": speed_rpm, "radial_load_n": radial_load_n,
           "distance_mm": distance_mm, "angle_deg": angle_deg,
           "seed": 0 if seed is None else seed,
           **levels, **parts,
           "velocity_bands_um_s": {k: getattr(vb, k) for k in ("low", "medium", "high")},
           "velocity_bands_hz": {k: list(v) for k, v in vb.bands.items()},
           **band_info,
           "peaks": peaks_json(peaks), "peaks_resolution_hz": spec.resolution,
           "peaks_max_frequency_hz": max_frequency,
           "kinematic": kin.to_dict(),
           **{k: v for k, v in summary.items() if k not in ("speed_rpm", "radial_load_n",
                                                            "distance_mm", "angle_deg",
                                                            "imperfections")},
           "imperfections": None if imperfections is None else imperfections.to_dict(),
           "warnings": warnings}
    if json_output:
        _emit_json(out)
        return
    _print(out, bearing, imperfections, spec, peaks)


# ------------------------------------------------------------------ checks
def _check_point(bearing, distance_mm: float) -> None:
    """The field point must lie outside the inner-ring cylinder and the balls' path (the
    sources of seed 003's eqs. 19 and 23); checked before the orbit runs."""
    ring = 0.5 * bearing.inner_raceway_diameter * 1e3
    path_in = 0.5 * (bearing.pitch_diameter - bearing.ball_diameter) * 1e3
    path_out = 0.5 * (bearing.pitch_diameter + bearing.ball_diameter) * 1e3
    if distance_mm <= ring or path_in <= distance_mm <= path_out:
        inside = f"({ring:.4g}, {path_in:.4g}) or " if path_in > ring else ""
        raise OptionError("--distance-mm", distance_mm,
                          f"a distance in {inside}more than {path_out:.4g} mm (outside the "
                          f"inner ring, radius {ring:.4g} mm, and the balls' path)")


_NOISE_FLAGS = {"duration": "--duration-s", "points": "--points", "point": "--distance-mm"}


def _noise_error(exc: InputError):
    flag = _NOISE_FLAGS.get(exc.parameter)
    return exc if flag is None else OptionError(flag, exc.value, exc.allowed)


def _warnings(bearing, distance_mm: float, imperfections) -> list[str]:
    out = []
    if imperfections is None or imperfections.is_empty:
        out.append("no form errors given: the sound comes only from the varying compliance "
                   "of a perfect bearing (give --waviness, --ball-size-error-um or --surface3d)")
    if bearing.outside_diameter is not None and distance_mm * 1e-3 < 0.5 * bearing.outside_diameter:
        out.append(f"the point ({distance_mm:g} mm) lies inside the outer ring's radius "
                   f"({0.5 * bearing.outside_diameter * 1e3:g} mm): the model, like seed "
                   "003's, radiates into free air and ignores the outer ring")
    return out


# ------------------------------------------------------------------ velocity bands
def _detrended_velocity(time, position) -> np.ndarray:
    """Velocity of a record by central differences, with the ramp taken off that brings
    the linearly extrapolated next sample onto the first (as the noise model does), so
    that the record's periodic extension has no jump [m/s]."""
    v = velocity_from_positions(time, position)
    n = v.size
    jump = 2.0 * v[-1] - v[-2] - v[0]
    return v - jump * np.arange(n) / n


def _bands(bearing, condition, imperfections, orbit, band_speed_rpm: float | None,
           bands_from: BandsFrom, progress):
    """ISO 15242 bands of the inner ring's velocity relative to the outer ring along the
    load (y): what a rig with a rigid spindle measures on the outer ring. The band edges
    are those of 1800 rpm, or scaled to ``band_speed_rpm``."""
    from ..dynamics import simulate
    from ..quasistatic.orbit import inner_ring_orbit

    bands = iso15242_bands(band_speed_rpm)
    top = max(hi for _, hi in bands.values())
    need_rate = 2.0 * top
    need_length = MIN_PERIODS / min(lo for lo, _ in bands.values())
    t = orbit.time
    rate = (t.size - 1) / (t[-1] - t[0])
    length = t.size / rate
    fits = rate > need_rate and length >= need_length * (1 - 1e-9)
    rate_out = BANDS_RATE_FACTOR * top
    length_out = max(need_length, length)
    if bands_from is BandsFrom.rigid or (bands_from is BandsFrom.auto and not fits):
        sim = simulate(bearing, condition, (), imperfections=imperfections, duration=length_out,
                       sample_rate=rate_out, progress=progress)
        y = sim.signal.channels["disp_y"]
        time = np.arange(y.size) / rate_out
        note = ("the rigid dynamic model (seed 003's 4-DOF model, no defects, the same form "
                "errors; its resonances set the high band)")
        if bands_from is BandsFrom.auto:
            note += (f": the orbit ({rate:.6g} Hz over {length:.4g} s) cannot resolve the "
                     f"bands (it needs > {need_rate:g} Hz over >= {need_length:g} s)")
        source = "rigid model"
    elif fits:
        time, y = t, orbit.y
        rate_out, length_out = rate, length
        source, note = "orbit", "the orbit of the noise calculation (quasi-static)"
    else:
        count = math.ceil(rate_out * length_out)
        second = inner_ring_orbit(bearing, condition, imperfections=imperfections,
                                  duration=length_out, points=count)
        time, y = second.time, second.y
        source = "orbit"
        note = (f"a second quasi-static orbit at {rate_out:g} Hz over {length_out:.4g} s (the "
                "noise orbit's sampling cannot resolve the bands)")
    vb = velocity_bands(_detrended_velocity(time, y), rate_out, "velocity",
                        speed_rpm=band_speed_rpm)
    return vb, {"velocity_bands_source": source, "velocity_bands_note": note,
                "velocity_bands_sample_rate_hz": rate_out,
                "velocity_bands_duration_s": length_out}


# ------------------------------------------------------------------ output
def _print(out: dict, bearing, imperfections, spec, peaks) -> None:
    rows = [["speed, radial load", f"{out['speed_rpm']:g} rpm, {out['radial_load_n']:g} N"],
            ["form errors", form_errors_text(imperfections)],
            ["field point", (f"{out['distance_mm']:g} mm from the centre, "
                            f"{out['angle_deg']:g} deg from +x")],
            ["record", (f"{out['points']} instants over {out['duration_s']:.4g} s "
                       f"({out['sample_rate_hz']:.5g} Hz)")],
            ["orbit peak to peak", f"{out['orbit_peak_to_peak_um']:.4g} um"],
            ["mean SPL (SPL over time, averaged)", _db(out["spl_mean_db"])],
            ["max SPL over time", _db(out["spl_max_db"])],
            ["SPL of the whole record (eq. 27)", _db(out["spl_db"])],
            ["inner ring, balls", (f"{_db(out.get('spl_inner_ring_db'))}, "
                                  f"{_db(out.get('spl_balls_db'))}")]]
    console.print(_table(f"{bearing.name or 'bearing'}: noise", ["", "value"], rows))
    console.print(escape(_geometry_line(bearing)))
    vb, hz = out["velocity_bands_um_s"], out["velocity_bands_hz"]
    console.print(_table(f"ISO 15242 velocity bands (RMS, um/s) from the "
                         f"{out['velocity_bands_source']}",
                         ["band", "Hz", "um/s"],
                         [[k, f"{hz[k][0]:g} - {hz[k][1]:g}", vb[k]] for k in vb]))
    console.print(f"[dim]{escape(out['velocity_bands_note'])}[/dim]")
    console.print(_table(f"Sound-pressure spectrum lines (resolution {spec.resolution:.3g} Hz)",
                         ["Hz", "amplitude [Pa]", "matched", "deviation %"],
                         peak_rows(peaks)))
    kin = out["kinematic"]
    console.print(f"BPFO {kin['bpfo_hz']:.4g} Hz, BPFI {kin['bpfi_hz']:.4g} Hz, FTF "
                  f"{kin['ftf_hz']:.4g} Hz, shaft {out['speed_rpm'] / 60:.4g} Hz")
    _print_warnings(out["warnings"])


def _db(value) -> str:
    return "-" if value is None else f"{value:.1f} dB"


def _plot(noise, spec, peaks, kin, max_frequency: float, path: Path) -> None:
    """Pressure and SPL over time (left), pressure spectrum and directivity (right)."""
    from ..plotting import _pyplot, draw_spectrum

    plt = _pyplot()
    fig = plt.figure(figsize=(14, 8.5))
    pressure = fig.add_subplot(2, 2, 1)
    level = fig.add_subplot(2, 2, 3, sharex=pressure)
    noise.sound.plot(axes=[pressure, level])
    draw_spectrum(fig.add_subplot(2, 2, 2), spec, peaks, kin, max_frequency,
                  title=f"sound-pressure spectrum (resolution {spec.resolution:.3g} Hz)",
                  ylabel="amplitude [Pa]", names=("shaft", "ftf", "bpfo", "bpfi"),
                  harmonics=PEAK_HARMONICS)
    noise.sound.directivity().plot(ax=fig.add_subplot(2, 2, 4, projection="polar"))
    fig.tight_layout()
    save_plot_figure(fig, path)
