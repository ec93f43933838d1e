"""Analyses of the bearing's vibration: the sound pressure of a bearing with form errors
(``noise``, seed 003 part 4, seed 002) and the simulated vibration with its envelope
diagnosis (``simulate``, seed 003's rigid model or seed 004's slip model). Each builds the
models from the request, calls the library once and keeps the result; a study may give a
simulation's faults as sweepable numbers (``fault``, ``defect_width_mm``, ...) and the
waviness per race, as well as the command's specifications."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import BearinglabError, InputError
from ..inputs import (
    INPUTS,
    FormErrors,
    Input,
    balls_only,
    bearing_from,
    bearing_warnings,
    check_defects,
    condition_from,
    parse_defect,
    restate,
    si,
    speed_from,
)
from .base import BEARING_INPUTS, FILES, Analysis, inputs, plot_file, specs

_SHAFT = {"speed_rpm": INPUTS["speed_rpm"].with_(help="Shaft (inner-ring) speed [rpm].")}
_FORMS = inputs("waviness", "ball_size_error_um", "surface3d")

#: Study-only inputs: the waviness of each race as sweepable numbers.
_WAVES = {}
for _race in ("outer", "inner", "ball"):
    _WAVES[f"waviness_{_race}_order"] = Input(
        "integer",
        None,
        f"Waviness order q of the {_race} {'race' if _race != 'ball' else 'balls'}.",
        low=1,
    )
    _WAVES[f"waviness_{_race}_amplitude_um"] = Input(
        "number", None, f"{_race.capitalize()} waviness amplitude [um].", low=0.0
    )


def forms_of(values: dict) -> FormErrors:
    """The form errors of a request: the specifications (``waviness``,
    ``ball_size_error_um``, ``surface3d``) and a study's per-race waviness numbers."""
    waves = specs(values.get("waviness"))
    for race in ("outer", "inner", "ball"):
        amplitude = values.get(f"waviness_{race}_amplitude_um") or 0.0
        order = values.get(f"waviness_{race}_order")
        if amplitude:
            if order is None:
                raise InputError(
                    f"waviness_{race}_order",
                    None,
                    f"a waviness order >= 1 with waviness_{race}_amplitude_um",
                )
            waves.append(f"{race}:order={int(order)},amplitude_um={amplitude!r}")
    band = values.get("ball_size_error_um")
    band = None if band is None or band == 0 else str(band)
    return FormErrors(waves, band, specs(values.get("surface3d")))


# ------------------------------------------------------------------ noise
#: Most instants of the orbit (about 1.3 ms each).
MAX_POINTS = 200_000


@dataclass(frozen=True)
class NoiseOutcome:
    """The noise of a request (:func:`bearinglab.noise.noise_analysis`)."""

    result: object
    bearing: object
    imperfections: object = None
    designation: str | None = None
    seed: int = 0
    warnings: tuple = field(default_factory=tuple)

    def to_dict(self) -> dict:
        d = self.result.to_dict()
        return {
            "designation": self.designation,
            "seed": self.seed,
            **d,
            "warnings": list(self.warnings),
        }

    def to_pandas(self):
        return self.result.to_pandas()

    def plot(self, *args, **kwargs):
        return self.result.plot(*args, **kwargs)


