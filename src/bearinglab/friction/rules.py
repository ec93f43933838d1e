"""Rules for what the friction models leave open (used by
:func:`bearinglab.friction.bearing_friction`): the seals from the designation, the operating
viscosity from a lubricant at its temperature (:func:`bearinglab.lubrication.lubricant.
operating_viscosity`), the lubrication method that sets SKF's K_rs, and seed 003's
equivalent load P (which the seed does not define: ISO 281:2007 Table 3 through
:func:`bearinglab.ratings.equivalent_dynamic_load` for ball bearings). Inputs in SI.
"""

from __future__ import annotations

import math

from ..errors import InputError, positive_number
from .bearing import FrictionBearing
from .skf_constants import K_RS

#: Seals as the friction models see them: none, non-contact shields (no moment), contact.
SEALS = ("none", "shields", "contact")
#: Most viscous lubricant accepted [m^2/s] (1e6 mm^2/s).
MAX_VISCOSITY = 1.0


def check_speed(shaft_speed) -> float:
    """A speed of the rotating ring [rad/s], finite and >= 0."""
    return positive_number("shaft_speed", shaft_speed, "a finite speed >= 0 [rad/s]", zero=True)


def check_load(name: str, value) -> float:
    """A load [N], finite and >= 0."""
    return positive_number(name, value, "a finite load >= 0 [N]", zero=True)


def seals_of(bearing: FrictionBearing, seals: str | None) -> str:
    """The seals: given, or from the designation's closures (2RS: contact; 2Z: shields)."""
    if seals is not None:
        if seals not in SEALS:
            raise InputError("seals", seals, "one of " + ", ".join(SEALS))
        return seals
    if bearing.closures in ("seal", "2seals"):
        return "contact"
    if bearing.closures in ("shield", "2shields"):
        return "shields"
    return "none"


def viscosity_of(viscosity, lubricant, temperature) -> tuple[float | None, str | None, object]:
    """(operating viscosity [m^2/s] or None, how it was found, the Lubricant or None)."""
    from ..lubrication.lubricant import operating_viscosity

    lub = None
    if lubricant is not None:
        from ..lubrication.lubricant import LUBRICANTS, Lubricant

        if isinstance(lubricant, str) and lubricant in LUBRICANTS:
            lub = LUBRICANTS[lubricant]
        elif isinstance(lubricant, Lubricant):
            lub = lubricant
        else:
            raise InputError(
                "lubricant", lubricant, "one of " + ", ".join(LUBRICANTS) + ", or a Lubricant"
            )
    if viscosity is not None:
        nu = positive_number(
            "viscosity", viscosity, f"a kinematic viscosity in (0, {MAX_VISCOSITY:g}] m^2/s"
        )
        if nu > MAX_VISCOSITY:
            raise InputError(
                "viscosity", viscosity, f"a kinematic viscosity in (0, {MAX_VISCOSITY:g}] m^2/s"
            )
        if temperature is not None:
            raise InputError(
                "temperature",
                temperature,
                "no temperature with a given "
                "viscosity (that is already the viscosity at the operating "
                "temperature)",
            )
        return nu, "given", lub
    if lub is None:
        if temperature is not None:
            raise InputError(
                "lubricant", None, "the lubricant whose viscosity the temperature applies to"
            )
        return None, None, None
    nu, how = operating_viscosity(lub, temperature)
    return nu, how, lub


def lubrication_of(lubrication: str | None, lub) -> tuple[str, str]:
    """The lubrication method (sets K_rs) and why: given; grease for a grease; oil-jet for an
    oil; grease when only a viscosity is known (the K_rs of grease and oil-air)."""
    if lubrication is not None:
        if lubrication not in K_RS:
            raise InputError("lubrication", lubrication, "one of " + ", ".join(K_RS))
        return lubrication, "given"
    if lub is None:
        return "grease", "default with a viscosity alone: K_rs of grease and oil-air"
    if "grease" in lub.name.lower():
        return "grease", f"default for a grease: {lub.name}"
    return "oil-jet", f"default for an oil: {lub.name}"


def equivalent_load_of(
    bearing: FrictionBearing, kind: str, fr: float, fa: float, given: float | None
) -> tuple[float, str]:
    """P for seed 003's model, which does not say how P is formed: given; F_r without axial
    load; ISO 281 Table 3 from the geometry of a ball bearing or of a roller bearing whose
    is tapered (its contact angle); P_a = F_a for a thrust ball bearing
    under axial load alone."""
    if given is not None:
        return check_load("equivalent_load", given), "given"
    if fa == 0.0:
        return fr, "P = F_r (no axial load)"
    ball = bearing.ball_bearing
    if ball is None and bearing.roller_bearing is not None and fr > 0:
        ball = bearing.roller_bearing  # ISO 281's roller rows of Table 3
    if ball is not None and ball.bearing_type in (
        "radial_ball",
        "angular_contact_ball",
        "thrust_ball",
        "tapered_roller",
    ):
        from ..ratings import equivalent_dynamic_load

        p, f = equivalent_dynamic_load(ball, fr, fa)
        return float(p), (
            f"ISO 281 Table 3 from the geometry (bearinglab.life): X = "
            f"{f.x:.4g}, Y = {f.y:.4g}, e = {f.e:.4g}"
        )
    if kind == "thrust_ball" and fr == 0.0:
        return fa, "ISO 281 thrust ball bearing: P_a = F_a"
    raise InputError(
        "axial_load",
        fa,
        "0, or the equivalent load P given",
        f"no equivalent-load rule is built in for {kind} under an axial load "
        "here; give P (`equivalent_load`)",
    )


def check_seal_constants(seal_constants, seals: str) -> tuple[float, float, float] | None:
    """(K_S1, K_S2, beta) checked, or None; they need contact seals."""
    if seal_constants is None:
        return None
    try:
        ks1, ks2, beta = (float(v) for v in seal_constants)
    except (TypeError, ValueError):
        raise InputError(
            "seal_constants", seal_constants, "three numbers K_S1, K_S2, beta >= 0 (SKF units)"
        ) from None
    if not all(math.isfinite(v) and v >= 0 for v in (ks1, ks2, beta)):
        raise InputError(
            "seal_constants", seal_constants, "three numbers K_S1, K_S2, beta >= 0 (SKF units)"
        )
    if seals != "contact":
        raise InputError(
            "seal_constants",
            seal_constants,
            "seal constants only with contact seals",
            f"the seals are '{seals}' (give seals='contact')",
        )
    return ks1, ks2, beta
