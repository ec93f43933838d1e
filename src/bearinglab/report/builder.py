"""Build an engineer's report of one bearing at one operating point."""

from __future__ import annotations

import datetime
import math
from collections.abc import Callable

from ..engine import reraise_interrupt
from ..errors import InputError
from ..geometry import BallBearing
from ..kinematics import defect_frequencies
from ..operating import OperatingCondition, speed_error
from ..plausibility import (
    LOCATION_FAMILY,
    check_record_length,
    operating_warnings,
    sampling_warnings,
)
from ..roller_geometry import RollerBearing
from . import mechanics, operation, spectra, vibration
from .context import Context
from .document import Report, Section

#: The sections in page order: key, title, function(Context) -> (html, highlights).
#: A section that does not apply to the bearing says why instead (:func:`left_out`).
SECTIONS = (
    ("identity", "Identity and geometry", mechanics.identity),
    ("load-distribution", "Load distribution", mechanics.load_distribution),
    ("contact", "Contact pressures and ellipses", mechanics.contact),
    ("stiffness", "Stiffness and its variation with load", mechanics.stiffness),
    ("ring-resonances", "Ring resonances", mechanics.rings),
    ("defect-frequencies", "Defect frequencies", spectra.frequencies),
    ("envelope-spectrum", "Simulated envelope spectrum", spectra.envelope),
    ("vibration-bands", "Vibration bands (ISO 15242)", vibration.bands),
    ("noise", "Sound pressure level", vibration.noise),
    ("friction", "Friction torque and power loss", operation.friction),
    ("life", "Rating life", operation.life),
)
_RIGID = (
    "the rigid dynamic model is planar: single-row cylindrical and needle roller bearings "
    "only (a tapered or two-row bearing's axial load and second row are not in it)"
)


def left_out(key: str, bearing) -> str | None:
    """Why section ``key`` is not computed for ``bearing`` (a model of ball bearings only,
    or a roller bearing the rigid model does not take), or None."""
    if bearing.rolling_element != "roller":
        return None
    if key == "ring-resonances":
        return (
            "seed 000's ring model rests the outer ring on ball contacts; no roller "
            "model of the ring modes is built"
        )
    if key == "noise":
        return (
            "seed 003's sound model radiates from the balls (pulsating spheres) and the "
            "inner ring; no roller model of the sound is built"
        )
    rigid = bearing.contact_modelled and not bearing.is_tapered and bearing.rows == 1
    if key in ("envelope-spectrum", "vibration-bands") and not rigid:
        return _RIGID
    return None


#: ISO 15242's top band edge at 1800 rpm [Hz]; the default sample rate resolves it.
_TOP_BAND_HZ = 10e3


def default_sample_rate(shaft_speed: float) -> float:
    """Sample rate for the simulated envelope record at ``shaft_speed`` [rad/s] [Hz]: at
    least 25.6 kHz, and 2.56 times the top ISO 15242 band edge at this speed (10 kHz at
    1800 rpm, scaled), so that at high speed the defect lines, their harmonics and the
    resonances they excite stay below the Nyquist frequency.

    Parameters
    ----------
    shaft_speed : float
        Shaft speed [rad/s].

    Returns
    -------
    float
        Sample rate [Hz], a multiple of 100 Hz and at least 25 600 Hz.

    Examples
    --------
    >>> default_sample_rate(1800 * math.pi / 30)
    25600.0
    """
    top = _TOP_BAND_HZ * shaft_speed * 30.0 / math.pi / 1800.0
    return float(max(25.6e3, math.ceil(2.56 * top / 100.0) * 100.0))


def _viscosity(lubricant, viscosity):
    from ..lubrication import operating_viscosity

    if viscosity is not None:
        if not (math.isfinite(viscosity) and viscosity > 0):
            raise InputError("viscosity", viscosity, "a kinematic viscosity > 0 [m^2/s]")
        return float(viscosity), "given"
    if lubricant is None:
        return None, ""
    return operating_viscosity(lubricant)  # the reading the friction analysis makes too