def noise(values: dict, progress=None) -> NoiseOutcome:
    """The ``noise`` request: SPL at a field point, the lines of the pressure spectrum
    and the ISO 15242 velocity bands of a bearing with form errors."""
    from ..noise import FieldPoint, least_field_distance, noise_analysis
    from ..noise.bearing import SAMPLE_RATE
    from ..noise.model import outer_radius

    speed_from(values, positive=True)
    if not values.get("radial_load_n"):
        raise InputError(
            "radial_load_n", values.get("radial_load_n"), "a load > 0 N", "the orbit needs a load"
        )
    condition = condition_from({k: values.get(k) for k in ("speed_rpm", "radial_load_n")})
    duration, points = values.get("duration_s"), values.get("points")
    if duration is not None and points is None and duration * SAMPLE_RATE > MAX_POINTS:
        raise InputError(
            "duration_s",
            duration,
            f"at most {MAX_POINTS / SAMPLE_RATE:g} s with the default sampling (or give `points`)",
        )
    forms = forms_of(values)
    bearing, decoded = bearing_from(values)
    balls_only(
        bearing,
        values,
        "the noise model (seed 003 part 4, seed 002) radiates the inner ring and the balls as "
        "pulsating spheres",
    )
    seed = values.get("seed")
    imperfections = forms.build(bearing, seed)
    angle = si(values, "angle_deg", math.pi / 2)
    distance = values.get("distance_mm")
    point = None if distance is None else FieldPoint(si(values, "distance_mm"), angle)
    try:
        result = noise_analysis(
            bearing,
            condition,
            imperfections,
            point=point,
            angle=None if point is not None else angle,
            duration=duration,
            points=points,
            bands_from=values.get("bands_from") or "auto",
            progress=progress,
        )
    except InputError as exc:
        if exc.parameter == "point":
            radius, how = outer_radius(bearing)
            raise InputError(
                "distance_mm",
                distance,
                f"a distance > {least_field_distance(bearing) * 1e3:.4g} mm (outside the "
                "inner ring and the balls' path)",
                f"the bearing's outside radius {how} is {radius * 1e3:.4g} mm",
            ) from None
        raise restate(exc, values, NOISE.options) from None
    warnings = bearing_warnings(bearing, decoded) + result.to_dict()["warnings"]
    return NoiseOutcome(
        result, bearing, imperfections, values.get("designation"), seed or 0, tuple(warnings)
    )


NOISE = Analysis(
    "noise",
    "Sound pressure of a bearing with form errors (noise_analysis).",
    {
        **BEARING_INPUTS,
        "speed_rpm": _SHAFT["speed_rpm"].with_(default=...),
        "radial_load_n": INPUTS["radial_load_n"].with_(
            default=..., help="Radial load F_r on the shaft, downwards [N] (> 0).", low_open=True
        ),
        **_FORMS,
        **inputs("seed"),
        "distance_mm": Input(
            "number",
            None,
            "Distance of the field point from the bearing centre [mm] (default: 10 mm outside "
            "the outside diameter; seed 003's point A is 10 mm from the centre).",
            low=0.0,
            high=1e5,
            low_open=True,
            what="a distance",
        ),
        "angle_deg": Input(
            "number",
            90.0,
            "Direction of the field point in the radial plane, from +x towards +y [deg] "
            "(90 = straight up, against the load).",
        ),
        "duration_s": INPUTS["duration_s"].with_(
            help="Length of the orbit record [s] (default: one cage revolution, so each ball "
            "carries its size error round once).",
        ),
        "points": Input(
            "integer",
            None,
            "Instants of the orbit (default: 8192 per second, at least 256). More points "
            "resolve higher frequencies; the time-mean SPL hardly changes.",
            low=16,
            high=MAX_POINTS,
        ),
        "bands_from": Input(
            "text",
            "auto",
            "Source of the ISO 15242 velocity bands (edges scaled with the speed from their "
            "1800 rpm values): auto (the orbit if it is sampled above twice the top band edge "
            "for long enough, else the rigid dynamic model), orbit (a second, finer orbit if "
            "needed) or rigid.",
            choices=("auto", "orbit", "rigid"),
        ),
        **_WAVES,
    },
    run=noise,
    outputs={
        "spl_leq_db": "f",
        "spl_time_mean_db": "f",
        "spl_time_max_db": "f",
        "spl_leq_inner_ring_db": "f",
        "spl_leq_balls_db": "f",
        "effective_pressure_upa": "f",
        "peak_pressure_upa": "f",
        "orbit_peak_to_peak_um": "f",
        "warnings": "s",
    },
    largest=50,
    warm=("bearinglab.noise",),
    probe={"duration_s": 0.005, "bands_from": "orbit"},
    extra=tuple(_WAVES),
    files={
        "plot": FILES["plot"].with_(
            help="Draw the pressure and SPL over time, the pressure spectrum and the "
            "directivity to this .png, .svg or .pdf file."
        )
    },
)


