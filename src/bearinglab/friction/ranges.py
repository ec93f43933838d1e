"""Plausible ranges of the SKF model's geometry constants R1, R2, S1, S2 (R3, S3), by
bearing type, and the check that refuses a constant outside them.

The constants are series values of SKF's table of geometry constants (catalogue 10000 EN,
chapter "Friction"; see :mod:`.skf_constants`) in SKF units (d_m mm, F N, n r/min, M N mm). A typed
exponent slip (3.9e-1 for 3.9e-7) is otherwise accepted and multiplies the rolling moment
by 10^6: a 6205 at 3000 rpm then loses 8 MW. Each range here is the smallest value of the
type's table / 10 to the largest x 10: every tabulated series lies inside by construction,
and an untabulated series should not differ from its neighbours by an order of magnitude
(the constants carry the series' internal geometry, which varies smoothly across series);
a value outside is an exponent or unit slip.

- Deep-groove ball bearings: :data:`.skf_constants.DEEP_GROOVE_CONSTANTS`, the shipped table.
- Angular-contact and four-point ball bearings: SKF's rows for the series 72 B, 73 B, 32 A,
  33 A, QJ 2, QJ 3, not shipped (:mod:`.skf_constants`). No stored source gives them; the envelope
  :data:`ANGULAR_CONTACT_TABLE` holds their orders of magnitude as recalled from the
  catalogue (unverified: only orders of magnitude are used, widened 10x each way). R3 and S3
  agree in order with the balls' centrifugal load, F_g = R3 d_m^4 n^2: a 7206's balls at
  the cage speed give Z m omega_c^2 D_pw / 2 = 3.2e-13 d_m^4 n^2 [N; mm, r/min]
  (tests/unit/test_cli_friction_life_inputs.py checks it against the range).
"""

from __future__ import annotations

from ..errors import InputError
from .skf_constants import DEEP_GROOVE_CONSTANTS, SkfGeometryConstants

#: Envelope (smallest, largest) of SKF's angular-contact and four-point rows, SKF units
#: (orders of magnitude, secondary; see the module docstring).
ANGULAR_CONTACT_TABLE = {
    "r1": (4.5e-7, 6.4e-7),
    "r2": (1.4, 2.5),
    "r3": (7.8e-13, 1.9e-12),
    "s1": (1.3e-2, 2.8e-2),
    "s2": (0.68, 1.0),
    "s3": (7.8e-13, 1.9e-12),
}
#: How far outside the table a constant may lie [-]: an order of magnitude either way.
MARGIN = 10.0
_WHAT = {
    "radial_ball": "a deep-groove ball bearing",
    "angular_contact_ball": "an angular-contact ball bearing",
    "four_point_contact_ball": "a four-point contact ball bearing",
}


def _widened(table: dict) -> dict:
    return {k: (low / MARGIN, high * MARGIN) for k, (low, high) in table.items()}


#: Plausible range [low, high] of each constant by bearing type, SKF units.
PLAUSIBLE_CONSTANTS: dict[str, dict[str, tuple[float, float]]] = {
    "radial_ball": _widened(
        {
            k: (
                min(getattr(c, k) for c in DEEP_GROOVE_CONSTANTS.values()),
                max(getattr(c, k) for c in DEEP_GROOVE_CONSTANTS.values()),
            )
            for k in ("r1", "r2", "s1", "s2")
        }
    ),
    "angular_contact_ball": _widened(ANGULAR_CONTACT_TABLE),
    "four_point_contact_ball": _widened(ANGULAR_CONTACT_TABLE),
}


def check_constants(bearing_type: str, constants: SkfGeometryConstants) -> None:
    """Refuse geometry constants outside :data:`PLAUSIBLE_CONSTANTS` of ``bearing_type``:
    an :class:`InputError` of ``constants`` naming the constant, its value and the range.
    A constant not given (R3, S3 as None) is left to the model, which asks for it where
    it needs it; R3 and S3 of a deep-groove bearing are not checked (it has none).

    >>> from bearinglab.friction import deep_groove_constants
    >>> check_constants("radial_ball", deep_groove_constants("62")) is None
    True
    """
    if not isinstance(constants, SkfGeometryConstants):
        return  # the model refuses it, naming what it needs
    what = _WHAT.get(bearing_type, bearing_type)
    for name, (low, high) in PLAUSIBLE_CONSTANTS.get(bearing_type, {}).items():
        value = getattr(constants, name)
        if value is not None and not low <= value <= high:
            raise InputError(
                "constants",
                constants,
                f"{name.upper()} in [{low:.3g}, {high:.3g}] for {what}",
                f"{name.upper()} = {value:g} is beyond 1/10 to 10 times SKF's table "
                "values, in SKF units",
            )


def unused_constants(bearing_type: str, constants: SkfGeometryConstants) -> tuple[str, ...]:
    """The constants given that the model of ``bearing_type`` has no term for: R3 and S3
    of a deep-groove ball bearing (SKF's deep-groove G_rr, G_sl have no centrifugal load).

    >>> unused_constants("radial_ball", SkfGeometryConstants(4e-7, 1.7, 3e-3, 30, 1e-12, 1e-12))
    ('r3', 's3')
    """
    if bearing_type != "radial_ball":
        return ()
    return tuple(n for n in ("r3", "s3") if getattr(constants, n) is not None)
