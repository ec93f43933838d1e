"""Friction of a bearing (layer 3): :func:`bearing_friction`, either model with every
rule for what the models leave open - the friction type, the equivalent load P (ISO 281),
C_0 (ISO 76), the seals, the viscosity (a lubricant at its temperature), the lubrication
method. The ``friction`` command and the report both call it, so they give the same
numbers.

The models themselves, from explicit inputs, are :func:`~.models.constant_friction`
(seed 003's M = mu P d_m / 2, :mod:`.constant`) and :func:`~.models.skf_friction` (the SKF
four-component model, :mod:`.skf`). Every function takes SI units and returns a
:class:`~.result.FrictionResult` whose ``to_dict`` is in engineering units with the unit
in each key (``friction_torque_n_mm``, ``power_loss_w``).
"""

from __future__ import annotations

from dataclasses import replace

from ..errors import InputError, positive_number
from ..lubrication.lubricant import check_operating_temperature
from ..units import rpm_to_rad_s  # noqa: F401 - used by the doctests
from .bearing import FrictionBearing, as_friction_bearing
from .constant import SEED003_COEFFICIENTS, friction_coefficient, friction_type_of
from .models import MODELS, constant_friction, skf_friction
from .ranges import check_constants, unused_constants
from .result import FrictionResult
from .rules import (
    check_load,
    check_seal_constants,
    check_speed,
    equivalent_load_of,
    lubrication_of,
    seals_of,
    viscosity_of,
)
from .skf import seal_moment
from .skf_constants import MU_EHL, SKF_BEARING_TYPES, SkfGeometryConstants, deep_groove_constants

_ISO76_C0 = "ISO 76 from the internal geometry (bearinglab.life)"

__all__ = ["bearing_friction"]


