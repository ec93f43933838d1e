"""Analyses of the bearing in operation: load ratings and rating life (``life``, ISO 281 /
ISO/TS 16281) and friction torque and power loss (``friction``, seed 003's constant
coefficient or the SKF model). Each builds the models from the request, calls the library
once and names the library's parameters in the request's terms."""

from __future__ import annotations

from ..errors import BearinglabError, CatalogError, InputError
from ..inputs import (
    INPUTS,
    Input,
    bearing_from,
    bearing_warnings,
    condition_from,
    input_for,
    no_effect,
    restate,
    si,
    speed_from,
)
from .base import BEARING_INPUTS, Analysis, Outcome, inputs, plot_file

_RATINGS = {
    "dynamic_load_rating_kn": Input(
        "number",
        None,
        "Basic dynamic load rating C [kN], e.g. the maker's (default: ISO 281 from the geometry).",
        low=0.0,
        high=1e5,
        low_open=True,
        what="a rating",
    ),
    "static_load_rating_kn": Input(
        "number",
        None,
        "Basic static load rating C0 [kN] (default: ISO 76 from the geometry).",
        low=0.0,
        high=1e5,
        low_open=True,
        what="a rating",
    ),
}
_SPEED = {"speed_rpm": INPUTS["speed_rpm"].with_(default=...)}


# ------------------------------------------------------------------ life


def _contamination(text):
    """contamination as a number when it reads as one, else the level's name (the
    library checks both)."""
    if text is None or not isinstance(text, str):
        return text
    try:
        return float(text)
    except ValueError:
        return text


def life(values: dict) -> Outcome:
    """The ``life`` request: load ratings, equivalent loads, basic and modified rating
    life (:func:`bearinglab.life.rating_life`)."""
    from ..life import ViscosityTooLow, rating_life
    from ..operating import OperatingCondition
    from ..units import UNITS

    speed_from(values, positive=True)
    condition = condition_from(
        {k: v for k, v in values.items() if k != "misalignment_mrad"},
        positive_speed=True,
        unloaded="an unloaded bearing has no rating life",
    )
    method = values.get("life_method") or "iso281"
    tilt = values.get("misalignment_mrad") or 0.0
    if tilt and method != "iso16281":
        raise InputError(
            "misalignment_mrad",
            tilt,
            "0 with `life_method` iso281",
            "ISO 281 has no misalignment; use `life_method` iso16281",
        )
    bearing, decoded = bearing_from(values)
    axial_note = _roller_axial(bearing, condition.axial_load)
    nu = values.get("viscosity_mm2_s")
    try:
        # the tilt turns the inner ring about the axis across the (downward) radial load
        condition = OperatingCondition(
            radial_load=condition.radial_load,
            axial_load=condition.axial_load,
            misalignment=(si(values, "misalignment_mrad", 0.0), 0.0),
            shaft_speed=condition.shaft_speed,
        )
        result = rating_life(
            bearing,
            condition,
            reliability_percent=values.get("reliability_percent") or 90.0,
            viscosity=si(values, "viscosity_mm2_s"),
            contamination=_contamination(values.get("contamination")),
            method=method,
            rotating="outer" if values.get("outer_rotating") else "inner",
            ep_additives=bool(values.get("ep_additives")),
            dynamic_load_rating=si(values, "dynamic_load_rating_kn"),
            static_load_rating=si(values, "static_load_rating_kn"),
            **(
                {"slices": values.get("slices"), "edge_stress": bool(values.get("edge_stress"))}
                if bearing.rolling_element == "roller"
                else {}
            ),
        )
    except ViscosityTooLow as exc:
        raise InputError(
            "viscosity_mm2_s",
            nu,
            f"a viscosity of at least {UNITS['mm2_s'].from_si(exc.minimum):.3g} mm²/s at this "
            "speed and size",
            exc.hint,
        ) from None
    except InputError as exc:
        raise restate(exc, values, LIFE.options) from None
    unused = no_effect(
        [("outer_rotating", "rotating" in result.unused)],
        "with `life_method` iso281 (only iso16281 tells which ring turns)",
    ) + no_effect(
        [("ep_additives", "ep_additives" in result.unused)],
        "without `viscosity_mm2_s` (the EP rule acts on a_ISO, which needs the viscosity)",
    )
    unused += no_effect(
        [(n, bearing.rolling_element == "ball" and bool(values.get(n))) for n in ("edge_stress",)],
        "for a ball bearing",
    )
    warnings = bearing_warnings(bearing, decoded) + axial_note + list(result.warnings) + unused
    return Outcome(result, values.get("designation"), tuple(warnings), bearing)


