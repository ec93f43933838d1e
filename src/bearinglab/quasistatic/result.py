"""Result of a quasi-static solve: per-ball contacts, ring displacements, stiffness."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..contact import hertz
from ..geometry import BallBearing, contact_radii
from ..materials import effective_modulus
from ..operating import OperatingCondition
from .solver import DOF_NAMES

#: Units of the stiffness matrix rows/columns (x, y, z in m; tilts in rad).
STIFFNESS_UNITS = [
    ["N/m", "N/m", "N/m", "N/rad", "N/rad"],
    ["N/m", "N/m", "N/m", "N/rad", "N/rad"],
    ["N/m", "N/m", "N/m", "N/rad", "N/rad"],
    ["N m/m", "N m/m", "N m/m", "N m/rad", "N m/rad"],
    ["N m/m", "N m/m", "N m/m", "N m/rad", "N m/rad"],
]


class RingResult:
    """What a ball and a roller load distribution share: the inner ring's displacement
    along the load, its stiffness along it and axially (seed 001's S_r, S_a, C_r, C_a), and
    the stiffness matrix as tables. Needs ``condition``, ``displacement`` (5,) [m, rad]
    and ``stiffness_matrix`` (5, 5) [SI]."""

    @property
    def radial_direction(self) -> np.ndarray:
        """Unit vector of the radial load (or of the radial displacement if no load)."""
        f = self.condition.load_vector()[:2]
        if np.hypot(*f) > 0:
            return f / np.hypot(*f)
        d = self.displacement[:2]
        return d / np.hypot(*d) if np.hypot(*d) > 0 else np.array([0.0, -1.0])

    @property
    def radial_displacement(self) -> float:
        """Inner-ring displacement along the radial load direction, S_r of seed 001 [m]."""
        return float(self.displacement[:2] @ self.radial_direction)

    @property
    def axial_displacement(self) -> float:
        """Axial inner-ring displacement S_a from the centred position [m]."""
        return float(self.displacement[2])

    @property
    def radial_stiffness(self) -> float:
        """C_r = dF_r/dS_r at fixed other displacements (seed 001) [N/m]."""
        e = self.radial_direction
        return float(e @ self.stiffness_matrix[:2, :2] @ e)

    @property
    def axial_stiffness(self) -> float:
        """C_a = dF_a/dS_a at fixed other displacements (seed 001) [N/m]."""
        return float(self.stiffness_matrix[2, 2])

    def stiffness_matrix_shown(self, relative: float = 1e-9) -> np.ndarray:
        """The stiffness matrix with the solver's round-off (entries below ``relative``
        times the largest) set to 0, for tables [SI].

        Parameters
        ----------
        relative : float
            Entries whose magnitude is below ``relative`` times the largest magnitude are set to
            0 [-]; default 1e-9.
        """
        k = np.asarray(self.stiffness_matrix, dtype=float)
        return np.where(np.abs(k) < relative * np.max(np.abs(k)), 0.0, k)

    def stiffness_frame(self):
        """The 5x5 stiffness matrix as a table with named rows and columns (SI), for CSV."""
        import pandas as pd

        return pd.DataFrame(self.stiffness_matrix, index=list(DOF_NAMES), columns=list(DOF_NAMES))


@dataclass(frozen=True)
class LoadDistribution(RingResult):
    """Quasi-static equilibrium of a ball bearing.

    Attributes
    ----------
    bearing, condition : the inputs.
    displacement : array (5,)
        Inner-ring displacement (x, y, z [m], tilt_x, tilt_y [rad]) from the centred position.
    ball_angle : array (Z,)
        Ball azimuths psi [rad] from +x towards +y.
    ball_centre : array (Z, 2)
        Ball centres (rho, z) in each ball's plane [m].
    ring : array (C,)
        0 for inner, 1 for outer groove halves (columns of the per-contact arrays).
    load, approach, contact_angle, film : arrays (Z, C)
        Contact loads [N], approaches [m], signed contact angles [rad] (positive when the
        contact line leans towards +z going from the inner to the outer ring) and film [m].
    stiffness_matrix : array (5, 5)
        Tangent stiffness K = -d(ball forces on inner ring)/du, order DOF_NAMES
        [N/m, N/rad; N m/m, N m/rad].
    reaction : array (5,)
        Sum of the ball forces on the inner ring (equal and opposite to the applied load
        for solved DOFs; the reaction to an imposed tilt otherwise) [N, N m].
    groove_radius : array (C,)
        Groove radius of each contact, for the truncation check [m].
    orbital_speed : array (Z,), optional
        Each ball's orbital (cage) speed omega_m, Jones's at its own contact angles [rad/s].
    ball_centrifugal_force : array (Z,), optional
        F_c = m d_m omega_m^2 / 2 of each ball [N].
    gyroscopic_moment : array (Z,), optional
        M_g of each ball (0 without ``gyroscopic``) [N m].
    race_control : str
        "outer", "inner" or "hybrid" [-].
    outer_controlled : bool array (Z,), optional
        Balls under outer raceway control [-].
    """

    bearing: BallBearing
    condition: OperatingCondition
    displacement: np.ndarray
    ball_angle: np.ndarray
    ball_centre: np.ndarray
    ring: np.ndarray
    load: np.ndarray
    approach: np.ndarray
    contact_angle: np.ndarray
    film: np.ndarray
    stiffness_matrix: np.ndarray
    reaction: np.ndarray
    groove_radius: np.ndarray
    orbital_speed: np.ndarray | None = None
    ball_centrifugal_force: np.ndarray | None = None
    gyroscopic_moment: np.ndarray | None = None
    race_control: str = "outer"
    outer_controlled: np.ndarray | None = None

    @property
    def cage_speed(self) -> float:
        """Mean orbital speed of the balls [rad/s] (the cage speed)."""
        if self.orbital_speed is None:
            return math.nan
        return float(np.mean(self.orbital_speed))

    @property
    def contact_points(self) -> np.ndarray:
        """Number of loaded contacts of each ball (0-4) [-]."""
        return np.count_nonzero(self.load > 0, axis=1)

    @property
    def max_ball_load(self) -> float:
        """Largest load of one ball on one race, arch halves summed (``max_ball_load_n``
        of :meth:`to_dict`) [N]."""
        return max(
            float(np.max(self.load[:, self.ring == race].sum(axis=1), initial=0.0))
            for race in (0, 1)
        )

    @property
    def max_pressure(self) -> float:
        """Largest maximum Hertz pressure p_0 of any contact [Pa] (the ISO 76 check,
        :func:`bearinglab.plausibility.contact_warnings`)."""
        return max(
            float(np.max(self._race_contacts(race).max_pressure, initial=0.0)) for race in (0, 1)
        )

    @cached_property
    def warnings(self) -> tuple[str, ...]:
        """What the user must know: contacts running over the shoulder, preload."""
        out = []
        if np.any(self.truncated):
            n = int(np.count_nonzero(np.any(self.truncated, axis=1)))
            out.append(
                f"the contact ellipse of {n} ball(s) runs over the groove shoulder: "
                "Hertz theory no longer holds there and the load is beyond what the "
                "groove can carry properly"
            )
        if self.bearing.diametral_clearance < 0:
            out.append(
                f"preloaded: diametral clearance {self.bearing.diametral_clearance * 1e6:.3g} um"
            )
        return tuple(out)

    def _race_contacts(self, race: int):
        """Hertz results of every contact of one race (arrays (Z, C_race)), computed once."""
        return self._hertz[race]

    @cached_property
    def _hertz(self):
        return {race: self._compute_race_contacts(race) for race in (0, 1)}

    def _compute_race_contacts(self, race: int):
        cols = self.ring == race
        b = self.bearing
        f = b.inner_groove_factor if race == 0 else b.outer_groove_factor
        rx, ry = contact_radii(
            b.ball_diameter,
            b.pitch_diameter,
            f,
            np.abs(self.contact_angle[:, cols]),
            "inner" if race == 0 else "outer",
        )
        e_prime = effective_modulus(b.ball_material, b.ring_material)
        return hertz.point_contact(self.load[:, cols], rx, np.full_like(rx, ry), e_prime)

    @property
    def truncated(self) -> np.ndarray:
        """(Z, C) True where the contact ellipse runs over the groove shoulder on the side
        it leans to: |alpha| + a/R exceeds that shoulder's angle
        (BallBearing.shoulder_angle: an angular-contact bearing's low side is lower)."""
        out = np.zeros(self.load.shape, dtype=bool)
        for race, name in ((0, "inner"), (1, "outer")):
            cols = self.ring == race
            a = self._race_contacts(race).semi_major
            angle = self.contact_angle[:, cols]
            shoulder = np.where(
                angle >= 0,
                self.bearing.shoulder_angle(name, 1),
                self.bearing.shoulder_angle(name, -1),
            )
            reach = np.abs(angle) + a / self.groove_radius[cols]
            out[:, cols] = (self.load[:, cols] > 0) & (reach > shoulder)
        return out

    def ball_table(self):
        """One row per ball (:meth:`ball_rows`) as a table."""
        import pandas as pd

        return pd.DataFrame(self.ball_rows())

    def ball_rows(self) -> list[dict]:
        """One dict per ball: angle, per-race loads (summed over arch halves), contact
        angles (None where unloaded) and pressures of the most loaded half, approaches,
        contact points. Plain Python values: JSON and the command's table need no pandas
        (0.3 s to import)."""
        rows = []
        hertz_by_race = {race: self._race_contacts(race) for race in (0, 1)}
        for j, psi in enumerate(self.ball_angle):
            row = {"ball": j + 1, "angle_deg": math.degrees(psi) % 360.0}
            for race, name in ((0, "inner"), (1, "outer")):
                cols = np.flatnonzero(self.ring == race)
                loads = self.load[j, cols]
                k = int(np.argmax(loads))
                pressures = np.atleast_2d(hertz_by_race[race].max_pressure)[j]
                semi = np.atleast_2d(hertz_by_race[race].semi_major)[j]
                loaded = bool(loads.sum() > 0)  # an unloaded contact has no angle
                row.update(
                    {
                        f"{name}_load_n": float(loads.sum()),
                        f"{name}_contact_angle_deg": math.degrees(self.contact_angle[j, cols[k]])
                        if loaded
                        else None,
                        f"{name}_max_pressure_gpa": float(pressures[k]) / 1e9,
                        f"{name}_semi_major_mm": float(semi[k]) * 1e3,
                        f"{name}_approach_um": float(max(self.approach[j, cols[k]], 0.0)) * 1e6,
                    }
                )
            if self.orbital_speed is not None:
                row["orbital_speed_rpm"] = float(self.orbital_speed[j]) * 30 / math.pi
                row["centrifugal_force_n"] = float(self.ball_centrifugal_force[j])
                row["gyroscopic_moment_n_mm"] = float(self.gyroscopic_moment[j]) * 1e3
                row["outer_raceway_control"] = bool(self.outer_controlled[j])
            row["contact_points"] = int(self.contact_points[j])
            row["truncated"] = bool(np.any(self.truncated[j]))
            rows.append(row)
        return rows

    def to_pandas(self):
        """The per-ball table (see :meth:`ball_table`)."""
        return self.ball_table()

    def to_dict(self) -> dict:
        """JSON-ready summary in engineering units; the stiffness matrix stays SI."""
        balls = self.ball_rows()
        residual = self.condition.load_vector() + self.reaction
        solved = np.array([True, True, True, self.condition.tilt_free, self.condition.tilt_free])
        return {
            "radial_displacement_um": self.radial_displacement * 1e6,
            "axial_displacement_um": self.axial_displacement * 1e6,
            "displacement_um": (self.displacement[:3] * 1e6).tolist(),
            "tilt_mrad": (self.displacement[3:] * 1e3).tolist(),
            "max_ball_load_n": max(max(b["inner_load_n"], b["outer_load_n"]) for b in balls),
            "stiffness_matrix_si": self.stiffness_matrix.tolist(),
            "stiffness_matrix_order": list(DOF_NAMES),
            "stiffness_matrix_units": STIFFNESS_UNITS,
            "radial_stiffness_n_per_um": self.radial_stiffness * 1e-6,
            "axial_stiffness_n_per_um": self.axial_stiffness * 1e-6,
            "reaction_moment_n_mm": (self.reaction[3:] * 1e3).tolist(),
            "equilibrium_residual_n": float(np.linalg.norm(residual[solved])),
            "speed_rpm": self.condition.shaft_speed * 30 / math.pi,
            "cage_speed_rpm": self.cage_speed * 30 / math.pi,
            "race_control": self.race_control,
            "diametral_clearance_um": self.bearing.diametral_clearance * 1e6,
            "radial_load_n": self.condition.radial_load,
            "axial_load_n": self.condition.axial_load,
            "warnings": list(self.warnings),
            "balls": balls,
        }

    def plot(self, axes=None):
        """Polar load distribution and contact angles on ``axes`` (a polar and a plain
        matplotlib Axes; a new figure by default); returns (fig, axes).

        Parameters
        ----------
        axes : pair of matplotlib Axes or None
            Where to draw: a polar Axes (the loads at their angles) and a plain one (the contact
            angles); None: a new figure.

        Returns
        -------
        (Figure, axes)
            The figure and the pair of Axes; the figure is not shown.
        """
        from ..plotting import load_distribution_figure

        return load_distribution_figure(self, axes)
