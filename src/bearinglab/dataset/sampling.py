"""What a synthetic data set randomises, and the draw of one record's inputs.

Every input is given as a value (fixed), a pair ``(low, high)`` (uniform in the range) or
a list (one of the values, equally likely); on the command line ``LOW:HIGH`` and ``A,B,C``.
Record ``i`` draws everything from a generator seeded by (data set seed, i) alone
(:func:`bearinglab.study.case_rng`), so any record can be made again on any worker.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..errors import InputError
from ..study.cases import case_rng

#: Fault classes a record can have: "compound" is two different defects.
FAULTS = ("none", "outer", "inner", "ball", "cage", "compound")
MODELS = ("rigid", "slip")
#: Where single defects can be (the dynamic models' Defect locations).
LOCATIONS = ("outer", "inner", "ball")


def parse_range(
    name: str, value, *, text: bool = False, positive: bool = False, signed: bool = False
):
    """("fixed", v) / ("uniform", low, high) / ("choice", [values]) from a value, a pair,
    a list or the command line's text ("V", "LOW:HIGH", "A,B,C").

    Parameters
    ----------
    name : str
        The input's name, which the errors name.
    value
        A value, a pair (low, high), a list of values, or the text "V", "LOW:HIGH" or
        "A,B,C" (numbers in the unit of the input).
    text : bool
        The values are names, not numbers: a pair or "LOW:HIGH" is no range (a pair is a
        list of names).
    positive : bool
        The numbers must be > 0.
    signed : bool
        The numbers may be negative (otherwise they must be >= 0); ``positive`` prevails.

    Examples
    --------
    >>> parse_range("speed_rpm", "1700:1800")
    ('uniform', 1700.0, 1800.0)
    >>> parse_range("model", "rigid,slip", text=True)
    ('choice', ['rigid', 'slip'])
    """

    def number(v):
        if isinstance(v, bool):
            raise InputError(name, value, "numbers")
        try:
            x = float(v)
        except (TypeError, ValueError):
            raise InputError(name, value, "a number, LOW:HIGH or A,B,C") from None
        if not math.isfinite(x) or (positive and x <= 0) or (not (positive or signed) and x < 0):
            raise InputError(
                name,
                value,
                "finite values" if signed else "values > 0" if positive else "values >= 0",
            )
        return x

    def word(v):
        if not isinstance(v, str) or not v.strip():
            raise InputError(name, value, "non-empty names")
        return v.strip()

    if isinstance(value, str):
        s = value.strip()
        if not s:
            raise InputError(name, value, "a value, LOW:HIGH or A,B,C", "it is empty")
        if not text and ":" in s[1:]:  # a leading '-' is a sign, not a range
            parts = s.split(":")
            if len(parts) != 2:
                raise InputError(name, value, "LOW:HIGH")
            value = (parts[0], parts[1])
        elif "," in s:
            value = [p for p in s.split(",")]
            if any(not p.strip() for p in value):
                raise InputError(name, s, "a list A,B,C without empty items")
        else:
            value = s
    if isinstance(value, tuple) and not text:
        if len(value) != 2:
            raise InputError(name, value, "a pair (low, high)")
        low, high = number(value[0]), number(value[1])
        if low > high:
            raise InputError(name, value, "a range with low <= high", "the range is empty")
        return ("fixed", low) if low == high else ("uniform", low, high)
    if isinstance(value, (list, tuple)):
        if not value:
            raise InputError(name, value, "at least one value", "the list is empty")
        items = [word(v) if text else number(v) for v in value]
        return ("choice", items) if len(items) > 1 else ("fixed", items[0])
    return ("fixed", word(value) if text else number(value))


def draw(spec: tuple, rng):
    """One value of a parsed range."""
    if spec[0] == "fixed":
        return spec[1]
    if spec[0] == "uniform":
        return float(rng.uniform(spec[1], spec[2]))
    return spec[1][int(rng.integers(len(spec[1])))]


def _bearing_options(b) -> dict:
    """A bearing entry: a designation or a dict of the study's bearing options."""
    from ..study.bearings import BEARING_OPTIONS

    if isinstance(b, str):
        if not b.strip():
            raise InputError("bearings", b, "designations or dicts of geometry options")
        return {"designation": b.strip()}
    if isinstance(b, dict):
        bad = [k for k in b if k not in BEARING_OPTIONS]
        if bad:
            raise InputError("bearings", bad[0], "geometry options: " + ", ".join(BEARING_OPTIONS))
        return dict(b)
    raise InputError("bearings", b, "designations or dicts of geometry options")


