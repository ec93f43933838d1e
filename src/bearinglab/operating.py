"""Operating conditions of a bearing (layer 2 model object).

Loads act on the inner ring (docs/conventions.md): a radial load of magnitude F_r acting
in the direction ``radial_load_angle`` (from +x towards +y; -90 deg = straight down),
an axial load along +z, and either a tilting moment or an imposed misalignment (tilt) of
the inner ring; the outer ring is fixed but may be given an imposed misalignment.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import InputError


def _finite(name: str, value: float, allowed: str = "a finite value") -> float:
    if isinstance(value, bool) or not (
        isinstance(value, (int, float, np.floating, np.integer)) and math.isfinite(value)
    ):
        raise InputError(name, value, allowed)
    return float(value)


def speed_error(shaft_speed, allowed: str, hint: str = "") -> InputError:
    """An error on a shaft speed [rad/s], its value and range in rpm: the unit users give a
    speed in (``speed_rpm``, ``--speed-rpm``), so an rpm input is never reported in rad/s.
    Named ``shaft_speed``, as the check of :func:`bearinglab.quasistatic.check_speed`.

    >>> e = speed_error(-math.pi, "a speed >= 0 rpm")
    >>> str(e), e.unit
    ('shaft_speed = -30.0 is not allowed: expected a speed >= 0 rpm', 'rpm')
    """
    try:
        value = float(f"{float(shaft_speed) * 30.0 / math.pi:.6g}")
    except (TypeError, ValueError):
        return InputError("shaft_speed", shaft_speed, allowed, hint)
    return InputError("shaft_speed", value, allowed, hint, unit="rpm")


@dataclass(frozen=True)
class OperatingCondition:
    """Loads, speed and imposed misalignments.

    Parameters
    ----------
    radial_load : float
        Radial load magnitude F_r on the inner ring [N], >= 0.
    radial_load_angle : float
        Direction in which the radial load acts, from +x towards +y [rad].
    axial_load : float
        Axial load F_a on the inner ring along +z [N].
    moment : tuple of float or None
        Tilting moment (M_x, M_y) on the inner ring [N m]; None means the inner ring's tilt
        is imposed instead (``misalignment``).
    misalignment : tuple of float
        Imposed tilt (about x, about y) of the inner ring when ``moment`` is None [rad].
    outer_misalignment : tuple of float
        Imposed tilt (about x, about y) of the outer ring [rad].
    shaft_speed : float
        Inner-ring speed [rad/s], >= 0 (outer ring fixed).

    Examples
    --------
    >>> OperatingCondition(radial_load=500.0).load_vector()[:3].round(6).tolist()
    [0.0, -500.0, 0.0]
    """

    radial_load: float = 0.0
    radial_load_angle: float = -0.5 * math.pi
    axial_load: float = 0.0
    moment: tuple[float, float] | None = None
    misalignment: tuple[float, float] = (0.0, 0.0)
    outer_misalignment: tuple[float, float] = (0.0, 0.0)
    shaft_speed: float = 0.0

    def __post_init__(self) -> None:
        if _finite("radial_load", self.radial_load, "a load >= 0 [N]") < 0:
            raise InputError("radial_load", self.radial_load, "a load >= 0 [N]")
        _finite("radial_load_angle", self.radial_load_angle)
        _finite("axial_load", self.axial_load, "a finite load [N]")
        if not isinstance(self.shaft_speed, bool) and isinstance(
            self.shaft_speed, (int, float, np.floating, np.integer)
        ):
            if not (math.isfinite(self.shaft_speed) and self.shaft_speed >= 0):
                raise speed_error(self.shaft_speed, "a finite speed >= 0 rpm")
        else:
            _finite("shaft_speed", self.shaft_speed, "a finite speed >= 0 (rad/s)")
        for name in ("misalignment", "outer_misalignment") + (
            ("moment",) if self.moment is not None else ()
        ):
            pair = getattr(self, name)
            if len(pair) != 2:
                raise InputError(name, pair, "a pair (about x, about y)")
            for v in pair:
                _finite(name, v)
        for name in ("misalignment", "outer_misalignment"):
            if max(abs(v) for v in getattr(self, name)) > 0.02:
                raise InputError(
                    name, getattr(self, name), "tilts within +-20 mrad (the small-rotation model)"
                )

    def load_vector(self) -> np.ndarray:
        """(F_x, F_y, F_z, M_x, M_y) applied to the inner ring [N, N m]."""
        m = self.moment or (0.0, 0.0)
        return np.array(
            [
                self.radial_load * math.cos(self.radial_load_angle),
                self.radial_load * math.sin(self.radial_load_angle),
                self.axial_load,
                m[0],
                m[1],
            ]
        )

    @classmethod
    def at_rpm(cls, speed_rpm: float, **loads) -> OperatingCondition:
        """The condition with the shaft speed given in rpm, ``speed_rpm`` (every other
        field as for the class, SI), so that a speed in rpm cannot pass for rad/s.

        Parameters
        ----------
        speed_rpm : float
            Shaft speed [rpm], finite and >= 0.
        **loads
            The other fields of the class (``radial_load`` [N], ``axial_load`` [N], ...), in SI;
            not ``shaft_speed``.

        Examples
        --------
        >>> round(OperatingCondition.at_rpm(1797, radial_load=500.0).shaft_speed, 4)
        188.1814
        """
        if "shaft_speed" in loads:
            raise InputError(
                "shaft_speed",
                loads["shaft_speed"],
                "not given with `speed_rpm` (one speed, in rpm)",
            )
        if _finite("speed_rpm", speed_rpm, "a speed >= 0 [rpm]") < 0:
            raise InputError("speed_rpm", speed_rpm, "a speed >= 0 [rpm]")
        return cls(shaft_speed=speed_rpm * math.pi / 30.0, **loads)

    @property
    def speed_rpm(self) -> float:
        """The shaft speed [rpm]."""
        return self.shaft_speed * 30.0 / math.pi

    @property
    def tilt_free(self) -> bool:
        """True when the inner ring's tilt is solved for (a moment is given)."""
        return self.moment is not None
