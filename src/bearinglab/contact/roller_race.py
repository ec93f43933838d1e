"""Contacts of one roller with both raceways of a :class:`~bearinglab.roller_geometry.RollerBearing`
(layer 3): the pressure along the roller for its profile and a tilt, edge stress included,
beside the slice model's values (the ``contact`` request with a roller's load).

Per raceway: Hertz's line contact of the mean load per length (p_0, half-width; Johnson
1985, eqs. 4.43-4.45), the pressure on the elastic half-space for the roller's profile and
half the tilt between the rings (:func:`~.line_pressure.line_contact_pressure`), and the
slice model of ISO/TS 16281 (the roller's slice loads for the tilt, the largest Hertz
pressure of a slice). The roller's approach between both raceways is ISO/TS 16281's
(c_l = 35 948 L_we^(8/9) N/mm^(10/9)) with Palmgren's as the check
(:mod:`~.line`). The largest pressure is checked against ISO 76's 4000 MPa.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, positive_number
from ..materials import BEARING_STEEL, effective_modulus
from ..roller_geometry import RollerBearing
from .line import (
    iso16281_roller_constant,
    line_contact,
    palmgren_approach,
    roller_raceway_radii,
    slice_positions,
)
from .line_pressure import LinePressure, line_contact_pressure

#: ISO 76's contact stress of roller bearings at C0 [Pa].
ISO76_ROLLER_STRESS = 4.0e9


def slice_loads(
    load: float, constant: float, positions, drop, tilt: float = 0.0
) -> tuple[np.ndarray, float]:
    """Slice loads of one roller between both raceways, ISO/TS 16281: q_k = (c_l/n_s)
    [delta - tilt x_k - 2 P(x_k)]_+^(10/9) with sum_k q_k = Q (the roller's approach delta
    found by bisection) [N], and delta [m].

    Parameters
    ----------
    load : float
        Roller load Q > 0 [N].
    constant : float
        c_l [N/m^(10/9)].
    positions : array (n_s,)
        Slice centres [m].
    drop : array (n_s,)
        Profile drop P(x_k) of the roller [m].
    tilt : float
        Tilt between the raceways in the roller's plane [rad].

    Examples
    --------
    >>> q, d = slice_loads(1000.0, 5e8, np.linspace(-4e-3, 4e-3, 5), np.zeros(5))
    >>> q.round(6).tolist(), round(d * 1e6, 4)
    ([200.0, 200.0, 200.0, 200.0, 200.0], 7.4289)
    """
    x = np.asarray(positions, float)
    gap = tilt * x + 2.0 * np.asarray(drop, float)
    per = constant / x.size

    def total(delta):
        return float(np.sum(per * np.clip(delta - gap, 0.0, None) ** (10.0 / 9.0)))

    lo = float(np.min(gap))
    hi = lo + (load / constant) ** 0.9 + 1e-9
    while total(hi) < load:
        hi = lo + 2.0 * (hi - lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if total(mid) < load else (lo, mid)
        if hi - lo <= 1e-15 * max(abs(hi), 1e-12):
            break
    delta = 0.5 * (lo + hi)
    q = per * np.clip(delta - gap, 0.0, None) ** (10.0 / 9.0)
    return q * load / q.sum(), delta


@dataclass(frozen=True)
class RollerContacts:
    """One roller's contacts with both raceways (SI).

    Attributes: ``bearing``, ``load`` Q [N], ``tilt`` between the rings in the roller's
    plane [rad]; per raceway (``inner``, ``outer``) the half-space pressure
    (:class:`~.line_pressure.LinePressure`) and the mean-load Hertz p_0 and half-width
    (``hertz_pressure``, ``hertz_half_width`` dicts by race); the slice model's
    ``slice_positions`` [m], ``slice_loads`` [N], its largest slice pressure by race
    ``slice_pressure`` [Pa]; the roller's approach between the raceways by ISO/TS 16281
    (``approach``) and Palmgren (``palmgren_approach``) [m].
    """

    bearing: RollerBearing
    load: float
    tilt: float
    inner: LinePressure
    outer: LinePressure
    hertz_pressure: dict
    hertz_half_width: dict
    slice_positions: np.ndarray
    slice_loads: np.ndarray
    slice_pressure: dict
    approach: float
    palmgren_approach: float

    @property
    def max_pressure(self) -> float:
        """Largest pressure of either contact on the half-space [Pa]."""
        return max(self.inner.max_pressure, self.outer.max_pressure)

    @property
    def warnings(self) -> list[str]:
        """The pressure against ISO 76's 4000 MPa, and edge stress, in the user's terms."""
        out = []
        for race, c in (("inner", self.inner), ("outer", self.outer)):
            if c.max_pressure > ISO76_ROLLER_STRESS:
                out.append(
                    f"{race} contact: {c.max_pressure / 1e6:.4g} MPa is above the 4000 MPa at "
                    "which ISO 76 puts a permanent deformation of 1e-4 D_we (the static "
                    "rating of roller bearings)"
                )
            if c.edge_ratio > 1.2:
                out.append(
                    f"{race} contact: edge stress, {c.edge_ratio:.3g} times the middle "
                    f"pressure at the roller's end ({self.bearing.profile.kind} profile); the "
                    "value depends on the mesh at a sharp edge"
                )
        return out

    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units (keys carry the unit)."""
        b = self.bearing

        def one(race: str, c: LinePressure) -> dict:
            return {
                "max_pressure_gpa": c.max_pressure / 1e9,
                "middle_pressure_gpa": c.middle_pressure / 1e9,
                "edge_pressure_ratio": c.edge_ratio,
                "hertz_pressure_gpa": self.hertz_pressure[race] / 1e9,
                "hertz_half_width_mm": self.hertz_half_width[race] * 1e3,
                "slice_max_pressure_gpa": self.slice_pressure[race] / 1e9,
                "approach_um": c.approach * 1e6,
                "positions_mm": (c.x * 1e3).tolist(),
                "pressure_along_gpa": (c.along / 1e9).tolist(),
            }

        return {
            "roller_load_n": self.load,
            "tilt_mrad": self.tilt * 1e3,
            "rolling_element": "roller",
            "roller_count": int(b.roller_count),
            "roller_diameter_mm": b.roller_diameter * 1e3,
            "roller_length_mm": b.roller_length * 1e3,
            "pitch_diameter_mm": b.pitch_diameter * 1e3,
            "contact_angle_deg": math.degrees(b.contact_angle),
            "roller_profile": b.profile.to_dict(),
            "geometry_source": b.geometry_source,
            "max_pressure_gpa": self.max_pressure / 1e9,
            "roller_approach_um": self.approach * 1e6,
            "palmgren_approach_um": self.palmgren_approach * 1e6,
            "slice_positions_mm": (self.slice_positions * 1e3).tolist(),
            "slice_loads_n": self.slice_loads.tolist(),
            "inner": one("inner", self.inner),
            "outer": one("outer", self.outer),
            "warnings": self.warnings,
        }

    def to_pandas(self):
        """The pressure along the roller: one row per cell position and raceway."""
        import pandas as pd

        rows = []
        for race, c in (("inner", self.inner), ("outer", self.outer)):
            for x, p in zip(c.x, c.along, strict=True):
                rows.append({"contact": race, "position_mm": x * 1e3, "pressure_gpa": p / 1e9})
        return pd.DataFrame(rows)

    def plot(self, ax=None):
        """The pressure along the roller on both raceways, with the slice model's; returns
        (fig, ax).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw [-].
        """
        from ..plotting import roller_pressure_figure

        return roller_pressure_figure(
            {"inner": (self.inner.x, self.inner.along), "outer": (self.outer.x, self.outer.along)},
            self.bearing.name,
            ax,
        )


