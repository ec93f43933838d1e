"""The specifications of what is wrong with a bearing, as a user writes them: ``defect``
(localised pits, issue 4) and the form errors ``waviness``, ``ball_size_error_um``,
``surface3d`` and ``seed`` (issue 5), parsed and checked in
their units into :class:`~bearinglab.dynamics.Defect` and one
:class:`~bearinglab.imperfections.Imperfections`."""

import math

import numpy as np

from ..errors import InputError

WAVINESS_ALLOWED = (
    "RACE:KEY=VALUE,... with RACE inner, outer or ball and keys order (waves "
    "round the circumference, >= 1) and amplitude_um (>= 0, half the peak to "
    "peak), both required, phase_deg (r = A cos(order theta + phase), default "
    "0) and ball (ball index, ball waviness only; default every ball), e.g. "
    "inner:order=7,amplitude_um=0.5"
)
SURFACE_ALLOWED = (
    "RACE:KEY=VALUE,... with RACE inner or outer and keys amplitude_um (RMS "
    "height >= 0), length_circ_mm and length_axial_mm (correlation lengths > 0 "
    "of seed 002 eq. 6), all required, e.g. "
    "outer:amplitude_um=0.2,length_circ_mm=0.5,length_axial_mm=0.5"
)
BALL_ERROR_ALLOWED = (
    "a band width >= 0 um (ball diameter errors uniform in [-BAND/2, +BAND/2] "
    "um about the nominal diameter) or LOW,HIGH um with LOW <= HIGH (uniform "
    "in [LOW, HIGH])"
)
_WAVINESS_KEYS = {
    race: {"order": "order", "amplitude_um": "nonnegative", "phase_deg": "number"}
    for race in ("inner", "outer")
}
_WAVINESS_KEYS["ball"] = {**_WAVINESS_KEYS["inner"], "ball": "index"}
_SURFACE_KEYS = {
    race: {
        "amplitude_um": "nonnegative",
        "length_circ_mm": "positive",
        "length_axial_mm": "positive",
    }
    for race in ("inner", "outer")
}
#: Largest random-surface grid (points round x across, with the generating margin): the
#: generator holds a few arrays of this size (complex FFTs).
MAX_SURFACE_POINTS = 1 << 22
#: Largest form-error amplitude, as a fraction of D_w (the load-distribution solver's limit
#: on an approach change).
MAX_FORM_ERROR = 0.05

#: What a defect specification may hold.
DEFECT_ALLOWED = (
    "LOCATION:KEY=VALUE,... with LOCATION outer, inner, ball (a ball bearing) or roller (a "
    "roller bearing) and keys width_mm (> 0, required), depth_mm (> 0), angle_deg (outer: "
    "position from +x towards +y, 270 = bottom; inner: position at t = 0; ball, roller: "
    "spin phase) and ball or roller (its index, its defects only), e.g. "
    "outer:width_mm=1.2,depth_mm=0.25"
)
_DEFECT_KEYS = {
    "outer": {"width_mm": "positive", "depth_mm": "positive", "angle_deg": "number"},
    "inner": {"width_mm": "positive", "depth_mm": "positive", "angle_deg": "number"},
    "ball": {
        "width_mm": "positive",
        "depth_mm": "positive",
        "angle_deg": "number",
        "ball": "index",
    },
    "roller": {
        "width_mm": "positive",
        "depth_mm": "positive",
        "angle_deg": "number",
        "roller": "index",
    },
}


# ------------------------------------------------------------------ KEY=VALUE specifications
#: Kinds of value a specification key takes: kind -> what it must be.
_SPEC_KINDS = ("number", "positive", "nonnegative", "index", "order")