def bearing_friction(
    bearing,
    shaft_speed: float,
    radial_load: float,
    axial_load: float = 0.0,
    *,
    model: str = "constant",
    designation=None,
    friction_type: str | None = None,
    equivalent_load: float | None = None,
    static_load_rating: float | None = None,
    viscosity: float | None = None,
    lubricant=None,
    temperature: float | None = None,
    lubrication: str | None = None,
    lubricant_kind: str = "mineral",
    constants: SkfGeometryConstants | None = None,
    series: str | None = None,
    seals: str | None = None,
    seal_constants=None,
    seal_diameter: float | None = None,
    **skf_options,
) -> FrictionResult:
    """Friction torque and power loss of a bearing by either model.

    ``model="constant"`` (seed 003, :func:`constant_friction`): the friction type is
    ``friction_type`` or the bearing's (:func:`~.constant.friction_type_of`), d_m the
    bearing's pitch diameter, P ``equivalent_load``, F_r without axial load, ISO 281's
    dynamic equivalent load from a ball bearing's geometry
    (:func:`bearinglab.ratings.equivalent_dynamic_load`), or F_a for a thrust ball bearing
    under axial load alone.

    ``model="skf"`` (:func:`skf_friction`): the type is ``friction_type`` or the bearing's
    (a ball bearing); d and D from the bearing; the viscosity is ``viscosity``, or that of
    ``lubricant`` at ``temperature`` (:func:`bearinglab.lubrication.lubricant.
    operating_viscosity`); the lubrication method (K_rs) is ``lubrication``, else grease
    for a grease, oil jet for an oil, grease with only a viscosity; the constants are
    ``constants`` or the deep-groove series' (``series``, else the designation's); with an
    axial load on a deep-groove bearing C_0 is ``static_load_rating`` or ISO 76's rating
    from the geometry (:func:`bearinglab.life.load_ratings`); contact seals add
    M_seal = K_S1 d_s^beta + K_S2 with ``seal_constants`` and ``seal_diameter``.

    Every input given is checked, whichever model runs; one the model does not use is
    named in the result's ``unused`` (and in ``to_dict``'s warnings), as are the R3, S3
    given for a deep-groove bearing, whose SKF model has no centrifugal terms. SKF
    constants outside the plausible range of the type are refused, with either model
    (:func:`~.ranges.check_constants`).

    Parameters
    ----------
    bearing : BallBearing or FrictionBearing
        The bearing (:class:`~.bearing.FrictionBearing` for types without a ball model).
    shaft_speed : float
        Speed of the rotating ring [rad/s], >= 0.
    radial_load, axial_load : float
        F_r, F_a [N], >= 0.
    model : str
        ``"constant"`` or ``"skf"`` [-].
    designation : Designation or None
        The decoded designation of a BallBearing (series, design variant, closures) [-].
    friction_type : str or None
        Seed-003 friction type (constant model) or SKF type (skf model) overriding the
        bearing's [-].
    equivalent_load : float or None
        P [N] for the constant model.
    static_load_rating : float or None
        C_0 [N] (SKF model with an axial load on a deep-groove bearing).
    viscosity : float or None
        Operating kinematic viscosity of the oil or the grease's base oil [m^2/s].
    lubricant : Lubricant, str or None
        A lubricant or a built-in one's name: its viscosity at ``temperature`` unless a
        ``viscosity`` is given, and its kind (grease or oil) for the lubrication default.
    temperature : float or None
        Operating temperature of the lubricant [K]; None: its reference temperature.
    lubrication : str or None
        ``"grease"``, ``"oil-air"``, ``"oil-jet"`` or ``"low-oil-bath"`` (K_rs) [-].
    lubricant_kind : str
        ``"mineral"``, ``"synthetic"`` or ``"transmission-fluid"`` (mu_EHL) [-].
    constants : SkfGeometryConstants or None
        SKF geometry constants.
    series : str or None
        Deep-groove series for the shipped constants [-].
    seals : str or None
        ``"none"``, ``"shields"`` or ``"contact"``; None: from the designation [-].
    seal_constants : tuple of 3 float or None
        K_S1, K_S2, beta of the seal [SKF units].
    seal_diameter : float or None
        Seal counterface diameter d_s [m].
    **skf_options
        ``k_z``, ``mu_bl``, ``drag``, ``notes`` of :func:`skf_friction`.

    Examples
    --------
    >>> from bearinglab.catalog import bearing_from_designation
    >>> b, _ = bearing_from_designation("6205")
    >>> r = bearing_friction(b, rpm_to_rad_s(3000), 1000.0, model="skf", viscosity=20e-6)
    >>> round(r.torque * 1e3, 1)
    20.2
    >>> r = bearing_friction(b, rpm_to_rad_s(3000), 1000.0, model="skf", lubricant="iso-vg68")
    >>> round(r.to_dict()["viscosity_mm2_s"], 3), r.to_dict()["lubrication"]
    (68.0, 'oil-jet')
    """
    if model not in MODELS:
        raise InputError("model", model, "one of " + ", ".join(MODELS))
    b = as_friction_bearing(bearing, designation)
    w = check_speed(shaft_speed)
    fr = check_load("radial_load", radial_load)
    fa = check_load("axial_load", axial_load)
    seal_kind = seals_of(b, seals)
    if static_load_rating is not None:
        positive_number("static_load_rating", static_load_rating, "a rating > 0 [N]")
    if equivalent_load is not None:
        check_load("equivalent_load", equivalent_load)
    if lubricant_kind not in MU_EHL:
        raise InputError("lubricant_kind", lubricant_kind, "one of " + ", ".join(MU_EHL))
    if seal_diameter is not None:
        positive_number("seal_diameter", seal_diameter, "a diameter > 0 [m]")
    if model == "constant" and lubricant is None and viscosity is None:
        if temperature is not None:  # unused by this model, but checked
            check_operating_temperature(temperature)
        nu, nu_how, lub = None, None, None
    else:
        nu, nu_how, lub = viscosity_of(viscosity, lubricant, temperature)
    ks = check_seal_constants(seal_constants, seal_kind)
    plausible = _operating_warnings(bearing, w, fr, fa)
    if model == "constant":
        unused = {
            "viscosity": viscosity,
            "lubricant": lubricant,
            "temperature": temperature,
            "lubrication": lubrication,
            "static_load_rating": static_load_rating,
            "constants": constants,
            "seal_constants": seal_constants,
            "seal_diameter": seal_diameter,
        }
        if lubrication is not None:
            lubrication_of(lubrication, lub)
        check_constants(friction_type or b.bearing_type, constants)  # checked, though unused
        result = _constant(b, w, fr, fa, friction_type, equivalent_load, seal_kind)
        return replace(result, warnings=plausible + result.warnings, unused=_given(unused))
    kind = friction_type or b.bearing_type
    if kind not in SKF_BEARING_TYPES:
        what = "for the SKF model one of " + ", ".join(SKF_BEARING_TYPES)
        if friction_type is not None:
            raise InputError("friction_type", friction_type, what)
        raise InputError(
            "bearing_type",
            kind,
            what,
            f"this bearing is {kind}; use `model` constant, which covers every type",
        )
    if b.bore is None or b.outside_diameter is None:
        raise InputError(
            "bore",
            None,
            "the bore and outside diameter (the SKF model uses d_m = 0.5 (d + D))",
            "give the bearing's `bore` and `outside_diameter`",
        )
    if nu is None:
        raise InputError(
            "viscosity",
            None,
            "the operating kinematic viscosity [m^2/s], or a lubricant (and its temperature)",
        )
    method, method_how = lubrication_of(lubrication, lub)
    if constants is None:
        if kind != "radial_ball":
            needed = {
                "cylindrical_roller": "R1, S1, S2 (R2 = 0)",
                "tapered_roller": "R1, R2, S1, S2",
            }.get(kind, "R1, R2, S1, S2, R3, S3")
            raise InputError(
                "constants",
                None,
                f"SKF geometry constants {needed} for {kind} (SKF's table is not shipped)",
                "give them (`constants`)",
            )
        constants = deep_groove_constants(series or b.series)
    notes = list(skf_options.pop("notes", ()))
    c0, c0_how = static_load_rating, "given"
    if kind == "radial_ball" and fa > 0 and c0 is None:
        ball = b.ball_bearing
        if ball is None or ball.bearing_type != "radial_ball":
            raise InputError(
                "static_load_rating",
                None,
                "the basic static load rating C_0 "
                "[N] when there is an axial load (SKF: alpha_F = 24.6 "
                "(F_a/C_0)^0.24)",
                "give it (`static_load_rating`)",
            )
        from ..ratings import load_ratings

        c0, c0_how = load_ratings(ball).static, _ISO76_C0
        notes.append(
            f"C_0 = {c0:.5g} N from ISO 76 and the internal geometry "
            "(bearinglab.ratings); give the maker's (`static_load_rating`)"
        )
    if c0 is not None and fa > c0:
        raise InputError("axial_load", fa, f"at most C_0 = {c0:g} N")
    seal = 0.0
    if seal_kind == "contact":
        if ks is None:
            notes.append(
                "contact seals: M_seal is not included (SKF's seal constants are not "
                "shipped; give the seal constants K_S1, K_S2, beta and the counterface "
                "diameter d_s)"
            )
        elif seal_diameter is None:
            raise InputError(
                "seal_diameter", None, "the seal counterface diameter d_s with seal constants"
            )
        else:
            seal = seal_moment(*ks, seal_diameter)
    axial_factor = None
    if kind == "tapered_roller":
        roller = b.roller_bearing
        if roller is None or not getattr(roller, "is_tapered", False):
            if fa > 0:
                raise InputError(
                    "bearing",
                    b.name,
                    "a tapered roller bearing with its geometry when there is an axial load",
                    "SKF's tapered G_rr and G_sl take the axial factor Y = 0.4 cot(alpha)",
                )
        else:
            from ..ratings.roller import tapered_factors

            axial_factor = tapered_factors(roller.contact_angle, int(roller.rows))[2]
            notes.append(f"Y = {axial_factor:.3g} from the contact angle (ISO 281: 0.4 cot alpha)")
    result = skf_friction(
        kind,
        b.bore,
        b.outside_diameter,
        fr,
        fa,
        w,
        nu,
        constants,
        name=b.name,
        static_load_rating=c0,
        lubrication=method,
        lubricant_kind=lubricant_kind,
        seal=seal,
        notes=tuple(notes),
        axial_factor=axial_factor,
        **skf_options,
    )
    parameters = {
        **result.parameters,
        "viscosity_source": nu_how,
        "lubrication_source": method_how,
        "lubricant_kind": lubricant_kind,
        "static_rating": c0,
        "static_rating_source": c0_how,
    }
    if lub is not None:
        parameters["lubricant"] = lub.name
    unused = {
        "equivalent_load": equivalent_load,
        "seal_diameter": seal_diameter if ks is None else None,
    }
    return replace(
        result,
        parameters=parameters,
        bearing_type=b.bearing_type,
        seals=seal_kind,
        warnings=plausible + result.warnings,
        unused=_given(unused) + unused_constants(kind, constants),
    )