def build_report(
    bearing: BallBearing,
    condition: OperatingCondition,
    *,
    designation=None,
    defects=None,
    lubricant="iso-vg68",
    viscosity: float | None = None,
    duration: float = 1.0,
    sample_rate: float | None = None,
    slip_duration: float = 0.1,
    progress: Callable[[str, int, int], None] | None = None,
) -> Report:
    """An HTML report of ``bearing`` under ``condition``: geometry and its sources, load
    distribution, contact, stiffness, ring resonances, defect frequencies, a simulated
    envelope spectrum, vibration bands, sound, friction and life.

    Each section's analysis runs on its own: one that fails shows its error in the page
    (``Report.failed`` lists them) and the others still run.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing (e.g. from :func:`bearinglab.catalog.bearing_from_designation`); a
        roller bearing's report leaves out what is modelled for ball bearings only (ring
        resonances, sound, the slip model), saying so in those sections.
    condition : OperatingCondition
        Loads and the shaft speed (> 0) [N, rad/s].
    designation : bearinglab.designation.Designation, optional
        The decoded designation, shown in the identity section.
    defects : sequence of Defect, optional
        Defects to simulate; None or empty: an example outer-race defect, said so.
    lubricant : str or Lubricant or None
        For the viscosity of the SKF friction model and a_ISO (at its reference
        temperature); a built-in name (``bearinglab.lubrication.LUBRICANTS``).
    viscosity : float, optional
        Operating kinematic viscosity instead [m^2/s].
    duration : float
        Length of the simulated vibration record (rigid model) [s].
    sample_rate : float, optional
        Its sample rate [Hz]; default :func:`default_sample_rate`.
    slip_duration : float
        Length of the slip-model run for the frequencies with slip [s]; 0 skips it.
    progress : callable, optional
        Called as ``progress(title, done, total)`` before each section.

    Returns
    -------
    Report
    """
    if not isinstance(bearing, (BallBearing, RollerBearing)):
        raise InputError("bearing", bearing, "a BallBearing or a RollerBearing")
    if not condition.shaft_speed > 0:
        raise speed_error(condition.shaft_speed, "a speed > 0 rpm")
    for name, value, zero in (
        ("duration", duration, False),
        ("slip_duration", slip_duration, True),
    ):
        if not (math.isfinite(value) and (value >= 0 if zero else value > 0)):
            raise InputError(name, value, "a duration >= 0 [s]" if zero else "a duration > 0 [s]")
    rate = default_sample_rate(condition.shaft_speed) if sample_rate is None else sample_rate
    nu, nu_source = _viscosity(lubricant, viscosity)
    given = bool(defects)
    chosen = tuple(defects) if given else (spectra.example_defect(bearing),)
    for d in chosen:
        d.check(bearing)
    # the operating point and the simulated record in the user's terms (raises past the
    # models' limits, before any section runs)
    kin = defect_frequencies(bearing, condition.shaft_speed)
    check_record_length(kin, duration)
    from ..inputs import bearing_warnings

    warnings = bearing_warnings(bearing, designation) + operating_warnings(bearing, condition)
    warnings += sampling_warnings(
        kin, rate, duration, [LOCATION_FAMILY[d.location] for d in chosen]
    )
    ctx = Context(
        bearing=bearing,
        condition=condition,
        designation=designation,
        defects=chosen,
        defects_given=given,
        viscosity=nu,
        viscosity_source=nu_source,
        lubricant=lubricant if viscosity is None else None,
        duration=float(duration),
        sample_rate=float(rate),
        slip_duration=float(slip_duration),
    )
    sections = []
    for i, (key, title, build) in enumerate(SECTIONS):
        if progress is not None:
            progress(title, i, len(SECTIONS))
        why = left_out(key, bearing)
        if why is not None:
            sections.append(Section(key, title, left_out=why))
            continue
        try:
            body, highlights = build(ctx)
            sections.append(Section(key, title, body, highlights=list(highlights)))
        except Exception as exc:  # noqa: BLE001 - one failed analysis must not sink the report
            reraise_interrupt(exc)  # a Ctrl-C is no failed section
            sections.append(Section(key, title, error=f"{type(exc).__name__}: {exc}"))
    if progress is not None:
        progress("done", len(SECTIONS), len(SECTIONS))
    return _report(ctx, sections, warnings)


def _report(ctx: Context, sections: list[Section], warnings: list[str]) -> Report:
    from .. import __version__

    b, c = ctx.bearing, ctx.condition
    des = ctx.designation
    name = b.name or (des.text if des is not None else "") or "ball bearing"
    what = des.description if des is not None else b.bearing_type.replace("_", " ")
    lines = [
        f"{what}",
        f"{ctx.speed_rpm:g} rpm (inner ring), F_r = {c.radial_load:g} N, "
        f"F_a = {c.axial_load:g} N"
        + (
            f"; lubricant viscosity {ctx.viscosity * 1e6:.4g} mm2/s ({ctx.viscosity_source})"
            if ctx.viscosity is not None
            else ""
        ),
    ]
    intro = (
        '<p class="small">Every number comes from a published method with stated '
        "assumptions (each section names its model and source); values marked "
        "<em>estimated</em> in the geometry are not the maker's. Run "
        "<code>bearinglab validate</code> to see how bearinglab reproduces the published "
        f"cases. Simulated record: {ctx.duration:g} s at {ctx.sample_rate:g} Hz.</p>"
    )
    now = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    return Report(
        title=f"bearinglab report: {name}",
        subtitle=lines,
        sections=sections,
        generated=now,
        version=__version__,
        intro=intro,
        warnings=tuple(warnings),
    )
