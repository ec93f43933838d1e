"""Report sections of vibration and noise: defect frequencies (kinematic and with slip),
the simulated envelope spectrum, ISO 15242 velocity bands and the sound pressure level.
Each function takes the :class:`.Context` and returns ``(body_html, highlights)``."""

from __future__ import annotations

import math

from ..diagnosis import analyze_signal, peak_label
from ..dynamics import Defect, simulate
from ..kinematics import FREQUENCY_NAMES, LONG_NAMES, defect_frequencies
from .context import Context
from .document import figure, notes, number, paragraph, table

#: Sample rate of the short slip-model run [Hz] (only its mean speeds are used).
SLIP_SAMPLE_RATE = 20e3
#: Envelope lines listed [-].
PEAKS_SHOWN = 12
#: Distance of the sound field point outside the outer ring [m].
FIELD_POINT_GAP = 0.010


def example_defect(bearing) -> Defect:
    """The outer-race spall simulated when the user gives no defect: 15 % of the ball
    diameter wide, a fifth of that deep, at the bottom of the load zone [-]."""
    width = round(0.15 * bearing.ball_diameter, 5)
    return Defect("outer", width=width, depth=round(0.2 * width, 6))


def _slip_frequencies(kin, cage_ratio: float, spin_ratio: float) -> dict:
    """Defect frequencies [Hz] with the mean cage and spin speeds of the slip model."""
    z = kin.bearing.ball_count
    ftf = kin.hz("ftf") * cage_ratio
    bsf = kin.hz("bsf") * spin_ratio
    return {"ftf": ftf, "bpfo": z * ftf, "bpfi": z * (kin.shaft_hz - ftf), "bsf": bsf,
            "ball_defect": 2 * bsf}


def frequencies(ctx: Context):
    """Kinematic defect frequencies and, from a short slip-model run, with slip."""
    kin = defect_frequencies(ctx.bearing, ctx.condition.shaft_speed)
    slip, slip_note = None, None
    if ctx.slip_duration > 0:
        try:
            sim = simulate(ctx.bearing, ctx.condition, [], model="slip",
                           duration=ctx.slip_duration, sample_rate=SLIP_SAMPLE_RATE)
            ctx.results["slip"] = sim
            slip = _slip_frequencies(kin, sim.cage_speed_ratio, sim.spin_speed_ratio)
            slip_note = (f"With slip: seed 004's model (balls sliding under EHL traction, a "
                         f"cage of its own) run for {ctx.slip_duration:g} s after settling; the "
                         f"mean cage speed is {sim.cage_speed_ratio:.4f} and the mean ball spin "
                         f"speed {sim.spin_speed_ratio:.4f} of their pure-rolling values. "
                         "BPFO = Z f_cage, BPFI = Z (f_shaft - f_cage), 2 BSF from the spin "
                         "speed.")
        except Exception as exc:  # noqa: BLE001 - the kinematic table stands without it
            slip_note = f"The slip model could not be run here: {type(exc).__name__}: {exc}"
    else:
        slip_note = "The slip model was not run (slip duration 0)."
    rows = [["shaft", LONG_NAMES["shaft"], 1.0, kin.shaft_hz,
             None if slip is None else kin.shaft_hz, None if slip is None else 0.0]]
    for name in FREQUENCY_NAMES:
        hz = kin.hz(name)
        s = None if slip is None else slip[name]
        rows.append([name.upper() if name != "ball_defect" else "2 BSF", LONG_NAMES[name],
                     float(kin.orders[name]), hz, s,
                     None if s is None else 100.0 * (s / hz - 1.0)])
    body = [paragraph(f"Frequencies at {ctx.speed_rpm:g} rpm, inner ring turning, outer ring "
                      "fixed; orders are multiples of the shaft frequency."),
            table(["line", "meaning", "order", "kinematic [Hz]", "with slip [Hz]",
                   "slip shift [%]"], rows, "Defect frequencies", numeric=(2, 3, 4, 5)),
            paragraph(slip_note, "small"),
            figure(kin.plot()[0], "Defect frequencies and their first harmonics (kinematic)")]
    both = f"{number(kin.hz('bpfo'))} / {number(kin.hz('bpfi'))} Hz"
    return "".join(body), [("BPFO / BPFI", both)]


def _defect_text(d: Defect) -> str:
    depth = "" if d.depth is None else f", {d.depth * 1e3:.3g} mm deep"
    where = {"outer": f"at {math.degrees(d.angle) % 360:.0f} deg", "inner": "",
             "ball": f"ball {d.ball}"}[d.location]
    return f"{d.location} {d.width * 1e3:.3g} mm wide{depth} {where}".strip()


