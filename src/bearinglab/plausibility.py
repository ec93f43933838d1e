"""Plausibility of an operating point and of a record, in the user's terms.

Inputs that run but make no physical sense get a warning (or, past the point where the
models stop describing the bearing, an :class:`~bearinglab.errors.InputError`):

- **load against the static rating** (ISO 76:2006): the static safety factor
  s0 = C0 / P0 with P0 the static equivalent load. Below 1 the contact pressure of the
  most heavily loaded ball passes the 4200 MPa at which ISO 76 puts a permanent
  deformation of 1e-4 D_w; a warning. Below 1/8 (P0 > 8 C0, a Hertz pressure twice that
  of C0, p ~ P^(1/3)) the elastic contact models no longer describe the bearing; an error.
- **contact pressure of the form errors** (ISO 76:2006): waviness, ball-size errors and
  random surfaces press some balls harder than the external load does, and the load
  check above sees only the external load. :func:`contact_warnings` reads the largest
  Hertz pressure of the solved contacts (the load distribution, or every instant of an
  orbit) and, when the external load alone passes the static rating check, warns past
  the 4200 MPa behind C0 and raises past 8.4 GPa, the pressure of 8 C0, naming the
  form-error inputs (``static``, its orbit, ``noise`` and the report).
- **speed**: the speed factor n d_m against 1e6 mm/min, above which standard ball bearings
  pass the limiting speeds their makers list (a rule of thumb from makers' speed factors,
  not a standard: no ISO standard sets limiting speeds, which are makers' ratings; ISO
  15312 defines the thermal speed rating), a warning;
  above :data:`bearinglab.quasistatic.MAX_SPEED_FACTOR` (3e6 mm/min) the quasi-static
  model is not valid, an error. And the balls' centrifugal force against the heaviest
  ball load of the external load (Stribeck's 5 F_r / (Z cos alpha)): when it is larger,
  the outer-race contacts are set by speed, not load (a warning).
- **sampling** of a record against the bearing's frequencies: the defect frequency of a
  fault family above the Nyquist frequency fs/2 cannot appear in the record (an error
  for the families a simulation contains, a warning for their first harmonics and the
  sidebands the physics puts on them: +-f_shaft around BPFI, +-FTF around the ball-defect
  rate); a frequency resolution 1/T coarser than FTF / 3 cannot separate the cage
  sidebands (a warning).

Each check returns the warnings as sentences and raises for the errors; the commands
(``static``, ``simulate``, ``noise``, ``report``) show the same sentences. Inputs are named
in backquotes by their public names (`waviness`); the command line words them as flags.
"""

from __future__ import annotations

import math

from .errors import InputError
from .units import rad_s_to_rpm

#: s0 below which the load is past the static rating (ISO 76) [-].
MIN_STATIC_SAFETY = 1.0
#: s0 below which the elastic contact models no longer apply [-].
MIN_ELASTIC_SAFETY = 1.0 / 8.0
#: Maximum Hertz pressure behind the static rating C0 of ball bearings (ISO 76:2006):
#: a permanent deformation of 1e-4 D_w [Pa].
STATIC_RATING_PRESSURE = 4.2e9
#: The pressure of a load 1 / MIN_ELASTIC_SAFETY = 8 times C0 (p ~ Q^(1/3): 8.4 GPa),
#: past which the elastic contact models no longer apply [Pa].
ELASTIC_LIMIT_PRESSURE = STATIC_RATING_PRESSURE * (1.0 / MIN_ELASTIC_SAFETY) ** (1.0 / 3.0)
#: Maximum Hertz pressure behind the static rating C0 of roller bearings (ISO 76:2006:
#: 4000 MPa for all roller bearings, a permanent deformation of 1e-4 D_we) [Pa].
STATIC_RATING_PRESSURE_ROLLER = 4.0e9
#: Speed factor above which standard ball bearings pass their makers' limiting speeds
#: [mm/min] (a rule of thumb; see the module docstring).
HIGH_SPEED_FACTOR = 1.0e6
#: Cage revolutions a record should hold to separate the cage sidebands (resolution
#: FTF / 3) [-].
MIN_CAGE_REVOLUTIONS = 3.0

