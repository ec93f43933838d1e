"""The result of a rating-life analysis: :class:`LifeResult` (ISO 281:2007 / ISO/TS 16281,
see :func:`bearinglab.life.rating_life`), with ``to_dict`` in engineering units whose keys
carry their unit (:mod:`bearinglab.units`), ``to_pandas`` and ``plot``."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..geometry import BallBearing
from ..operating import OperatingCondition
from ..ratings.basic import LoadRatings
from ..ratings.equivalent import LoadFactors
from ..units import rad_s_to_hz, rad_s_to_rpm, unit_of


def hours(million_rev: float, shaft_speed: float) -> float:
    """A life in million revolutions, in hours at ``shaft_speed`` [rad/s]."""
    return million_rev * 1e6 / rad_s_to_hz(shaft_speed) / 3600.0


@dataclass(frozen=True)
class LifeResult:
    """Rating life of one bearing under one operating condition.

    Attributes
    ----------
    bearing, condition : the inputs.
    method : str
        ``iso281`` or ``iso16281``.
    ratings : LoadRatings
        C, C_0, C_u and the factors used.
    equivalent_load : float
        P of ISO 281 [N] (``iso16281``: the dynamic equivalent reference load P_ref).
    factors : LoadFactors
        X, Y, e used for the ISO 281 P.
    static_equivalent_load : float
        P_0 [N].
    l10 : float
        Basic rating life L10 (``iso16281``: the basic reference rating life L10r)
        [million revolutions].
    reliability_percent, a1 : float
        Reliability [%] and its factor a_1 [-].
    viscosity, rated_viscosity : float or None
        nu and nu_1 [m^2/s] (None when no viscosity was given).
    kappa, a_iso : float or None
        nu/nu_1 and a_ISO [-].
    contamination : float or None
        e_C [-]; ``contamination_source`` says where it came from.
    lnm : float or None
        Modified rating life a_1 a_ISO L10 at the chosen reliability [million revolutions].
    reference : dict or None
        ISO/TS 16281 details: contact ratings Q_ci, Q_ce, equivalent loads Q_ei, Q_ee [N],
        the per-ball inner and outer contact loads [N] and the rotating ring.
    warnings : tuple of str
    unused : tuple of str
        Inputs of :func:`~.life.rating_life` given that had no effect (``rotating`` with
        ``iso281``, ``ep_additives`` without a viscosity), which ``to_dict`` names in its
        warnings and an interface can name in its own terms.
    """

    bearing: BallBearing
    condition: OperatingCondition
    method: str
    ratings: LoadRatings
    equivalent_load: float
    factors: LoadFactors
    static_equivalent_load: float
    l10: float
    reliability_percent: float
    a1: float
    viscosity: float | None = None
    rated_viscosity: float | None = None
    kappa: float | None = None
    contamination: float | None = None
    contamination_source: str | None = None
    a_iso: float | None = None
    lnm: float | None = None
    iso281_equivalent_load: float | None = None
    reference: dict | None = field(default=None, repr=False)
    warnings: tuple[str, ...] = ()
    unused: tuple[str, ...] = ()

    @property
    def shaft_speed(self) -> float:
        """Speed of the rotating ring [rad/s]."""
        return self.condition.shaft_speed

    @property
    def static_safety_factor(self) -> float:
        """s_0 = C_0 / P_0 [-]."""
        return self.ratings.static / self.static_equivalent_load

    @property
    def l10_hours(self) -> float:
        """L10 at the operating speed [h]."""
        return hours(self.l10, self.shaft_speed)

    @property
    def lnm_hours(self) -> float | None:
        """L_nm at the operating speed [h], None without a viscosity."""
        return None if self.lnm is None else hours(self.lnm, self.shaft_speed)

    def to_dict(self) -> dict:
        """JSON-ready summary in engineering units (keys carry their unit)."""

        def mm2(v):
            return None if v is None else v * 1e6

        out = {
            "method": self.method,
            **self.ratings.to_dict(),
            "radial_load_n": self.condition.radial_load,
            "axial_load_n": self.condition.axial_load,
            "speed_rpm": rad_s_to_rpm(self.shaft_speed),
            "equivalent_load_n": self.equivalent_load,
            "x_factor": self.factors.x,
            "y_factor": self.factors.y,
            # ISO 281 gives no e for a bearing that carries no axial load (alpha = 0 rollers)
            "e_limit": self.factors.e if math.isfinite(self.factors.e) else None,
            "static_equivalent_load_n": self.static_equivalent_load,
            "static_safety_factor": self.static_safety_factor,
            "l10_million_rev": self.l10,
            "l10_hours": self.l10_hours,
            "reliability_percent": self.reliability_percent,
            "a1": self.a1,
            "viscosity_mm2_s": mm2(self.viscosity),
            "rated_viscosity_mm2_s": mm2(self.rated_viscosity),
            "kappa": self.kappa,
            "contamination_factor": self.contamination,
            "contamination_source": self.contamination_source,
            "a_iso": self.a_iso,
            "l10m_million_rev": self.lnm,
            "l10m_hours": self.lnm_hours,
            "warnings": list(self.warnings)
            + ([f"given without effect: {', '.join(self.unused)}"] if self.unused else []),
        }
        if self.reference is not None:
            ref = self.reference
            element = getattr(self.bearing, "rolling_element", "ball")
            out.update(
                {
                    "iso281_equivalent_load_n": self.iso281_equivalent_load,
                    "reference_load_n": self.equivalent_load,
                    "inner_contact_rating_n": ref["inner_rating"],
                    "outer_contact_rating_n": ref["outer_rating"],
                    f"inner_equivalent_{element}_load_n": ref["inner_equivalent"],
                    f"outer_equivalent_{element}_load_n": ref["outer_equivalent"],
                    "rotating_ring": ref["rotating"],
                    f"inner_{element}_loads_n": [float(q) for q in ref["inner_loads"]],
                    f"outer_{element}_loads_n": [float(q) for q in ref["outer_loads"]],
                }
            )
            if element == "roller":
                out["slices"] = ref["slices"]
                out["edge_stress"] = ref["edge_stress"]
        out["life_exponent"] = self.life_exponent
        return out

    @property
    def life_exponent(self) -> float:
        """p of L10 = (C/P)^p: 3 for ball bearings, 10/3 for roller bearings [-]."""
        return 10.0 / 3.0 if getattr(self.bearing, "rolling_element", "ball") == "roller" else 3.0

    def to_pandas(self):
        """The main results as a table: quantity, value, unit (symbol of
        :mod:`bearinglab.units`), source (given or computed, for the ratings) and key (of
        :meth:`to_dict`, whose suffix is the unit)."""
        import pandas as pd

        d = self.to_dict()
        rows = [
            ("basic dynamic load rating C", "dynamic_rating_n", d["dynamic_rating_source"]),
            ("basic static load rating C0", "static_rating_n", d["static_rating_source"]),
            ("fatigue load limit Cu", "fatigue_load_limit_n", d["fatigue_load_limit_source"]),
            (
                "equivalent dynamic load P"
                if self.method == "iso281"
                else "dynamic equivalent reference load P_ref",
                "equivalent_load_n",
                "",
            ),
            ("equivalent static load P0", "static_equivalent_load_n", ""),
            ("static safety factor s0", "static_safety_factor", ""),
            (
                "basic rating life L10"
                if self.method == "iso281"
                else "basic reference rating life L10r",
                "l10_million_rev",
                "",
            ),
            ("  in hours", "l10_hours", ""),
            ("viscosity ratio kappa", "kappa", ""),
            ("contamination factor e_C", "contamination_factor", d["contamination_source"] or ""),
            ("life modification factor a_ISO", "a_iso", ""),
            (f"modified rating life at {self.reliability_percent:g} %", "l10m_million_rev", ""),
            ("  in hours", "l10m_hours", ""),
        ]
        return pd.DataFrame(
            [
                {
                    "quantity": q,
                    "value": d[k],
                    "unit": unit_of(k).symbol if unit_of(k) is not None else "-",
                    "source": src,
                    "key": k,
                }
                for q, k, src in rows
            ]
        )

    def plot(self, ax=None):
        """Basic rating life against the equivalent load (log-log), with the operating
        point and, when known, the modified life, on ``ax`` (a matplotlib Axes; a new
        figure by default); returns (fig, ax).

        Parameters
        ----------
        ax : matplotlib Axes or None
            Where to draw; None: a new figure.
        """
        from ..plotting import figure_axes

        fig, ax = figure_axes(ax, figsize=(7, 4.5))
        c = self.ratings.dynamic
        p = np.geomspace(0.02 * c, c, 100)
        e = self.life_exponent
        ax.loglog(
            p,
            hours((c / p) ** e, self.shaft_speed),
            color="C0",
            label=f"L10 = (C/P)^{'10/3' if e > 3 else '3'}",
        )
        ax.loglog(
            [self.equivalent_load],
            [self.l10_hours],
            "o",
            color="C0",
            label=f"operating point ({self.method})",
        )
        if self.lnm_hours is not None:
            ax.loglog(
                [self.equivalent_load],
                [self.lnm_hours],
                "s",
                color="C1",
                label=f"modified life (a1 a_ISO = {self.a1 * self.a_iso:.3g})",
            )
        ax.set_xlabel("equivalent load P [N]")
        ax.set_ylabel(f"life at {rad_s_to_rpm(self.shaft_speed):g} rpm [h]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        return fig, ax
