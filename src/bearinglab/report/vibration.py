"""Report sections of vibration and noise: ISO 15242 velocity bands and the sound pressure
level (the defect frequencies and the envelope spectrum are in :mod:`.spectra`).
Each function takes the :class:`.Context` and returns ``(body_html, highlights)``."""

from __future__ import annotations

import math

from .context import Context
from .document import figure, notes, number, paragraph, table

#: Sample rate of the short slip-model run [Hz] (only its mean speeds are used).
SLIP_SAMPLE_RATE = 20e3
#: Envelope lines listed [-].
PEAKS_SHOWN = 12
#: Distance of the sound field point outside the outer ring [m].
FIELD_POINT_GAP = 0.010


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