#: fault family -> the kinematic frequency that carries it and the sideband spacing
FAMILIES = {
    "outer_race": ("bpfo", None),
    "inner_race": ("bpfi", "shaft"),
    "ball": ("ball_defect", "ftf"),
    "cage": ("ftf", None),
}
#: how the frequencies are named in messages
_LABEL = {
    "bpfo": "BPFO",
    "bpfi": "BPFI",
    "ball_defect": "the ball-defect rate 2 BSF",
    "ftf": "FTF",
    "shaft": "the shaft frequency",
}
#: Defect.location -> fault family
LOCATION_FAMILY = {"outer": "outer_race", "inner": "inner_race", "ball": "ball"}


def static_safety(bearing, radial_load: float, axial_load: float = 0.0) -> float | None:
    """s0 = C0 / P0 (ISO 76:2006) [-]; None without a load or for a geometry the rating
    does not cover."""
    from .life import equivalent_static_load, load_ratings

    try:
        p0 = equivalent_static_load(bearing, radial_load, abs(axial_load))
        c0 = load_ratings(bearing).static
    except InputError:
        return None
    return c0 / p0 if p0 > 0 else None


def load_warnings(bearing, radial_load: float, axial_load: float = 0.0) -> list[str]:
    """The load against the static rating C0: a warning below s0 = 1, an error below 1/8.

    Raises
    ------
    InputError
        Named ``radial_load`` (or ``axial_load`` when only that is given), when the static
        equivalent load passes 8 C0.
    """
    s0 = static_safety(bearing, radial_load, axial_load)
    if s0 is None or s0 >= MIN_STATIC_SAFETY:
        return []
    from .life import equivalent_static_load, load_ratings

    c0 = load_ratings(bearing).static
    p0 = equivalent_static_load(bearing, radial_load, abs(axial_load))
    if s0 < MIN_ELASTIC_SAFETY:
        name, value = (
            ("radial_load", radial_load) if radial_load > 0 else ("axial_load", axial_load)
        )
        raise InputError(
            name,
            value,
            f"a load whose static equivalent P0 is at most "
            f"{1 / MIN_ELASTIC_SAFETY:g} C0 = {c0 / MIN_ELASTIC_SAFETY:.4g} N",
            f"P0 = {p0:.4g} N is {p0 / c0:.3g} times the static rating C0 = "
            f"{c0:.4g} N (ISO 76): the contacts would flow plastically and no "
            "elastic model applies",
        )
    return [
        f"static safety factor s0 = C0/P0 = {s0:.3g} < 1: the static equivalent load "
        f"P0 = {p0:.4g} N is above the static rating C0 = {c0:.4g} N (ISO 76): the "
        "raceways deform permanently by more than 1e-4 D_w; results assume elastic "
        "contacts"
    ]


#: part of :class:`~bearinglab.imperfections.Imperfections` -> the input that gives it
FORM_ERROR_INPUTS = {
    "waviness": "waviness",
    "ball_size_errors": "ball_size_error_um",
    "surfaces": "surface3d",
}


def form_error_inputs(imperfections) -> dict:
    """The inputs (:data:`FORM_ERROR_INPUTS`) that hold the parts of ``imperfections``
    given, each with its description (``to_dict()``); empty for None or no form error."""
    if imperfections is None:
        return {}
    d = imperfections.to_dict()
    return {name: d[part] for part, name in FORM_ERROR_INPUTS.items() if d.get(part)}


