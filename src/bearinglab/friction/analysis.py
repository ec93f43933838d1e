"""Friction analyses (layer 3): the two models on one result object.

- :func:`constant_friction` -- seed 003's M = mu P d_m / 2 (:mod:`.constant`).
- :func:`skf_friction` -- the SKF four-component model (:mod:`.skf`).
- :func:`bearing_friction` -- either model for a :class:`~bearinglab.geometry.BallBearing`.

Every function takes SI units and returns a :class:`FrictionResult` whose ``to_dict`` is in
engineering units with the unit in each key (``friction_torque_nmm``, ``power_loss_w``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..errors import DesignationError, InputError
from .constant import (
    SEED003_SOURCE,
    constant_coefficient_torque,
    friction_coefficient,
    friction_type_of,
    power_loss,
)
from .skf import (
    K_RS,
    K_Z,
    MU_BL,
    MU_EHL,
    SKF_SOURCE,
    SkfGeometryConstants,
    deep_groove_constants,
    skf_frictional_moment,
    viscosity_ratio,
)

MODELS = ("constant", "skf")
_CONSTANT_CAVEAT = ("seed 003's coefficients hold for a lubricant of about 20 mm^2/s at the "
                    "operating temperature and do not depend on speed; seals not included")
_NO_LOAD = ("no load: the model gives no load-dependent moment (a running bearing needs its "
            "minimum load, and real unloaded bearings still have drag and seal friction)")
_NMM = 1e3        # N m -> N mm
_MM = 1e3         # m -> mm
_MM2_S = 1e6      # m^2/s -> mm^2/s


def _speed(shaft_speed) -> float:
    if isinstance(shaft_speed, bool) or not isinstance(shaft_speed, (int, float)) \
            or not math.isfinite(shaft_speed) or shaft_speed < 0:
        raise InputError("shaft_speed", shaft_speed, "a finite speed >= 0 [rad/s]")
    return float(shaft_speed)


def _load(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not math.isfinite(value) or value < 0:
        raise InputError(name, value, "a finite load >= 0 [N]")
    return float(value)


@dataclass(frozen=True)
class FrictionResult:
    """Friction torque and power loss of a bearing at one operating point.

    Attributes: ``model`` (``"constant"`` or ``"skf"``), ``name``, ``shaft_speed``
    [rad/s], ``radial_load``, ``axial_load`` [N], ``torque`` M [N m], ``components``
    (name -> moment [N m]: ``rolling``, ``sliding``, ``seal``, ``drag`` for the SKF model;
    empty for the constant model), ``parameters`` (the coefficients, factors and
    diameters used, SI or dimensionless), ``sources`` and ``warnings``.
    """

    model: str
    name: str
    shaft_speed: float
    radial_load: float
    axial_load: float
    torque: float
    components: dict = field(default_factory=dict)
    parameters: dict = field(default_factory=dict)
    sources: tuple = ()
    warnings: tuple = ()

    @property
    def power_loss(self) -> float:
        """Frictional power loss N = M omega [W]."""
        return float(power_loss(self.torque, self.shaft_speed))

    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units (N mm, W, mm, mm^2/s, rpm, N)."""
        p = self.parameters
        out = {"name": self.name, "model": self.model,
               "speed_rpm": self.shaft_speed * 30.0 / math.pi,
               "radial_load_n": self.radial_load, "axial_load_n": self.axial_load,
               "friction_torque_nmm": self.torque * _NMM, "power_loss_w": self.power_loss}
        if self.model == "constant":
            out.update({"friction_type": p["friction_type"],
                        "friction_coefficient": p["friction_coefficient"],
                        "equivalent_load_n": p["equivalent_load"],
                        "pitch_diameter_mm": p["pitch_diameter"] * _MM})
        else:
            out.update({f"{k}_torque_nmm": v * _NMM for k, v in self.components.items()})
            c = p["constants"]
            nu1 = p["rated_viscosity"]
            out.update({
                "mean_diameter_mm": p["mean_diameter"] * _MM,
                "viscosity_mm2_s": p["viscosity"] * _MM2_S,
                "rated_viscosity_mm2_s": None if nu1 is None else nu1 * _MM2_S,
                "viscosity_ratio": p["viscosity_ratio"],
                "inlet_shear_factor": p["inlet_shear_factor"],
                "replenishment_factor": p["replenishment_factor"],
                "sliding_weighting_factor": p["sliding_weighting_factor"],
                "sliding_friction_coefficient": p["sliding_friction_coefficient"],
                "rolling_variable_skf": p["rolling_variable"],
                "sliding_variable_skf": p["sliding_variable"],
                "k_rs": p["k_rs"], "k_z": p["k_z"], "lubrication": p["lubrication"],
                "geometry_constants": {"r1": c.r1, "r2": c.r2, "s1": c.s1, "s2": c.s2,
                                       "r3": c.r3, "s3": c.s3, "source": c.source,
                                       "verified": c.verified},
            })
        out["sources"] = list(self.sources)
        out["warnings"] = list(self.warnings)
        return out

    def to_pandas(self):
        """Table of the torque and its components: component, torque [N mm], share [-]."""
        import pandas as pd

        parts = self.components or {"total (constant coefficient)": self.torque}
        rows = [{"component": k, "torque_nmm": v * _NMM,
                 "share": (v / self.torque) if self.torque > 0 else 0.0}
                for k, v in parts.items()]
        return pd.DataFrame(rows)

    def plot(self, ax=None):
        """Bar chart of the torque components [N mm]; returns (fig, ax), never shows."""
        from ..plotting import _pyplot

        if ax is None:
            fig, ax = _pyplot().subplots(figsize=(6, 3.5))
        else:
            fig = ax.figure
        table = self.to_pandas()
        ax.bar(table["component"], table["torque_nmm"], color="tab:blue")
        ax.set_ylabel("friction torque [N mm]")
        ax.set_title(f"{self.name or 'bearing'}: {self.torque * _NMM:.4g} N mm, "
                     f"{self.power_loss:.4g} W ({self.model} model)")
        return fig, ax


