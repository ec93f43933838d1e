"""Study analyses of the bearing's mechanics: the quasi-static load distribution
(``static``), stiffness and displacements (``stiffness``), the kinematic defect
frequencies (``frequencies``) and the outer-ring natural frequencies (``ring-modes``,
seed 000). The registry is :data:`bearinglab.study.analyses.ANALYSES`.

``stiffness`` hands the cases of a partition that differ only in radial load to one
:func:`bearinglab.quasistatic.study.stiffness_map` line, which warm-starts each load from
the previous solution. Physics is never repeated here: these functions only convert units
and pick result fields.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ._analysis import LOADS, Analysis, pick, with_bearing
from ._inputs import bearing_of, condition_of, rad_s
from .cases import Option

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
    return pick(d, _STATIC_OUT)


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
            out[i] = pick(row, _STIFFNESS_OUT)
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


# ------------------------------------------------------------------ kinematics
_FREQ_OUT = {
    f"{n}_{u}": "f" for u in ("hz", "order") for n in ("ftf", "bpfo", "bpfi", "bsf", "ball_defect")
}
_FREQ_OUT["shaft_hz"] = "f"


def _frequencies(case: dict, seed: int) -> dict:
    from ..kinematics import defect_frequencies

    r = defect_frequencies(
        bearing_of(case), rad_s(case), outer_rotating=bool(case.get("outer_rotating"))
    )
    return pick(r.to_dict(), _FREQ_OUT)


# ------------------------------------------------------------------ ring modes
_MODES = (2, 3, 4, 5, 6)
_RING_OUT = {
    "rigid_body_frequency_hz": "f",
    "radial_stiffness_n_per_um": "f",
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
    return pick(d, _RING_OUT)


STIFFNESS = Analysis(
    "stiffness",
    "Radial and axial stiffness and displacements (stiffness_map lines, warm-started).",
    with_bearing(
        **LOADS,
        radial_load_angle_deg=Option("number", -90.0, "Direction of the radial load [deg]."),
    ),
    _STIFFNESS_OUT,
    _stiffness,
    2000,
    _stiffness_batch,
    ("bearinglab.quasistatic.study",),
)


STATIC = Analysis(
    "static",
    "Quasi-static load distribution (solve_load_distribution).",
    with_bearing(
        **LOADS,
        radial_load_angle_deg=Option("number", -90.0, "Direction of the radial load [deg]."),
        misalignment_mrad=Option("number", 0.0, "Imposed inner-ring tilt [mrad]."),
        gyroscopic=Option("bool", False, "Ball gyroscopic moments."),
        ring_expansion=Option("bool", False, "Centrifugal inner-ring expansion."),
    ),
    _STATIC_OUT,
    _static,
    500,
    None,
    ("bearinglab.quasistatic",),
)


FREQUENCIES = Analysis(
    "frequencies",
    "Kinematic defect frequencies (defect_frequencies).",
    with_bearing(
        speed_rpm=LOADS["speed_rpm"],
        outer_rotating=Option("bool", False, "The outer ring turns."),
    ),
    _FREQ_OUT,
    _frequencies,
    20000,
)


RING_MODES = Analysis(
    "ring-modes",
    "Outer-ring natural frequencies m = 2..6 (ring_modes, seed 000).",
    with_bearing(
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
)
