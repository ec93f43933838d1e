"""Study analyses of the bearing in operation: load ratings and rating life (``life``,
ISO 281 / ISO 16281) and friction torque and power loss (``friction``). The registry is
:data:`bearinglab.study.analyses.ANALYSES`; these functions only convert units and pick
result fields.
"""

from __future__ import annotations

from ._analysis import LOADS, Analysis, pick, with_bearing
from ._inputs import bearing_of, condition_of, rad_s
from .cases import Option

# ------------------------------------------------------------------ life, friction
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
    return pick(r.to_dict(), _LIFE_OUT)


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
    return pick(r.to_dict(), _FRICTION_OUT)


LIFE = Analysis(
    "life",
    "Load ratings and rating life (rating_life, ISO 281 / ISO 16281).",
    with_bearing(
        **LOADS,
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
)


FRICTION = Analysis(
    "friction",
    "Friction torque and power loss (bearing_friction).",
    with_bearing(
        **LOADS,
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
)