#: The quantities a table of both contacts shows: key of to_dict()["inner"], label, unit.
SUMMARY = (
    ("max_pressure_gpa", "largest pressure (half-space, edges included)", "GPa"),
    ("middle_pressure_gpa", "pressure at the middle", "GPa"),
    ("edge_pressure_ratio", "edge / middle pressure", "-"),
    ("hertz_pressure_gpa", "Hertz line-contact p0", "GPa"),
    ("hertz_half_width_mm", "Hertz half-width b", "mm"),
    ("approach_um", "approach delta", "um"),
)


def roller_contacts(
    bearing: RollerBearing,
    roller_load: float,
    tilt: float = 0.0,
    *,
    slices: int = 30,
    axial_cells: int = 40,
    transverse_cells: int = 15,
) -> RollerContacts:
    """Contacts of one roller loaded by Q against both raceways, with a tilt between the rings.

    Parameters
    ----------
    bearing : RollerBearing
        Cylindrical, needle or tapered roller bearing (its profile, D_we, L_we, d_m, angles).
    roller_load : float
        Roller load Q > 0 [N].
    tilt : float
        Tilt between the rings in the roller's plane [rad]; each contact takes half.
    slices : int
        Slices of the slice model [-].
    axial_cells, transverse_cells : int
        Cells of the half-space solution along and across the contact [-].

    Examples
    --------
    >>> from bearinglab.roller_geometry import RollerBearing, RollerProfile
    >>> b = RollerBearing(roller_count=14, roller_diameter=10e-3, roller_length=9.6e-3,
    ...                   pitch_diameter=65e-3)
    >>> r = roller_contacts(b, 3000.0)
    >>> round(r.inner.edge_ratio, 3), r.max_pressure < 4e9
    (0.0, True)
    """
    if not isinstance(bearing, RollerBearing) or not bearing.contact_modelled:
        raise InputError(
            "bearing", getattr(bearing, "name", bearing), "a cylindrical or tapered roller bearing"
        )
    q = positive_number("roller_load", roller_load, "a roller load > 0 [N]")
    if not (isinstance(tilt, (int, float)) and math.isfinite(tilt) and abs(tilt) <= 0.02):
        raise InputError("tilt", tilt, "a tilt within +-20 mrad")
    e = effective_modulus(bearing.roller_material, bearing.ring_material)
    length = bearing.roller_length
    r_i = float(
        roller_raceway_radii(bearing.roller_diameter, bearing.pitch_diameter, bearing.inner_angle)[
            0
        ]
    )
    r_o = float(
        roller_raceway_radii(
            bearing.roller_diameter, bearing.pitch_diameter, bearing.contact_angle
        )[1]
    )
    radii = {"inner": r_i, "outer": r_o}
    fields = {
        race: line_contact_pressure(
            q,
            length,
            radius,
            e,
            drop=bearing.profile_drop,
            tilt=0.5 * tilt,
            axial_cells=axial_cells,
            transverse_cells=transverse_cells,
        )
        for race, radius in radii.items()
    }
    hertz = {race: line_contact(q / length, radius, e) for race, radius in radii.items()}
    x = slice_positions(length, slices)
    c_l = iso16281_roller_constant(length, e, effective_modulus(BEARING_STEEL, BEARING_STEEL))
    loads, delta = slice_loads(q, c_l, x, bearing.profile_drop(x), tilt)
    width = length / slices
    slice_pressure = {
        race: float(np.max(line_contact(loads / width, radius, e).max_pressure))
        for race, radius in radii.items()
    }
    return RollerContacts(
        bearing=bearing,
        load=q,
        tilt=float(tilt),
        inner=fields["inner"],
        outer=fields["outer"],
        hertz_pressure={k: float(v.max_pressure) for k, v in hertz.items()},
        hertz_half_width={k: float(v.half_width) for k, v in hertz.items()},
        slice_positions=x,
        slice_loads=loads,
        slice_pressure=slice_pressure,
        approach=float(delta),
        palmgren_approach=2.0 * float(palmgren_approach(q, length)),
    )
