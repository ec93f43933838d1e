"""Sinusoidal waviness of a raceway or a ball, and ball-size errors (layer 2).

Waviness (seed 003, section 4, eqs. 9-16). The seed writes the waviness of a raceway at a
ball's contact as P = A_max sin(2 pi s / lambda + theta_0) (eq. 9) with lambda =
2 pi R / N_w (eq. 10), s the arc length from a reference point on the ring: with the
ring-frame angle theta = s / R this is P = A_max sin(N_w theta + theta_0). The angle of
ball j in each ring's frame is 2 pi (j - 1)/N_b + (omega_c - omega_i) t on the turning
inner ring (eq. 14) and 2 pi (j - 1)/N_b + omega_c t on the fixed outer ring (eq. 15).
P is a deviation of the raceway *radius*: the ball's approach changes by P_k = P_i - P_o
(eq. 16, entering eq. 17 as delta_k = [delta_r cos(theta_k) - (D_w - D_wk) + P_k]_+), so a
positive P on the inner race (radius larger) presses the ball, a positive P on the outer
race (radius larger) frees it. Here, as the issue asks, the form is written with a
cosine,

    r(theta) = R + A cos(q theta + phase),        (phase = theta_0 - pi/2 for eq. 9's sine)

A the amplitude (half the peak-to-peak height, the seed's A_max), q = N_w the number of
waves round the circumference; several orders are several objects. The seed's "first-order
sinusoid" means one harmonic, not q = 1.

A ball's waviness is the same form on the ball, r_b(phi) = D_w/2 + A cos(q phi + phase),
phi the spin angle along the great circle the contacts trace (measured from a mark on the
ball, the outer contact at phi, the inner one diametrically opposite at phi + pi). Its
diameter along the contact line is D_w + A [cos(q phi + phase) + cos(q phi + q pi + phase)]:
2 A cos(q phi + phase) for even q, unchanged for odd q.

Ball-size errors (seed 003, section 4, eqs. 7-8): D_wj - D_w of each ball; they add to the
approach of both contacts of ball j (eq. 7: delta_k = delta_r cos(theta_k) - (D_w - D_wk)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import InputError

Race = Literal["inner", "outer", "ball"]
RACES = ("inner", "outer", "ball")


def finite(name: str, value, allowed: str = "a finite value") -> float:
    """``value`` as a float, or InputError naming ``name``."""
    if (
        isinstance(value, bool)
        or not isinstance(value, (int, float, np.integer, np.floating))
        or not math.isfinite(value)
    ):
        raise InputError(name, value, allowed)
    return float(value)


def index(name: str, value, allowed: str = "an integer >= 0", minimum: int = 0) -> int:
    """``value`` as an int >= ``minimum``, or InputError naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise InputError(name, value, allowed)
    return int(value)


def generator(seed) -> np.random.Generator:
    """A NumPy Generator from an int seed (or the Generator itself)."""
    if isinstance(seed, np.random.Generator):
        return seed
    return np.random.default_rng(index("seed", seed, "an integer >= 0 or a numpy Generator"))


@dataclass(frozen=True)
class Waviness:
    """Sinusoidal form error r(theta) = A cos(q theta + phase) of a raceway or a ball.

    Seed 003, section 4, eqs. 9-16 (module docstring: the seed's sine with phase theta_0 is
    this cosine with phase = theta_0 - pi/2).

    Parameters
    ----------
    race : {"inner", "outer", "ball"}
        The surface that is wavy [-].
    order : int
        q, number of waves round the circumference (the seed's N_w), >= 1 [-].
    amplitude : float
        A, radial deviation amplitude (half the peak-to-peak), >= 0 [m]. Positive r is a
        larger radius: more approach on the inner race and the ball, less on the outer.
    phase : float
        Phase of the wave [rad]. Raceways: theta is the angle in the ring's own frame from
        +x towards +y at time 0 (the inner ring turns with the shaft, the outer is fixed).
        Balls: theta is the ball's spin angle phi, 0 when the mark faces the outer race at
        time 0.
    ball : int or None
        Ball waviness only: the index of the wavy ball (ball 0 is at psi = 0 at time 0,
        docs/conventions.md); None means every ball, all with the same phase [-].

    Examples
    --------
    >>> w = Waviness("outer", order=8, amplitude=0.1e-6)
    >>> round(float(w.radius_deviation(math.pi / 8)) * 1e6, 3)    # a trough
    -0.1
    """

    race: Race
    order: int
    amplitude: float
    phase: float = 0.0
    ball: int | None = None

    def __post_init__(self) -> None:
        if self.race not in RACES:
            raise InputError("race", self.race, f"one of {RACES}")
        index("order", self.order, "an integer >= 1 (waves round the circumference)", 1)
        if finite("amplitude", self.amplitude, "a length >= 0 [m]") < 0:
            raise InputError("amplitude", self.amplitude, "a length >= 0 [m]")
        finite("phase", self.phase, "a finite angle [rad]")
        if self.ball is not None:
            if self.race != "ball":
                raise InputError(
                    "ball",
                    self.ball,
                    "None for a raceway's waviness",
                    "a ball index applies to race='ball' only",
                )
            index("ball", self.ball, "a ball index >= 0 or None (every ball)")

    def radius_deviation(self, angle):
        """r - R = A cos(q angle + phase) at ``angle`` [m] (ring-frame angle or spin angle,
        [rad]); vectorised.

        Parameters
        ----------
        angle : array_like
            Raceways: the angle theta in the ring's own frame [rad]; balls: the spin angle phi
            [rad].

        Returns
        -------
        numpy.ndarray or float
            r - R [m], of the shape of ``angle``.
        """
        return self.amplitude * np.cos(self.order * np.asarray(angle, float) + self.phase)

    def check(self, bearing) -> None:
        """Refuse a ball index beyond the ball count of ``bearing``.

        Parameters
        ----------
        bearing : BallBearing
            The bearing: a ball index must be in [0, Z - 1].
        """
        if self.ball is not None and self.ball >= bearing.ball_count:
            raise InputError("ball", self.ball, f"a ball index in [0, {bearing.ball_count - 1}]")

    def to_dict(self) -> dict:
        """JSON-ready description in engineering units."""
        out = {
            "race": self.race,
            "order": int(self.order),
            "amplitude_um": self.amplitude * 1e6,
            "phase_deg": math.degrees(self.phase),
        }
        if self.race == "ball":
            out["ball"] = self.ball
        return out


