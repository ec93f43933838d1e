"""Report sections of the defect frequencies (kinematic and with slip) and of the
simulated envelope spectrum. Each function takes the :class:`.Context` and returns
``(body_html, highlights)``."""

from __future__ import annotations

import math

from ..diagnosis import peak_label
from ..dynamics import Defect, simulate
from ..dynamics.record import simulate_record
from ..engine import reraise_interrupt
from ..kinematics import FREQUENCY_NAMES, LONG_NAMES, defect_frequencies
from .context import Context
from .document import figure, notes, number, paragraph, table

#: Sample rate of the short slip-model run [Hz] (only its mean speeds are used).
SLIP_SAMPLE_RATE = 20e3
#: Envelope lines listed [-].
PEAKS_SHOWN = 12


def example_defect(bearing) -> Defect:
    """The outer-race spall simulated when the user gives no defect: 15 % of the ball
    diameter wide, a fifth of that deep, at the bottom of the load zone [-]."""
    width = round(0.15 * bearing.element_diameter, 5)
    return Defect("outer", width=width, depth=round(0.2 * width, 6))


def _slip_frequencies(kin, cage_ratio: float, spin_ratio: float) -> dict:
    """Defect frequencies [Hz] with the mean cage and spin speeds of the slip model."""
    z = kin.bearing.ball_count
    ftf = kin.hz("ftf") * cage_ratio
    bsf = kin.hz("bsf") * spin_ratio
    return {
        "ftf": ftf,
        "bpfo": z * ftf,
        "bpfi": z * (kin.shaft_hz - ftf),
        "bsf": bsf,
        "ball_defect": 2 * bsf,
    }


def frequencies(ctx: Context):
    """Kinematic defect frequencies and, from a short slip-model run, with slip."""
    kin = defect_frequencies(ctx.bearing, ctx.condition.shaft_speed)
    slip, slip_note = None, None
    if ctx.bearing.rolling_element == "roller":
        slip_note = "The slip model (seed 004) is for ball bearings: no frequencies with slip."
    elif ctx.slip_duration > 0:
        try:
            sim = simulate(
                ctx.bearing,
                ctx.condition,
                [],
                model="slip",
                duration=ctx.slip_duration,
                sample_rate=SLIP_SAMPLE_RATE,
            )
            ctx.results["slip"] = sim
            slip = _slip_frequencies(kin, sim.cage_speed_ratio, sim.spin_speed_ratio)
            slip_note = (
                f"With slip: seed 004's model (balls sliding under EHL traction, a "
                f"cage of its own) run for {ctx.slip_duration:g} s after settling; the "
                f"mean cage speed is {sim.cage_speed_ratio:.4f} and the mean ball spin "
                f"speed {sim.spin_speed_ratio:.4f} of their pure-rolling values. "
                "BPFO = Z f_cage, BPFI = Z (f_shaft - f_cage), 2 BSF from the spin "
                "speed."
            )
        except Exception as exc:  # noqa: BLE001 - the kinematic table stands without it
            reraise_interrupt(exc)
            slip_note = f"The slip model could not be run here: {type(exc).__name__}: {exc}"
    else:
        slip_note = "The slip model was not run (slip duration 0)."
    rows = [
        [
            "shaft",
            LONG_NAMES["shaft"],
            1.0,
            kin.shaft_hz,
            None if slip is None else kin.shaft_hz,
            None if slip is None else 0.0,
        ]
    ]
    for name in FREQUENCY_NAMES:
        hz = kin.hz(name)
        s = None if slip is None else slip[name]
        rows.append(
            [
                name.upper() if name != "ball_defect" else "2 BSF",
                LONG_NAMES[name],
                float(kin.orders[name]),
                hz,
                s,
                None if s is None else 100.0 * (s / hz - 1.0),
            ]
        )
    body = [
        paragraph(
            f"Frequencies at {ctx.speed_rpm:g} rpm, inner ring turning, outer ring "
            "fixed; orders are multiples of the shaft frequency."
        ),
        table(
            ["line", "meaning", "order", "kinematic [Hz]", "with slip [Hz]", "slip shift [%]"],
            rows,
            "Defect frequencies",
            numeric=(2, 3, 4, 5),
        ),
        paragraph(slip_note, "small"),
        figure(kin.plot()[0], "Defect frequencies and their first harmonics (kinematic)"),
    ]
    both = f"{number(kin.hz('bpfo'))} / {number(kin.hz('bpfi'))} Hz"
    return "".join(body), [("BPFO / BPFI", both)]


