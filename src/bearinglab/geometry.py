"""Geometry of a single-row ball bearing: :class:`BallBearing` (layer 2), which validates a
geometry and exposes the derived quantities by calling the layer-1 functions of
:mod:`bearinglab.macrogeometry` (raceway diameters, free contact angle, contact radii,
curvature) and :mod:`bearinglab.geometry_sections` (ring cross-sections); both are
re-exported here, so ``from bearinglab.geometry import contact_radii`` keeps working.

Sources: Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing Technology*,
5th ed., 2007, ch. 2 ("Rolling bearing macrogeometry": diametral clearance
P_d = d_o - d_i - 2 D, eq. 2.1; free contact angle cos(alpha_0) = 1 - P_d / (2 A),
eq. 2.5; end play P_e = 2 A sin(alpha_0), eq. 2.6; curvature sums and differences,
eqs. 2.26-2.33). Conventions: docs/conventions.md; names: docs/nomenclature.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import NamedTuple

import numpy as np

from .errors import InputError, bore_below_outside, positive_number
from .geometry_sections import RingSection, grooved_ring_section
from .macrogeometry import (
    Race,
    clearance_for_contact_angle,
    contact_radii,
    curvature_sum_difference,
    free_contact_angle,
    raceway_diameters,
)
from .materials import BEARING_STEEL, Material

__all__ = [
    "ANGULAR_SHOULDER_DEPTH_RATIO",
    "GROOVE_DEPTH_RATIO",
    "INTERNAL_FIELDS",
    "BallBearing",
    "Race",
    "RingSection",
    "Source",
    "clearance_for_contact_angle",
    "contact_radii",
    "curvature_sum_difference",
    "free_contact_angle",
    "grooved_ring_section",
    "raceway_diameters",
]

#: Groove depth of both rings as a fraction of the ball diameter, used only to place the
#: ring shoulders for the ring cross-sections. Estimate: SKF's shoulder diameter
#: d1 = 34.4 mm of a 6205 (D_w = 7.94 mm, d_m = 39.04 mm) gives a depth of 0.21 D_w.
GROOVE_DEPTH_RATIO = 0.20
#: Depth of the high (thrust-side) shoulder of angular-contact bearings, as a fraction of
#: D_w, for the check that a contact ellipse stays on the groove. Estimate: makers build
#: that shoulder about twice as high as a deep-groove shoulder so the ellipse is contained
#: up to roughly the nominal angle plus 30 deg.
ANGULAR_SHOULDER_DEPTH_RATIO = 0.40


class Source(NamedTuple):
    """Where a geometry value came from: ``kind`` is catalog, estimated, user or default."""

    kind: str
    reference: str = ""


class References:
    """Numbers each distinct source reference once, so that a table's cells read
    "catalog [1]" and the full references (``refs``, in order) are listed once under it."""

    def __init__(self) -> None:
        self.refs: list[str] = []

    def cell(self, bearing: BallBearing, field: str) -> str:
        """Where ``bearing``'s ``field`` came from, with its reference number."""
        src = bearing.sources.get(field)
        if src is None:
            return "default"
        if not src.reference:
            return src.kind
        if src.reference not in self.refs:
            self.refs.append(src.reference)
        return f"{src.kind} [{self.refs.index(src.reference) + 1}]"


# ---------------------------------------------------------------- layer 2: the model


def _mm(value: float | None) -> float | None:
    return None if value is None else value * 1e3


def _positive(name: str, value: float) -> None:
    positive_number(name, value, "a positive length [m]")