def _check_bearing(given, options: dict) -> None:
    """Refuse a bearing that cannot be made (a designation not read, a geometry out of
    range) before any record is: every record drawing it would fail the same way."""
    from ..errors import BearinglabError
    from ..study.bearings import bearing_of

    try:
        return bearing_of(options)
    except BearinglabError as exc:
        allowed = exc.allowed if isinstance(exc, InputError) else "bearings bearinglab can make"
        hint = exc.hint if isinstance(exc, InputError) else " ".join(str(exc).split())
        raise InputError("bearings", given, allowed, hint) from None


def _load_warnings(given, bearing, parsed: dict) -> list[str]:
    """The highest radial load drawn against the bearing's static rating
    (:func:`bearinglab.plausibility.load_warnings`): past 8 C0 refused before any record,
    past C0 a warning for the set."""
    from ..plausibility import load_warnings

    load = _highest(parsed["radial_load_n"])
    try:
        return [f"{given}: {w}" for w in load_warnings(bearing, load)]
    except InputError as exc:
        raise InputError(
            "radial_load_n", parsed["radial_load_n"][1], exc.allowed, f"{given}: {exc.hint}"
        ) from None


def _check_rollers(given, bearing, parsed: dict) -> None:
    """Refuse, before any record, what the models take for ball bearings only when a
    roller bearing is drawn: waviness, ball-size errors and the slip model."""
    if bearing.rolling_element != "roller":
        return
    why = f"{given} is a roller bearing; the model takes it for ball bearings only"
    for name in ("waviness_amplitude_um", "ball_size_error_um"):
        if _highest(parsed[name]) > 0:
            raise InputError(name, parsed[name][1], "0 with a roller bearing", why)
    models = parsed["model"][1] if parsed["model"][0] == "choice" else [parsed["model"][1]]
    if "slip" in models:
        raise InputError("model", "slip", "rigid with a roller bearing", why)


