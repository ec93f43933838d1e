"""Kinematic (pure-rolling) frequencies of a rolling bearing.

Source: seed 003, section "Коэффициенты частоты вибрации" (cage, outer race, inner race
and rolling-element factors per shaft revolution) and the ER-16K example of its dynamic
model section (eqs. 22-23: f_BPFO = (Z/2) f_r (1 - D_w/d_m cos alpha) and the ball
defect rate f_BPB = (d_m/D_w) f_r (1 - (D_w/d_m cos alpha)^2)); the general form for
either ring rotating is Harris & Kotzalas, *Essential Concepts of Bearing Technology*,
5th ed., 2007, ch. 7 (cage speed omega_c = [omega_i (1 - gamma) + omega_o (1 + gamma)]/2).

Two conventions for the ball frequency are in use and both are reported:
``bsf`` is the ball spin frequency (one spin revolution of the ball relative to the
cage), ``ball_defect`` = 2 bsf is the rate at which a ball defect strikes a race (it
meets the inner and the outer race once each per spin revolution). Some published
tables print 2 bsf under "ball spin" or "rolling element" (e.g. the CWRU bearing data
centre's table); the IMS/NASA table prints 1 bsf.

Assumptions: rigid bodies, no slip (seed 004 shows real lubricated bearings run slower:
see the slip model), contact angle constant around the bearing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import InputError
from .geometry import BallBearing
from .operating import speed_error

#: Names of the frequencies, in the order reports list them.
FREQUENCY_NAMES = ("ftf", "bpfo", "bpfi", "bsf", "ball_defect")
LONG_NAMES = {
    "shaft": "shaft rotation",
    "ftf": "cage (fundamental train)",
    "bpfo": "ball pass, outer race",
    "bpfi": "ball pass, inner race",
    "bsf": "ball spin (1x, one spin revolution)",
    "ball_defect": "ball defect (2x spin: strikes both races)",
}


#: The bearing's fields that pure rolling reads (the nominal contact angle: the
#: frequencies of a loaded bearing at its working angles are :mod:`bearinglab.quasistatic`'s).
KINEMATIC_FIELDS = ("ball_count", "ball_diameter", "pitch_diameter", "contact_angle")
#: The same fields of a roller bearing.
ROLLER_KINEMATIC_FIELDS = ("roller_count", "roller_diameter", "pitch_diameter", "contact_angle")
#: How the rolling-element frequencies are named for rollers: the key in ``orders`` (the
#: same for both kinds, so diagnosis code reads one family) -> the name in JSON and tables.
ROLLER_NAMES = {"ball_defect": "roller_defect"}
ROLLER_LONG_NAMES = {
    "bsf": "roller spin (1x, one spin revolution)",
    "ball_defect": "roller defect (2x spin: strikes both races)",
}


def _element(bearing) -> str:
    return getattr(bearing, "rolling_element", "ball")


def frequency_label(bearing, name: str) -> str:
    """The public name of frequency ``name`` (a key of FREQUENCY_NAMES) for ``bearing``:
    ``roller_defect`` stands for ``ball_defect`` of a roller bearing; the others (``bsf``,
    the rolling element's spin, included) are the same for both kinds.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing [-].
    name : str
        One of FREQUENCY_NAMES [-].

    Examples
    --------
    >>> from bearinglab.geometry import BallBearing
    >>> frequency_label(BallBearing(ball_count=9, ball_diameter=8e-3, pitch_diameter=39e-3),
    ...                 "ball_defect")
    'ball_defect'
    """
    if _element(bearing) == "roller":
        return ROLLER_NAMES.get(name, name)
    return name


def geometry_inputs(bearing: BallBearing) -> set[str]:
    """The fields of ``bearing`` its defect frequencies depend on: KINEMATIC_FIELDS (or
    ROLLER_KINEMATIC_FIELDS), and the bore and outside diameter when Z, D_w or d_m were
    estimated from them."""
    fields = ROLLER_KINEMATIC_FIELDS if _element(bearing) == "roller" else KINEMATIC_FIELDS
    used = set(fields)
    if any(getattr(bearing.sources.get(k), "kind", None) == "estimated" for k in fields[:3]):
        used |= {"bore", "outside_diameter"}
    return used


def frequency_orders(
    ball_count, ball_diameter, pitch_diameter, contact_angle=0.0, outer_rotating: bool = False
) -> dict:
    """Defect frequencies as orders of the rotating ring's speed (pure rolling).

    With gamma = D_w cos(alpha) / d_m, the inner ring turning and the outer fixed:
    FTF = (1 - gamma)/2, BPFO = Z (1 - gamma)/2, BPFI = Z (1 + gamma)/2,
    BSF = d_m/(2 D_w) (1 - gamma^2), ball defect = 2 BSF. With the outer ring turning
    instead the cage turns at (1 + gamma)/2 of it; the ball-pass and spin orders are
    unchanged (they depend on the relative speed of the rings).

    Parameters
    ----------
    ball_count : int or array
        Z [-].
    ball_diameter : float or array
        D_w [m] (any length unit, as long as it matches pitch_diameter).
    pitch_diameter : float or array
        d_m [m].
    contact_angle : float or array
        alpha [rad].
    outer_rotating : bool
        True if the outer ring turns and the inner ring is fixed.

    Examples
    --------
    >>> o = frequency_orders(9, 0.3126, 1.537)   # CWRU drive-end 6205, inches
    >>> [round(float(o[k]), 3) for k in ("ftf", "bpfo", "bpfi", "ball_defect")]
    [0.398, 3.585, 5.415, 4.713]
    """
    gamma = (
        np.asarray(ball_diameter, float) * np.cos(contact_angle) / np.asarray(pitch_diameter, float)
    )
    z = np.asarray(ball_count)
    ftf = 0.5 * (1.0 + gamma) if outer_rotating else 0.5 * (1.0 - gamma)
    bsf = (
        np.asarray(pitch_diameter, float)
        / (2.0 * np.asarray(ball_diameter, float))
        * (1.0 - gamma**2)
    )
    return {
        "ftf": ftf,
        "bpfo": 0.5 * z * (1.0 - gamma),
        "bpfi": 0.5 * z * (1.0 + gamma),
        "bsf": bsf,
        "ball_defect": 2.0 * bsf,
    }


@dataclass(frozen=True)
class DefectFrequencies:
    """Kinematic frequencies of a bearing at one speed.

    Attributes: ``bearing``, ``shaft_speed`` [rad/s] of the rotating ring,
    ``outer_rotating``, ``contact_angle`` [rad] used, and ``orders`` (dict of
    :data:`FREQUENCY_NAMES` -> order of the shaft speed). Use :meth:`hz` or the
    ``ftf_hz`` ... properties for frequencies in Hz.
    """

    bearing: BallBearing
    shaft_speed: float
    outer_rotating: bool
    contact_angle: float
    orders: dict

    @property
    def shaft_hz(self) -> float:
        """Rotating ring's frequency [Hz]."""
        return self.shaft_speed / (2.0 * math.pi)

    def hz(self, name: str) -> float:
        """Frequency ``name`` (one of FREQUENCY_NAMES or "shaft"; ``roller_defect`` for
        ``ball_defect``) [Hz]."""
        if name == "shaft":
            return self.shaft_hz
        name = {v: k for k, v in ROLLER_NAMES.items()}.get(name, name)
        if name not in self.orders:
            raise InputError("name", name, f"one of {('shaft',) + FREQUENCY_NAMES}")
        return float(self.orders[name]) * self.shaft_hz

    def to_dict(self) -> dict:
        """JSON-ready dict: ``<name>_hz`` and ``<name>_order`` for each frequency, and the
        geometry used (``ball_count``, ``ball_diameter_mm``, ``pitch_diameter_mm``,
        ``contact_angle_deg``, ``geometry_source``). A roller bearing's keys read "roller"
        for "ball" (``roller_count``, ``roller_diameter_mm``, ``roller_defect_hz``);
        ``bpfo_hz``, ``bpfi_hz``, ``bsf_hz``, ``ftf_hz`` are the same."""
        b = self.bearing
        element = _element(b)
        out = {
            "speed_rpm": self.shaft_hz * 60.0,
            "shaft_hz": self.shaft_hz,
            "outer_rotating": self.outer_rotating,
            f"{element}_count": int(b.element_count),
            f"{element}_diameter_mm": b.element_diameter * 1e3,
            "pitch_diameter_mm": b.pitch_diameter * 1e3,
            "contact_angle_deg": math.degrees(self.contact_angle),
            "geometry_source": b.geometry_source,
        }
        for name in FREQUENCY_NAMES:
            out[f"{frequency_label(b, name)}_hz"] = self.hz(name)
        for name in FREQUENCY_NAMES:
            out[f"{frequency_label(b, name)}_order"] = float(self.orders[name])
        return out

    def plot(self, harmonics: int = 3, ax=None):
        """Stem chart of the frequencies and harmonics; returns (fig, ax)."""
        from .plotting import frequencies_figure

        return frequencies_figure(self, ("shaft", *FREQUENCY_NAMES), harmonics, ax)

    def to_pandas(self):
        """Table: frequency, long name, order, Hz."""
        import pandas as pd

        roller = _element(self.bearing) == "roller"
        return pd.DataFrame(
            [
                {
                    "frequency": frequency_label(self.bearing, n),
                    "description": (ROLLER_LONG_NAMES if roller else LONG_NAMES).get(
                        n, LONG_NAMES[n]
                    ),
                    "order": float(self.orders[n]),
                    "hz": self.hz(n),
                }
                for n in FREQUENCY_NAMES
            ]
        )


def defect_frequencies(
    bearing: BallBearing,
    shaft_speed: float | None = None,
    *,
    speed_rpm: float | None = None,
    outer_rotating: bool = False,
    contact_angle: float | None = None,
) -> DefectFrequencies:
    """Kinematic defect frequencies of ``bearing`` with one ring turning at ``shaft_speed``.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        Geometry (Z, D_w or D_we, d_m, nominal contact angle; for a tapered roller bearing
        the mean roller diameter and the cup angle).
    shaft_speed : float
        Speed of the rotating ring [rad/s], >= 0; or give ``speed_rpm`` instead.
    speed_rpm : float, optional
        The same speed in rpm (keyword only, so that rpm cannot pass for rad/s) [rpm].
    outer_rotating : bool
        True if the outer ring turns and the inner ring is fixed.
    contact_angle : float, optional
        Contact angle to use instead of the nominal one [rad].

    Examples
    --------
    >>> from bearinglab.geometry import BallBearing
    >>> er16k = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=38.51e-3)
    >>> f = defect_frequencies(er16k, 1750 * 2 * math.pi / 60)
    >>> round(f.hz("bpfo"), 2), round(f.hz("ball_defect"), 2)   # seed 003: 104.19, 135.5
    (104.19, 135.45)
    >>> round(defect_frequencies(er16k, speed_rpm=1750).hz("bpfo"), 2)
    104.19
    """
    if (shaft_speed is None) == (speed_rpm is None):
        raise InputError(
            "shaft_speed",
            shaft_speed,
            "a speed [rad/s], or speed_rpm= [rpm] instead (exactly one of them)",
        )
    if speed_rpm is not None:
        if not (
            isinstance(speed_rpm, (int, float, np.floating))
            and math.isfinite(speed_rpm)
            and speed_rpm >= 0
        ):
            raise InputError("speed_rpm", speed_rpm, "a speed >= 0 [rpm]")
        shaft_speed = speed_rpm * math.pi / 30.0
    if not (
        isinstance(shaft_speed, (int, float, np.floating))
        and math.isfinite(shaft_speed)
        and shaft_speed >= 0
    ):
        raise speed_error(shaft_speed, "a finite speed >= 0 rpm")
    alpha = bearing.contact_angle if contact_angle is None else float(contact_angle)
    if not 0.0 <= alpha <= 0.5 * math.pi:
        raise InputError("contact_angle", contact_angle, "an angle in [0, 90] degrees")
    orders = {
        k: float(v)
        for k, v in frequency_orders(
            bearing.element_count,
            bearing.element_diameter,
            bearing.pitch_diameter,
            alpha,
            outer_rotating,
        ).items()
    }
    return DefectFrequencies(bearing, float(shaft_speed), outer_rotating, alpha, orders)