def contact_warnings(bearing, result, *, cause) -> list[str]:
    """The contact pressure the form errors cause, against the static rating (ISO 76:2006).

    ISO 76:2006 sets the basic static load rating C0 of a ball bearing at the load whose
    most heavily loaded contact reaches a Hertz pressure of 4200 MPa, at which the
    permanent deformation of ball and raceway together is about 1e-4 D_w.
    :func:`load_warnings` checks the external load against C0 (P0 / C0); this checks the
    pressures actually solved with the form errors, which press the balls they enlarge
    harder than the external load does. The thresholds are those of
    :func:`load_warnings` in pressure: a warning past 4200 MPa (s0 = 1) and an error past
    :data:`ELASTIC_LIMIT_PRESSURE` = 8.4 GPa, the pressure of 8 C0 (p ~ Q^(1/3), so
    8^(1/3) = 2 times 4200 MPa): there the contacts would flow plastically, relieving
    the interference the elastic solution assumes, so its loads, orbit and sound are no
    longer those of the bearing. The check speaks only when the form errors cause the
    pressure: when the external load alone has s0 < 1, :func:`load_warnings` already
    warns (or raises); under a radial load with s0 >= 1 the solved pressure of a perfect
    deep-groove bearing stays under 4200 MPa (3.86 GPa for a 608, a 6205 and a 6308 at
    F_r = C0: C0 rests on Stribeck's Q_max = 5 F_r / (Z cos alpha), more than the solver
    finds at the catalogue clearances), so what passes it comes from the form errors.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    result : LoadDistribution or Orbit
        The solved contacts with the form errors: ``max_pressure`` [Pa] and
        ``max_ball_load`` [N] (an orbit's per instant; the worst instant is reported with
        its time), ``condition`` the operating condition.
    cause : mapping
        The inputs that gave the form errors in ``result`` (their public names:
        ``waviness``, ``ball_size_error_um``, ``surface3d``) -> the value as given
        (:func:`form_error_inputs` of an Imperfections); empty: no check.

    Raises
    ------
    InputError
        Named after the first input of ``cause``, past :data:`ELASTIC_LIMIT_PRESSURE`.
    """
    import numpy as np

    pressure = getattr(result, "max_pressure", None)
    if not cause or pressure is None:
        return []
    pressure = np.atleast_1d(np.asarray(pressure, float))
    k = int(np.argmax(pressure))
    p = float(pressure[k])
    if not p > STATIC_RATING_PRESSURE:
        return []
    condition = result.condition
    s0 = static_safety(bearing, condition.radial_load, condition.axial_load)
    if s0 is not None and s0 < MIN_STATIC_SAFETY:
        return []  # the external load is past C0 by itself: load_warnings says so
    load = float(np.atleast_1d(np.asarray(result.max_ball_load, float))[k])
    time = getattr(result, "time", None)
    when = "" if time is None else f" at t = {time[k] * 1e3:.4g} ms of the orbit"
    names = ", ".join(f"`{name}`" for name in cause)
    what = f"the form errors ({names}) put {load:.4g} N and {p / 1e9:.3g} GPa on a ball{when}"
    limit = STATIC_RATING_PRESSURE / 1e9
    if p > ELASTIC_LIMIT_PRESSURE:
        name = next(iter(cause))
        raise InputError(
            name,
            cause[name],
            f"form errors that keep the contact pressure below "
            f"{ELASTIC_LIMIT_PRESSURE / 1e9:.3g} GPa, that of 8 C0 (ISO 76)",
            f"{what}: the contacts would flow plastically and no elastic model applies",
        )
    return [
        f"{what}, past the {limit:g} GPa of ISO 76 (the static rating C0): the contacts "
        "would deform permanently by more than 1e-4 D_w and the results assume elastic "
        "contacts; check the amplitudes"
    ]