@dataclass(frozen=True)
class BallBearing:
    """A single-row ball bearing: boundary dimensions, internal geometry, materials.

    All lengths in metres, angles in radians. The nominal ``contact_angle`` is the one
    kinematics and contact calculations use unless an analysis finds the operating
    angle; the free contact angle follows from the clearance. If ``contact_angle`` is
    given (> 0) and ``diametral_clearance`` is not, the clearance is the one that
    gives that free contact angle (angular-contact bearings); a radial bearing with no
    clearance given has none.

    Parameters
    ----------
    ball_count : int
        Number of balls Z [-], >= 3.
    ball_diameter : float
        Ball diameter D_w [m].
    pitch_diameter : float
        Pitch diameter d_m [m].
    inner_groove_factor, outer_groove_factor : float
        Groove curvature factors f_i, f_o = groove radius / D_w [-], each > 0.5.
    contact_angle : float
        Nominal contact angle alpha [rad], 0 <= alpha <= pi/2 (pi/2: thrust ball bearing).
    diametral_clearance : float or None
        Diametral clearance P_d [m]; negative means interference.
    bore, outside_diameter, width : float or None
        Boundary dimensions d, D, B [m]; needed for ring masses and sections.
    ring_material, ball_material : Material
        Materials of the rings and of the balls.
    name : str
        Label, e.g. the designation.
    bearing_type : str
        One of the types in :data:`bearinglab.designation.BEARING_TYPES`.
    sources : dict
        Field name -> :class:`Source` (catalog, estimated, user, default).
    inner_arch_angle, outer_arch_angle : float
        Gothic-arch angle alpha_T of a ring's groove (two groove halves whose centres are
        offset axially by (f D_w - D_w/2) sin(alpha_T), as in four-point and split-race
        bearings, seed 001); 0 for a circular groove [rad].

    Examples
    --------
    >>> b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)
    >>> round(b.inner_raceway_diameter * 1e3, 2), round(b.outer_raceway_diameter * 1e3, 2)
    (31.1, 46.98)
    """

    ball_count: int
    ball_diameter: float
    pitch_diameter: float
    inner_groove_factor: float = 0.52
    outer_groove_factor: float = 0.52
    contact_angle: float = 0.0
    diametral_clearance: float | None = None
    bore: float | None = None
    outside_diameter: float | None = None
    width: float | None = None
    ring_material: Material = BEARING_STEEL
    ball_material: Material = BEARING_STEEL
    name: str = ""
    bearing_type: str = "radial_ball"
    sources: dict = field(default_factory=dict, compare=False, repr=False)
    inner_arch_angle: float = 0.0
    outer_arch_angle: float = 0.0

    def __post_init__(self) -> None:
        z = self.ball_count
        if isinstance(z, bool) or not isinstance(z, (int, np.integer)) or z < 3:
            raise InputError("ball_count", z, "an integer >= 3")
        _positive("ball_diameter", self.ball_diameter)
        _positive("pitch_diameter", self.pitch_diameter)
        for name in ("inner_groove_factor", "outer_groove_factor"):
            f = getattr(self, name)
            if not (isinstance(f, (int, float, np.floating)) and 0.5 < f <= 1.0):
                raise InputError(
                    name,
                    f,
                    "a value in (0.5, 1.0]",
                    "the groove radius must exceed the ball radius",
                )
        if not (
            isinstance(self.contact_angle, (int, float, np.floating))
            and 0.0 <= self.contact_angle <= 0.5 * math.pi
        ):
            raise InputError("contact_angle", self.contact_angle, "an angle in [0, 90] degrees")
        for name in ("inner_arch_angle", "outer_arch_angle"):
            arch = getattr(self, name)
            if not (isinstance(arch, (int, float, np.floating)) and 0.0 <= arch < math.pi / 3):
                raise InputError(name, arch, "an angle in [0, 60) degrees (0 = circular groove)")
        if self.pitch_diameter <= self.ball_diameter:
            raise InputError(
                "pitch_diameter",
                self.pitch_diameter,
                "more than the ball diameter {D_w}",
                unit="m",
                numbers={"D_w": self.ball_diameter},
            )
        zmax = math.floor(math.pi / math.asin(self.ball_diameter / self.pitch_diameter))
        if z > zmax:
            raise InputError(
                "ball_count",
                z,
                f"at most {zmax} balls",
                f"{z} balls of {self.ball_diameter * 1e3:.4g} mm do not fit around "
                f"a {self.pitch_diameter * 1e3:.4g} mm pitch circle",
            )
        a = (self.inner_groove_factor + self.outer_groove_factor - 1.0) * self.ball_diameter
        if self.diametral_clearance is None:
            derived = float(
                clearance_for_contact_angle(
                    self.contact_angle,
                    self.ball_diameter,
                    self.inner_groove_factor,
                    self.outer_groove_factor,
                )
            )
            object.__setattr__(self, "diametral_clearance", derived)
        pd = self.diametral_clearance
        if not (
            isinstance(pd, (int, float, np.floating))
            and -0.05 * self.ball_diameter <= pd <= 2.0 * a
        ):
            raise InputError(
                "diametral_clearance",
                pd,
                "a value in [{low}, {high}]",
                "beyond 2 A the balls are loose even at 90 degrees",
                unit="m",
                numbers={"low": -0.05 * self.ball_diameter, "high": 2 * a},
            )
        for name in ("bore", "outside_diameter", "width"):
            if getattr(self, name) is not None:
                _positive(name, getattr(self, name))
        d, big_d = self.bore, self.outside_diameter
        if d is not None and big_d is not None:
            bore_below_outside(d, big_d, "bore")
        if self.is_thrust:
            self._check_thrust_washers()
            return
        if d is not None and self.inner_raceway_diameter <= d:
            raise InputError(
                "ball_diameter",
                self.ball_diameter,
                "a ball that leaves material under the inner raceway",
                f"inner groove bottom {self.inner_raceway_diameter * 1e3:.4g} mm "
                f"is not above the bore {d * 1e3:.4g} mm",
            )
        if big_d is not None and self.outer_raceway_diameter >= big_d:
            raise InputError(
                "ball_diameter",
                self.ball_diameter,
                "a ball that leaves material outside the outer raceway",
                f"outer groove bottom {self.outer_raceway_diameter * 1e3:.4g} mm "
                f"is not inside the outside diameter {big_d * 1e3:.4g} mm",
            )

    def _check_thrust_washers(self) -> None:
        """A thrust bearing's balls run on the faces of its washers: the ball set must clear
        the shaft (d_m - D_w > d) and the pitch circle lie inside the outside diameter."""
        d, big_d = self.bore, self.outside_diameter
        if d is not None and self.pitch_diameter - self.ball_diameter <= d:
            raise InputError(
                "pitch_diameter",
                self.pitch_diameter,
                "more than the bore plus the ball diameter {limit}",
                "the balls of a thrust bearing must clear the shaft",
                unit="m",
                numbers={"limit": d + self.ball_diameter},
            )
        if big_d is not None and self.pitch_diameter >= big_d:
            raise InputError(
                "pitch_diameter",
                self.pitch_diameter,
                "less than the outside diameter {D}",
                unit="m",
                numbers={"D": big_d},
            )

    @property
    def rolling_element(self) -> str:
        """``"ball"`` (a :class:`~bearinglab.roller_geometry.RollerBearing` gives
        ``"roller"``): how analyses tell the kinds apart [-]."""
        return "ball"

    @property
    def element_count(self) -> int:
        """Rolling elements per row, Z = ``ball_count`` [-]."""
        return int(self.ball_count)

    @property
    def element_diameter(self) -> float:
        """Rolling-element diameter D_w = ``ball_diameter`` [m]."""
        return self.ball_diameter

    @property
    def is_thrust(self) -> bool:
        """True for a thrust ball bearing (balls between two washers, ``bearing_type``
        ``thrust_ball``): its rings are not radial rings, so raceway-versus-bore checks and
        ring cross-sections do not apply."""
        return self.bearing_type == "thrust_ball"

    # ---- internal geometry
    @property
    def inner_raceway_diameter(self) -> float:
        """Inner groove-bottom diameter d_i [m]."""
        return float(
            raceway_diameters(self.pitch_diameter, self.ball_diameter, self.diametral_clearance)[0]
        )

    @property
    def outer_raceway_diameter(self) -> float:
        """Outer groove-bottom diameter d_o [m]."""
        return float(
            raceway_diameters(self.pitch_diameter, self.ball_diameter, self.diametral_clearance)[1]
        )

    @property
    def total_curvature(self) -> float:
        """B = f_i + f_o - 1 [-]."""
        return self.inner_groove_factor + self.outer_groove_factor - 1.0

    @property
    def groove_centre_distance(self) -> float:
        """A = B D_w, distance between the groove curvature centres [m]."""
        return self.total_curvature * self.ball_diameter

    @property
    def free_contact_angle(self) -> float:
        """Free contact angle from the clearance [rad]: arccos(H / A), H the radial distance
        of the groove centres of a loaded pair (seed 001 eq. 6; for circular grooves
        H = A - P_d/2, Harris & Kotzalas eq. 2.5)."""
        h, _ = self._pair_geometry()
        return math.acos(max(-1.0, min(1.0, h / self.groove_centre_distance)))

    @property
    def end_play(self) -> float:
        """Free end play P_e [m]: 2 (A sin(alpha_0) - e_i - e_o), e the axial offsets of
        gothic-arch groove halves (0 for circular grooves: 2 A sin(alpha_0), Harris &
        Kotzalas eq. 2.6)."""
        _, offsets = self._pair_geometry()
        return 2.0 * max(
            self.groove_centre_distance * math.sin(self.free_contact_angle) - offsets, 0.0
        )

    def _pair_geometry(self) -> tuple[float, float]:
        """(H, e_i + e_o): radial distance of a pair of groove centres (one per ring) and
        the sum of their axial offsets from the groove mid-planes, rings centred [m]."""
        free_i = (self.inner_groove_factor - 0.5) * self.ball_diameter
        free_o = (self.outer_groove_factor - 0.5) * self.ball_diameter
        h = (
            free_i * math.cos(self.inner_arch_angle)
            + free_o * math.cos(self.outer_arch_angle)
            - 0.5 * self.diametral_clearance
        )
        return h, free_i * math.sin(self.inner_arch_angle) + free_o * math.sin(
            self.outer_arch_angle
        )

    @property
    def gamma(self) -> float:
        """D_w cos(alpha) / d_m at the nominal contact angle [-]."""
        return self.ball_diameter * math.cos(self.contact_angle) / self.pitch_diameter

    def shoulder_depth(self, side: int = 1) -> float:
        """Groove depth from the groove bottom to a shoulder [m] (an estimate):
        GROOVE_DEPTH_RATIO D_w, except the thrust-side (``side`` = +1) shoulder of an
        angular-contact bearing, ANGULAR_SHOULDER_DEPTH_RATIO D_w. The thrust side is the
        one a positive contact angle leans to (docs/conventions.md).

        Parameters
        ----------
        side : int
            +1: the thrust side (the deeper shoulder of an angular-contact bearing); any other
            value (-1): the other side.
        """
        high = self.contact_angle > 0 and side > 0
        return (ANGULAR_SHOULDER_DEPTH_RATIO if high else GROOVE_DEPTH_RATIO) * self.ball_diameter

    def shoulder_angle(self, race: Race, side: int = 1) -> float:
        """Contact angle, measured at the groove centre from the groove bottom, at which
        the groove meets its shoulder on ``side`` (+1 thrust side, -1 the other) of the
        ``race`` ("inner" or "outer"): arccos(1 - depth / (f D_w)) [rad].

        Parameters
        ----------
        race : {"inner", "outer"}
            The ring whose groove it is (its groove factor f).
        side : int
            +1: the thrust side (the shoulder a positive contact angle leans to); any other
            value (-1): the other side.
        """
        f = self.inner_groove_factor if race == "inner" else self.outer_groove_factor
        return math.acos(
            max(-1.0, min(1.0, 1.0 - self.shoulder_depth(side) / (f * self.ball_diameter)))
        )

    def contact_radii(self, race: Race, contact_angle: float | None = None):
        """(R_x, R_y) of the ``race``'s contact ("inner" or "outer") at ``contact_angle``
        [rad] (default: the nominal contact angle) [m]; see :func:`contact_radii`.

        Parameters
        ----------
        race : {"inner", "outer"}
            The raceway whose contact it is.
        contact_angle : float or None
            Contact angle [rad]; None: the bearing's nominal ``contact_angle``.
        """
        f = self.inner_groove_factor if race == "inner" else self.outer_groove_factor
        alpha = self.contact_angle if contact_angle is None else contact_angle
        return contact_radii(self.ball_diameter, self.pitch_diameter, f, alpha, race)

    def curvature(self, race: Race, contact_angle: float | None = None):
        """Curvature sum [1/m] and difference [-] of the ``race``'s contact ("inner" or
        "outer") at ``contact_angle`` [rad] (default: the nominal contact angle).

        Parameters
        ----------
        race : {"inner", "outer"}
            The raceway whose contact it is.
        contact_angle : float or None
            Contact angle [rad]; None: the bearing's nominal ``contact_angle``.
        """
        return curvature_sum_difference(*self.contact_radii(race, contact_angle))

    # ---- masses and ring sections
    @property
    def ball_mass(self) -> float:
        """Mass of one ball, rho pi D_w^3 / 6 [kg]."""
        return self.ball_material.density * math.pi * self.ball_diameter**3 / 6.0

    def _needs_boundary(self, what: str) -> tuple[float, float, float]:
        if self.is_thrust:
            raise InputError(
                "bearing_type",
                self.bearing_type,
                "a radial bearing",
                f"the {what} is modelled for radial rings only",
            )
        for name in ("bore", "outside_diameter", "width"):
            if getattr(self, name) is None:
                raise InputError(name, None, "a value [m]", f"needed for the {what}")
        return self.bore, self.outside_diameter, self.width

    @cached_property
    def outer_ring_section(self) -> RingSection:
        """Outer ring cross-section between D and its shoulder, less the groove.

        The shoulder sits GROOVE_DEPTH_RATIO D_w inside the groove bottom (an estimate;
        see the module constant). Used by the ring-resonance model (seed 000: R, S, I).
        """
        _, big_d, width = self._needs_boundary("outer ring cross-section")
        bottom = 0.5 * self.outer_raceway_diameter
        shoulder = bottom - GROOVE_DEPTH_RATIO * self.ball_diameter
        return grooved_ring_section(
            shoulder,
            0.5 * big_d,
            width,
            self.outer_groove_factor * self.ball_diameter,
            bottom,
            "outer",
        )

    @cached_property
    def inner_ring_section(self) -> RingSection:
        """Inner ring cross-section between the bore and its shoulder, less the groove."""
        d, _, width = self._needs_boundary("inner ring cross-section")
        bottom = 0.5 * self.inner_raceway_diameter
        shoulder = bottom + GROOVE_DEPTH_RATIO * self.ball_diameter
        return grooved_ring_section(
            0.5 * d, shoulder, width, self.inner_groove_factor * self.ball_diameter, bottom, "inner"
        )

    @property
    def outer_ring_mass(self) -> float:
        """Mass of the outer ring, 2 pi R S rho (Pappus) [kg]."""
        s = self.outer_ring_section
        return 2.0 * math.pi * s.mean_radius * s.area * self.ring_material.density

    @property
    def inner_ring_mass(self) -> float:
        """Mass of the inner ring, 2 pi R S rho (Pappus) [kg]."""
        s = self.inner_ring_section
        return 2.0 * math.pi * s.mean_radius * s.area * self.ring_material.density

    def to_dict(self) -> dict:
        """JSON-ready summary in engineering units, with each value's source."""
        out = {
            "name": self.name,
            "bearing_type": self.bearing_type,
            "bore_mm": _mm(self.bore),
            "outside_diameter_mm": _mm(self.outside_diameter),
            "width_mm": _mm(self.width),
            "ball_count": int(self.ball_count),
            "ball_diameter_mm": _mm(self.ball_diameter),
            "pitch_diameter_mm": _mm(self.pitch_diameter),
            "contact_angle_deg": math.degrees(self.contact_angle),
            "inner_groove_factor": self.inner_groove_factor,
            "outer_groove_factor": self.outer_groove_factor,
            "diametral_clearance_um": self.diametral_clearance * 1e6,
            "inner_raceway_diameter_mm": _mm(self.inner_raceway_diameter),
            "outer_raceway_diameter_mm": _mm(self.outer_raceway_diameter),
            "free_contact_angle_deg": math.degrees(self.free_contact_angle),
            "end_play_um": self.end_play * 1e6,
            "ball_mass_g": self.ball_mass * 1e3,
            "geometry_source": self.geometry_source,
            "geometry_sources": {
                k: {"kind": v.kind, "reference": v.reference} for k, v in self.sources.items()
            },
        }
        if None not in (self.bore, self.outside_diameter, self.width) and not self.is_thrust:
            s = self.outer_ring_section
            out.update(
                {
                    "inner_ring_mass_g": self.inner_ring_mass * 1e3,
                    "outer_ring_mass_g": self.outer_ring_mass * 1e3,
                    "outer_ring_section_area_mm2": s.area * 1e6,
                    "outer_ring_mean_radius_mm": s.mean_radius * 1e3,
                    "outer_ring_second_moment_mm4": s.second_moment * 1e12,
                }
            )
        return out

    @property
    def geometry_source(self) -> str:
        """catalog, estimated or user when all internal values share one kind, else mixed."""
        kinds = {self.sources[k].kind for k in INTERNAL_FIELDS if k in self.sources}
        if not kinds:
            return "user"
        return kinds.pop() if len(kinds) == 1 else "mixed"


#: The internal-geometry fields whose provenance ``geometry_source`` summarises.
INTERNAL_FIELDS = (
    "ball_count",
    "ball_diameter",
    "pitch_diameter",
    "inner_groove_factor",
    "outer_groove_factor",
    "contact_angle",
    "diametral_clearance",
)
