"""Bearing friction: torque and power loss by two published models.

- :mod:`.constant` -- seed 003's constant coefficient by bearing type, M = mu P d_m / 2
  (d_m the pitch diameter, as the seed defines it), N = M omega; the equivalent load P of
  ball bearings from ISO 281 (:func:`bearinglab.ratings.equivalent_dynamic_load`).
- :mod:`.skf` -- the SKF four-component model M = phi_ish phi_rs M_rr + M_sl + M_seal +
  M_drag (SKF catalogue 10000 EN), and the viscosity ratio kappa (ISO 281's nu_1 from
  :mod:`bearinglab.life`); :mod:`.skf_loads` its geometric and load variables G_rr, G_sl
  by bearing type (Table 2a); :mod:`.skf_constants` its constants (mu, K_rs, K_Z, the
  deep-groove series' geometry constants) and units.
- :mod:`.bearing` -- :class:`FrictionBearing`: what the models need of a bearing (a ball
  bearing's geometry, or any type's ISO boundary dimensions).
- :mod:`.models` -- :func:`constant_friction` and :func:`skf_friction`, each model as a
  result from explicit inputs.
- :mod:`.analysis` -- :func:`bearing_friction` (either model, with the rules for P, C_0,
  seals, viscosity and lubrication of :mod:`.rules`), used by the ``friction`` command and
  the report alike.
- :mod:`.result` -- :class:`FrictionResult`.

Core API in SI units (N, m, rad/s, m^2/s, N m, W); ``FrictionResult.to_dict()`` in
engineering units (N·mm, W, mm, mm²/s, rpm) with the unit in each key. What is and is not
checked against the sources: docs/capabilities/friction.md.

>>> from bearinglab.units import rpm_to_rad_s
>>> r = constant_friction(1000.0, 0.039, rpm_to_rad_s(1500), "radial_ball")
>>> round(r.to_dict()["friction_torque_n_mm"], 2)
29.25
"""

from .analysis import bearing_friction
from .bearing import FrictionBearing
from .constant import (
    SEED003_COEFFICIENTS,
    SEED003_SOURCE,
    constant_coefficient_torque,
    friction_coefficient,
    friction_type_of,
    power_loss,
)
from .models import MODELS, constant_friction, skf_friction
from .result import FrictionResult
from .rules import SEALS
from .skf import (
    SkfMoment,
    inlet_shear_heating_factor,
    replenishment_factor,
    seal_moment,
    skf_frictional_moment,
    sliding_friction_coefficient,
    sliding_weighting_factor,
    viscosity_ratio,
)
from .skf_constants import (
    DEEP_GROOVE_CONSTANTS,
    K_RS,
    K_Z,
    MU_BL,
    MU_EHL,
    SKF_BEARING_TYPES,
    SKF_SOURCE,
    SkfGeometryConstants,
    deep_groove_constants,
)
from .skf_loads import (
    angular_contact_load_variables,
    deep_groove_load_angle,
    deep_groove_load_variables,
)

__all__ = [
    "DEEP_GROOVE_CONSTANTS",
    "K_RS",
    "K_Z",
    "MODELS",
    "MU_BL",
    "MU_EHL",
    "SEALS",
    "SEED003_COEFFICIENTS",
    "SEED003_SOURCE",
    "SKF_BEARING_TYPES",
    "SKF_SOURCE",
    "FrictionBearing",
    "FrictionResult",
    "SkfGeometryConstants",
    "SkfMoment",
    "angular_contact_load_variables",
    "bearing_friction",
    "constant_coefficient_torque",
    "constant_friction",
    "deep_groove_constants",
    "deep_groove_load_angle",
    "deep_groove_load_variables",
    "friction_coefficient",
    "friction_type_of",
    "inlet_shear_heating_factor",
    "power_loss",
    "replenishment_factor",
    "seal_moment",
    "skf_friction",
    "skf_frictional_moment",
    "sliding_friction_coefficient",
    "sliding_weighting_factor",
    "viscosity_ratio",
]
