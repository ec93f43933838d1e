"""The result of a friction analysis: :class:`FrictionResult` (torque, its components,
the inputs and how each was found), in SI, with ``to_dict`` in engineering units whose
keys carry their unit (:mod:`bearinglab.units`: ``friction_torque_n_mm``, ``power_loss_w``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..units import UNITS, rad_s_to_rpm
from .constant import power_loss

_N_MM = UNITS["n_mm"].from_si(1.0)  # N m -> N mm
_MM = UNITS["mm"].from_si(1.0)  # m -> mm
_MM2_S = UNITS["mm2_s"].from_si(1.0)  # m^2/s -> mm^2/s


def _scaled(value, factor):
    return None if value is None else value * factor


@dataclass(frozen=True)
class FrictionResult:
    """Friction torque and power loss of a bearing at one operating point.

    Attributes: ``model`` (``"constant"`` or ``"skf"``), ``name``, ``shaft_speed``
    [rad/s], ``radial_load``, ``axial_load`` [N], ``torque`` M [N m], ``components``
    (name -> moment [N m]: ``rolling``, ``sliding``, ``seal``, ``drag`` for the SKF model;
    empty for the constant model), ``parameters`` (the coefficients, factors, diameters and
    loads used, SI or dimensionless, and where each came from: ``*_source``), ``sources``,
    ``warnings``, the ``bearing_type`` and ``seals`` of the bearing (None when the
    model was called with numbers only), and ``unused``: the inputs given that the model
    does not use (parameter names of :func:`~.analysis.bearing_friction`; ``r3``, ``s3``
    for the R3, S3 of a deep-groove bearing's constants), which ``to_dict`` names in its
    warnings and an interface can name in its own terms.
    """

    model: str
    name: str
    shaft_speed: float
    radial_load: float
    axial_load: float
    torque: float
    components: dict = field(default_factory=dict)
    parameters: dict = field(default_factory=dict)
    sources: tuple = ()
    warnings: tuple = ()
    bearing_type: str | None = None
    seals: str | None = None
    unused: tuple = ()

    @property
    def power_loss(self) -> float:
        """Frictional power loss N = M omega [W]."""
        return float(power_loss(self.torque, self.shaft_speed))

    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units (N·mm, W, mm, mm²/s, rpm, N); every key
        carries its unit or is listed in :data:`bearinglab.units.DIMENSIONLESS`.

        >>> import math
        >>> from bearinglab.friction import constant_friction
        >>> r = constant_friction(1000.0, 0.039, 157.08, "radial_ball")
        >>> round(r.to_dict()["friction_torque_n_mm"], 2)
        29.25
        """
        p = self.parameters
        out = {"name": self.name, "model": self.model}
        if self.bearing_type is not None:
            out["bearing_type"] = self.bearing_type
        if self.seals is not None:
            out["seals"] = self.seals
        out.update(
            {
                "speed_rpm": rad_s_to_rpm(self.shaft_speed),
                "radial_load_n": self.radial_load,
                "axial_load_n": self.axial_load,
                "friction_torque_n_mm": self.torque * _N_MM,
                "power_loss_w": self.power_loss,
            }
        )
        if self.model == "constant":
            out.update(
                {
                    "friction_type": p["friction_type"],
                    "friction_coefficient": p["friction_coefficient"],
                    "equivalent_load_n": p["equivalent_load"],
                    "pitch_diameter_mm": p["pitch_diameter"] * _MM,
                }
            )
            for key in ("equivalent_load_source", "pitch_diameter_source"):
                if key in p:
                    out[key] = p[key]
        else:
            out.update({f"{k}_torque_n_mm": v * _N_MM for k, v in self.components.items()})
            c = p["constants"]
            out.update(
                {
                    "mean_diameter_mm": p["mean_diameter"] * _MM,
                    "viscosity_mm2_s": p["viscosity"] * _MM2_S,
                    "rated_viscosity_mm2_s": _scaled(p["rated_viscosity"], _MM2_S),
                    "kappa": p["viscosity_ratio"],
                    "inlet_shear_factor": p["inlet_shear_factor"],
                    "replenishment_factor": p["replenishment_factor"],
                    "sliding_weighting_factor": p["sliding_weighting_factor"],
                    "sliding_friction_coefficient": p["sliding_friction_coefficient"],
                    "rolling_variable_skf": p["rolling_variable"],
                    "sliding_variable_skf": p["sliding_variable"],
                    "k_rs": p["k_rs"],
                    "k_z": p["k_z"],
                    "lubrication": p["lubrication"],
                    "geometry_constants": {
                        "r1": c.r1,
                        "r2": c.r2,
                        "s1": c.s1,
                        "s2": c.s2,
                        "r3": c.r3,
                        "s3": c.s3,
                        "source": c.source,
                        "verified": c.verified,
                    },
                }
            )
            for key in ("viscosity_source", "lubricant", "lubricant_kind", "lubrication_source"):
                if key in p:
                    out[key] = p[key]
            if p.get("static_rating") is not None:
                out["static_rating_n"] = p["static_rating"]
                out["static_rating_source"] = p.get("static_rating_source", "given")
        out["sources"] = list(self.sources)
        out["warnings"] = list(self.warnings) + self._unused_note()
        return out

    def _unused_note(self) -> list[str]:
        """The inputs of :attr:`unused`, named in one warning."""
        if not self.unused:
            return []
        model = "SKF" if self.model == "skf" else self.model
        return [f"the {model} model does not use: {', '.join(self.unused)}"]

    def quantities(self) -> list[tuple[str, str]]:
        """The main numbers for a table: (what, key of :meth:`to_dict`); the key's suffix
        gives the unit (:func:`bearinglab.units.unit_of`)."""
        rows = [("friction torque M", "friction_torque_n_mm"), ("power loss N", "power_loss_w")]
        if self.model == "constant":
            return rows + [
                ("friction type", "friction_type"),
                ("coefficient mu (seed 003)", "friction_coefficient"),
                ("equivalent load P", "equivalent_load_n"),
                ("pitch diameter d_m", "pitch_diameter_mm"),
            ]
        rows += [
            ("rolling phi_ish phi_rs M_rr", "rolling_torque_n_mm"),
            ("sliding M_sl", "sliding_torque_n_mm"),
            ("seals M_seal", "seal_torque_n_mm"),
            ("drag M_drag", "drag_torque_n_mm"),
            ("mean diameter d_m = (d + D)/2", "mean_diameter_mm"),
            ("viscosity nu", "viscosity_mm2_s"),
            ("rated viscosity nu_1 (ISO 281)", "rated_viscosity_mm2_s"),
            ("viscosity ratio kappa", "kappa"),
            ("inlet shear factor phi_ish", "inlet_shear_factor"),
            ("replenishment factor phi_rs", "replenishment_factor"),
            ("weighting factor phi_bl", "sliding_weighting_factor"),
            ("sliding coefficient mu_sl", "sliding_friction_coefficient"),
        ]
        if self.parameters.get("static_rating") is not None:
            rows.append(("static load rating C_0", "static_rating_n"))
        return rows

    def to_pandas(self):
        """Table of the torque and its components: component, torque_n_mm, share [-]."""
        import pandas as pd

        parts = self.components or {"total (constant coefficient)": self.torque}
        rows = [
            {
                "component": k,
                "torque_n_mm": v * _N_MM,
                "share": (v / self.torque) if self.torque > 0 else 0.0,
            }
            for k, v in parts.items()
        ]
        return pd.DataFrame(rows)

    def plot(self, ax=None):
        """Bar chart of the torque components [N·mm] on ``ax`` (a matplotlib Axes; a new
        figure by default); returns (fig, ax), never shows.

        Parameters
        ----------
        ax : matplotlib Axes or None
            Where to draw; None: a new figure.
        """
        from ..plotting import figure_axes

        fig, ax = figure_axes(ax, figsize=(6, 3.5))
        table = self.to_pandas()
        ax.bar(table["component"], table["torque_n_mm"], color="tab:blue")
        ax.set_ylabel("friction torque [N·mm]")
        ax.set_title(
            f"{self.name or 'bearing'}: {self.torque * _N_MM:.4g} N·mm, "
            f"{self.power_loss:.4g} W ({self.model} model)"
        )
        return fig, ax