def parse_spec(
    text: str,
    name: str,
    allowed: str,
    keys: dict[str, dict[str, str]],
    *,
    noun: str,
    word: str = "location",
    required: tuple[str, ...] = (),
) -> tuple[str, dict]:
    """Read one ``PREFIX:KEY=VALUE,...`` specification (defect, waviness, surface3d).

    Parameters
    ----------
    text : str
        The specification as typed.
    name : str
        The input, for the error (e.g. ``defect``).
    allowed : str
        What the input accepts (the error's "expected ...").
    keys : dict
        Prefix (lower case) -> {key: kind}; kinds: ``number`` (finite), ``positive``
        (> 0), ``nonnegative`` (>= 0), ``index`` (whole number >= 0), ``order`` (whole
        number >= 1).
    noun : str
        What the prefix qualifies, for "unknown key 'x' for outer {noun}".
    word : str
        What the prefix is called ("location", "race").
    required : tuple of str
        Keys that must be given.

    Returns
    -------
    (prefix, {key: int or float})
        In the input's units (no conversion).

    Raises
    ------
    InputError
        One line naming the input, the specification and the part that is wrong.

    Examples
    --------
    >>> parse_spec("Inner : order=7, amplitude_um=0.5", "waviness", "...",
    ...            {"inner": {"order": "order", "amplitude_um": "nonnegative"}},
    ...            noun="waviness", word="race")
    ('inner', {'order': 7, 'amplitude_um': 0.5})
    """

    def bad(hint: str) -> InputError:
        return InputError(name, text, allowed, hint)

    prefix, sep, rest = text.strip().partition(":")
    prefix = prefix.strip().lower()
    if prefix not in keys:
        raise bad(f"unknown {word} {prefix!r}")
    if not sep or not rest.strip():
        need = (
            f"; {', '.join(required)} {'is' if len(required) == 1 else 'are'} required"
            if required
            else ""
        )
        raise bad(f"no KEY=VALUE given{need}")
    values: dict = {}
    for item in rest.split(","):
        key, eq, value = (s.strip() for s in item.partition("="))
        kind = keys[prefix].get(key)
        if kind is None:
            raise bad(f"unknown key {key!r} for {prefix} {noun} (keys: {', '.join(keys[prefix])})")
        if not eq or not value:
            raise bad(f"{key} has no value")
        if key in values:
            raise bad(f"{key} given twice")
        if kind in ("index", "order"):
            try:
                number = int(value)
            except ValueError:
                raise bad(f"{key} = {value!r} is not a whole number") from None
            least = 0 if kind == "index" else 1
            if number < least:
                raise bad(f"{key} must be >= {least}")
        else:
            try:
                number = float(value)
            except ValueError:
                raise bad(f"{key} = {value!r} is not a number") from None
            if not math.isfinite(number):
                raise bad(f"{key} must be finite")
            if kind == "positive" and number <= 0:
                raise bad(f"{key} must be > 0")
            if kind == "nonnegative" and number < 0:
                raise bad(f"{key} must be >= 0")
        values[key] = number
    for key in required:
        if key not in values:
            raise bad(f"{key} is required")
    return prefix, values


def parse_defect(text: str):
    """A :class:`~bearinglab.dynamics.Defect` (SI) from a defect specification ``text``.

    ``outer:width_mm=1.2,depth_mm=0.25[,angle_deg=270]``, ``inner:...`` or
    ``ball:width_mm=1.2[,ball=0]``; widths and depths in mm, angles in degrees (for the
    outer race from +x towards +y, default 270 = the bottom of the load zone).

    Parameters
    ----------
    text : str
        The specification: ``LOCATION:KEY=VALUE,...`` with LOCATION one of outer, inner,
        ball, roller (any case) and keys ``width_mm`` (required, > 0), ``depth_mm`` (> 0),
        ``angle_deg`` (outer: position, default 270; inner: position at t = 0; ball,
        roller: spin phase) and, for a ball or roller, ``ball`` / ``roller`` (its index,
        >= 0).

    Examples
    --------
    >>> parse_defect("outer:width_mm=1.2,depth_mm=0.25").to_dict()["angle_deg"]
    -90.0
    """
    location, values = parse_spec(
        text, "defect", DEFECT_ALLOWED, _DEFECT_KEYS, noun="defects", required=("width_mm",)
    )
    kwargs = {
        "width": values["width_mm"] * 1e-3,
        "depth": values["depth_mm"] * 1e-3 if "depth_mm" in values else None,
    }
    if "angle_deg" in values:  # into [-pi, pi): 270 deg is -90 deg, the bottom
        kwargs["angle"] = (math.radians(values["angle_deg"]) + math.pi) % (2 * math.pi) - math.pi
    if "ball" in values or "roller" in values:
        kwargs["ball"] = values.get("ball", values.get("roller"))
    from ..dynamics import Defect  # the dynamics package imports scipy.signal

    # a roller's defect is the rolling element's: the models' "ball" location
    return Defect("ball" if location == "roller" else location, **kwargs)


def form_errors_text(imperfections) -> str:
    """One line describing the form errors (or "none")."""
    if imperfections is None or imperfections.is_empty:
        return "none"
    parts = []
    for w in imperfections.waviness:
        where = w.race + (f" {w.ball}" if w.ball is not None else "")
        parts.append(f"{where} waviness q = {w.order}, {w.amplitude * 1e6:g} um")
    if imperfections.ball_size_errors is not None:
        parts.append(f"ball sizes within {imperfections.ball_size_errors.band * 1e6:.3g} um")
    for srf in imperfections.surfaces:
        parts.append(f"{srf.race} 3-D surface {srf.amplitude * 1e6:g} um RMS")
    return "; ".join(parts)