# ------------------------------------------------------------------ simulate + diagnosis
@dataclass(frozen=True)
class SimulateOutcome:
    """A simulated record of a request (:func:`bearinglab.dynamics.record.simulate_record`):
    the simulation, its diagnosis and the lines of its plain spectrum."""

    record: object
    bearing: object
    defects: tuple = ()
    imperfections: object = None
    designation: str | None = None
    seed: int | None = None
    warnings: tuple = field(default_factory=tuple)

    def to_dict(self) -> dict:
        return {
            "designation": self.designation,
            **self.record.to_dict(),
            "seed": self.seed,
            "warnings": list(self.warnings),
        }

    def to_pandas(self):
        return self.record.to_pandas()

    def plot(self, *args, **kwargs):
        return self.record.plot(*args, **kwargs)


def defects_of(values: dict) -> list:
    """The defects of a request: the ``defect`` specifications, and a study's ``fault``
    (none, outer, inner, ball or '+'-joined) with one ``defect_width_mm``,
    ``defect_depth_mm`` and ``defect_angle_deg`` for every defect it names."""
    from ..dynamics import Defect

    out = [parse_defect(text) for text in specs(values.get("defect"))]
    fault = values.get("fault") or "none"
    if fault in ("none", "normal"):
        return out
    parts = fault.split("+")
    if "cage" in parts:
        raise InputError(
            "fault",
            fault,
            "none, outer, inner, ball or a '+'-joined compound",
            "the dynamic models have no cage defect model",
        )
    depth, angle = values.get("defect_depth_mm"), values.get("defect_angle_deg")
    for part in parts:
        if part not in ("outer", "inner", "ball", "roller"):
            raise InputError(
                "fault",
                fault,
                "none, outer, inner, ball, roller or a '+'-joined compound such as outer+inner",
            )
        kwargs = {} if angle is None else {"angle": math.radians(angle)}
        width = values.get("defect_width_mm") or 0.5
        where = "ball" if part == "roller" else part  # the models' rolling element
        out.append(Defect(where, width * 1e-3, None if depth is None else depth * 1e-3, **kwargs))
    return out


def simulate(values: dict, progress=None) -> SimulateOutcome:
    """The ``simulate`` request: the vibration of a bearing with defects and form errors,
    its envelope diagnosis and the lines of its plain spectrum."""
    from ..dynamics import SlipParameters
    from ..dynamics.record import simulate_record

    speed_from(values, positive=True)
    condition = condition_from(
        {k: values.get(k) for k in ("speed_rpm", "radial_load_n", "axial_load_n")}
    )
    model = values.get("dynamic_model") or "rigid"
    defects = defects_of(values)
    forms = forms_of(values)
    bearing, decoded = bearing_from(values)
    seed = values.get("seed")
    imperfections = forms.build(bearing, seed)
    check_defects(specs(values.get("defect")), defects[: len(specs(values.get("defect")))], bearing)
    slip = {k: values.get(k) for k in ("cage_friction", "oil_fraction")}
    slip["spin_drag"] = values.get("spin_drag") or None
    parameters = None
    if model == "slip":
        try:
            parameters = SlipParameters(**{k: v for k, v in slip.items() if v is not None})
        except InputError as exc:
            raise restate(exc, values, SIMULATE.options) from None
    elif any(v is not None for v in slip.values()):
        name = next(k for k, v in slip.items() if v is not None)
        raise InputError(
            name, slip[name], "no value with `dynamic_model` rigid (a slip-model parameter)"
        )
    try:
        record = simulate_record(
            bearing,
            condition,
            defects,
            model=model,
            duration=values.get("duration_s") or 1.0,
            sample_rate=values.get("sample_rate_hz") or 50000.0,
            settle=values.get("settle_s"),
            noise=values.get("noise_ms2") or 0.0,
            seed=seed,
            imperfections=imperfections,
            parameters=parameters,
            spectrum_channel=values.get("spectrum_channel") or "disp_y",
            progress=progress,
        )
    except InputError as exc:
        name = bearing.name or "the bearing"
        if exc.parameter in ("inner_mass", "outer_mass") and exc.value is None:
            raise BearinglabError(
                "`dynamic_model` slip needs the ring masses, which follow from the boundary "
                f"dimensions {name} lacks: give `bore_mm`, `outside_diameter_mm` and `width_mm`"
            ) from None
        if exc.parameter == "contact_angle":
            raise InputError(
                "dynamic_model",
                "slip",
                "rigid for this bearing (the slip model is planar: contact angle 0; "
                f"{name} has {exc.value:g} deg)",
            ) from None
        raise restate(exc, values, SIMULATE.options) from None
    warnings = bearing_warnings(bearing, decoded) + list(record.warnings)
    return SimulateOutcome(
        record,
        bearing,
        tuple(defects),
        imperfections,
        values.get("designation"),
        seed,
        tuple(warnings),
    )


