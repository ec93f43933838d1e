"""The two friction models as results, from explicit inputs (layer 3).

- :func:`constant_friction` -- seed 003's M = mu P d_m / 2 (:mod:`.constant`; seed 003,
  "Расчет трения подшипника", Table III).
- :func:`skf_friction` -- the SKF four-component model (:mod:`.skf`; SKF catalogue 10000
  EN, "The SKF model for calculating the frictional moment"), with its warnings: the
  constants not checked against the catalogue, the roller bearings' K_Z and mu_EHL, no
  load, oil-bath drag not modelled, an axial load beyond 0.5 C_0.

Each takes SI units and returns a :class:`~.result.FrictionResult` whose ``to_dict`` is
in engineering units with the unit in each key (``friction_torque_n_mm``,
``power_loss_w``). :func:`bearinglab.friction.bearing_friction` (:mod:`.analysis`) calls
them for a bearing, with the rules for what the models leave open.
"""

from __future__ import annotations

from ..errors import InputError
from ..units import rpm_to_rad_s  # noqa: F401 - used by the doctests
from .constant import SEED003_SOURCE, constant_coefficient_torque, friction_coefficient
from .ranges import check_constants
from .result import FrictionResult
from .rules import check_load, check_speed
from .skf import skf_frictional_moment, viscosity_ratio
from .skf_constants import (
    K_RS,
    K_Z,
    K_Z_UNVERIFIED,
    MU_BL,
    MU_EHL,
    MU_EHL_ROLLER,
    SKF_SOURCE,
    SkfGeometryConstants,
)

MODELS = ("constant", "skf")
_CONSTANT_CAVEAT = (
    "seed 003's coefficients hold for a lubricant of about 20 mm^2/s at the "
    "operating temperature and do not depend on speed; seals not included"
)
_NO_LOAD = (
    "no load: the model gives no load-dependent moment (a running bearing needs its "
    "minimum load, and real unloaded bearings still have drag and seal friction)"
)


def constant_friction(
    equivalent_load: float,
    pitch_diameter: float,
    shaft_speed: float,
    friction_type: str,
    *,
    name: str = "",
    radial_load: float | None = None,
    axial_load: float = 0.0,
) -> FrictionResult:
    """Seed 003's constant-coefficient estimate M = mu P d_m / 2, N = M omega.

    Parameters
    ----------
    equivalent_load : float
        Equivalent bearing load P [N].
    pitch_diameter : float
        Pitch (mean) diameter d_m [m].
    shaft_speed : float
        Speed of the rotating ring [rad/s].
    friction_type : str
        Key of :data:`~bearinglab.friction.SEED003_COEFFICIENTS` [-].
    name : str
        Label [-].
    radial_load, axial_load : float
        The loads P was formed from, for the report [N]; ``radial_load`` defaults to P.

    Examples
    --------
    >>> r = constant_friction(1000.0, 0.039, rpm_to_rad_s(1500), "radial_ball")
    >>> round(r.torque * 1e3, 3), round(r.power_loss, 3)
    (29.25, 4.595)
    """
    w = check_speed(shaft_speed)
    p = check_load("equivalent_load", equivalent_load)
    mu = friction_coefficient(friction_type)
    torque = float(constant_coefficient_torque(mu, p, pitch_diameter))
    fr = p if radial_load is None else check_load("radial_load", radial_load)
    return FrictionResult(
        "constant",
        name,
        w,
        fr,
        check_load("axial_load", axial_load),
        torque,
        parameters={
            "friction_type": friction_type,
            "friction_coefficient": mu,
            "equivalent_load": p,
            "pitch_diameter": float(pitch_diameter),
        },
        sources=(SEED003_SOURCE,),
        warnings=(_CONSTANT_CAVEAT,) + ((_NO_LOAD,) if p == 0.0 else ()),
    )