@dataclass(frozen=True)
class DatasetSpec:
    """The ranges a data set draws from (SI-free: the units are in the names).

    See :func:`bearinglab.dataset.make_dataset` for each field; ``resonances`` is a list
    of (frequency range [Hz], damping-ratio range) pairs, one per resonance of the path.
    """

    records: int
    bearings: tuple = ("6205-2RS",)
    speed_rpm: object = (1700.0, 1800.0)
    radial_load_n: object = (200.0, 2000.0)
    faults: tuple = ("none", "outer", "inner", "ball")
    defect_width_mm: object = (0.2, 1.5)
    defect_depth_mm: object = (0.1, 0.3)
    defect_position_deg: object = (-135.0, -45.0)
    waviness_amplitude_um: object = 0.0
    waviness_orders: object = (2.0, 30.0)
    ball_size_error_um: object = 0.0
    noise_ms2: object = (0.5, 5.0)
    resonances: tuple = (((2500.0, 4500.0), (0.02, 0.08)),)
    sample_rate_hz: object = 20000.0
    duration_s: object = 1.0
    model: object = "rigid"
    parsed: dict = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        if isinstance(self.records, bool) or not isinstance(self.records, int) or self.records < 1:
            raise InputError("records", self.records, "a whole number >= 1")
        bearings = self.bearings if isinstance(self.bearings, (list, tuple)) else [self.bearings]
        if isinstance(self.bearings, str):
            bearings = [b for b in self.bearings.split(",")]
        if not bearings:
            raise InputError("bearings", self.bearings, "at least one bearing")
        p = {"bearings": [_bearing_options(b) for b in bearings]}
        made = [
            _check_bearing(b, options) for b, options in zip(bearings, p["bearings"], strict=True)
        ]
        faults = parse_range(
            "faults",
            list(self.faults) if isinstance(self.faults, tuple) else self.faults,
            text=True,
        )
        names = faults[1] if faults[0] == "choice" else [faults[1]]
        for f in names:
            if f not in FAULTS:
                raise InputError("faults", f, "some of " + ", ".join(FAULTS))
            if f == "cage":
                raise InputError(
                    "faults",
                    f,
                    "none, outer, inner, ball or compound",
                    "the dynamic models have no cage defect model, so no "
                    "cage-fault record can be made",
                )
        p["faults"] = faults
        model = parse_range(
            "model", list(self.model) if isinstance(self.model, tuple) else self.model, text=True
        )
        for m in model[1] if model[0] == "choice" else [model[1]]:
            if m not in MODELS:
                raise InputError("model", m, "rigid or slip")
        p["model"] = model
        for name, positive in (
            ("speed_rpm", True),
            ("radial_load_n", False),
            ("defect_width_mm", True),
            ("defect_depth_mm", True),
            ("waviness_amplitude_um", False),
            ("waviness_orders", True),
            ("ball_size_error_um", False),
            ("noise_ms2", False),
            ("sample_rate_hz", True),
            ("duration_s", True),
        ):
            p[name] = parse_range(name, getattr(self, name), positive=positive)
        p["defect_position_deg"] = parse_range(
            "defect_position_deg", self.defect_position_deg, signed=True
        )
        path = []
        for item in self.resonances:
            if not (isinstance(item, (list, tuple)) and len(item) == 2):
                raise InputError("resonances", item, "(frequency range [Hz], damping range)")
            path.append(
                (
                    parse_range("resonance frequency", item[0], positive=True),
                    parse_range("damping ratio", item[1], positive=True),
                )
            )
        p["resonances"] = path
        warnings = []
        for b, bearing in zip(bearings, made, strict=True):
            _check_rollers(b, bearing, p)
            warnings += _load_warnings(b, bearing, p)
        object.__setattr__(self, "warnings", tuple(warnings))
        default_path = self.resonances == type(self).__dataclass_fields__["resonances"].default
        _check_path(path, p["sample_rate_hz"], blame_rate=default_path)
        object.__setattr__(self, "parsed", p)

    def identity(self) -> dict:
        """JSON-ready description of everything drawn from (for resuming)."""
        return {k: v for k, v in self.parsed.items()} | {"records": self.records}

    @property
    def defect_locations(self) -> set[str]:
        """Where the set's records can have defects (outer, inner, ball): none for a set of
        healthy records only; all three with compound faults."""
        faults = self.parsed["faults"]
        names = faults[1] if faults[0] == "choice" else [faults[1]]
        return {
            where
            for f in names
            for where in (LOCATIONS if f == "compound" else [f])
            if where in LOCATIONS
        }

    @property
    def has_waviness(self) -> bool:
        """Whether a record can have raceway waviness (an amplitude above 0)."""
        return _highest(self.parsed["waviness_amplitude_um"]) > 0


def _highest(spec: tuple) -> float:
    """The largest value a parsed range can draw."""
    return spec[1] if spec[0] == "fixed" else (spec[2] if spec[0] == "uniform" else max(spec[1]))