def _given(inputs: dict) -> tuple[str, ...]:
    """The names of the inputs given (not None)."""
    return tuple(name for name, value in inputs.items() if value is not None)


def _operating_warnings(bearing, shaft_speed, radial_load, axial_load) -> tuple:
    """The load against C0 and the speed against the limit (plausibility.py), for a ball
    bearing whose geometry gives them; none for a FrictionBearing of dimensions only."""
    from ..geometry import BallBearing
    from ..operating import OperatingCondition
    from ..plausibility import operating_warnings
    from ..roller_geometry import RollerBearing

    if not isinstance(bearing, (BallBearing, RollerBearing)):
        return ()
    condition = OperatingCondition(
        radial_load=radial_load, axial_load=axial_load, shaft_speed=shaft_speed
    )
    return tuple(operating_warnings(bearing, condition))


def _constant(
    b: FrictionBearing,
    w: float,
    fr: float,
    fa: float,
    friction_type,
    given_load,
    seal_kind: str,
) -> FrictionResult:
    kind = friction_type
    if kind is None:
        try:
            kind = friction_type_of(b.bearing_type, b.design_variant)
        except InputError:
            raise InputError(
                "friction_type",
                None,
                f"a friction type for this {b.bearing_type} "
                "bearing, one of " + ", ".join(SEED003_COEFFICIENTS),
                "seed 003's Table III has no row for it",
            ) from None
    friction_coefficient(kind)
    p, how = equivalent_load_of(b, kind, fr, fa, given_load)
    result = constant_friction(
        p, b.pitch_diameter, w, kind, name=b.name, radial_load=fr, axial_load=fa
    )
    seal_note = (
        ("contact seals add friction that the constant model leaves out",)
        if seal_kind == "contact"
        else ()
    )
    return replace(
        result,
        parameters={
            **result.parameters,
            "equivalent_load_source": how,
            "pitch_diameter_source": b.pitch_diameter_source,
        },
        bearing_type=b.bearing_type,
        seals=seal_kind,
        warnings=result.warnings + seal_note,
    )