def defect_text(d) -> str:
    x = d.to_dict()
    text = f"{d.location}: width {x['width_mm']:g} mm"
    if x["depth_mm"] is not None:
        text += f", depth {x['depth_mm']:g} mm"
    text += f", angle {x['angle_deg'] % 360:g} deg"
    return text + (f", ball {d.ball}" if d.location == "ball" else "")


def check_defects(specs: list[str], defects: list, bearing) -> None:
    """Each defect of ``specs`` (as typed) and ``defects`` (as parse_defect read them)
    checked against the ``bearing``
    (Defect.check): one that does not fit is a one-line error in the spec's units.

    Parameters
    ----------
    specs : list of str
        The defect specifications as typed (``outer:width_mm=1.2,...``).
    defects : list of Defect
        The same, as :func:`parse_defect` read them (one per specification).
    bearing : BallBearing or RollerBearing
        The bearing they must fit (a ``ball:`` defect needs balls, a ``roller:`` one
        rollers).
    """
    element = bearing.rolling_element
    for text, defect in zip(specs, defects, strict=True):
        written = str(text).partition(":")[0].strip().lower()
        if written in ("ball", "roller") and written != element:
            raise InputError(
                "defect",
                text,
                DEFECT_ALLOWED,
                f"{bearing.name or 'the bearing'} has {element}s: write {element}:...",
            )
        try:
            defect.check(bearing)
        except InputError as exc:
            shown = (
                f"width_mm = {exc.value * 1e3:g}"
                if exc.parameter == "width"
                else f"{exc.parameter} = {exc.value!r}"
            )
            raise InputError(
                "defect",
                text,
                DEFECT_ALLOWED,
                f"for {bearing.name or 'this bearing'}: {shown} must be {exc.allowed}",
            ) from None


def parse_waviness(text: str):
    """A :class:`~bearinglab.imperfections.Waviness` (SI) from a waviness specification.

    >>> w = parse_waviness("ball:order=2,amplitude_um=0.5,phase_deg=90,ball=3")
    >>> w.race, w.order, round(w.amplitude * 1e6, 9), round(w.phase, 6), w.ball
    ('ball', 2, 0.5, 1.570796, 3)
    """
    from ..imperfections import Waviness

    race, v = parse_spec(
        text,
        "waviness",
        WAVINESS_ALLOWED,
        _WAVINESS_KEYS,
        noun="waviness",
        word="race",
        required=("order", "amplitude_um"),
    )
    return Waviness(
        race,
        v["order"],
        v["amplitude_um"] * 1e-6,
        math.radians(v.get("phase_deg", 0.0)),
        v.get("ball"),
    )


def parse_ball_band(text: str):
    """ball_size_error_um: a band width [m] or a pair (low, high) [m].

    >>> parse_ball_band("2"), parse_ball_band("0, 3")
    (2e-06, (0.0, 3e-06))
    """
    parts = [p.strip() for p in text.split(",")]
    try:
        values = [float(p) for p in parts]
    except ValueError:
        values = []
    if len(values) not in (1, 2) or not all(math.isfinite(v) for v in values):
        raise InputError("ball_size_error_um", text, BALL_ERROR_ALLOWED)
    if len(values) == 1:
        if values[0] < 0:
            raise InputError(
                "ball_size_error_um", text, BALL_ERROR_ALLOWED, "the band must be >= 0"
            )
        return values[0] * 1e-6
    if values[0] > values[1]:
        raise InputError("ball_size_error_um", text, BALL_ERROR_ALLOWED, "LOW > HIGH")
    return values[0] * 1e-6, values[1] * 1e-6


def parse_surface(text: str) -> tuple[str, dict]:
    """(race, {amplitude_um, length_circ_mm, length_axial_mm}) from a surface3d
    specification (the surface itself needs the bearing: :meth:`FormErrors.build`)."""
    return parse_spec(
        text,
        "surface3d",
        SURFACE_ALLOWED,
        _SURFACE_KEYS,
        noun="surfaces",
        word="race",
        required=("amplitude_um", "length_circ_mm", "length_axial_mm"),
    )