def _defect_text(d: Defect) -> str:
    depth = "" if d.depth is None else f", {d.depth * 1e3:.3g} mm deep"
    where = {
        "outer": f"at {math.degrees(d.angle) % 360:.0f} deg",
        "inner": "",
        "ball": f"ball {d.ball}",
    }[d.location]
    return f"{d.location} {d.width * 1e3:.3g} mm wide{depth} {where}".strip()


def envelope(ctx: Context):
    """Simulated vibration with the defects (rigid model) and its envelope spectrum."""
    defects = list(ctx.defects)
    # the same call as 'bearinglab simulate' (dynamics.simulate_record): the same numbers
    record = simulate_record(
        ctx.bearing,
        ctx.condition,
        defects,
        model="rigid",
        duration=ctx.duration,
        sample_rate=ctx.sample_rate,
    )
    sim, diag = record.simulation, record.diagnosis
    ctx.results["simulation"] = sim
    found = (diag.likely_fault or "no fault detected").replace("_", " ")
    said = [f"Defects simulated: {'; '.join(_defect_text(d) for d in defects)}."]
    if not ctx.defects_given:
        said.insert(
            0,
            "No defect was given (`defect`): this is an example outer-race "
            "defect, to show what such a fault looks like on this bearing.",
        )
    rows = [
        [
            p["frequency_hz"],
            p["amplitude"],
            peak_label(p),
            None if p.get("deviation") is None else 100.0 * p["deviation"],
        ]
        for p in diag.peaks[:PEAKS_SHOWN]
    ]
    band = (
        "none"
        if diag.band is None
        else f"{diag.band[0]:.0f}-{diag.band[1]:.0f} Hz (spectral kurtosis)"
    )
    assumptions = [
        (
            "The rigid-ring model has no slip, so the defect lines sit at the "
            "kinematic frequencies; in a real bearing they lie lower by the slip "
            "shown in the frequency section (seed 004's slip model costs about 5 s "
            "of computing per simulated second, too slow for a report)."
        )
    ]
    if ctx.condition.axial_load:
        assumptions.append("The model is planar: the axial load does not enter it.")
    body = [
        paragraph(
            f"Seed 003's rigid-ring model (4 degrees of freedom, Hertz ball "
            f"contacts, the defect as a loss of contact) simulated for "
            f"{sim.signal.duration:g} s at {sim.signal.sample_rate:g} Hz; the "
            "vertical pedestal acceleration is band-passed and enveloped "
            "(bearinglab.diagnosis.analyze_signal)."
        ),
        notes(said, "Defects"),
        figure(
            diag.plot()[0],
            "Envelope spectrum of the simulated acceleration with "
            "the defect frequencies and harmonics marked",
        ),
        table(
            ["frequency [Hz]", "amplitude [(m/s²)²]", "matched line", "deviation [%]"],
            rows,
            f"Strongest envelope lines (band {band}, resolution {diag.resolution:.3g} Hz)",
            numeric=(0, 1, 3),
        ),
        paragraph(f"Likely fault: {found}. {diag.reason}"),
        notes(assumptions, "Assumptions"),
    ]
    if not ctx.defects_given:  # an example is not a finding: say so on the card too
        return "".join(body), [
            ("Example defect (not a finding)", f"outer race simulated; diagnosis: {found}")
        ]
    return "".join(body), [("Diagnosis of the simulated defects", found)]