def skf_friction(
    bearing_type: str,
    bore: float,
    outside_diameter: float,
    radial_load: float,
    axial_load: float,
    shaft_speed: float,
    viscosity: float,
    constants: SkfGeometryConstants,
    *,
    name: str = "",
    static_load_rating: float | None = None,
    lubrication: str = "grease",
    k_z: float | None = None,
    lubricant_kind: str = "mineral",
    mu_bl: float = MU_BL,
    seal: float = 0.0,
    drag: float = 0.0,
    notes: tuple = (),
    axial_factor: float | None = None,
) -> FrictionResult:
    """The SKF model (:func:`~bearinglab.friction.skf.skf_frictional_moment`) as a result.

    Parameters
    ----------
    bearing_type : str
        ``"radial_ball"``, ``"angular_contact_ball"``, ``"four_point_contact_ball"``,
        ``"cylindrical_roller"`` or ``"tapered_roller"`` [-].
    bore, outside_diameter : float
        d, D [m].
    radial_load, axial_load : float
        F_r, F_a [N].
    shaft_speed : float
        [rad/s].
    viscosity : float
        Operating kinematic viscosity (oil, or the grease's base oil) [m^2/s].
    constants : SkfGeometryConstants
        Geometry constants of the series.
    name : str
        Label [-].
    static_load_rating : float or None
        C_0 [N] (deep-groove bearings with F_a > 0).
    lubrication : str
        ``"grease"``, ``"oil-air"``, ``"oil-jet"`` or ``"low-oil-bath"`` (sets K_rs) [-].
    k_z : float or None
        K_Z [-]; None for the shipped value of the type.
    lubricant_kind : str
        ``"mineral"``, ``"synthetic"`` or ``"transmission-fluid"`` (sets mu_EHL) [-].
    mu_bl : float
        Boundary sliding coefficient [-].
    seal, drag : float
        M_seal and M_drag [N m] (see :func:`~bearinglab.friction.skf.seal_moment`).
    notes : tuple of str
        Caveats of the caller, added to the warnings [-].
    axial_factor : float or None
        Y of a tapered roller bearing [-].

    Examples
    --------
    >>> from bearinglab.friction import deep_groove_constants
    >>> r = skf_friction("radial_ball", 0.025, 0.052, 1000.0, 0.0, rpm_to_rad_s(3000), 20e-6,
    ...                  deep_groove_constants("62"))
    >>> round(r.to_dict()["friction_torque_n_mm"], 2)
    20.16
    """
    if lubrication not in K_RS:
        raise InputError("lubrication", lubrication, "one of " + ", ".join(K_RS))
    if lubricant_kind not in MU_EHL:
        raise InputError("lubricant_kind", lubricant_kind, "one of " + ", ".join(MU_EHL))
    check_constants(bearing_type, constants)
    w = check_speed(shaft_speed)
    fr = check_load("radial_load", radial_load)
    fa = check_load("axial_load", axial_load)
    m = skf_frictional_moment(
        bearing_type,
        bore,
        outside_diameter,
        fr,
        fa,
        w,
        viscosity,
        constants,
        static_load_rating=static_load_rating,
        k_rs=K_RS[lubrication],
        k_z=k_z,
        mu_bl=mu_bl,
        mu_ehl=MU_EHL_ROLLER.get(bearing_type, MU_EHL[lubricant_kind]),
        seal=seal,
        drag=drag,
        axial_factor=axial_factor,
    )
    dm = 0.5 * (float(bore) + float(outside_diameter))
    nu1 = float(viscosity) / viscosity_ratio(viscosity, w, dm) if w > 0 else None
    warnings = list(notes)
    if not constants.verified:
        warnings.append(
            "SKF geometry constants not checked against the catalogue table ("
            + constants.source
            + ")"
        )
    if k_z is None and bearing_type in K_Z_UNVERIFIED:
        warnings.append(
            f"K_Z = {K_Z[bearing_type]:g} of a {bearing_type.replace('_', ' ')} bearing is "
            "SKF's value as recalled, not checked against the catalogue table (give k_z)"
        )
    if bearing_type in MU_EHL_ROLLER:
        warnings.append(
            f"mu_EHL = {MU_EHL_ROLLER[bearing_type]:g} of a {bearing_type.replace('_', ' ')} "
            "bearing (SKF catalogue), whatever the lubricant kind"
        )
    if fr == 0.0 and fa == 0.0:
        warnings.append(_NO_LOAD)
    if lubrication == "low-oil-bath" and drag == 0.0:
        warnings.append("oil-bath drag losses (M_drag) are not modelled and are taken as 0")
    if static_load_rating is not None and fa > 0.5 * static_load_rating:
        warnings.append("F_a > 0.5 C_0: beyond the axial load a deep-groove bearing should carry")
    return FrictionResult(
        "skf",
        name,
        w,
        fr,
        fa,
        m.total,
        components={"rolling": m.rolling, "sliding": m.sliding, "seal": m.seal, "drag": m.drag},
        parameters={
            "mean_diameter": dm,
            "viscosity": float(viscosity),
            "rated_viscosity": nu1,
            "viscosity_ratio": None if nu1 is None else float(viscosity) / nu1,
            "inlet_shear_factor": m.inlet_shear_factor,
            "replenishment_factor": m.replenishment_factor,
            "sliding_weighting_factor": m.sliding_weighting_factor,
            "sliding_friction_coefficient": m.sliding_friction_coefficient,
            "rolling_variable": m.rolling_variable,
            "sliding_variable": m.sliding_variable,
            "k_rs": K_RS[lubrication],
            "k_z": K_Z.get(bearing_type) if k_z is None else k_z,
            "lubrication": lubrication,
            "constants": constants,
        },
        sources=(SKF_SOURCE, "ISO 281:2007 rated viscosity nu_1"),
        warnings=tuple(warnings),
    )