@dataclass(frozen=True)
class BallSizeErrors:
    """Diameter errors D_wj - D_w of each ball [m] (seed 003, section 4, eqs. 7-8).

    Parameters
    ----------
    errors : array (Z,)
        D_wj - D_w of ball j; positive for a ball larger than nominal [m].

    Examples
    --------
    >>> e = BallSizeErrors.random(7, 2e-6, seed=1)
    >>> bool(np.all(np.abs(e.errors) <= 1e-6)), e == BallSizeErrors.random(7, 2e-6, seed=1)
    (True, True)
    """

    errors: np.ndarray

    def __post_init__(self) -> None:
        e = np.asarray(self.errors, dtype=float) if not isinstance(self.errors, str) else None
        if e is None or e.ndim != 1 or e.size == 0 or not np.all(np.isfinite(e)):
            raise InputError("errors", self.errors, "a 1-D array of finite D_wj - D_w [m]")
        e = e.copy()
        e.flags.writeable = False
        object.__setattr__(self, "errors", e)

    def __eq__(self, other) -> bool:
        return isinstance(other, BallSizeErrors) and np.array_equal(self.errors, other.errors)

    __hash__ = None

    @classmethod
    def random(cls, ball_count: int, band, seed=None) -> BallSizeErrors:
        """Errors drawn uniformly within a band, reproducible from ``seed``.

        Seed 003 (section 4, fig. 20) studies "ball-size error bands" of 1, 1.5, 2, 2.5 and
        3 um, drawn with MATLAB's random function, without printing the formula. The band
        is read here as the width of the interval the errors fill, i.e. the lot diameter
        variation (largest minus smallest ball, V_DwL of ISO 3290-1), centred on the
        nominal diameter so that the mean clearance is unchanged: a number ``band`` gives
        D_wj - D_w uniform in [-band/2, +band/2]. A pair ``(low, high)`` gives uniform in
        [low, high] instead (e.g. ``(0, band)`` for MATLAB's ``band * rand``).

        Parameters
        ----------
        ball_count : int
            Z, >= 1 [-].
        band : float or (float, float)
            Band width >= 0, or the interval (low, high) with low <= high [m].
        seed : int or numpy.random.Generator
            Random source; the same int gives the same errors. Required (no hidden global
            state): pass an int.
        """
        z = index("ball_count", ball_count, "an integer >= 1", 1)
        if seed is None:
            raise InputError(
                "seed",
                seed,
                "an integer >= 0 or a numpy Generator",
                "random errors must be reproducible",
            )
        rng = generator(seed)
        if isinstance(band, (tuple, list, np.ndarray)):
            if len(band) != 2:
                raise InputError("band", band, "a width [m] or a pair (low, high) [m]")
            low, high = (finite("band", v, "finite lengths [m]") for v in band)
            if low > high:
                raise InputError("band", band, "a pair (low, high) with low <= high [m]")
        else:
            width = finite("band", band, "a width >= 0 [m] or a pair (low, high)")
            if width < 0:
                raise InputError("band", band, "a width >= 0 [m]")
            low, high = -0.5 * width, 0.5 * width
        return cls(rng.uniform(low, high, z))

    def check(self, bearing) -> None:
        """Refuse a count that differs from the Z of ``bearing`` or errors beyond
        +-5 % D_w.

        Parameters
        ----------
        bearing : BallBearing
            The bearing: there must be one error per ball (Z values), each within +-5 % of its
            ball diameter D_w.
        """
        if self.errors.shape != (bearing.ball_count,):
            raise InputError(
                "errors", self.errors.tolist(), f"{bearing.ball_count} values (one per ball)"
            )
        if np.any(np.abs(self.errors) > 0.05 * bearing.ball_diameter):
            raise InputError("errors", self.errors.tolist(), "values within +-5 % of D_w [m]")

    @property
    def band(self) -> float:
        """Largest minus smallest error (the lot diameter variation) [m]."""
        return float(np.ptp(self.errors))

    def to_dict(self) -> dict:
        """JSON-ready description in um."""
        return {"ball_size_errors_um": (self.errors * 1e6).tolist(), "band_um": self.band * 1e6}
