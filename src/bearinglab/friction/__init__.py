"""Bearing friction: torque and power loss by two published models.

- :mod:`.constant` -- seed 003's constant coefficient by bearing type, M = mu P d_m / 2
  (d_m the pitch diameter, as the seed defines it), N = M omega; the equivalent load P of
  ball bearings from ISO 281 (:func:`bearinglab.life.equivalent_dynamic_load`).
- :mod:`.skf` -- the SKF four-component model M = phi_ish phi_rs M_rr + M_sl + M_seal +
  M_drag (SKF catalogue 10000 EN), and the viscosity ratio kappa (ISO 281's nu_1 from
  :mod:`bearinglab.life`).
- :mod:`.analysis` -- :class:`FrictionResult` and :func:`constant_friction`,
  :func:`skf_friction`, :func:`bearing_friction`.

Core API in SI units (N, m, rad/s, m^2/s, N m, W); ``FrictionResult.to_dict()`` in
engineering units (N mm, W, mm, mm^2/s, rpm). What is and is not checked against the
sources: docs/capabilities/friction.md.

>>> import math
>>> r = constant_friction(1000.0, 0.039, 1500 * math.pi / 30, "radial_ball")
>>> round(r.to_dict()["friction_torque_nmm"], 2)
29.25
"""

from .analysis import MODELS, FrictionResult, bearing_friction, constant_friction, skf_friction
from .constant import (
    SEED003_COEFFICIENTS,
    SEED003_SOURCE,
    constant_coefficient_torque,
    friction_coefficient,
    friction_type_of,
    power_loss,
)
from .skf import (
    DEEP_GROOVE_CONSTANTS,
    K_RS,
    K_Z,
    MU_BL,
    MU_EHL,
    SKF_BEARING_TYPES,
    SKF_SOURCE,
    SkfGeometryConstants,
    SkfMoment,
    angular_contact_load_variables,
    deep_groove_constants,
    deep_groove_load_angle,
    deep_groove_load_variables,
    inlet_shear_heating_factor,
    replenishment_factor,
    seal_moment,
    skf_frictional_moment,
    sliding_friction_coefficient,
    sliding_weighting_factor,
    viscosity_ratio,
)

__all__ = [
    "DEEP_GROOVE_CONSTANTS", "K_RS", "K_Z", "MODELS", "MU_BL", "MU_EHL", "SEED003_COEFFICIENTS",
    "SEED003_SOURCE", "SKF_BEARING_TYPES", "SKF_SOURCE", "FrictionResult",
    "SkfGeometryConstants", "SkfMoment", "angular_contact_load_variables", "bearing_friction",
    "constant_coefficient_torque", "constant_friction", "deep_groove_constants",
    "deep_groove_load_angle", "deep_groove_load_variables",
    "friction_coefficient", "friction_type_of", "inlet_shear_heating_factor",
    "power_loss", "replenishment_factor",
    "seal_moment", "skf_friction", "skf_frictional_moment", "sliding_friction_coefficient",
    "sliding_weighting_factor", "viscosity_ratio",
]