def _roller_axial(bearing, axial_load: float) -> list[str]:
    """An axial load on a cylindrical roller bearing: refused where a ring has no ribs (NU,
    N: nothing carries it), else a warning that ISO 281 does not count it (P = F_r) and the
    ribs' sliding contacts limit it."""
    if bearing.rolling_element != "roller" or bearing.contact_angle > 0 or not axial_load:
        return []
    if bearing.design in ("NU", "N", "NN", ""):
        raise InputError(
            "axial_load_n",
            axial_load,
            f"0 for an {bearing.design or 'unribbed'} cylindrical roller bearing (a ring "
            "without ribs carries no axial load)",
        )
    return [
        f"ISO 281 counts no axial load on a cylindrical roller bearing (P = F_r): the "
        f"{abs(axial_load):g} N on the ribs of an {bearing.design} bearing is limited by their "
        "sliding contact's heat and wear, not by fatigue; check the maker's permissible "
        "axial load"
    ]


LIFE = Analysis(
    "life",
    "Load ratings and rating life (rating_life, ISO 281 / ISO/TS 16281).",
    {
        **BEARING_INPUTS,
        **_SPEED,
        **inputs("radial_load_n", "axial_load_n"),
        "reliability_percent": Input(
            "number",
            90.0,
            "Reliability for the modified life, 90-99.95 [%] (a_1 of ISO 281 Table 12).",
            low=90.0,
            high=99.95,
            what="a reliability",
        ),
        **inputs("viscosity_mm2_s"),
        "contamination": Input(
            "text",
            None,
            "Contamination factor e_C: a number in [0, 1] or a level of ISO 281 Table 13 "
            "(extreme-cleanliness, high-cleanliness, normal-cleanliness, slight, typical, "
            "severe, very-severe); default normal-cleanliness with a viscosity.",
        ),
        "life_method": Input(
            "text",
            "iso281",
            "iso281: L10 = (C/P)^3; iso16281: reference life from the solved load "
            "distribution (clearance, misalignment).",
            choices=("iso281", "iso16281"),
            aliases=("method",),
            sets="method",
        ),
        "misalignment_mrad": INPUTS["misalignment_mrad"].with_(
            help="Imposed tilt of the inner ring across the radial load [mrad] (iso16281 only)."
        ),
        "outer_rotating": INPUTS["outer_rotating"].with_(
            help="The outer ring turns (iso16281: which ring's equivalent load uses exponent 3).",
        ),
        "ep_additives": Input(
            "bool", False, "The lubricant has proven EP additives (ISO 281 rule for kappa < 1)."
        ),
        **_RATINGS,
        **inputs("slices"),
        "edge_stress": Input(
            "bool",
            False,
            "ISO/TS 16281: count the edge stress of the roller contacts in the slice lives "
            "(roller bearings, `life_method` iso16281).",
        ),
    },
    run=life,
    outputs={
        **{
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
        },
        "warnings": "s",
    },
    largest=5000,
    warm=("bearinglab.life",),
    files=plot_file("life against load"),
)


# ------------------------------------------------------------------ friction
#: The lubricant when neither lubricant nor viscosity_mm2_s is given (SKF model).
DEFAULT_LUBRICANT = "iso-vg68"


def _numbers(name: str, text, allowed: str, counts: tuple) -> list[float] | None:
    """A comma-separated input A,B,C: finite numbers >= 0, as many as one of ``counts``."""
    if text is None:
        return None
    try:
        values = [float(v) for v in str(text).split(",")]
    except ValueError:
        values = []
    if len(values) not in counts or not all(0 <= v < float("inf") for v in values):
        raise InputError(name, text, allowed)
    return values