def pressure_warnings(bearing, result) -> list[str]:
    """The largest contact pressure of a solved roller bearing against ISO 76's 4000 MPa.

    ISO 76:2006 sets the static rating C0 of a roller bearing at the load whose most loaded
    contact reaches 4000 MPa (a permanent deformation of 1e-4 D_we). The slice model's
    pressures (:attr:`~bearinglab.quasistatic.roller_result.RollerLoadDistribution.max_pressure`)
    can pass it below C0, when a tilt or a misalignment puts the load on the rollers'
    ends; this says so in the user's terms. Empty for a ball bearing (whose form-error
    pressures :func:`contact_warnings` checks) or below the limit.

    Parameters
    ----------
    bearing : RollerBearing or BallBearing
        The bearing.
    result : RollerLoadDistribution
        The solved distribution (``max_pressure`` [Pa], ``max_roller_load`` [N]).
    """
    if getattr(bearing, "rolling_element", "ball") != "roller":
        return []
    p = float(getattr(result, "max_pressure", 0.0))
    if not p > STATIC_RATING_PRESSURE_ROLLER:
        return []
    tilted = any(result.condition.misalignment) or any(result.condition.outer_misalignment)
    why = (
        "the tilt between the rings puts the load on the rollers' ends"
        if tilted or result.condition.moment is not None
        else "the load is beyond the static rating"
    )
    return [
        f"the largest roller contact pressure is {p / 1e6:.4g} MPa, past the 4000 MPa of "
        f"ISO 76 (the static rating C0 of roller bearings): {why}; the raceways would "
        "deform permanently by more than 1e-4 D_we, and the results assume elastic contacts"
    ]


def speed_factor(bearing, shaft_speed: float) -> float:
    """n d_m [mm/min] of the shaft speed [rad/s]."""
    return abs(rad_s_to_rpm(shaft_speed)) * bearing.pitch_diameter * 1e3


def speed_factor_warnings(bearing, shaft_speed: float) -> list[str]:
    """The speed factor n d_m against the makers' usual limit (a warning); light, for the
    kinematic commands that need no model of the contacts."""
    ndm = speed_factor(bearing, shaft_speed)
    if not ndm > HIGH_SPEED_FACTOR:
        return []
    return [
        f"speed factor n d_m = {ndm:.3g} mm/min is above {HIGH_SPEED_FACTOR:.0e} "
        "mm/min, beyond the limiting speeds makers list for standard ball "
        "bearings: check the maker's limiting speed for this design and "
        "lubrication"
    ]


def speed_warnings(
    bearing, shaft_speed: float, radial_load: float = 0.0, axial_load: float = 0.0
) -> list[str]:
    """The speed against the makers' usual limits and against the load (warnings), and
    against the quasi-static model's limit (an error).

    Raises
    ------
    InputError
        Named ``shaft_speed``, above :func:`bearinglab.quasistatic.speed_limit`.
    """
    from .quasistatic import centrifugal_force, check_speed
    from .quasistatic.roller import roller_centrifugal_force

    if shaft_speed == 0:
        return []
    check_speed(
        bearing,
        shaft_speed,
        "beyond it the balls' centrifugal force swamps the contact loads "
        "and no model here is valid",
    )
    out = speed_factor_warnings(bearing, shaft_speed)
    roller = getattr(bearing, "rolling_element", "ball") == "roller"
    fc = (roller_centrifugal_force if roller else centrifugal_force)(bearing, shaft_speed)
    z, alpha = bearing.element_count, bearing.contact_angle
    element = "roller" if roller else "ball"
    q_max = max(
        5.0 * radial_load / (z * max(math.cos(alpha), 1e-9)),
        abs(axial_load) / (z * max(math.sin(alpha), 1e-9)) if axial_load else 0.0,
    )
    if fc > q_max and (radial_load or axial_load):
        out.append(
            f"each {element}'s centrifugal force F_c = {fc:.4g} N exceeds the heaviest "
            f"{element} load of the external load (about {q_max:.4g} N, Stribeck): the outer "
            "contacts are set by speed rather than load"
        )
    return out


