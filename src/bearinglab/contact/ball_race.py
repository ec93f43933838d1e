"""Hertz contacts of a ball with both raceways of a :class:`~bearinglab.geometry.BallBearing`.

Layer 3 (analysis): takes the bearing model and a ball load and returns a result object;
all physics is in :mod:`bearinglab.contact.hertz` and :mod:`bearinglab.geometry`.
Source: Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., 2007,
ch. 6 (ball-raceway contacts, K_n for a ball between both races).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..geometry import BallBearing
from ..materials import effective_modulus
from . import hertz


@dataclass(frozen=True)
class BallContacts:
    """Inner and outer Hertz contacts of one ball (arrays when the load is an array).

    Attributes: the inputs (bearing, load [N], contact_angle [rad], method), ``inner``
    and ``outer`` (:class:`~bearinglab.contact.hertz.PointContact`), their
    load-deflection constants ``inner_constant``, ``outer_constant`` and the series
    constant ``ball_constant`` K_n [N/m^1.5] of the ball between both races.
    """

    bearing: BallBearing
    load: np.ndarray
    contact_angle: float
    method: str
    inner: hertz.PointContact
    outer: hertz.PointContact
    inner_constant: float
    outer_constant: float
    ball_constant: float

    @property
    def total_approach(self):
        """Approach of the two races along the contact line, inner + outer [m]."""
        return self.inner.approach + self.outer.approach

    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units (keys carry the unit)."""
        def one(c: hertz.PointContact, constant: float) -> dict:
            return {
                "semi_major_mm": _num(c.semi_major * 1e3),
                "semi_minor_mm": _num(c.semi_minor * 1e3),
                "max_pressure_gpa": _num(c.max_pressure / 1e9),
                "mean_pressure_gpa": _num(c.mean_pressure / 1e9),
                "approach_um": _num(c.approach * 1e6),
                "ellipticity": _num(c.ellipticity),
                "stiffness_n_per_um": _num(c.stiffness * 1e-6),
                "load_deflection_constant_n_per_m1_5": float(constant),
            }
        return {
            "ball_load_n": _num(self.load),
            "contact_angle_deg": float(np.degrees(self.contact_angle)),
            "method": self.method,
            "inner": one(self.inner, self.inner_constant),
            "outer": one(self.outer, self.outer_constant),
            "total_approach_um": _num(self.total_approach * 1e6),
            "ball_load_deflection_constant_n_per_m1_5": float(self.ball_constant),
        }

    def plot(self, axes=None):
        """Pressure and approach against load, and the contact ellipses; returns (fig, axes)."""
        from ..plotting import ball_contacts_figure

        return ball_contacts_figure(self, axes)

    def to_pandas(self) -> pd.DataFrame:
        """One row per (contact, load), engineering units."""
        rows = []
        loads = np.atleast_1d(self.load)
        for race, c in (("inner", self.inner), ("outer", self.outer)):
            columns = {"semi_major_mm": c.semi_major * 1e3, "semi_minor_mm": c.semi_minor * 1e3,
                       "max_pressure_gpa": c.max_pressure / 1e9, "approach_um": c.approach * 1e6,
                       "ellipticity": c.ellipticity, "stiffness_n_per_um": c.stiffness * 1e-6}
            columns = {k: np.broadcast_to(v, loads.shape) for k, v in columns.items()}
            for i, q in enumerate(loads):
                rows.append({"contact": race, "ball_load_n": q,
                             **{k: float(v[i]) for k, v in columns.items()}})
        return pd.DataFrame(rows)


def _num(value):
    arr = np.asarray(value, dtype=float)
    return float(arr) if arr.ndim == 0 else arr.tolist()


def load_deflection_constants(bearing: BallBearing, contact_angle: float | None = None,
                              method: hertz.Method = "exact"):
    """(K_i, K_o, K_n): Q = K delta^1.5 for the inner, outer and both contacts of a ball.

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    contact_angle : float, optional
        Operating contact angle [rad]; the bearing's nominal angle by default.
    method : {"exact", "hamrock_brewe"}
        How the ellipticity and elliptic integrals are obtained.

    Returns
    -------
    tuple of float
        K_i, K_o, K_n [N/m^1.5].
    """
    e_prime = effective_modulus(bearing.ball_material, bearing.ring_material)
    k_i = float(hertz.load_deflection_constant(*bearing.contact_radii("inner", contact_angle),
                                               e_prime, method))
    k_o = float(hertz.load_deflection_constant(*bearing.contact_radii("outer", contact_angle),
                                               e_prime, method))
    return k_i, k_o, float(hertz.series_constant(k_i, k_o))


def ball_contacts(bearing: BallBearing, ball_load, contact_angle: float | None = None,
                  method: hertz.Method = "exact") -> BallContacts:
    """Hertz contacts of one ball loaded by Q against the inner and outer raceway.

    Parameters
    ----------
    bearing : BallBearing
        The bearing (geometry and materials).
    ball_load : float or array
        Normal ball load Q [N], >= 0.
    contact_angle : float, optional
        Operating contact angle [rad]; the bearing's nominal angle by default.
    method : {"exact", "hamrock_brewe"}
        How the ellipticity and elliptic integrals are obtained.

    >>> from bearinglab.geometry import BallBearing
    >>> b = BallBearing(ball_count=9, ball_diameter=12.7e-3, pitch_diameter=65e-3)
    >>> r = ball_contacts(b, 4000.0)
    >>> round(float(r.inner.max_pressure) / 1e9, 2), round(float(r.outer.max_pressure) / 1e9, 2)
    (2.98, 2.49)
    """
    alpha = bearing.contact_angle if contact_angle is None else float(contact_angle)
    e_prime = effective_modulus(bearing.ball_material, bearing.ring_material)
    inner = hertz.point_contact(ball_load, *bearing.contact_radii("inner", alpha), e_prime, method)
    outer = hertz.point_contact(ball_load, *bearing.contact_radii("outer", alpha), e_prime, method)
    k_i, k_o, k_n = load_deflection_constants(bearing, alpha, method)
    return BallContacts(bearing, inner.load, alpha, method, inner, outer, k_i, k_o, k_n)