_FAULT_NAMES = {"outer_race": "outer", "inner_race": "inner", "ball": "ball", "cage": "cage"}


def _simulate_columns(outcome: SimulateOutcome) -> dict:
    from scipy.stats import kurtosis

    sim = outcome.record.simulation
    x = sim.signal.channels["acc_y"]
    rms = float(np.sqrt(np.mean((x - x.mean()) ** 2)))
    peak = float(np.max(np.abs(x - x.mean())))
    d = {
        "rms_m_s2": rms,
        "peak_m_s2": peak,
        "kurtosis": float(kurtosis(x, fisher=False)),
        "crest_factor": peak / rms if rms > 0 else None,
        **sim.stats,
        "cage_speed_ratio": sim.cage_speed_ratio,
        "spin_speed_ratio": sim.spin_speed_ratio,
        "warnings": list(outcome.warnings),
    }
    # a roller bearing fills the roller columns, a ball bearing the ball columns
    element = outcome.bearing.rolling_element
    d.update({f"{k}_hz": sim.kinematic.hz(k) for k in ("bpfo", "bpfi", "ftf")})
    d[f"{element}_defect_hz"] = sim.kinematic.hz("ball_defect")
    g = outcome.record.diagnosis.to_dict()
    d.update(
        {
            "likely_fault": g["likely_fault"] or "none",
            "primary_fault": g["primary_fault"] or "none",
            "band_kurtosis": g["band_kurtosis"],
            f"{element}_defect_frequency_hz": g[f"{element}_defect_frequency_hz"],
        }
    )
    if g["band_hz"] is not None:
        d["band_low_hz"], d["band_high_hz"] = g["band_hz"]
    for name, value in g["scores"].items():
        d[f"score_{_FAULT_NAMES.get(name, name)}"] = value
    return d


_FAULTS = {
    "fault": Input("text", "none", "none, outer, inner, ball, roller or '+'-joined (outer+inner)."),
    "defect_width_mm": INPUTS["defect_width_mm"].with_(
        default=0.5, help="Width of the fault's defects [mm]."
    ),
    "defect_depth_mm": INPUTS["defect_depth_mm"].with_(help="Depth of the fault's defects [mm]."),
    "defect_angle_deg": INPUTS["defect_angle_deg"].with_(
        help="Position of the fault's defects [deg]."
    ),
}

