"""Study analyses of the bearing's vibration: the sound pressure of a bearing with form
errors (``noise``) and the simulated vibration with its envelope diagnosis (``simulate``,
faults from :func:`defects_of`). The registry is
:data:`bearinglab.study.analyses.ANALYSES`; these functions only convert units and pick
result fields.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ._analysis import LOADS, Analysis, pick, with_bearing
from ._inputs import FORM_OPTIONS, bearing_of, condition_of, imperfections_of
from .cases import Option

# ------------------------------------------------------------------ noise
_NOISE_OUT = {
    "spl_leq_db": "f",
    "spl_time_mean_db": "f",
    "spl_time_max_db": "f",
    "spl_leq_inner_ring_db": "f",
    "spl_leq_balls_db": "f",
    "effective_pressure_upa": "f",
    "peak_pressure_upa": "f",
    "orbit_peak_to_peak_um": "f",
}


def _noise(case: dict, seed: int) -> dict:
    from ..noise import FieldPoint, bearing_noise

    bearing = bearing_of(case)
    imperfections = imperfections_of(case, bearing, seed)
    duration = case.get("duration_s")
    r = bearing_noise(
        bearing,
        condition_of(case, positive_speed=True),
        imperfections,
        duration=duration,
        point=FieldPoint(
            case.get("distance_mm", 10.0) * 1e-3, math.radians(case.get("angle_deg", 90.0))
        ),
    )
    return pick(r.to_dict(), _NOISE_OUT)


# ------------------------------------------------------------------ simulate + diagnosis
_FAULT_NAMES = {"outer_race": "outer", "inner_race": "inner", "ball": "ball", "cage": "cage"}
_SIM_OUT = {
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
    "score_cage": "f",
    "ball_defect_frequency_hz": "f",
}


def defects_of(case: dict) -> list:
    """Defects from ``fault`` (none, outer, inner, ball or '+'-joined) and the defect_*
    options (one size and angle for every defect of the case)."""
    from ..dynamics import Defect

    fault = case.get("fault", "none")
    if fault in ("none", "normal"):
        return []
    parts = fault.split("+")
    if "cage" in parts:
        raise InputError(
            "fault",
            fault,
            "none, outer, inner, ball or a '+'-joined compound",
            "the dynamic models have no cage defect model",
        )
    depth = case.get("defect_depth_mm")
    angle = case.get("defect_angle_deg")
    out = []
    for part in parts:
        if part not in ("outer", "inner", "ball"):
            raise InputError(
                "fault",
                fault,
                "none, outer, inner, ball or a '+'-joined compound such as outer+inner",
            )
        kwargs = {} if angle is None else {"angle": math.radians(angle)}
        out.append(
            Defect(
                part,
                case.get("defect_width_mm", 0.5) * 1e-3,
                None if depth is None else depth * 1e-3,
                **kwargs,
            )
        )
    return out


def _simulate(case: dict, seed: int) -> dict:
    from scipy.stats import kurtosis

    from ..diagnosis import analyze_signal
    from ..dynamics import simulate

    bearing = bearing_of(case)
    sim = simulate(
        bearing,
        condition_of(case, positive_speed=True),
        defects_of(case),
        model=case.get("model", "rigid"),
        duration=case.get("duration_s", 0.5),
        sample_rate=case.get("sample_rate_hz", 20000.0),
        noise=case.get("noise_ms2", 0.0),
        seed=seed,
        imperfections=imperfections_of(case, bearing, seed),
    )
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
    }
    d.update({f"{k}_hz": sim.kinematic.hz(k) for k in ("bpfo", "bpfi", "ftf", "ball_defect")})
    diag = analyze_signal(sim.signal, None, sim.kinematic, channel="acc_y")
    g = diag.to_dict()
    d.update(
        {
            "likely_fault": g["likely_fault"] or "none",
            "primary_fault": g["primary_fault"] or "none",
            "band_kurtosis": g["band_kurtosis"],
            "ball_defect_frequency_hz": g["ball_defect_frequency_hz"],
        }
    )
    if g["band_hz"] is not None:
        d["band_low_hz"], d["band_high_hz"] = g["band_hz"]
    for name, value in g["scores"].items():
        d[f"score_{_FAULT_NAMES.get(name, name)}"] = value
    return pick(d, _SIM_OUT)


NOISE = Analysis(
    "noise",
    "Sound pressure of a bearing with form errors (bearing_noise).",
    with_bearing(
        radial_load_n=LOADS["radial_load_n"],
        axial_load_n=LOADS["axial_load_n"],
        speed_rpm=LOADS["speed_rpm"],
        **FORM_OPTIONS,
        distance_mm=Option("number", 10.0, "Field point distance [mm]."),
        angle_deg=Option("number", 90.0, "Field point direction [deg]."),
        duration_s=Option("number", None, "Orbit length [s]."),
    ),
    _NOISE_OUT,
    _noise,
    50,
    None,
    ("bearinglab.noise",),
    {"duration_s": 0.005},
)


SIMULATE = Analysis(
    "simulate",
    "Simulated vibration (simulate) and its envelope diagnosis (analyze_signal) on acc_y.",
    with_bearing(
        radial_load_n=LOADS["radial_load_n"],
        speed_rpm=LOADS["speed_rpm"],
        **FORM_OPTIONS,
        fault=Option("text", "none", "none, outer, inner, ball or '+'-joined (outer+inner)."),
        defect_width_mm=Option("number", 0.5, "Defect width [mm]."),
        defect_depth_mm=Option("number", None, "Defect depth [mm]."),
        defect_angle_deg=Option("number", None, "Defect position [deg]."),
        model=Option("text", "rigid", "rigid or slip.", ("rigid", "slip")),
        duration_s=Option("number", 0.5, "Record length [s]."),
        sample_rate_hz=Option("number", 20000.0, "Sample rate [Hz]."),
        noise_ms2=Option("number", 0.0, "Measurement noise RMS [m/s^2].", seeded=True),
    ),
    _SIM_OUT,
    _simulate,
    20,
    None,
    ("bearinglab.dynamics", "bearinglab.diagnosis"),
    {"duration_s": 0.02, "sample_rate_hz": 20000.0},
)
