"""Localised defects and the extra clearance they open at a ball's contacts.

Layer 1 (pure NumPy functions, SI) and layer 2 (:class:`Defect`). Every surface
feature enters the dynamic models through one function, the packed table of
:func:`pack_defects` evaluated by ``_kernels.surface_deviation``; raceway waviness and
ball-size errors are further rows of the same table.

Geometry (seed 003, part 7 sec. 2.1-2.2, after Liu & Shao and Patel et al.; the printed
equations were lost in the seed's translation, the model is rebuilt from its prose):
a defect is a rectangular pit of width ``w`` (along the rolling direction) and depth
``H``; the edge radius is neglected (seed assumption iv). A ball of radius r whose
contact point lies a distance s inside the pit (s measured from the pit centre) rests
on the nearer edge; that edge is d = w/2 - |s| from the contact point, and the ball
centre moves towards the defective surface by (exact circle-chord geometry, the curved
race of radius R being concave for the outer race and convex for the inner race)

    lambda(d) = (r - sqrt(r^2 - d^2)) -+ (R - sqrt(R^2 - d^2)),   limited by H,

minus for the outer race (its concavity holds the ball up), plus for the inner race.
At the pit centre (d = w/2) this is the maximum displacement of seed 003; away from
it lambda falls to zero at the edges, which is the finite ball-centre path over the
edge. A defect on the ball is the same pit on the ball's surface: it meets the outer
race once and the inner race once per spin revolution (seed 003 sec. 2.1; seed 004
eqs. 17-19), with the same lambda against the race it faces.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..errors import InputError, positive_number

Location = Literal["outer", "inner", "ball"]
LOCATIONS = ("outer", "inner", "ball")
#: Row kinds of the packed surface table (see :func:`pack_defects`).
KIND = {"outer": 0, "inner": 1, "ball": 2}
#: Columns of a packed row (see :func:`pack_defects`).
ROW_SIZE = 5


def edge_drop(distance, ball_radius, race_radius, race: Literal["inner", "outer"]):
    """Displacement lambda of the ball centre into a pit whose edge is ``distance`` away [m].

    lambda = (r - sqrt(r^2 - d^2)) - (R - sqrt(R^2 - d^2)) for the concave outer race,
    ... + (R - sqrt(R^2 - d^2)) for the convex inner race; 0 for d <= 0 (module
    docstring; seed 003 sec. 2). Depth limits are applied by the caller.

    Parameters
    ----------
    distance : float or array
        d, distance from the contact point to the nearer pit edge [m].
    ball_radius : float
        r [m].
    race_radius : float
        R, radius of the raceway groove bottom [m].
    race : {"inner", "outer"}
        Which race the pit is on, or faces (for a ball defect).

    Examples
    --------
    >>> round(float(edge_drop(0.6e-3, 3.97e-3, 23.235e-3, "outer")) * 1e6, 2)  # ER-16K, 1.2 mm
    37.85
    """
    d = np.clip(np.asarray(distance, dtype=float), 0.0, None)
    d = np.minimum(d, ball_radius)
    ball = ball_radius - np.sqrt(ball_radius**2 - d**2)
    ring = race_radius - np.sqrt(np.maximum(race_radius**2 - d**2, 0.0))
    return (ball - ring if race == "outer" else ball + ring)[()]


def wrap_angle(angle):
    """Angle brought into [-pi, pi) [rad]."""
    return (np.asarray(angle, dtype=float) + math.pi) % (2.0 * math.pi) - math.pi


@dataclass(frozen=True)
class Defect:
    """A localised defect (spall, pit) on a race or a ball.

    Parameters
    ----------
    location : {"outer", "inner", "ball"}
        Where the defect is [-].
    width : float
        Extent w along the rolling direction [m], > 0 and less than the ball diameter.
    depth : float or None
        Depth H [m], > 0; None for a pit deeper than the ball can reach (lambda limits).
    angle : float
        Outer race: angular position in the fixed frame, from +x towards +y (default
        -90 deg, the bottom of the load zone: seed 003's "6 o'clock"). Inner race:
        position on the inner ring at time 0 (it turns with the shaft). Ball: spin phase
        at time 0, measured from the direction facing the outer race [rad].
    ball : int
        Index of the defective ball (ball 0 is at psi = 0 at time 0); ball defects only.

    Examples
    --------
    >>> Defect("outer", width=1.2e-3, depth=0.25e-3).to_dict()["width_mm"]
    1.2
    """

    location: Location
    width: float
    depth: float | None = None
    angle: float = -0.5 * math.pi
    ball: int = 0

    def __post_init__(self) -> None:
        if self.location not in LOCATIONS:
            raise InputError("location", self.location, f"one of {LOCATIONS}")
        for name, value in (("width", self.width), ("depth", self.depth)):
            if name == "depth" and value is None:
                continue
            positive_number(name, value, "a positive length [m]")
        if not (isinstance(self.angle, (int, float, np.floating)) and math.isfinite(self.angle)):
            raise InputError("angle", self.angle, "a finite angle [rad]")
        if (
            isinstance(self.ball, bool)
            or not isinstance(self.ball, (int, np.integer))
            or self.ball < 0
        ):
            raise InputError("ball", self.ball, "a ball index >= 0")

    def check(self, bearing) -> None:
        """Refuse a defect that does not fit ``bearing`` (width below D_w, ball index < Z);
        for a roller bearing, the rolling element ("ball") is a roller.

        Parameters
        ----------
        bearing : BallBearing or RollerBearing
            The bearing the defect is on: the width must be less than its rolling-element
            diameter, and a ball defect's index less than its element count.
        """
        element = getattr(bearing, "rolling_element", "ball")
        if self.width >= bearing.element_diameter:
            raise InputError(
                "width",
                self.width,
                f"less than the {element} diameter {bearing.element_diameter * 1e3:g} mm",
            )
        if self.location == "ball" and self.ball >= bearing.element_count:
            raise InputError(
                "ball", self.ball, f"a {element} index in [0, {bearing.element_count - 1}]"
            )

    def to_dict(self) -> dict:
        """JSON-ready description in engineering units."""
        out = {
            "location": self.location,
            "width_mm": self.width * 1e3,
            "depth_mm": None if self.depth is None else self.depth * 1e3,
            "angle_deg": math.degrees(self.angle),
        }
        if self.location == "ball":
            out["ball"] = self.ball
        return out


def pack_defects(defects, bearing, imperfections=None) -> np.ndarray:
    """The surface table the kernels read (``_kernels.surface_deviation``), one row of
    :data:`ROW_SIZE` columns per feature:

    ====  =========================================  ==========================================
    kind  feature                                    columns 1-4
    ====  =========================================  ==========================================
    0-2   pit on the outer race, inner race, ball    width, depth (+inf: none), angle, ball
    3, 4  outer, inner raceway waviness              order, amplitude, phase, -
    5     ball waviness                              order, amplitude, phase, ball (-1: all)
    6     ball-size error                            D_wj - D_w, -, -, ball
    7     raceway track sampled at the groove's      race (0 outer, 1 inner), count n, -, -;
          mid-plane (a random 3-D surface)           then n rows of kind 8 with the heights
    ====  =========================================  ==========================================

    Waviness, ball-size errors and random surfaces come from ``imperfections``
    (:class:`bearinglab.imperfections.Imperfections`); a random surface enters the planar
    dynamic models along its mid-plane track, sampled at its own circumferential grid
    and interpolated linearly (the ball's axial shift of seed 002 eqs. 7-9 is the
    quasi-static orbit's).
    """
    rows = []
    for d in defects:
        if not isinstance(d, Defect):
            raise InputError("defects", d, "Defect objects")
        d.check(bearing)
        rows.append(
            (KIND[d.location], d.width, math.inf if d.depth is None else d.depth, d.angle, d.ball)
        )
    if imperfections is not None:
        from ..imperfections import Imperfections

        if not isinstance(imperfections, Imperfections):
            raise InputError("imperfections", type(imperfections).__name__, "Imperfections")
        imperfections.check(bearing)
        for w in imperfections.waviness:
            kind = {"outer": 3, "inner": 4, "ball": 5}[w.race]
            rows.append((kind, w.order, w.amplitude, w.phase, -1 if w.ball is None else w.ball))
        errors = imperfections.ball_size_errors
        if errors is not None:
            rows += [(6, e, 0.0, 0.0, j) for j, e in enumerate(errors.errors) if e]
        for surface in imperfections.surfaces:
            count = surface.heights.shape[0]
            track = surface.height(2 * np.pi * np.arange(count) / count, 0.0)
            rows.append((7, 0 if surface.race == "outer" else 1, count, 0.0, 0.0))
            rows += [(8, h, 0.0, 0.0, 0.0) for h in track]
    return np.array(rows, dtype=float).reshape(len(rows), ROW_SIZE)
