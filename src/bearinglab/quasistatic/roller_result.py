"""Result of a roller-bearing load distribution: per roller and per slice loads, ring
displacement, stiffness (:func:`bearinglab.quasistatic.roller.solve_roller_distribution`).

JSON keys follow the ball bearing's with "roller" for "ball" (``max_roller_load_n``,
``rollers``, ``roller_count``); the stiffness keys are the same (``stiffness_matrix_si``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..contact.line import line_contact, roller_raceway_radii
from ..operating import OperatingCondition
from ..roller_geometry import RollerBearing
from .result import STIFFNESS_UNITS, RingResult

DOF_NAMES = ("x", "y", "z", "tilt_x", "tilt_y")
#: An end slice carrying this many times its roller's mean slice load is edge loading [-].
EDGE_LOAD_RATIO = 1.5


@dataclass(frozen=True)
class RollerLoadDistribution(RingResult):
    """Quasi-static equilibrium of a roller bearing.

    Attributes
    ----------
    bearing, condition : the inputs.
    displacement : array (5,)
        Inner-ring displacement (x, y, z [m], tilt_x, tilt_y [rad]).
    roller_angle : array (N,)
        Roller azimuths psi [rad] (N = rows x Z; row by row).
    roller_row : array (N,)
        Row of each roller (0, 1) [-].
    slice_positions : array (n_s,)
        Slice centres along the roller from its middle [m].
    inner_load, outer_load : arrays (N, n_s)
        Slice loads of the inner and outer line contacts [N].
    inner_approach, outer_approach : arrays (N, n_s)
        Slice approaches (negative: a gap) [m].
    flange_load : array (N,)
        Rib (flange) load of each tapered roller, 0 for cylindrical rollers [N].
    roller_state : array (N, 3)
        Roller displacement (rho, z [m], tilt times L_we [m]) in its plane.
    stiffness_matrix : array (5, 5)
        Tangent stiffness K = -d(roller forces on the inner ring)/du, order DOF_NAMES.
    reaction : array (5,)
        Sum of the roller forces on the inner ring [N, N m] (minus the applied load where
        solved; the reaction to an imposed displacement or tilt otherwise).
    centrifugal_force : float
        F_c of one roller [N].
    effective_modulus : float
        E' of roller and rings [Pa].
    free : bool array (5,)
        The ring DOFs solved for (the others imposed).
    """

    bearing: RollerBearing
    condition: OperatingCondition
    displacement: np.ndarray
    roller_angle: np.ndarray
    roller_row: np.ndarray
    slice_positions: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray
    inner_approach: np.ndarray
    outer_approach: np.ndarray
    flange_load: np.ndarray
    roller_state: np.ndarray
    stiffness_matrix: np.ndarray
    reaction: np.ndarray
    centrifugal_force: float
    effective_modulus: float
    free: np.ndarray

    @classmethod
    def from_solution(cls, problem, u, v, q, delta, force, stiff) -> RollerLoadDistribution:
        """The result from a solved :class:`~bearinglab.quasistatic.roller.RollerProblem`.

        Parameters
        ----------
        problem : RollerProblem
            The solve's fixed data [-].
        u : array (5,)
            Ring displacement [m, rad].
        v : array (N, 3)
            Roller states [m].
        q, delta : arrays (N, C)
            Contact loads [N] and approaches [m].
        force : array (5,)
            Roller forces on the inner ring [N, N m].
        stiff : array (5, 5)
            Tangent stiffness [SI].
        """
        s = problem.slices
        nz = q.shape[0]
        flange = q[:, -1] if problem.bearing.is_tapered else np.zeros(nz)
        return cls(
            bearing=problem.bearing,
            condition=problem.condition,
            displacement=np.asarray(u, float).copy(),
            roller_angle=problem.psi.copy(),
            roller_row=problem.row.copy(),
            slice_positions=problem.x.copy(),
            inner_load=q[:, :s].copy(),
            outer_load=q[:, s : 2 * s].copy(),
            inner_approach=delta[:, :s].copy(),
            outer_approach=delta[:, s : 2 * s].copy(),
            flange_load=np.asarray(flange, float).copy(),
            roller_state=np.asarray(v, float).copy(),
            stiffness_matrix=np.asarray(stiff, float).copy(),
            reaction=np.asarray(force, float).copy(),
            centrifugal_force=float(problem.centrifugal_force),
            effective_modulus=float(problem.e_prime),
            free=problem.free.copy(),
        )

    # ---------------------------------------------------------------- derived
    @property
    def slices(self) -> int:
        """Slices per line contact n_s [-]."""
        return int(self.slice_positions.size)

    @property
    def inner_roller_load(self) -> np.ndarray:
        """Load of each roller on the inner raceway, its slices summed (N,) [N]."""
        return self.inner_load.sum(axis=1)

    @property
    def outer_roller_load(self) -> np.ndarray:
        """Load of each roller on the outer raceway (N,) [N]."""
        return self.outer_load.sum(axis=1)

    @property
    def max_roller_load(self) -> float:
        """Largest load of one roller on one raceway (``max_roller_load_n``) [N]."""
        return float(max(np.max(self.inner_roller_load), np.max(self.outer_roller_load)))

    @property
    def induced_axial_force(self) -> float:
        """Axial force the rollers push the inner ring with, -reaction_z [N] (with an imposed
        axial displacement: the tapered bearing's induced axial force)."""
        return float(-self.reaction[2])

    @cached_property
    def _pressures(self) -> tuple[np.ndarray, np.ndarray]:
        b = self.bearing
        width = b.roller_length / self.slices
        r_i = roller_raceway_radii(b.roller_diameter, b.pitch_diameter, b.inner_angle)[0]
        r_o = roller_raceway_radii(b.roller_diameter, b.pitch_diameter, b.contact_angle)[1]
        e = self.effective_modulus
        p_in = line_contact(self.inner_load / width, float(r_i), e).max_pressure
        p_out = line_contact(self.outer_load / width, float(r_o), e).max_pressure
        return np.asarray(p_in), np.asarray(p_out)

    def pressure(self, race: str) -> np.ndarray:
        """Maximum Hertz pressure p_0 of every slice of one raceway (N, n_s) [Pa]: the line
        contact of the slice's load over its width.

        Parameters
        ----------
        race : str
            ``"inner"`` or ``"outer"`` [-].
        """
        return self._pressures[0 if race == "inner" else 1]

    @property
    def max_pressure(self) -> float:
        """Largest p_0 of any slice [Pa] (checked against ISO 76's 4000 MPa,
        :func:`bearinglab.plausibility.contact_warnings`)."""
        return float(max(np.max(self._pressures[0]), np.max(self._pressures[1])))

    @property
    def edge_loaded(self) -> np.ndarray:
        """(N,) True where a loaded roller's end slice carries more than EDGE_LOAD_RATIO
        times its mean slice load (edge loading: tilt against a weak profile)."""
        load = np.maximum(self.inner_load, self.outer_load)
        mean = load.mean(axis=1)
        ends = np.maximum(load[:, 0], load[:, -1])
        return (mean > 0) & (ends > EDGE_LOAD_RATIO * np.maximum(mean, 1e-300))

    @cached_property
    def warnings(self) -> tuple[str, ...]:
        """What the user must know: edge loading, preload, rib loads."""
        out = []
        n = int(np.count_nonzero(self.edge_loaded))
        if n:
            out.append(
                f"edge loading on {n} roller(s): an end slice carries more than "
                f"{EDGE_LOAD_RATIO:g} times the roller's mean slice load (tilt or misalignment "
                f"against a {self.bearing.profile.kind} profile); the slice model does not "
                "resolve the stress peak at the roller's edge"
            )
        b = self.bearing
        if b.diametral_clearance < 0:
            out.append(f"preloaded: diametral clearance {b.diametral_clearance * 1e6:.3g} um")
        if b.rows == 2 and b.is_tapered and b.axial_clearance < 0:
            out.append(f"preloaded pair: axial clearance {b.axial_clearance * 1e6:.3g} um")
        return tuple(out)

    def roller_rows(self) -> list[dict]:
        """One dict per roller (plain Python values): angle, row, the raceway loads (slices
        summed), rib load (tapered), largest slice pressure of each raceway, approach at the
        most loaded slice, the ratio of the most loaded end slice to the mean slice load."""
        rows = []
        p_in, p_out = self._pressures
        for j, psi in enumerate(self.roller_angle):
            load = np.maximum(self.inner_load[j], self.outer_load[j])
            mean = float(load.mean())
            k = int(np.argmax(self.inner_load[j]))
            row = {
                "roller": j + 1,
                "row": int(self.roller_row[j]) + 1,
                "angle_deg": math.degrees(psi) % 360.0,
                "inner_load_n": float(self.inner_roller_load[j]),
                "outer_load_n": float(self.outer_roller_load[j]),
                "inner_max_pressure_gpa": float(np.max(p_in[j])) / 1e9,
                "outer_max_pressure_gpa": float(np.max(p_out[j])) / 1e9,
                "inner_approach_um": float(max(self.inner_approach[j, k], 0.0)) * 1e6,
                "end_load_ratio": (float(max(load[0], load[-1]) / mean) if mean > 0 else None),
            }
            if self.bearing.is_tapered:
                row["flange_load_n"] = float(self.flange_load[j])
            if self.centrifugal_force > 0:
                row["centrifugal_force_n"] = self.centrifugal_force
            rows.append(row)
        return rows

    def to_pandas(self):
        """The per-roller table (:meth:`roller_rows`)."""
        import pandas as pd

        return pd.DataFrame(self.roller_rows())

    def slice_table(self):
        """One row per (roller, slice): position, inner and outer load and pressure."""
        import pandas as pd

        p_in, p_out = self._pressures
        rows = []
        for j in range(len(self.roller_angle)):
            for k, x in enumerate(self.slice_positions):
                rows.append(
                    {
                        "roller": j + 1,
                        "slice": k + 1,
                        "position_mm": float(x) * 1e3,
                        "inner_load_n": float(self.inner_load[j, k]),
                        "outer_load_n": float(self.outer_load[j, k]),
                        "inner_pressure_gpa": float(p_in[j, k]) / 1e9,
                        "outer_pressure_gpa": float(p_out[j, k]) / 1e9,
                    }
                )
        return pd.DataFrame(rows)

    def to_dict(self) -> dict:
        """JSON-ready summary in engineering units; the stiffness matrix stays SI."""
        rollers = self.roller_rows()
        residual = self.condition.load_vector() + self.reaction
        b = self.bearing
        heaviest = int(np.argmax(np.maximum(self.inner_roller_load, self.outer_roller_load)))
        out = {
            "rolling_element": "roller",
            "roller_count": int(b.roller_count),
            "roller_diameter_mm": b.roller_diameter * 1e3,
            "roller_length_mm": b.roller_length * 1e3,
            "slices": self.slices,
            "radial_displacement_um": self.radial_displacement * 1e6,
            "axial_displacement_um": self.axial_displacement * 1e6,
            "displacement_um": (self.displacement[:3] * 1e6).tolist(),
            "tilt_mrad": (self.displacement[3:] * 1e3).tolist(),
            "max_roller_load_n": self.max_roller_load,
            "max_pressure_gpa": self.max_pressure / 1e9,
            "loaded_rollers": int(np.count_nonzero(self.inner_roller_load > 0)),
            "stiffness_matrix_si": self.stiffness_matrix.tolist(),
            "stiffness_matrix_order": list(DOF_NAMES),
            "stiffness_matrix_units": STIFFNESS_UNITS,
            "radial_stiffness_n_per_um": self.radial_stiffness * 1e-6,
            "axial_stiffness_n_per_um": self.axial_stiffness * 1e-6,
            "reaction_moment_n_mm": (self.reaction[3:] * 1e3).tolist(),
            "equilibrium_residual_n": float(np.linalg.norm(residual[self.free])),
            "speed_rpm": self.condition.shaft_speed * 30 / math.pi,
            "cage_speed_rpm": 0.5 * (1.0 - b.gamma) * self.condition.shaft_speed * 30 / math.pi,
            "diametral_clearance_um": b.diametral_clearance * 1e6,
            "radial_load_n": self.condition.radial_load,
            "axial_load_n": self.condition.axial_load,
            "heaviest_roller_slice_loads_n": np.maximum(
                self.inner_load[heaviest], self.outer_load[heaviest]
            ).tolist(),
            "slice_positions_mm": (self.slice_positions * 1e3).tolist(),
            "warnings": list(self.warnings),
            "rollers": rollers,
        }
        if b.is_tapered:
            out["max_flange_load_n"] = float(np.max(self.flange_load))
            out["axial_clearance_um"] = b.axial_clearance * 1e6
            if not self.free[2]:
                out["induced_axial_force_n"] = self.induced_axial_force
        if self.centrifugal_force > 0:
            out["centrifugal_force_n"] = self.centrifugal_force
        return out

    def plot(self, axes=None):
        """Roller loads round the bearing and the slice loads of the heaviest roller on
        ``axes`` (a polar and a plain matplotlib Axes; a new figure by default); returns
        (fig, axes).

        Parameters
        ----------
        axes : tuple of two matplotlib Axes, optional
            Where to draw [-].
        """
        from ..plotting import roller_distribution_figure

        heaviest = int(np.argmax(np.maximum(self.inner_roller_load, self.outer_roller_load)))
        return roller_distribution_figure(
            self.roller_angle,
            self.inner_roller_load,
            self.outer_roller_load,
            self.slice_positions,
            self.inner_load[heaviest],
            self.outer_load[heaviest],
            self.bearing.name,
            axes,
        )
