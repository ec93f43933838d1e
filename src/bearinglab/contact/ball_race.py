"""Hertz contacts of a ball with both raceways of a :class:`~bearinglab.geometry.BallBearing`.

Layer 3 (analysis): takes the bearing model and a ball load and returns a result object;
all physics is in :mod:`bearinglab.contact.hertz` and :mod:`bearinglab.geometry`.
Source: Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., 2007,
ch. 6 (ball-raceway contacts, K_n for a ball between both races).

Validity: Hertz theory assumes the contact ellipse lies inside the groove.  The result
warns (``warnings``, also in ``to_dict()``) when the ellipse runs over the groove
shoulder, by the criterion of the load-distribution model (:mod:`bearinglab.quasistatic`):
|alpha - alpha_g| + a/(f D_w) > arccos(1 - h/(f D_w)), with a the semi-major axis (across
the groove), f D_w the groove radius, h = BallBearing.shoulder_depth() the groove depth (an
estimate, see :data:`bearinglab.geometry.GROOVE_DEPTH_RATIO`) and alpha_g the direction of
the groove bottom: 0 for radial rings, 90 deg for the washers of a thrust bearing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

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
    def warnings(self) -> list[str]:
        """Validity warnings: a contact ellipse that runs over its groove shoulder (see the
        module docstring for the criterion), and a pressure above the 4200 MPa at which
        ISO 76 puts a permanent deformation of 1e-4 D_w (the static rating's criterion)."""
        from ..ratings.tables import STATIC_CONTACT_STRESS

        out = []
        for race, c in (("inner", self.inner), ("outer", self.outer)):
            peak = float(np.max(c.max_pressure))
            if peak > STATIC_CONTACT_STRESS:
                out.append(
                    f"{race} contact: p_max = {peak / 1e6:.4g} MPa is above the "
                    f"{STATIC_CONTACT_STRESS / 1e6:.4g} MPa at which ISO 76 puts a permanent "
                    "deformation of 1e-4 D_w (the load is past the static rating)"
                )
        b = self.bearing
        axis = 0.5 * math.pi if b.is_thrust else 0.0
        loads = np.broadcast_to(np.asarray(self.load, dtype=float), np.shape(self.inner.semi_major))
        for race, c, f in (
            ("inner", self.inner, b.inner_groove_factor),
            ("outer", self.outer, b.outer_groove_factor),
        ):
            radius = f * b.ball_diameter
            side = 1 if self.contact_angle >= 0 else -1
            shoulder = b.shoulder_angle(race, side)
            a = np.asarray(c.semi_major, dtype=float)
            reach = abs(self.contact_angle - axis) + a / radius
            angle_text = "|90 deg - alpha|" if b.is_thrust else "|alpha|"
            over = (loads > 0) & (reach > shoulder)
            if np.any(over):
                i = np.flatnonzero(over.ravel())[np.argmin(loads.ravel()[over.ravel()])]
                out.append(
                    f"{race} contact: the contact ellipse runs over the groove shoulder at "
                    f"Q = {loads.ravel()[i]:.4g} N (half-length a = {a.ravel()[i] * 1e3:.3g} mm: "
                    f"{angle_text} + a/(f D_w) = {math.degrees(reach.ravel()[i]):.3g} deg > "
                    f"shoulder angle {math.degrees(shoulder):.3g} deg, groove depth "
                    f"{b.shoulder_depth(side) / b.ball_diameter:g} D_w assumed); Hertz results are "
                    "not valid there"
                )
        return out

    @property
    def total_approach(self):
        """Approach of the two races along the contact line, inner + outer [m]."""
        return self.inner.approach + self.outer.approach

    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units (keys carry the unit): the geometry used
        (``ball_count``, ``ball_diameter_mm``, ``pitch_diameter_mm``, ``contact_angle_deg``,
        ``geometry_source``), ``inner`` and ``outer`` contacts and ``warnings``."""

        def one(c: hertz.PointContact, constant: float) -> dict:
            return {
                "semi_major_mm": _num(c.semi_major * 1e3),
                "semi_minor_mm": _num(c.semi_minor * 1e3),
                "max_pressure_gpa": _num(c.max_pressure / 1e9),
                "mean_pressure_gpa": _num(c.mean_pressure / 1e9),
                "approach_um": _num(c.approach * 1e6),
                "ellipticity": _num(c.ellipticity),
                "stiffness_n_per_um": _num(c.stiffness * 1e-6),
                "load_deflection_constant_n_per_um1_5": float(constant) * 1e-9,
            }

        b = self.bearing
        return {
            "ball_load_n": _num(self.load),
            "ball_count": int(b.ball_count),
            "ball_diameter_mm": b.ball_diameter * 1e3,
            "pitch_diameter_mm": b.pitch_diameter * 1e3,
            "contact_angle_deg": float(np.degrees(self.contact_angle)),
            "geometry_source": b.geometry_source,
            "method": self.method,
            "inner": one(self.inner, self.inner_constant),
            "outer": one(self.outer, self.outer_constant),
            "total_approach_um": _num(self.total_approach * 1e6),
            "ball_load_deflection_constant_n_per_um1_5": float(self.ball_constant) * 1e-9,
            "warnings": self.warnings,
        }

    def plot(self, axes=None):
        """Pressure and approach against load, and the contact ellipses; returns (fig, axes)."""
        from ..plotting import ball_contacts_figure

        q_max = float(np.max(self.load))
        curve = ball_contacts(
            self.bearing, np.linspace(0.0, q_max, 121), self.contact_angle, self.method
        )
        final = ball_contacts(self.bearing, q_max, self.contact_angle, self.method)
        return ball_contacts_figure(curve, final, axes)

    def to_pandas(self):
        """One row per (contact, load), engineering units."""
        import pandas as pd

        rows = []
        loads = np.atleast_1d(self.load)
        for race, c in (("inner", self.inner), ("outer", self.outer)):
            columns = {
                "semi_major_mm": c.semi_major * 1e3,
                "semi_minor_mm": c.semi_minor * 1e3,
                "max_pressure_gpa": c.max_pressure / 1e9,
                "approach_um": c.approach * 1e6,
                "ellipticity": c.ellipticity,
                "stiffness_n_per_um": c.stiffness * 1e-6,
            }
            columns = {k: np.broadcast_to(v, loads.shape) for k, v in columns.items()}
            for i, q in enumerate(loads):
                rows.append(
                    {
                        "contact": race,
                        "ball_load_n": q,
                        **{k: float(v[i]) for k, v in columns.items()},
                    }
                )
        return pd.DataFrame(rows)


def _num(value):
    arr = np.asarray(value, dtype=float)
    return float(arr) if arr.ndim == 0 else arr.tolist()


def load_deflection_constants(
    bearing: BallBearing, contact_angle: float | None = None, method: hertz.Method = "exact"
):
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
    k_i = float(
        hertz.load_deflection_constant(
            *bearing.contact_radii("inner", contact_angle), e_prime, method
        )
    )
    k_o = float(
        hertz.load_deflection_constant(
            *bearing.contact_radii("outer", contact_angle), e_prime, method
        )
    )
    return k_i, k_o, float(hertz.series_constant(k_i, k_o))


#: The quantities a table of both contacts shows: key of to_dict()["inner"], label, unit.
SUMMARY = (
    ("semi_major_mm", "semi-major axis a", "mm"),
    ("semi_minor_mm", "semi-minor axis b", "mm"),
    ("ellipticity", "ellipticity k = a/b", "-"),
    ("max_pressure_gpa", "maximum pressure p_max", "GPa"),
    ("mean_pressure_gpa", "mean pressure", "GPa"),
    ("approach_um", "approach delta", "um"),
    ("stiffness_n_per_um", "contact stiffness dQ/d(delta)", "N/um"),
)


def ball_contacts(
    bearing: BallBearing,
    ball_load,
    contact_angle: float | None = None,
    method: hertz.Method = "exact",
) -> BallContacts:
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

    Examples
    --------
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