def envelope(ctx: Context):
    """Simulated vibration with the defects (rigid model) and its envelope spectrum."""
    defects = list(ctx.defects)
    sim = simulate(ctx.bearing, ctx.condition, defects, model="rigid", duration=ctx.duration,
                   sample_rate=ctx.sample_rate)
    ctx.results["simulation"] = sim
    diag = analyze_signal(sim.signal, None, sim.kinematic, channel="acc_y")
    said = [f"Defects simulated: {'; '.join(_defect_text(d) for d in defects)}."]
    if not ctx.defects_given:
        said.insert(0, "No defect was given (--defect): this is an example outer-race "
                       "defect, to show what such a fault looks like on this bearing.")
    rows = [[p["frequency_hz"], p["amplitude"], peak_label(p),
             None if p.get("deviation") is None else 100.0 * p["deviation"]]
            for p in diag.peaks[:PEAKS_SHOWN]]
    band = ("none" if diag.band is None else
            f"{diag.band[0]:.0f}-{diag.band[1]:.0f} Hz (spectral kurtosis)")
    assumptions = [("The rigid-ring model has no slip, so the defect lines sit at the "
                    "kinematic frequencies; in a real bearing they lie lower by the slip "
                    "shown in the frequency section (seed 004's slip model costs about 5 s "
                    "of computing per simulated second, too slow for a report).")]
    if ctx.condition.axial_load:
        assumptions.append("The model is planar: the axial load does not enter it.")
    body = [paragraph(f"Seed 003's rigid-ring model (4 degrees of freedom, Hertz ball "
                      f"contacts, the defect as a loss of contact) simulated for "
                      f"{sim.signal.duration:g} s at {sim.signal.sample_rate:g} Hz; the "
                      "vertical pedestal acceleration is band-passed and enveloped "
                      "(bearinglab.diagnosis.analyze_signal)."),
            notes(said, "Defects"),
            figure(diag.plot()[0], "Envelope spectrum of the simulated acceleration with "
                                   "the defect frequencies and harmonics marked"),
            table(["frequency [Hz]", "amplitude [m/s2]", "matched line",
                   "deviation [%]"], rows, f"Strongest envelope lines (band {band}, "
                   f"resolution {diag.resolution:.3g} Hz)", numeric=(0, 1, 3)),
            paragraph(f"Likely fault: {diag.likely_fault or 'none found'}. {diag.reason}"),
            notes(assumptions, "Assumptions")]
    return "".join(body), [("Simulated fault found", diag.likely_fault or "none")]


def bands(ctx: Context):
    """RMS vibration velocity in the ISO 15242 bands of the simulated signal."""
    from ..signal import velocity_bands

    sim = ctx.need("simulation", "simulation (envelope section)")
    acc = sim.signal.channels["acc_y"]
    vb = velocity_bands(acc, sim.signal.sample_rate, "acceleration", speed_rpm=ctx.speed_rpm)
    rows = [[name, vb.bands[name][0], vb.bands[name][1], getattr(vb, name)]
            for name in ("low", "medium", "high")]
    from ..plotting import _pyplot

    fig, ax = _pyplot().subplots(figsize=(6.5, 3.2))
    ax.bar([f"{n}\n{lo:.0f}-{hi:.0f} Hz" for n, lo, hi, _ in rows], [r[3] for r in rows],
           color=["C0", "C1", "C2"])
    ax.set_ylabel("RMS velocity [um/s]")
    ax.set_title("ISO 15242 bands (simulated pedestal)", fontsize=10)
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    body = [paragraph("Root-mean-square vibration velocity in the low, medium and high bands "
                      "of ISO 15242 (50-300, 300-1800, 1800-10000 Hz at 1800 rpm, scaled in "
                      f"proportion to the speed: here {ctx.speed_rpm:g} rpm), from the "
                      "simulated vertical acceleration of the envelope section."),
            table(["band", "from [Hz]", "to [Hz]", "RMS velocity [um/s]"], rows,
                  "ISO 15242 velocity bands"),
            figure(fig, "RMS velocity by band", 60),
            notes([("The signal is the rigid model's pedestal acceleration with the "
                    "defect(s) of the envelope section, not a measurement on an ISO 15242 "
                    "rig (which holds the outer ring on a compliant fixture): compare "
                    "bearings and defects with it, not against a standard's limits.")],
                  "Assumptions")]
    return "".join(body), [("Velocity (medium band)", f"{number(vb.medium / 1e3, 3)} mm/s")]


def noise(ctx: Context):
    """Sound pressure level of the running bearing (seed 003 part 4 chain)."""
    from ..noise import FieldPoint, bearing_noise

    b = ctx.bearing
    if b.outside_diameter is None:
        raise ValueError("the sound field point is placed outside the outer ring: the "
                         "bearing needs its outside diameter")
    point = FieldPoint(0.5 * b.outside_diameter + FIELD_POINT_GAP, 0.5 * math.pi)
    n = bearing_noise(b, ctx.condition, point=point)
    d = n.to_dict()
    keys = (("SPL over the record (eq. 27)", "spl_db"), ("mean SPL (time average)",
                                                         "spl_mean_db"),
            ("maximum SPL", "spl_max_db"), ("inner ring alone", "spl_inner_ring_db"),
            ("balls alone", "spl_balls_db"))
    rows = [[label, d.get(k), "dB re 20 uPa"] for label, k in keys]
    rows.append(["effective pressure p_e", d.get("effective_pressure_pa"), "Pa"])
    body = [paragraph("Sound radiated by the inner ring (a vibrating cylinder, eq. 19) and "
                      "the balls (pulsating spheres, eq. 23), driven by the quasi-static "
                      "orbit of the bearing over one cage revolution (seed 003 part 4; "
                      "bearinglab.noise.bearing_noise), at a point "
                      f"{point.distance * 1e3:.3g} mm from the centre, "
                      f"{FIELD_POINT_GAP * 1e3:g} mm outside the outer ring, above the "
                      "bearing."),
            table(["quantity", "value", "unit"], rows, "Sound pressure level", numeric=(1,)),
            figure(n.plot()[0], "Sound pressure and SPL against time at the field point", 70),
            notes([("A perfect bearing: no waviness or ball-size errors (give them through "
                    "the Python API, bearinglab.noise.bearing_noise); its sound comes from "
                    "the balls passing through the load zone only."),
                   ("Only the inner ring and the balls radiate, into free air (the seed's "
                    "assumptions); housing and outer ring are left out.")], "Assumptions")]
    return "".join(body), [("SPL (mean)", f"{d['spl_mean_db']:.3g} dB")]
