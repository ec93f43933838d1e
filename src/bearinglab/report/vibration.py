"""Report sections of vibration and noise: ISO 15242 velocity bands and the sound pressure
level (the defect frequencies and the envelope spectrum are in :mod:`.spectra`).

Both come from one :func:`bearinglab.noise.noise_analysis` of the bearing at the report's
operating point, the function the ``noise`` command calls with the same defaults (field
point 10 mm outside the outside diameter, one cage revolution, bands from the rigid model
when the orbit cannot resolve them), so the page and ``bearinglab noise --json`` give the
same numbers. Each function takes the :class:`.Context` and returns
``(body_html, highlights)``."""

from __future__ import annotations

from .context import Context
from .document import figure, notes, number, paragraph, table


def _noise(ctx: Context):
    """The noise analysis of the report's bearing (a perfect one: no form errors), run once
    for both sections; a failure is kept and raised again by the other section."""
    if "noise" not in ctx.results:
        from ..noise import noise_analysis

        try:
            ctx.results["noise"] = noise_analysis(ctx.bearing, ctx.condition)
        except Exception as exc:
            ctx.results["noise"] = exc
            raise
    result = ctx.results["noise"]
    if isinstance(result, Exception):
        raise RuntimeError(f"the noise analysis failed: {type(result).__name__}: {result}")
    return result


def bands(ctx: Context):
    """RMS vibration velocity in the ISO 15242 bands
    (:func:`bearinglab.noise.bearing_velocity_bands`, through ``noise_analysis``)."""
    if ctx.bearing.rolling_element == "roller":  # no noise model: the rigid model's bands
        from ..noise import bearing_velocity_bands

        vb = bearing_velocity_bands(ctx.bearing, ctx.condition, source="rigid")
    else:
        vb = _noise(ctx).bands
    edges = vb.bands.bands
    rows = [[name, edges[name][0], edges[name][1], vb[name]] for name in ("low", "medium", "high")]
    body = [
        paragraph(
            "Root-mean-square radial vibration velocity in the low, medium and high "
            "bands of ISO 15242 (50-300, 300-1800, 1800-10000 Hz at 1800 rpm, scaled "
            f"in proportion to the speed: here {vb.speed_rpm:g} rpm), of the inner "
            "ring relative to the outer ring along the load: what an ISO 15242 rig "
            "measures on the outer ring with the inner ring on a stiff spindle. "
            f"Source: {vb.note}."
        ),
        table(
            ["band", "from [Hz]", "to [Hz]", "RMS velocity [um/s]"],
            rows,
            "ISO 15242 velocity bands",
        ),
        figure(vb.plot()[0], "RMS velocity by band", 60),
        notes(
            [
                (
                    "A perfect bearing at the report's load and speed (no defects, no form "
                    "errors; give waviness through `bearinglab noise` or the Python API, "
                    "bearinglab.noise.noise_analysis): its vibration comes from the balls "
                    "passing through the load zone. `bearinglab noise` with the same bearing, "
                    "speed and load gives the same numbers."
                ),
                (
                    "A model, not a measurement on an ISO 15242 rig (whose fixture and "
                    "spindle set the resonances): compare bearings with it, not against a "
                    "standard's limits."
                ),
            ],
            "Assumptions",
        ),
    ]
    return "".join(body), [("Velocity (medium band)", f"{number(vb['medium'], 3)} um/s")]


def noise(ctx: Context):
    """Sound pressure level of the running bearing (seed 003 part 4 chain)."""
    from ..noise import LEVEL_ROWS
    from ..units import unit_of

    result = _noise(ctx)
    d = result.to_dict()
    rows = [
        [what, d.get(key), "dB re 20 uPa" if key.endswith("_db") else unit_of(key).symbol]
        for what, key in LEVEL_ROWS
    ]
    body = [
        paragraph(
            "Sound radiated by the inner ring (a vibrating cylinder, eq. 19) and "
            "the balls (pulsating spheres, eq. 23), driven by the quasi-static "
            "orbit of the bearing over one cage revolution (seed 003 part 4; "
            "bearinglab.noise.noise_analysis, as `bearinglab noise`), at a point "
            f"{d['distance_mm']:.3g} mm from the centre, above the bearing "
            f"({d['field_point_source']}). L_eq is eq. 27 over the whole record (the "
            "energy mean); the time mean and maximum are those of the level curve "
            "SPL(t), the time mean being seed 003's 'mean SPL'."
        ),
        table(["quantity", "value", "unit"], rows, "Sound pressure level", numeric=(1,)),
        figure(
            result.sound.plot()[0], "Sound pressure and SPL against time at the field point", 70
        ),
        notes(
            [
                (
                    "A perfect bearing: no waviness or ball-size errors (give them through "
                    "`bearinglab noise` or the Python API, bearinglab.noise.noise_analysis); "
                    "its sound comes from the balls passing through the load zone only."
                ),
                (
                    "Only the inner ring and the balls radiate, into free air (the seed's "
                    "assumptions); housing and outer ring are left out."
                ),
            ],
            "Assumptions",
        ),
    ]
    return "".join(body), [("SPL (L_eq)", f"{d['spl_leq_db']:.3g} dB")]
