"""Geometry of a roller bearing: :class:`RollerBearing` and its :class:`RollerProfile`
(layer 2), beside :class:`~bearinglab.geometry.BallBearing`.

Code tells the kinds apart by ``bearing.rolling_element``: ``"ball"`` for a BallBearing,
``"roller"`` here. Both expose the neutral ``element_count`` and ``element_diameter``
(Z and D_w / D_we) that kinematics and reports read; every analysis that models the
contacts dispatches on the kind (docs/capabilities/roller_bearings.md).

Kinds (``bearing_type``): ``cylindrical_roller`` (NU, N, NJ, NUP, NF; NN with two rows),
``needle_roller`` (long thin cylindrical rollers, the same model), ``tapered_roller``
(single row; two rows mirrored for a back-to-back or face-to-face pair or a double-row
bearing) and ``spherical_roller`` (kinematics only: the barrel-roller contact is not
modelled).

Geometry (Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing Technology*, 5th
ed., 2007, ch. 2; conventions: docs/conventions.md): Z rollers per row of mean diameter
D_we and effective length L_we on the pitch diameter d_m. A tapered bearing's contact
angle alpha is the cup (outer raceway) angle, the one behind ISO 281's e = 1.5 tan(alpha)
and Y = 0.4 cot(alpha); the cone (inner raceway) angle alpha_i and the roller half-angle
phi = (alpha - alpha_i)/2 follow, unless given, from the on-apex design in which cup,
cone and roller generatrices meet at one point of the bearing axis:
alpha = alpha_m + atan((D_we/d_m) sin(alpha_m)), alpha_i = alpha_m - atan(...), alpha_m
the angle of the roller axis. The rollers' large ends bear on the cone's rib (flange),
a point contact of the roller's spherical end (radius ``roller_end_radius``, by default
the distance from the apex to the large end, so that the contact normal runs along the
roller axis, ``flange_angle`` = 0) with the rib face.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .contact.line import crowned_profile, logarithmic_profile
from .errors import InputError, bore_below_outside, positive_number
from .geometry import Source
from .materials import BEARING_STEEL, Material

__all__ = [
    "ARRANGEMENTS",
    "PROFILE_KINDS",
    "ROLLER_INTERNAL_FIELDS",
    "ROLLER_TYPES",
    "RollerBearing",
    "RollerProfile",
    "Source",
    "on_apex_angles",
]

#: Bearing types a RollerBearing may be.
ROLLER_TYPES = ("cylindrical_roller", "needle_roller", "tapered_roller", "spherical_roller")
#: Roller profiles: unprofiled (flat over L_we, edge radii beyond it), ISO/TS 16281's
#: logarithmic profile, a circular crown, or one the user gives (positions and drops).
PROFILE_KINDS = ("flat", "logarithmic", "crowned", "user")
#: Row arrangements: one row; two rows of tapered rollers mirrored (back-to-back "O",
#: face-to-face "X"); two rows side by side of the same orientation (NN, tandem).
ARRANGEMENTS = ("single", "back_to_back", "face_to_face", "tandem")
#: The internal-geometry fields whose provenance ``geometry_source`` summarises.
ROLLER_INTERNAL_FIELDS = (
    "roller_count",
    "roller_diameter",
    "roller_length",
    "pitch_diameter",
    "contact_angle",
    "diametral_clearance",
)
#: Largest contact angle of a tapered roller bearing modelled (ISO 355 ends at 30 deg).
MAX_TAPERED_ANGLE = math.radians(45.0)


def _mm(value: float | None) -> float | None:
    return None if value is None else value * 1e3


@dataclass(frozen=True)
class RollerProfile:
    """The profile of a roller: how far its generatrix drops below the straight line, P(x).

    Parameters
    ----------
    kind : str
        ``"flat"`` (unprofiled: straight over L_we; ``edge_radius`` rounds the ends beyond
        it), ``"logarithmic"`` (ISO/TS 16281 eqs. 42-44), ``"crowned"`` (a circular crown
        of ``crown_radius`` beyond a straight middle ``flat_length``) or ``"user"``
        (``positions`` and ``drops``, interpolated linearly) [-].
    crown_radius : float or None
        R_c of a crowned profile [m].
    flat_length : float
        Straight middle of a crowned profile [m].
    edge_radius : float or None
        Corner radius of an unprofiled roller, outside L_we (reported; the slices cover
        L_we) [m].
    positions, drops : tuple of float
        A user profile: axial positions from the roller's middle [m] and the radius drop
        there [m] (>= 0), positions increasing.

    Examples
    --------
    >>> round(float(RollerProfile("crowned", crown_radius=1.0).drop(5e-3, 10e-3, 10e-3)) * 1e6, 3)
    12.5
    """

    kind: str = "logarithmic"
    crown_radius: float | None = None
    flat_length: float = 0.0
    edge_radius: float | None = None
    positions: tuple[float, ...] = ()
    drops: tuple[float, ...] = ()

    def __post_init__(self) -> None:
        if self.kind not in PROFILE_KINDS:
            raise InputError("roller_profile", self.kind, "one of " + ", ".join(PROFILE_KINDS))
        if self.kind == "crowned":
            positive_number("crown_radius", self.crown_radius, "a crown radius > 0 [m]")
            positive_number("flat_length", self.flat_length, "a length >= 0 [m]", zero=True)
        if self.edge_radius is not None:
            positive_number("edge_radius", self.edge_radius, "a radius >= 0 [m]", zero=True)
        if self.kind == "user":
            x = np.asarray(self.positions, float)
            y = np.asarray(self.drops, float)
            if (
                x.ndim != 1
                or x.size < 2
                or x.shape != y.shape
                or not np.all(np.isfinite(x))
                or not np.all(np.isfinite(y))
                or np.any(np.diff(x) <= 0)
                or np.any(y < 0)
            ):
                raise InputError(
                    "roller_profile",
                    "user",
                    "at least two increasing positions [m] with drops >= 0 [m] of the same count",
                )
            object.__setattr__(self, "positions", tuple(float(v) for v in x))
            object.__setattr__(self, "drops", tuple(float(v) for v in y))

    def drop(self, x, roller_diameter: float, effective_length: float, tapered: bool = False):
        """The radius drop P(x) of the roller at axial positions ``x`` [m].

        Parameters
        ----------
        x : float or array
            Positions from the roller's middle [m].
        roller_diameter : float
            D_we [m].
        effective_length : float
            L_we [m].
        tapered : bool
            A tapered roller (the logarithmic profile's tapered form) [-].
        """
        x = np.asarray(x, float)
        if self.kind == "flat":
            return np.zeros_like(x)[()]
        if self.kind == "logarithmic":
            return logarithmic_profile(x, roller_diameter, effective_length, tapered)
        if self.kind == "crowned":
            return crowned_profile(x, self.crown_radius, self.flat_length)
        return np.interp(x, self.positions, self.drops)[()]

    def to_dict(self) -> dict:
        """JSON-ready description in engineering units."""
        out: dict = {"kind": self.kind}
        if self.kind == "crowned":
            out["crown_radius_mm"] = self.crown_radius * 1e3
            out["flat_length_mm"] = self.flat_length * 1e3
        if self.edge_radius is not None:
            out["edge_radius_mm"] = self.edge_radius * 1e3
        if self.kind == "user":
            out["positions_mm"] = [v * 1e3 for v in self.positions]
            out["drops_um"] = [v * 1e6 for v in self.drops]
        return out


def on_apex_angles(contact_angle: float, roller_diameter: float, pitch_diameter: float):
    """(alpha_i, alpha_m, phi): cone angle, roller-axis angle and roller half-angle of an
    on-apex tapered bearing whose cup angle is ``contact_angle`` [rad].

    alpha = alpha_m + phi, alpha_i = alpha_m - phi, tan(phi) = (D_we/d_m) sin(alpha_m): the
    cup, cone and roller generatrices meet at one point of the bearing axis (Harris &
    Kotzalas 2007, ch. 2, tapered roller bearings).

    Parameters
    ----------
    contact_angle : float
        Cup angle alpha [rad].
    roller_diameter : float
        Mean roller diameter D_we [m].
    pitch_diameter : float
        d_m [m].

    Examples
    --------
    >>> [round(math.degrees(a), 3) for a in on_apex_angles(math.radians(13.86), 6.8, 38.5)]
    [9.725, 11.793, 2.067]
    """
    ratio = roller_diameter / pitch_diameter
    alpha_m = contact_angle
    for _ in range(60):
        new = contact_angle - math.atan(ratio * math.sin(alpha_m))
        if abs(new - alpha_m) < 1e-15:
            break
        alpha_m = new
    phi = contact_angle - alpha_m
    return alpha_m - phi, alpha_m, phi


def _number(name: str, value, allowed: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InputError(name, value, allowed)
    value = float(value)
    if not math.isfinite(value):
        raise InputError(name, value, allowed)
    return value


@dataclass(frozen=True)
class RollerBearing:
    """A cylindrical, needle, tapered (or, for kinematics, spherical) roller bearing.

    All lengths in metres, angles in radians (docs/conventions.md). ``rolling_element`` is
    ``"roller"``.

    Parameters
    ----------
    roller_count : int
        Rollers per row Z [-], >= 3.
    roller_diameter : float
        Roller diameter D_we (mean diameter of a tapered roller) [m].
    roller_length : float
        Effective roller length L_we, the length of the line contact [m].
    pitch_diameter : float
        d_m [m].
    contact_angle : float
        Nominal contact angle alpha [rad]: 0 for cylindrical and needle bearings, the cup
        angle of a tapered bearing (0 < alpha <= 45 deg).
    cone_angle : float or None
        Cone (inner raceway) angle alpha_i of a tapered bearing [rad]; None: on-apex
        (:func:`on_apex_angles`).
    rows : int
        Rows of rollers i [-] (1 or 2).
    arrangement : str
        ``"single"``, ``"back_to_back"``, ``"face_to_face"`` (two mirrored tapered rows)
        or ``"tandem"`` (two rows alike, e.g. NN) [-].
    row_spacing : float or None
        Axial distance between the two rows' middles [m]; None: the bearing ``width`` for a
        pair of tapered bearings (each of width T, side by side), half the ``width`` for a
        double-row bearing, else 1.5 L_we.
    diametral_clearance : float
        Radial internal clearance P_d (the whole radial play) [m]; negative: an
        interference (preload).
    axial_clearance : float
        Axial play of a mirrored pair or double-row tapered bearing [m]; negative: a
        preload (an axial interference).
    profile : RollerProfile
        The roller profile (default: ISO/TS 16281's logarithmic profile).
    flange_angle : float
        Tapered: angle of the rib contact normal to the roller axis, positive towards the
        cup [rad].
    roller_end_radius : float or None
        Tapered: radius of the roller's spherical large end bearing on the rib [m]; None:
        the distance from the apex to the large end.
    bore, outside_diameter, width : float or None
        Boundary dimensions d, D, and B (T of a tapered bearing) [m].
    ring_material, roller_material : Material
        Materials.
    name : str
        Label, e.g. the designation [-].
    bearing_type : str
        One of :data:`ROLLER_TYPES` [-].
    design : str
        Design variant as written (NU, N, NJ, NUP, NF, NN ...) [-].
    sources : dict
        Field -> :class:`~bearinglab.geometry.Source`.

    Examples
    --------
    >>> b = RollerBearing(roller_count=14, roller_diameter=10e-3, roller_length=9.6e-3,
    ...                   pitch_diameter=65.01e-3, profile=RollerProfile("flat"))
    >>> b.rolling_element, round(b.inner_raceway_diameter * 1e3, 2)
    ('roller', 55.01)
    """

    roller_count: int
    roller_diameter: float
    roller_length: float
    pitch_diameter: float
    contact_angle: float = 0.0
    cone_angle: float | None = None
    rows: int = 1
    arrangement: str = "single"
    row_spacing: float | None = None
    diametral_clearance: float = 0.0
    axial_clearance: float = 0.0
    profile: RollerProfile = field(default_factory=RollerProfile)
    flange_angle: float = 0.0
    roller_end_radius: float | None = None
    bore: float | None = None
    outside_diameter: float | None = None
    width: float | None = None
    ring_material: Material = BEARING_STEEL
    roller_material: Material = BEARING_STEEL
    name: str = ""
    bearing_type: str = "cylindrical_roller"
    design: str = ""
    sources: dict = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        if self.bearing_type not in ROLLER_TYPES:
            raise InputError("bearing_type", self.bearing_type, "one of " + ", ".join(ROLLER_TYPES))
        z = self.roller_count
        if isinstance(z, bool) or not isinstance(z, (int, np.integer)) or z < 3:
            raise InputError("roller_count", z, "an integer >= 3")
        for name in ("roller_diameter", "roller_length", "pitch_diameter"):
            positive_number(name, getattr(self, name), "a positive length [m]")
        dw, dm = self.roller_diameter, self.pitch_diameter
        if dm <= dw:
            raise InputError("pitch_diameter", dm, f"more than the roller diameter {dw:.6g} m")
        zmax = math.floor(math.pi / math.asin(dw / dm))
        if z > zmax:
            raise InputError(
                "roller_count",
                z,
                f"at most {zmax} rollers",
                f"{z} rollers of {dw * 1e3:.4g} mm do not fit around a "
                f"{dm * 1e3:.4g} mm pitch circle",
            )
        alpha = _number("contact_angle", self.contact_angle, "an angle [rad]")
        if self.is_tapered:
            if not 0.0 < alpha <= MAX_TAPERED_ANGLE:
                raise InputError(
                    "contact_angle", alpha, "an angle in (0, 45] degrees for a tapered bearing"
                )
        elif self.bearing_type == "spherical_roller":
            if not 0.0 <= alpha <= MAX_TAPERED_ANGLE:
                raise InputError("contact_angle", alpha, "an angle in [0, 45] degrees")
        elif alpha != 0.0:
            raise InputError(
                "contact_angle",
                alpha,
                "0 for a cylindrical or needle roller bearing",
                "its rollers run on cylindrical raceways",
            )
        if self.cone_angle is not None:
            if not self.is_tapered:
                raise InputError("cone_angle", self.cone_angle, "None: only tapered bearings")
            cone = _number("cone_angle", self.cone_angle, "an angle [rad]")
            if not 0.0 <= cone < alpha:
                raise InputError(
                    "cone_angle", cone, f"an angle in [0, {math.degrees(alpha):.4g}) degrees"
                )
        rows = self.rows
        if isinstance(rows, bool) or not isinstance(rows, (int, np.integer)) or rows not in (1, 2):
            raise InputError("rows", rows, "1 or 2")
        if self.arrangement not in ARRANGEMENTS:
            raise InputError("arrangement", self.arrangement, "one of " + ", ".join(ARRANGEMENTS))
        if (rows == 1) != (self.arrangement == "single"):
            raise InputError(
                "arrangement",
                self.arrangement,
                "single for one row, back_to_back, face_to_face or tandem for two",
            )
        if self.arrangement in ("back_to_back", "face_to_face") and self.bearing_type not in (
            "tapered_roller",
            "spherical_roller",
        ):
            raise InputError(
                "arrangement", self.arrangement, "tandem for two rows of cylindrical rollers"
            )
        if self.row_spacing is not None:
            positive_number("row_spacing", self.row_spacing, "a spacing >= 0 [m]", zero=True)
        limit = 0.1 * dw
        for name in ("diametral_clearance", "axial_clearance"):
            value = _number(name, getattr(self, name), "a finite length [m]")
            if abs(value) > limit:
                raise InputError(
                    name, value, f"a value in [{-limit:.3g}, {limit:.3g}] m (10 % of D_we)"
                )
        if not isinstance(self.profile, RollerProfile):
            raise InputError("roller_profile", self.profile, "a RollerProfile")
        beta = _number("flange_angle", self.flange_angle, "an angle [rad]")
        if abs(beta) >= math.radians(30.0):
            raise InputError("flange_angle", beta, "an angle within +-30 degrees")
        if self.roller_end_radius is not None:
            positive_number("roller_end_radius", self.roller_end_radius, "a radius > 0 [m]")
        for name in ("bore", "outside_diameter", "width"):
            if getattr(self, name) is not None:
                positive_number(name, getattr(self, name), "a positive length [m]")
        d, big_d = self.bore, self.outside_diameter
        if d is not None and big_d is not None:
            bore_below_outside(d, big_d, "bore")
        if d is not None and self.inner_raceway_diameter <= d:
            raise InputError(
                "roller_diameter",
                dw,
                "a roller that leaves material under the inner raceway",
                f"inner raceway {self.inner_raceway_diameter * 1e3:.4g} mm is not above the "
                f"bore {d * 1e3:.4g} mm",
            )
        if big_d is not None and self.outer_raceway_diameter >= big_d:
            raise InputError(
                "roller_diameter",
                dw,
                "a roller that leaves material outside the outer raceway",
                f"outer raceway {self.outer_raceway_diameter * 1e3:.4g} mm is not inside the "
                f"outside diameter {big_d * 1e3:.4g} mm",
            )

    # ---- the kind
    @property
    def rolling_element(self) -> str:
        """``"roller"`` (a BallBearing gives ``"ball"``) [-]."""
        return "roller"

    @property
    def element_count(self) -> int:
        """Rolling elements per row, Z [-]."""
        return int(self.roller_count)

    @property
    def element_diameter(self) -> float:
        """D_we [m]."""
        return self.roller_diameter

    @property
    def is_tapered(self) -> bool:
        """A tapered roller bearing [-]."""
        return self.bearing_type == "tapered_roller"

    @property
    def is_thrust(self) -> bool:
        """False: radial bearings only [-]."""
        return False

    @property
    def contact_modelled(self) -> bool:
        """Whether the line contacts are modelled (not for spherical rollers) [-]."""
        return self.bearing_type != "spherical_roller"

    # ---- derived geometry
    @property
    def gamma(self) -> float:
        """D_we cos(alpha) / d_m [-]."""
        return self.roller_diameter * math.cos(self.contact_angle) / self.pitch_diameter

    @property
    def inner_angle(self) -> float:
        """Cone (inner raceway) angle alpha_i [rad]: 0 for cylindrical bearings."""
        if not self.is_tapered:
            return self.contact_angle
        if self.cone_angle is not None:
            return self.cone_angle
        return on_apex_angles(self.contact_angle, self.roller_diameter, self.pitch_diameter)[0]

    @property
    def roller_axis_angle(self) -> float:
        """Angle alpha_m of the roller axis to the bearing axis [rad]."""
        return 0.5 * (self.contact_angle + self.inner_angle)

    @property
    def roller_half_angle(self) -> float:
        """Half the roller's cone angle, phi = (alpha - alpha_i)/2 [rad]."""
        return 0.5 * (self.contact_angle - self.inner_angle)

    @property
    def apex_distance(self) -> float:
        """Distance from the apex to the roller's middle along its axis, (d_m/2)/sin(alpha_m)
        [m]; infinite for a cylindrical bearing."""
        s = math.sin(self.roller_axis_angle)
        return math.inf if s <= 0 else 0.5 * self.pitch_diameter / s

    @property
    def end_radius(self) -> float:
        """Radius of the roller's spherical large end on the rib [m] (tapered)."""
        if self.roller_end_radius is not None:
            return self.roller_end_radius
        return self.apex_distance + 0.5 * self.roller_length

    @property
    def inner_raceway_diameter(self) -> float:
        """Inner raceway diameter at the roller's middle, d_m - D_we cos(alpha_i) [m]
        (cylindrical: d_m - D_we)."""
        return self.pitch_diameter - self.roller_diameter * math.cos(self.inner_angle)

    @property
    def outer_raceway_diameter(self) -> float:
        """Outer raceway diameter at the roller's middle, d_m + D_we cos(alpha) [m]."""
        return self.pitch_diameter + self.roller_diameter * math.cos(self.contact_angle)

    @property
    def effective_row_spacing(self) -> float:
        """Axial distance between the rows' middles [m] (0 for one row)."""
        if self.rows == 1:
            return 0.0
        if self.row_spacing is not None:
            return self.row_spacing
        if self.width is not None:
            return (
                self.width
                if self.arrangement in ("back_to_back", "face_to_face")
                else (0.5 * self.width)
            )
        return 1.5 * self.roller_length

    def row_layout(self) -> tuple[np.ndarray, np.ndarray]:
        """(axial offsets of the rows' middles [m], orientation sign of each row [-]).

        A row of sign +1 has its contact lines leaning towards +z going from the inner to
        the outer ring (a positive axial load on the inner ring seats it,
        docs/conventions.md), so that its pressure centre (where the contact line through
        the roller meets the axis) lies on its -z side; -1 is its mirror image.
        Back-to-back ("O"): the pressure centres lie outside the pair, the row at -z has
        sign +1; face-to-face ("X"): inside, sign -1 at -z.
        """
        if self.rows == 1:
            return np.zeros(1), np.ones(1)
        half = 0.5 * self.effective_row_spacing
        offsets = np.array([-half, half])
        if self.arrangement == "back_to_back":
            return offsets, np.array([1.0, -1.0])
        if self.arrangement == "face_to_face":
            return offsets, np.array([-1.0, 1.0])
        return offsets, np.ones(2)

    @property
    def roller_mass(self) -> float:
        """Mass of one roller, rho pi D_we^2 L_we / 4 [kg] (the mean diameter for a tapered
        roller; the corners outside L_we neglected)."""
        d = self.roller_diameter
        return self.roller_material.density * math.pi * d * d * self.roller_length / 4.0

    def profile_drop(self, x):
        """The roller's profile drop P(x) at positions ``x`` from its middle [m].

        Parameters
        ----------
        x : float or array
            Positions along the roller from its middle [m].
        """
        return self.profile.drop(x, self.roller_diameter, self.roller_length, self.is_tapered)

    # ---- reporting
    def to_dict(self) -> dict:
        """JSON-ready summary in engineering units, with each value's source."""
        return {
            "name": self.name,
            "bearing_type": self.bearing_type,
            "design": self.design,
            "rolling_element": "roller",
            "bore_mm": _mm(self.bore),
            "outside_diameter_mm": _mm(self.outside_diameter),
            "width_mm": _mm(self.width),
            "roller_count": int(self.roller_count),
            "roller_diameter_mm": self.roller_diameter * 1e3,
            "roller_length_mm": self.roller_length * 1e3,
            "pitch_diameter_mm": self.pitch_diameter * 1e3,
            "contact_angle_deg": math.degrees(self.contact_angle),
            "cone_angle_deg": math.degrees(self.inner_angle),
            "rows": int(self.rows),
            "arrangement": self.arrangement,
            "row_spacing_mm": self.effective_row_spacing * 1e3,
            "diametral_clearance_um": self.diametral_clearance * 1e6,
            "axial_clearance_um": self.axial_clearance * 1e6,
            "roller_profile": self.profile.to_dict(),
            "inner_raceway_diameter_mm": self.inner_raceway_diameter * 1e3,
            "outer_raceway_diameter_mm": self.outer_raceway_diameter * 1e3,
            "roller_mass_g": self.roller_mass * 1e3,
            "geometry_source": self.geometry_source,
            "geometry_sources": {
                k: {"kind": v.kind, "reference": v.reference} for k, v in self.sources.items()
            },
        }

    @property
    def geometry_source(self) -> str:
        """catalog, estimated or user when all internal values share one kind, else mixed."""
        kinds = {self.sources[k].kind for k in ROLLER_INTERNAL_FIELDS if k in self.sources}
        if not kinds:
            return "user"
        return kinds.pop() if len(kinds) == 1 else "mixed"