def _friction_bearing(values: dict):
    """(the bearing, its Designation or None, warnings): a ball bearing through the
    catalogue's full model, any other type through its ISO boundary dimensions, or
    bore_mm and outside_diameter_mm alone."""
    from ..friction import FrictionBearing

    designation = values.get("designation")
    sizes = {k: si(values, f"{k}_mm") for k in ("bore", "outside_diameter", "pitch_diameter")}
    ball_given = any(values.get(k) is not None for k in ("balls", "ball_diameter_mm", "geometry"))
    if designation is None and not ball_given:
        if sizes["bore"] is None or sizes["outside_diameter"] is None:
            raise InputError(
                "designation",
                None,
                "a designation, or `bore_mm` and `outside_diameter_mm` (with `friction_type`)",
            )
        try:
            bearing = FrictionBearing.from_dimensions(
                sizes["bore"],
                sizes["outside_diameter"],
                bearing_type=values.get("friction_type"),
                pitch_diameter=sizes["pitch_diameter"],
            )
        except InputError as exc:
            if exc.parameter == "bearing_type":
                raise InputError(
                    "friction_type",
                    values.get("friction_type"),
                    exc.allowed + ", or a friction type of seed 003",
                ) from None
            raise
        return bearing, None, []
    try:
        bearing, decoded = bearing_from(values)
        return bearing, decoded, bearing_warnings(bearing, decoded)
    except CatalogError as first:
        if designation is None:
            raise
        try:
            bearing = FrictionBearing.from_designation(designation, values.get("system"), **sizes)
        except InputError:
            raise
        except BearinglabError:
            raise first from None
        return bearing, None, []


def friction(values: dict) -> Outcome:
    """The ``friction`` request: torque and power loss
    (:func:`bearinglab.friction.bearing_friction`)."""
    from ..friction import SkfGeometryConstants, bearing_friction
    from ..lubrication.lubricant import ZERO_CELSIUS

    omega = speed_from(values, positive=False)
    condition_from({k: values.get(k) for k in ("radial_load_n", "axial_load_n")})
    model = values.get("friction_model") or "constant"
    c = _numbers(
        "skf_constants",
        values.get("skf_constants"),
        "R1,R2,S1,S2 (deep-groove) or R1,R2,S1,S2,R3,S3 (angular contact), numbers >= 0 in "
        "SKF units",
        (4, 6),
    )
    ks = _numbers(
        "seal_constants",
        values.get("seal_constants"),
        "K_S1,K_S2,BETA, numbers >= 0 in SKF units",
        (3,),
    )
    nu, t = values.get("viscosity_mm2_s"), values.get("temperature_c")
    try:
        bearing, decoded, warnings = _friction_bearing(values)
        result = bearing_friction(
            bearing,
            omega,
            values.get("radial_load_n") or 0.0,
            values.get("axial_load_n") or 0.0,
            model=model,
            designation=decoded,
            friction_type=values.get("friction_type"),
            equivalent_load=values.get("equivalent_load_n"),
            static_load_rating=si(values, "static_load_rating_kn"),
            viscosity=si(values, "viscosity_mm2_s"),
            lubricant=values.get("lubricant")
            or (DEFAULT_LUBRICANT if nu is None and model == "skf" else None),
            temperature=None if t is None else t + ZERO_CELSIUS,
            lubrication=values.get("lubrication"),
            lubricant_kind=values.get("oil") or "mineral",
            constants=None
            if c is None
            else SkfGeometryConstants(
                *c[:4], *(c[4:] or (None, None)), source="user (`skf_constants`)"
            ),
            seals=values.get("seals"),
            seal_constants=ks,
            seal_diameter=si(values, "seal_diameter_mm"),
        )
    except InputError as exc:
        raise restate(exc, values, FRICTION.options) from None
    unused = result.unused
    seal = model == "skf" and "seal_diameter" in unused
    rest = [n for n in unused if n not in ("r3", "s3") and not (seal and n == "seal_diameter")]
    warnings = (
        warnings
        + list(result.warnings)
        + no_effect(
            [(input_for(n, FRICTION.options) or n, True) for n in rest],
            f"with `friction_model` {model}",
        )
        + no_effect([("seal_diameter_mm", seal)], "without `seal_constants`")
        + no_effect(
            [("R3,S3 of `skf_constants`", "r3" in unused or "s3" in unused)],
            "for a deep-groove ball bearing (its SKF model has no centrifugal-load terms)",
        )
    )
    return Outcome(result, values.get("designation"), tuple(warnings), bearing)