class FormErrors:
    """The form-error inputs as given and parsed (before the bearing is known):
    waviness, ball_size_error_um, surface3d. :meth:`build` makes the
    :class:`~bearinglab.imperfections.Imperfections` for a bearing and a seed."""

    def __init__(
        self,
        waviness: list[str] | None = None,
        ball_size_error_um: str | None = None,
        surface3d: list[str] | None = None,
    ) -> None:
        self.waviness = [(text, parse_waviness(text)) for text in waviness or ()]
        self.band_text = ball_size_error_um
        self.band = None if ball_size_error_um is None else parse_ball_band(ball_size_error_um)
        self.surfaces = [(text, *parse_surface(text)) for text in surface3d or ()]

    @property
    def given(self) -> bool:
        """True when any form error was asked for."""
        return bool(self.waviness or self.surfaces or self.band is not None)

    def build(self, bearing, seed: int | None = None):
        """The Imperfections on ``bearing``, random ones drawn with ``seed`` (None: 0;
        None when none were given); errors name the
        input and the specification.

        Parameters
        ----------
        bearing : BallBearing
            The bearing the form errors are on; the amplitudes are checked against its ball
            diameter and the surfaces sized on its raceways.
        seed : int or None
            Seed (>= 0) of the random form errors (ball-size errors, random surfaces); None
            gives 0.

        Returns
        -------
        Imperfections or None
            None when no form error was given.
        """
        from ..imperfections import BallSizeErrors, Imperfections, RandomSurface

        if not self.given:
            return None
        if seed is not None and seed < 0:
            raise InputError("seed", seed, "an integer >= 0")
        seed = 0 if seed is None else int(seed)
        name = bearing.name or "this bearing"
        limit = MAX_FORM_ERROR * bearing.ball_diameter
        for text, w in self.waviness:
            try:
                w.check(bearing)
            except InputError as exc:
                raise InputError(
                    "waviness",
                    text,
                    WAVINESS_ALLOWED,
                    f"for {name}: {exc.parameter} = {exc.value!r} must be {exc.allowed}",
                ) from None
            if w.amplitude > limit:
                raise InputError(
                    "waviness",
                    text,
                    WAVINESS_ALLOWED,
                    f"amplitude_um must be at most {limit * 1e6:.4g} for {name} "
                    f"({MAX_FORM_ERROR:.0%} of the ball diameter)",
                )
        errors = None
        if self.band is not None:
            errors = BallSizeErrors.random(bearing.ball_count, self.band, seed=seed)
            if np.max(np.abs(errors.errors)) > limit:
                raise InputError(
                    "ball_size_error_um",
                    self.band_text,
                    BALL_ERROR_ALLOWED,
                    f"errors must stay within +-{limit * 1e6:.4g} um for {name} "
                    f"({MAX_FORM_ERROR:.0%} of the ball diameter)",
                )
        surfaces = []
        for i, (text, race, v) in enumerate(self.surfaces):
            if v["amplitude_um"] * 1e-6 > limit / 3:
                raise InputError(
                    "surface3d",
                    text,
                    SURFACE_ALLOWED,
                    f"amplitude_um must be at most {limit / 3 * 1e6:.4g} for "
                    f"{name} (its peaks reach about 3 RMS; "
                    f"{MAX_FORM_ERROR:.0%} of the ball diameter)",
                )
            length_r, length_z = v["length_circ_mm"] * 1e-3, v["length_axial_mm"] * 1e-3
            radius = 0.5 * (
                bearing.inner_raceway_diameter
                if race == "inner"
                else bearing.outer_raceway_diameter
            )
            if length_r > math.pi * radius:
                raise InputError(
                    "surface3d",
                    text,
                    SURFACE_ALLOWED,
                    f"length_circ_mm must be at most {math.pi * radius * 1e3:.4g} "
                    f"for {name} (half the {race} raceway's circumference)",
                )
            points = _surface_points(bearing, race, length_r, length_z)
            if points > MAX_SURFACE_POINTS:
                raise InputError(
                    "surface3d",
                    text,
                    SURFACE_ALLOWED,
                    f"the correlation lengths need a grid of {points:.3g} points "
                    f"on {name}, more than {MAX_SURFACE_POINTS:.3g}: give longer "
                    "length_circ_mm or length_axial_mm",
                )
            try:
                surfaces.append(
                    RandomSurface.for_bearing(
                        bearing, race, v["amplitude_um"] * 1e-6, length_r, length_z, seed + 1 + i
                    )
                )
            except InputError as exc:
                raise InputError("surface3d", text, SURFACE_ALLOWED, f"for {name}: {exc}") from None
        return Imperfections(
            [w for _, w in self.waviness], ball_size_errors=errors, surfaces=surfaces
        )


def _surface_points(bearing, race: str, length_r: float, length_z: float) -> int:
    """Grid points RandomSurface.for_bearing generates (round x across with its margin)."""
    from ..imperfections.surface import AXIAL_MARGIN

    radius = 0.5 * (
        bearing.inner_raceway_diameter if race == "inner" else bearing.outer_raceway_diameter
    )
    width = bearing.ball_diameter
    n_r = max(256, 1 << max(0, math.ceil(math.log2(8 * math.pi * radius / length_r))))
    n_z = max(17, math.ceil(4 * width / length_z) + 1)
    margin = math.ceil(AXIAL_MARGIN * length_z / (width / (n_z - 1)))
    return n_r * (n_z + margin)