SIMULATE = Analysis(
    "simulate",
    "Simulated vibration (simulate_record) and its envelope diagnosis on acc_y.",
    {
        **BEARING_INPUTS,
        "speed_rpm": _SHAFT["speed_rpm"].with_(default=...),
        # unloaded, the rings of the planar models do not move: there is nothing to record
        "radial_load_n": INPUTS["radial_load_n"].with_(default=..., low_open=True),
        "axial_load_n": inputs("axial_load_n")["axial_load_n"].with_(
            help="Axial load [N] (the models are planar: not used)."
        ),
        **inputs("defect"),
        **inputs("dynamic_model"),
        "duration_s": INPUTS["duration_s"].with_(
            default=1.0, help="Length of the recorded signal [s]."
        ),
        "sample_rate_hz": INPUTS["sample_rate_hz"].with_(
            default=50000.0, help="Sample rate of the signal [Hz].", high=1e6
        ),
        "settle_s": Input(
            "number",
            None,
            "Time simulated and discarded first [s] (default: 0.05 s rigid; slip: detected, "
            "whole cage revolutions, at least 4, until the cage and spin ratios change by less "
            "than 1e-3).",
            low=0.0,
            high=60.0,
            what="a settling time",
        ),
        "cage_friction": Input(
            "number",
            None,
            "Slip model: ball-cage pocket friction coefficient mu_c [-], 0-0.3 (lubricated "
            "pockets 0.05-0.2; default 0.1 = seed 004 eq. 11 at pure sliding).",
        ),
        "spin_drag": Input(
            "bool",
            False,
            "Slip model: add the drag moment of each ball spinning in the oil-air mixture "
            "(Dennis, Singh & Ingham 1980; not in seed 004).",
        ),
        "oil_fraction": Input(
            "number",
            None,
            "Slip model: volume fraction of oil in the oil-air mixture that drags balls and "
            "cage [-], 0-1 (default 0.03; Harris & Kotzalas give 0.01-0.05).",
        ),
        **inputs("noise_ms2"),
        **_FORMS,
        "seed": inputs("seed")["seed"].with_(
            help="Seed of the noise (default: fresh noise) and of the random form errors "
            "(`ball_size_error_um`, `surface3d`; default 0 for those)."
        ),
        "spectrum_channel": Input(
            "text",
            "disp_y",
            "Channel of the plain spectrum (spectrum_peaks): disp_y, disp_x (inner ring "
            "relative to the outer: the form-error lines stand out), acc_y or acc_x (the "
            "resonances dominate).",
            choices=("disp_y", "disp_x", "acc_y", "acc_x"),
        ),
        **_FAULTS,
        **_WAVES,
    },
    run=simulate,
    outputs={
        "rms_m_s2": "f",
        "peak_m_s2": "f",
        "kurtosis": "f",
        "crest_factor": "f",
        "steps": "i",
        "rejected_steps": "i",
        "bpfo_hz": "f",
        "bpfi_hz": "f",
        "ftf_hz": "f",
        "ball_defect_hz": "f",
        "roller_defect_hz": "f",
        "cage_speed_ratio": "f",
        "spin_speed_ratio": "f",
        "likely_fault": "s",
        "primary_fault": "s",
        "band_low_hz": "f",
        "band_high_hz": "f",
        "band_kurtosis": "f",
        "score_outer": "f",
        "score_inner": "f",
        "score_ball": "f",
        "score_roller": "f",
        "score_cage": "f",
        "ball_defect_frequency_hz": "f",
        "roller_defect_frequency_hz": "f",
        "warnings": "s",
    },
    largest=20,
    columns=_simulate_columns,
    warm=("bearinglab.dynamics", "bearinglab.diagnosis"),
    probe={"duration_s": 0.02, "sample_rate_hz": 20000.0},
    extra=(*_FAULTS, *_WAVES),
    files={
        "output": FILES["output"].with_(
            help="Write the signal to this .npz, .csv, .wav or .mat file."
        ),
        **plot_file("the envelope spectrum (acc_y) and the plain spectrum (`spectrum_channel`)"),
    },
)