FRICTION = Analysis(
    "friction",
    "Friction torque and power loss (bearing_friction).",
    {
        **BEARING_INPUTS,
        "designation": INPUTS["designation"].with_(
            help="Bearing designation or catalogue name; optional with `bore_mm` and "
            "`outside_diameter_mm`.",
            sets=("bearing_type", "series"),
        ),
        **_SPEED,
        **inputs("radial_load_n", "axial_load_n"),
        "friction_model": Input(
            "text",
            "constant",
            "constant: seed 003's M = mu P d_m / 2; skf: SKF's rolling + sliding + seal "
            "(+ drag) model.",
            choices=("constant", "skf"),
            aliases=("model",),
            sets="model",
        ),
        "friction_type": Input(
            "text",
            None,
            "Friction type (constant model: seed 003's types, e.g. radial_ball, "
            "angular_contact_ball, cylindrical_roller, tapered_roller, thrust_ball; skf: "
            "radial_ball, angular_contact_ball, four_point_contact_ball). Default: from the "
            "designation.",
            aliases=("type",),
        ),
        "equivalent_load_n": Input(
            "number",
            None,
            "Equivalent load P [N] (constant model; default: F_r, or ISO 281 from a ball "
            "bearing's geometry).",
            low=0.0,
            high=1e7,
            what="a load",
        ),
        "static_load_rating_kn": _RATINGS["static_load_rating_kn"].with_(
            help="Basic static load rating C_0 [kN] for the SKF model with an axial load on "
            "a deep-groove bearing (default: ISO 76 from the geometry)."
        ),
        "lubricant": INPUTS["lubricant"].with_(
            help="Lubricant (built-in: iso-vg68, seed004-grease) for the viscosity at "
            "`temperature_c`, and grease or oil for the lubrication default (SKF model; default "
            "iso-vg68 unless `viscosity_mm2_s` is given).",
        ),
        **inputs("viscosity_mm2_s", "temperature_c"),
        "lubrication": Input(
            "text",
            None,
            "Lubrication method, sets K_rs (default: grease for a grease, oil-jet for an oil, "
            "grease for a viscosity alone).",
            choices=("grease", "oil-air", "oil-jet", "low-oil-bath"),
        ),
        "oil": Input(
            "text",
            "mineral",
            "Kind of oil, sets mu_EHL.",
            choices=("mineral", "synthetic", "transmission-fluid"),
            sets="lubricant_kind",
        ),
        "skf_constants": Input(
            "text",
            None,
            "SKF geometry constants R1,R2,S1,S2 (deep groove) or R1,R2,S1,S2,R3,S3 (angular "
            "contact).",
            sets="constants",
        ),
        "seals": Input(
            "text",
            None,
            "Seals (default: from the designation's suffix).",
            choices=("none", "shields", "contact"),
        ),
        "seal_constants": Input(
            "text",
            None,
            "SKF seal constants K_S1,K_S2,BETA (M_seal = K_S1 d_s^BETA + K_S2 in N mm, d_s in mm).",
        ),
        "seal_diameter_mm": Input(
            "number",
            None,
            "Seal counterface diameter d_s [mm].",
            low=0.0,
            high=1e5,
            low_open=True,
            what="a diameter",
        ),
    },
    run=friction,
    outputs={
        "friction_torque_n_mm": "f",
        "power_loss_w": "f",
        "friction_coefficient": "f",
        "rolling_torque_n_mm": "f",
        "sliding_torque_n_mm": "f",
        "seal_torque_n_mm": "f",
        "drag_torque_n_mm": "f",
        "warnings": "s",
    },
    largest=5000,
    warm=("bearinglab.friction",),
)