def constant_friction(equivalent_load: float, pitch_diameter: float, shaft_speed: float,
                      friction_type: str, *, name: str = "", radial_load: float | None = None,
                      axial_load: float = 0.0) -> FrictionResult:
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

    >>> r = constant_friction(1000.0, 0.039, 1500 * math.pi / 30, "radial_ball")
    >>> round(r.torque * 1e3, 3), round(r.power_loss, 3)
    (29.25, 4.595)
    """
    w = _speed(shaft_speed)
    p = _load("equivalent_load", equivalent_load)
    mu = friction_coefficient(friction_type)
    torque = float(constant_coefficient_torque(mu, p, pitch_diameter))
    fr = p if radial_load is None else _load("radial_load", radial_load)
    return FrictionResult(
        "constant", name, w, fr, _load("axial_load", axial_load), torque,
        parameters={"friction_type": friction_type, "friction_coefficient": mu,
                    "equivalent_load": p, "pitch_diameter": float(pitch_diameter)},
        sources=(SEED003_SOURCE,),
        warnings=(_CONSTANT_CAVEAT,) + ((_NO_LOAD,) if p == 0.0 else ()))


def skf_friction(bearing_type: str, bore: float, outside_diameter: float, radial_load: float,
                 axial_load: float, shaft_speed: float, viscosity: float,
                 constants: SkfGeometryConstants, *, name: str = "",
                 static_load_rating: float | None = None, lubrication: str = "grease",
                 k_z: float | None = None, lubricant_kind: str = "mineral", mu_bl: float = MU_BL,
                 seal: float = 0.0, drag: float = 0.0,
                 notes: tuple = ()) -> FrictionResult:
    """The SKF model (:func:`~bearinglab.friction.skf.skf_frictional_moment`) as a result.

    Parameters
    ----------
    bearing_type : str
        ``"radial_ball"``, ``"angular_contact_ball"`` or ``"four_point_contact_ball"`` [-].
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

    >>> from bearinglab.friction import deep_groove_constants
    >>> r = skf_friction("radial_ball", 0.025, 0.052, 1000.0, 0.0, 3000 * math.pi / 30, 20e-6,
    ...                  deep_groove_constants("62"))
    >>> round(r.to_dict()["friction_torque_nmm"], 2)
    20.16
    """
    if lubrication not in K_RS:
        raise InputError("lubrication", lubrication, "one of " + ", ".join(K_RS))
    if lubricant_kind not in MU_EHL:
        raise InputError("lubricant_kind", lubricant_kind, "one of " + ", ".join(MU_EHL))
    w = _speed(shaft_speed)
    fr = _load("radial_load", radial_load)
    fa = _load("axial_load", axial_load)
    m = skf_frictional_moment(bearing_type, bore, outside_diameter, fr, fa, w, viscosity,
                              constants, static_load_rating=static_load_rating,
                              k_rs=K_RS[lubrication], k_z=k_z, mu_bl=mu_bl,
                              mu_ehl=MU_EHL[lubricant_kind], seal=seal, drag=drag)
    dm = 0.5 * (float(bore) + float(outside_diameter))
    nu1 = float(viscosity) / viscosity_ratio(viscosity, w, dm) if w > 0 else None
    warnings = list(notes)
    if not constants.verified:
        warnings.append("SKF geometry constants not checked against the catalogue table ("
                        + constants.source + ")")
    if fr == 0.0 and fa == 0.0:
        warnings.append(_NO_LOAD)
    if lubrication == "low-oil-bath" and drag == 0.0:
        warnings.append("oil-bath drag losses (M_drag) are not modelled and are taken as 0")
    if static_load_rating is not None and fa > 0.5 * static_load_rating:
        warnings.append("F_a > 0.5 C_0: beyond the axial load a deep-groove bearing should carry")
    return FrictionResult(
        "skf", name, w, fr, fa, m.total,
        components={"rolling": m.rolling, "sliding": m.sliding, "seal": m.seal,
                    "drag": m.drag},
        parameters={"mean_diameter": dm, "viscosity": float(viscosity), "rated_viscosity": nu1,
                    "viscosity_ratio": None if nu1 is None else float(viscosity) / nu1,
                    "inlet_shear_factor": m.inlet_shear_factor,
                    "replenishment_factor": m.replenishment_factor,
                    "sliding_weighting_factor": m.sliding_weighting_factor,
                    "sliding_friction_coefficient": m.sliding_friction_coefficient,
                    "rolling_variable": m.rolling_variable,
                    "sliding_variable": m.sliding_variable, "k_rs": K_RS[lubrication],
                    "k_z": K_Z.get(bearing_type) if k_z is None else k_z,
                    "lubrication": lubrication, "constants": constants},
        sources=(SKF_SOURCE, "ISO 281:2007 rated viscosity nu_1"),
        warnings=tuple(warnings))


def _series_of(bearing) -> str | None:
    from ..designation import parse

    try:
        return parse(bearing.name).series if bearing.name else None
    except (DesignationError, InputError):
        return None


def bearing_friction(bearing, shaft_speed: float, radial_load: float, axial_load: float = 0.0,
                     *, model: str = "constant", friction_type: str | None = None,
                     equivalent_load: float | None = None, viscosity: float | None = None,
                     constants: SkfGeometryConstants | None = None, series: str | None = None,
                     **skf_options) -> FrictionResult:
    """Friction of a :class:`~bearinglab.geometry.BallBearing` by either model.

    ``model="constant"``: the friction type comes from ``bearing.bearing_type`` (or
    ``friction_type``), d_m is the bearing's pitch diameter, and P is ``equivalent_load``
    or ISO 281's dynamic equivalent load from the geometry
    (:func:`bearinglab.life.equivalent_dynamic_load`; P = F_r without axial load).
    ``model="skf"``: needs ``bearing.bore`` and ``outside_diameter``, ``viscosity``
    [m^2/s], and ``constants`` or a deep-groove series (``series``, else read from
    ``bearing.name``); with an axial load on a deep-groove bearing C_0 is
    ``skf_options["static_load_rating"]`` or ISO 76's rating from the geometry
    (:func:`bearinglab.life.load_ratings`); ``skf_options`` go to :func:`skf_friction`.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    shaft_speed : float
        [rad/s].
    radial_load, axial_load : float
        F_r, F_a [N].
    model : str
        ``"constant"`` or ``"skf"`` [-].
    friction_type : str or None
        Seed-003 friction type overriding the bearing's [-].
    equivalent_load : float or None
        P [N] for the constant model.
    viscosity : float or None
        Operating viscosity [m^2/s] (SKF model).
    constants : SkfGeometryConstants or None
        SKF geometry constants.
    series : str or None
        Deep-groove series for the shipped constants [-].
    **skf_options
        Keyword arguments of :func:`skf_friction`.

    >>> from bearinglab.catalog import bearing_from_designation
    >>> b, _ = bearing_from_designation("6205")
    >>> r = bearing_friction(b, 3000 * math.pi / 30, 1000.0, model="skf", viscosity=20e-6)
    >>> round(r.torque * 1e3, 1)
    20.2
    """
    if model not in MODELS:
        raise InputError("model", model, "one of " + ", ".join(MODELS))
    fr = _load("radial_load", radial_load)
    fa = _load("axial_load", axial_load)
    if model == "constant":
        kind = friction_type or friction_type_of(bearing.bearing_type)
        if equivalent_load is None:
            equivalent_load = fr if fa == 0.0 else _iso281_load(bearing, fr, fa)
        return constant_friction(equivalent_load, bearing.pitch_diameter, shaft_speed, kind,
                                 name=bearing.name, radial_load=fr, axial_load=fa)
    if bearing.bore is None or bearing.outside_diameter is None:
        raise InputError("bearing", bearing.name or "bearing",
                         "a bearing with bore and outside_diameter (the SKF model uses "
                         "d_m = 0.5 (d + D))")
    if viscosity is None:
        raise InputError("viscosity", None, "the operating kinematic viscosity [m^2/s]")
    if constants is None:
        if bearing.bearing_type != "radial_ball":
            raise InputError("constants", None, "SKF geometry constants for "
                             f"{bearing.bearing_type} (none are shipped)")
        series = series or _series_of(bearing)
        constants = deep_groove_constants(series)
    if (bearing.bearing_type == "radial_ball" and fa > 0
            and skf_options.get("static_load_rating") is None):
        from ..life import load_ratings

        skf_options["static_load_rating"] = load_ratings(bearing).static
        skf_options["notes"] = (*skf_options.get("notes", ()),
                                "C_0 from ISO 76 and the internal geometry (bearinglab.life)")
    return skf_friction(bearing.bearing_type, bearing.bore, bearing.outside_diameter, fr, fa,
                        shaft_speed, viscosity, constants, name=bearing.name, **skf_options)


def _iso281_load(bearing, radial_load: float, axial_load: float) -> float:
    """ISO 281 dynamic equivalent load P of a ball bearing [N] (bearinglab.life)."""
    from ..life import equivalent_dynamic_load

    return float(equivalent_dynamic_load(bearing, radial_load, axial_load)[0])