def _article(word: str) -> str:
    """'an' before a vowel ('an inner-race', 'an outer-race'), else 'a'."""
    return "an" if word[:1].lower() in "aeiou" else "a"


def sampling_warnings(
    frequencies, sample_rate: float, duration: float | None = None, families=None
) -> list[str]:
    """The sample rate and record length against the bearing's frequencies.

    Parameters
    ----------
    frequencies : DefectFrequencies
        The kinematic frequencies (:func:`bearinglab.kinematics.defect_frequencies`).
    sample_rate : float
        [Hz].
    duration : float or None
        Record length T [s]; None skips the resolution check.
    families : iterable of str or None
        The fault families the record must show (``outer_race``, ``inner_race``, ``ball``,
        ``cage``): the error is for these; None checks every family, as warnings only.

    Raises
    ------
    InputError
        Named ``sample_rate``, when the defect frequency of a family in ``families`` is
        above the Nyquist frequency.
    """
    nyquist = 0.5 * sample_rate
    must = set(families or ())
    out = []
    too_high = []
    for family, (name, sideband) in FAMILIES.items():
        f = frequencies.hz(name)
        if f > nyquist:
            too_high.append((family, name, f))
            continue
        top = 2.0 * f + (frequencies.hz(sideband) if sideband else 0.0)
        if top > nyquist and (families is None or family in must):
            what = "harmonic and its sidebands reach" if sideband else "harmonic lies at"
            out.append(
                f"the second {what} {top:.5g} Hz (of {_LABEL[name]} = {f:.5g} Hz), "
                f"above the Nyquist frequency {nyquist:.5g} Hz: the "
                f"{family.replace('_', '-')} family shows only its first line"
            )
    required = [t for t in too_high if t[0] in must]
    if required:
        family, name, f = max(required, key=lambda t: t[2])
        raise InputError(
            "sample_rate",
            sample_rate,
            f"a sample rate above {2 * f:.6g} Hz [Hz]",
            f"{_LABEL[name]} = {f:.5g} Hz, the {family.replace('_', '-')} defect "
            f"frequency, is above the Nyquist frequency {nyquist:.5g} Hz",
        )
    for family, name, f in too_high:
        out.append(
            f"{_LABEL[name]} = {f:.5g} Hz is above the Nyquist frequency "
            f"{nyquist:.5g} Hz: {_article(family)} {family.replace('_', '-')} fault cannot "
            "show in this record"
        )
    if duration is not None:
        ftf = frequencies.hz("ftf")
        if duration * ftf < MIN_CAGE_REVOLUTIONS:
            out.append(
                f"the frequency resolution 1/T = {1 / duration:.3g} Hz is too coarse "
                f"to separate the cage sidebands (FTF = {ftf:.4g} Hz): record at least "
                f"{MIN_CAGE_REVOLUTIONS / ftf:.3g} s"
            )
    return out


def check_record_length(frequencies, duration: float) -> None:
    """Refuse a record to be diagnosed that holds fewer than :data:`MIN_CAGE_REVOLUTIONS`
    cage revolutions (the envelope diagnosis cannot separate the cage line).

    Raises
    ------
    InputError
        Named ``duration``.
    """
    ftf = frequencies.hz("ftf")
    if duration * ftf < MIN_CAGE_REVOLUTIONS:
        raise InputError(
            "duration",
            duration,
            f"at least {MIN_CAGE_REVOLUTIONS / ftf:.4g} s",
            f"{MIN_CAGE_REVOLUTIONS:g} cage revolutions at FTF = {ftf:.4g} Hz, "
            "which the envelope diagnosis needs to separate the cage line",
        )


def operating_warnings(bearing, condition) -> list[str]:
    """:func:`load_warnings` and :func:`speed_warnings` of an operating condition."""
    return load_warnings(bearing, condition.radial_load, condition.axial_load) + speed_warnings(
        bearing, condition.shaft_speed, condition.radial_load, condition.axial_load
    )