def _check_path(path, rates, blame_rate: bool = False) -> None:
    """Every resonance must sit below 0.45 x the lowest sample rate the set may draw. The
    error names the resonance, or with ``blame_rate`` (the path is the default one, so the
    sample rate is what was chosen) the sample rate."""
    from .path import MAX_FRACTION

    lowest = rates[1] if rates[0] != "choice" else min(rates[1])
    for f, z in path:
        top = _highest(f)
        if top > MAX_FRACTION * lowest:
            if blame_rate:
                raise InputError(
                    "sample_rate_hz",
                    lowest,
                    f"a sample rate of at least {top / MAX_FRACTION:.6g} Hz, so that the "
                    f"transfer path's highest resonance, {top:g} Hz, lies below "
                    f"{MAX_FRACTION:g} x the sample rate",
                    "or give the path lower resonances",
                )
            raise InputError(
                "resonance frequency",
                top,
                f"at most {MAX_FRACTION:g} x the lowest sample rate ({MAX_FRACTION * lowest:g} Hz)",
            )
        zeta = _highest(z)
        if zeta >= 1:
            raise InputError("damping ratio", zeta, "ratios in (0, 1)")


def draw_record(spec: DatasetSpec, seed: int, index: int) -> dict:
    """Inputs of record ``index`` of the data set ``spec``, drawn from the data set
    ``seed`` and ``index`` alone (:func:`bearinglab.study.case_rng`): bearing, operating
    point, defects, form errors, noise, path, sampling (engineering units; defects as
    dicts).

    Parameters
    ----------
    spec : DatasetSpec
        The data set's specification (its ranges and choices).
    seed : int
        The data set's seed (>= 0).
    index : int
        The record's index in the set (>= 0).

    Returns
    -------
    dict
        The record's inputs: ``bearing``, ``fault``, ``defects``, ``speed_rpm``,
        ``radial_load_n``, ``model``, ``sample_rate_hz``, ``duration_s``, ``noise_ms2``,
        form errors, ``resonances`` ((f [Hz], zeta [-]) pairs), ...
    """
    p = spec.parsed
    rng = case_rng(seed, index)
    bearing = p["bearings"][int(rng.integers(len(p["bearings"])))]
    fault = draw(p["faults"], rng)
    if fault == "compound":
        locations = sorted(rng.choice(len(LOCATIONS), size=2, replace=False).tolist())
        parts = [LOCATIONS[i] for i in locations]
    else:
        parts = [] if fault == "none" else [fault]
    defects = []
    for part in parts:
        width, depth = draw(p["defect_width_mm"], rng), draw(p["defect_depth_mm"], rng)
        if part == "outer":
            angle = draw(p["defect_position_deg"], rng)
        else:  # inner ring angle at t = 0, or the ball's spin phase: anywhere
            angle = float(rng.uniform(0.0, 360.0))
        defects.append({"location": part, "width_mm": width, "depth_mm": depth, "angle_deg": angle})
    record = {
        "bearing": bearing,
        "fault": fault,
        "defects": defects,
        "speed_rpm": draw(p["speed_rpm"], rng),
        "radial_load_n": draw(p["radial_load_n"], rng),
        "model": draw(p["model"], rng),
        "sample_rate_hz": draw(p["sample_rate_hz"], rng),
        "duration_s": draw(p["duration_s"], rng),
        "noise_ms2": draw(p["noise_ms2"], rng),
        "ball_size_error_um": draw(p["ball_size_error_um"], rng),
        "waviness_amplitude_um": draw(p["waviness_amplitude_um"], rng),
        "resonances": [(draw(f, rng), draw(z, rng)) for f, z in p["resonances"]],
    }
    record["waviness"] = [
        {
            "race": race,
            "order": round(draw(p["waviness_orders"], rng)),
            "phase_deg": float(rng.uniform(0.0, 360.0)),
        }
        for race in ("outer", "inner")
    ]
    record["ball_index"] = int(rng.integers(1 << 30))  # which ball (mod Z) has the defect
    record["seed"] = int(rng.integers(1 << 31))  # noise and ball-size errors
    return record
