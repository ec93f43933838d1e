"""The analyses a study can sweep: their options (the command line's names, engineering
units) and output columns (the result's ``to_dict()`` keys, unit in every name).

Each analysis is one layer-3 call per case (:func:`evaluate`); ``stiffness`` hands the
cases of a partition that differ only in radial load to one
:func:`bearinglab.quasistatic.study.stiffness_map` line, which warm-starts each load from
the previous solution. Physics is never repeated here: these functions only convert units
and pick result fields.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from ._inputs import (
    BEARING_OPTIONS,
    FORM_OPTIONS,
    bearing_of,
    condition_of,
    imperfections_of,
    rad_s,
)
from .cases import Option

_BEARING = {name: spec[0] for name, spec in BEARING_OPTIONS.items()}
_LOADS = {
    "radial_load_n": Option("number", 0.0, "Radial load F_r [N]."),
    "axial_load_n": Option("number", 0.0, "Axial load F_a [N]."),
    "speed_rpm": Option("number", 0.0, "Speed of the rotating (inner) ring [rpm]."),
}


@dataclass(frozen=True)
class Analysis:
    """One sweepable analysis: ``options`` (name -> Option), ``outputs`` (column -> "f"
    float, "i" integer, "s" text), ``evaluate(case, seed) -> dict`` of outputs,
    ``largest`` cases per partition, optional ``batch(cases, seed) -> list`` of (outputs or
    exception) for a whole partition, the modules a worker imports first and ``probe``:
    options that make the warm-up case (the study's first case, run once per worker to
    load the compiled kernels) short."""

    name: str
    help: str
    options: dict
    outputs: dict
    evaluate: Callable
    largest: int
    batch: Callable | None = None
    warm: tuple = field(default_factory=tuple)
    probe: dict = field(default_factory=dict)


def _pick(d: dict, outputs: dict) -> dict:
    out = {}
    for k, kind in outputs.items():
        v = d.get(k)
        if isinstance(v, (list, tuple)):
            v = "; ".join(map(str, v)) if kind == "s" else None
        out[k] = v
    return out


# ------------------------------------------------------------------ quasi-static
_STATIC_OUT = {
    "radial_displacement_um": "f",
    "axial_displacement_um": "f",
    "tilt_x_mrad": "f",
    "tilt_y_mrad": "f",
    "radial_stiffness_n_per_um": "f",
    "axial_stiffness_n_per_um": "f",
    "max_ball_load_n": "f",
    "equilibrium_residual_n": "f",
    "diametral_clearance_um": "f",
    "warnings": "s",
}


def _static(case: dict, seed: int) -> dict:
    from ..quasistatic import solve_load_distribution

    bearing = bearing_of(case)
    r = solve_load_distribution(
        bearing,
        condition_of(case),
        gyroscopic=bool(case.get("gyroscopic")),
        ring_expansion=bool(case.get("ring_expansion")),
    )
    d = r.to_dict()
    d["tilt_x_mrad"], d["tilt_y_mrad"] = d["tilt_mrad"]
    return _pick(d, _STATIC_OUT)


_STIFFNESS_OUT = {
    "radial_displacement_um": "f",
    "axial_displacement_um": "f",
    "radial_stiffness_n_per_um": "f",
    "axial_stiffness_n_per_um": "f",
    "max_ball_load_n": "f",
}


def _stiffness_line(case: dict, radial: list[float]) -> list:
    """One stiffness_map line: the cases' radial loads at one (bearing, axial load, speed,
    direction); results in the order of ``radial``."""
    from ..quasistatic.study import stiffness_map

    bearing = bearing_of(case)
    rad_s(case)
    table = stiffness_map(
        bearing,
        radial,
        [case.get("axial_load_n", 0.0)],
        [case.get("speed_rpm", 0.0)],
        radial_load_angle=math.radians(case.get("radial_load_angle_deg", -90.0)),
        workers=1,
    )
    # stiffness_map returns the loads sorted: put the rows back in the cases' order
    order = np.argsort(np.asarray(radial, float), kind="stable")
    out = [None] * len(radial)
    for row, i in zip(table.to_dict(orient="records"), order, strict=True):
        if row["status"] == "ok":
            out[i] = _pick(row, _STIFFNESS_OUT)
        else:
            out[i] = InputError(
                "radial_load_n", row["radial_load_n"], "a load the bearing carries", row["status"]
            )
    return out


def _stiffness(case: dict, seed: int) -> dict:
    result = _stiffness_line(case, [case.get("radial_load_n", 0.0)])[0]
    if isinstance(result, Exception):
        raise result
    return result


def _stiffness_batch(cases: list[dict], seed: int) -> list:
    """Group a partition's cases into stiffness_map lines; a line that fails as a whole
    (a bad bearing, a negative load) is retried case by case so only bad cases fail."""
    lines: dict = {}
    for i, case in enumerate(cases):
        key = tuple((k, v) for k, v in case.items() if k not in ("case", "radial_load_n"))
        lines.setdefault(key, []).append(i)
    out: list = [None] * len(cases)
    for members in lines.values():
        first = cases[members[0]]
        try:
            results = _stiffness_line(first, [cases[i].get("radial_load_n", 0.0) for i in members])
        except Exception:  # noqa: BLE001 - retried case by case below
            results = []
            for i in members:
                try:
                    results.append(_stiffness(cases[i], seed))
                except Exception as exc:  # noqa: BLE001 - a failed case never stops a study
                    results.append(exc)
        for i, r in zip(members, results, strict=True):
            out[i] = r
    return out


# ------------------------------------------------------------------ kinematics, life, friction
_FREQ_OUT = {
    f"{n}_{u}": "f" for u in ("hz", "order") for n in ("ftf", "bpfo", "bpfi", "bsf", "ball_defect")
}
_FREQ_OUT["shaft_hz"] = "f"


def _frequencies(case: dict, seed: int) -> dict:
    from ..kinematics import defect_frequencies

    r = defect_frequencies(
        bearing_of(case), rad_s(case), outer_rotating=bool(case.get("outer_rotating"))
    )
    return _pick(r.to_dict(), _FREQ_OUT)


_LIFE_OUT = {
    k: "f"
    for k in (
        "dynamic_rating_n",
        "static_rating_n",
        "fatigue_load_limit_n",
        "equivalent_load_n",
        "static_equivalent_load_n",
        "static_safety_factor",
        "l10_million_rev",
        "l10_hours",
        "kappa",
        "contamination_factor",
        "a_iso",
        "l10m_million_rev",
        "l10m_hours",
    )
}
_LIFE_OUT["warnings"] = "s"


def _life(case: dict, seed: int) -> dict:
    from ..life import rating_life

    viscosity = case.get("viscosity_mm2_s")
    contamination = case.get("contamination")
    if isinstance(contamination, str):
        try:
            contamination = float(contamination)
        except ValueError:
            pass
    r = rating_life(
        bearing_of(case),
        condition_of(case, positive_speed=True),
        reliability_percent=case.get("reliability_percent", 90.0),
        viscosity=None if viscosity is None else viscosity * 1e-6,
        contamination=contamination,
        method=case.get("method", "iso281"),
        ep_additives=bool(case.get("ep_additives")),
    )
    return _pick(r.to_dict(), _LIFE_OUT)


_FRICTION_OUT = {
    "friction_torque_n_mm": "f",
    "power_loss_w": "f",
    "friction_coefficient": "f",
    "rolling_torque_n_mm": "f",
    "sliding_torque_n_mm": "f",
    "seal_torque_n_mm": "f",
    "drag_torque_n_mm": "f",
    "warnings": "s",
}


def _friction(case: dict, seed: int) -> dict:
    from ..friction import bearing_friction

    viscosity = case.get("viscosity_mm2_s")
    p = case.get("equivalent_load_n")
    r = bearing_friction(
        bearing_of(case),
        rad_s(case),
        case.get("radial_load_n", 0.0),
        case.get("axial_load_n", 0.0),
        model=case.get("model", "constant"),
        friction_type=case.get("friction_type"),
        equivalent_load=p,
        viscosity=None if viscosity is None else viscosity * 1e-6,
    )
    return _pick(r.to_dict(), _FRICTION_OUT)


# ------------------------------------------------------------------ ring modes
_MODES = (2, 3, 4, 5, 6)
_RING_OUT = {
    "rigid_body_frequency_hz": "f",
    "radial_stiffness_n_per_m": "f",
    "ring_mass_kg": "f",
    "ball_mass_ratio": "f",
    "contact_stiffness_ratio": "f",
}
for _m in _MODES:
    _RING_OUT.update(
        {
            f"m{_m}_free_hz": "f",
            f"m{_m}_approx_low_hz": "f",
            f"m{_m}_approx_high_hz": "f",
            f"m{_m}_refined_low_hz": "f",
            f"m{_m}_refined_high_hz": "f",
        }
    )


def _ring_modes(case: dict, seed: int) -> dict:
    from ..rings import ring_modes

    mass = case.get("ring_mass_kg")
    kx = case.get("radial_stiffness_n_per_m")
    axial = case.get("axial_load_n")
    r = ring_modes(
        bearing_of(case),
        axial_load=axial if kx is None else None,
        modes=_MODES,
        ring_mass=mass,
        radial_stiffness=kx,
        ball_mass_ratio=case.get("ball_mass_ratio"),
        contact_stiffness_ratio=case.get("contact_stiffness_ratio"),
        radial_stiffness_from=case.get("radial_stiffness_from", "closed_form"),
    )
    d = r.to_dict()
    for m in d["modes"]:
        k = m["m"]
        if k not in _MODES:
            continue
        d[f"m{k}_free_hz"] = m["free_hz"]
        d[f"m{k}_approx_low_hz"], d[f"m{k}_approx_high_hz"] = (
            min(m["approx_hz"]),
            max(m["approx_hz"]),
        )
        refined = [f for f in m["refined_hz"] if f is not None]
        if refined:
            d[f"m{k}_refined_low_hz"], d[f"m{k}_refined_high_hz"] = min(refined), max(refined)
    return _pick(d, _RING_OUT)


# ------------------------------------------------------------------ noise
_NOISE_OUT = {
    "spl_leq_db": "f",
    "spl_time_mean_db": "f",
    "spl_time_max_db": "f",
    "spl_leq_inner_ring_db": "f",
    "spl_leq_balls_db": "f",
    "effective_pressure_pa": "f",
    "peak_pressure_pa": "f",
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
    return _pick(r.to_dict(), _NOISE_OUT)


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
    return _pick(d, _SIM_OUT)


# ------------------------------------------------------------------ the registry
def _with_bearing(**more) -> dict:
    return {**_BEARING, **more}


ANALYSES = {
    a.name: a
    for a in (
        Analysis(
            "stiffness",
            "Radial and axial stiffness and displacements (stiffness_map lines, warm-started).",
            _with_bearing(
                **_LOADS,
                radial_load_angle_deg=Option(
                    "number", -90.0, "Direction of the radial load [deg]."
                ),
            ),
            _STIFFNESS_OUT,
            _stiffness,
            2000,
            _stiffness_batch,
            ("bearinglab.quasistatic.study",),
        ),
        Analysis(
            "static",
            "Quasi-static load distribution (solve_load_distribution).",
            _with_bearing(
                **_LOADS,
                radial_load_angle_deg=Option(
                    "number", -90.0, "Direction of the radial load [deg]."
                ),
                misalignment_mrad=Option("number", 0.0, "Imposed inner-ring tilt [mrad]."),
                gyroscopic=Option("bool", False, "Ball gyroscopic moments."),
                ring_expansion=Option("bool", False, "Centrifugal inner-ring expansion."),
            ),
            _STATIC_OUT,
            _static,
            500,
            None,
            ("bearinglab.quasistatic",),
        ),
        Analysis(
            "frequencies",
            "Kinematic defect frequencies (defect_frequencies).",
            _with_bearing(
                speed_rpm=_LOADS["speed_rpm"],
                outer_rotating=Option("bool", False, "The outer ring turns."),
            ),
            _FREQ_OUT,
            _frequencies,
            20000,
        ),
        Analysis(
            "life",
            "Load ratings and rating life (rating_life, ISO 281 / ISO 16281).",
            _with_bearing(
                **_LOADS,
                reliability_percent=Option("number", 90.0, "Reliability [%]."),
                viscosity_mm2_s=Option("number", None, "Operating viscosity [mm^2/s]."),
                contamination=Option("text", None, "e_C or an ISO 281 level."),
                method=Option("text", "iso281", "iso281 or iso16281.", ("iso281", "iso16281")),
                misalignment_mrad=Option("number", 0.0, "Inner-ring tilt [mrad] (iso16281)."),
                ep_additives=Option("bool", False, "Proven EP additives."),
            ),
            _LIFE_OUT,
            _life,
            5000,
            None,
            ("bearinglab.life",),
        ),
        Analysis(
            "friction",
            "Friction torque and power loss (bearing_friction).",
            _with_bearing(
                **_LOADS,
                model=Option("text", "constant", "constant or skf.", ("constant", "skf")),
                friction_type=Option("text", None, "Seed-003 friction type."),
                equivalent_load_n=Option("number", None, "Equivalent load P [N]."),
                viscosity_mm2_s=Option("number", None, "Viscosity [mm^2/s] (skf)."),
            ),
            _FRICTION_OUT,
            _friction,
            5000,
            None,
            ("bearinglab.friction",),
        ),
        Analysis(
            "ring-modes",
            "Outer-ring natural frequencies m = 2..6 (ring_modes, seed 000).",
            _with_bearing(
                axial_load_n=Option("number", None, "Axial load for K_x [N]."),
                ring_mass_kg=Option("number", None, "Vibrating ring mass [kg]."),
                radial_stiffness_n_per_m=Option("number", None, "K_x [N/m]."),
                ball_mass_ratio=Option("number", None, "kappa."),
                contact_stiffness_ratio=Option("number", None, "K1/K2."),
                radial_stiffness_from=Option(
                    "text",
                    "closed_form",
                    "K_x from seed 000's closed form or the load distribution.",
                    ("closed_form", "load_distribution"),
                ),
            ),
            _RING_OUT,
            _ring_modes,
            2000,
            None,
            ("bearinglab.rings",),
        ),
        Analysis(
            "noise",
            "Sound pressure of a bearing with form errors (bearing_noise).",
            _with_bearing(
                radial_load_n=_LOADS["radial_load_n"],
                axial_load_n=_LOADS["axial_load_n"],
                speed_rpm=_LOADS["speed_rpm"],
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
        ),
        Analysis(
            "simulate",
            "Simulated vibration (simulate) and its envelope diagnosis (analyze_signal) on acc_y.",
            _with_bearing(
                radial_load_n=_LOADS["radial_load_n"],
                speed_rpm=_LOADS["speed_rpm"],
                **FORM_OPTIONS,
                fault=Option(
                    "text", "none", "none, outer, inner, ball or '+'-joined (outer+inner)."
                ),
                defect_width_mm=Option("number", 0.5, "Defect width [mm]."),
                defect_depth_mm=Option("number", None, "Defect depth [mm]."),
                defect_angle_deg=Option("number", None, "Defect position [deg]."),
                model=Option("text", "rigid", "rigid or slip.", ("rigid", "slip")),
                duration_s=Option("number", 0.5, "Record length [s]."),
                sample_rate_hz=Option("number", 20000.0, "Sample rate [Hz]."),
                noise_ms2=Option("number", 0.0, "Measurement noise RMS [m/s^2]."),
            ),
            _SIM_OUT,
            _simulate,
            20,
            None,
            ("bearinglab.dynamics", "bearinglab.diagnosis"),
            {"duration_s": 0.02, "sample_rate_hz": 20000.0},
        ),
    )
}
ALIASES = {"ring_modes": "ring-modes", "load-distribution": "static"}


def analysis(name: str) -> Analysis:
    """The analysis called ``name`` (InputError naming the choices otherwise)."""
    name = ALIASES.get(name, name)
    if name not in ANALYSES:
        raise InputError("analysis", name, "one of " + ", ".join(ANALYSES))
    return ANALYSES[name]


def error_text(exc: BaseException) -> str:
    """One line saying why a case failed (the InputError message names the input)."""
    text = " ".join(str(exc).split())
    if isinstance(exc, (InputError,)) or type(exc).__module__.startswith("bearinglab"):
        return text or type(exc).__name__
    return f"{type(exc).__name__}: {text}"


def warm_up(args) -> None:
    """Run a few cases (outputs discarded): loads the analysis' compiled kernels."""
    name, cases = args
    a = analysis(name)
    run_cases(a, [{**case, **a.probe} for case in cases], 0)


def run_cases(a: Analysis, cases: list[dict], seed: int) -> list[dict]:
    """Outputs (and ``error``) of every case; a failing case gets its error text and the
    others go on. Options a case does not give take their defaults."""
    from .cases import case_seed

    full = [
        {
            **{k: o.default for k, o in a.options.items() if o.default is not None},
            **{k: v for k, v in c.items() if v is not None},
        }
        for c in cases
    ]
    seeds = [case_seed(seed, c["case"]) for c in cases]
    if a.batch is not None:
        results = a.batch(full, seed)
    else:
        results = []
        for c, s in zip(full, seeds, strict=True):
            try:
                results.append(a.evaluate(c, s))
            except Exception as exc:  # noqa: BLE001 - a failed case never stops a study
                results.append(exc)
    rows = []
    for r in results:
        if isinstance(r, BaseException):
            rows.append({**dict.fromkeys(a.outputs), "error": error_text(r)})
        else:
            rows.append({**{k: _clean(r.get(k)) for k in a.outputs}, "error": None})
    return rows


def _clean(v):
    if isinstance(v, (np.floating, np.integer, np.bool_)):
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v
