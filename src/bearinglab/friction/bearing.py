"""What the friction models need of a bearing (layer 2): its type, bore d, outside
diameter D, pitch diameter d_m, and from the designation its series (for the SKF
constants), design variant (a full-complement cylindrical roller bearing) and closures
(seals), with where d_m came from.

A ball bearing comes with its internal geometry (:class:`~bearinglab.geometry.BallBearing`,
from the catalogue or the user), so d_m is its ball pitch diameter and ISO 281 can form
the equivalent load from it. Other bearing types have no internal-geometry model in
bearinglab: they are read from their ISO boundary dimensions
(:func:`bearinglab.catalog.boundary_dimensions`, ISO 15 / 355 / 104), and d_m is estimated
as (d + D) / 2 -- the mean diameter that SKF's model uses by definition (SKF catalogue
10000 EN, "The SKF model for calculating the frictional moment") and the usual estimate
of the pitch diameter that seed 003's M = mu P d_m / 2 asks for.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import InputError, bore_below_outside, positive_number

#: How d_m is estimated when it is not known.
MEAN_DIAMETER_ESTIMATE = "estimated as (d + D) / 2"
#: Seed-003 friction types that are not bearing types of the designation glossary, and the
#: bearing type they belong to.
_FRICTION_TYPE_BEARING = {
    "cylindrical_roller_full_complement": "cylindrical_roller",
    "cylindrical_roller_thrust": "thrust_roller",
    "tapered_roller_thrust": "thrust_roller",
    "tapered_roller_thrust_full_complement": "thrust_roller",
}


def _length(name: str, value, *, optional: bool = False) -> float | None:
    if value is None and optional:
        return None
    if positive_number(name, value, "a length in (0, 100] m") > 100.0:
        raise InputError(name, value, "a length in (0, {most}]", unit="m", numbers={"most": 100.0})
    return float(value)


@dataclass(frozen=True)
class FrictionBearing:
    """A bearing as the friction models see it.

    Parameters
    ----------
    name : str
        Label (the designation or catalogue name) [-].
    bearing_type : str
        One of :data:`bearinglab.designation.BEARING_TYPES` [-].
    bore, outside_diameter : float or None
        d, D [m] (the SKF model needs both; None when a ball bearing was given without
        them).
    pitch_diameter : float
        d_m [m]: the ball pitch diameter, or the estimate (d + D) / 2.
    pitch_diameter_source : str
        Where d_m came from [-].
    series : str or None
        ISO series of the designation (``"62"``) for the SKF deep-groove constants [-].
    design_variant : str or None
        ISO type prefix or GOST design variant (``"NCF"``) [-].
    closures : str
        Shields and seals of the designation (:data:`bearinglab.designation.CLOSURES`) [-].
    ball_bearing : BallBearing or None
        The internal geometry, when the bearing is a ball bearing bearinglab models.
    roller_bearing : RollerBearing or None
        The internal geometry, when it is a roller bearing bearinglab models.

    Examples
    --------
    >>> FrictionBearing.from_dimensions(0.025, 0.052).pitch_diameter
    0.0385
    """

    name: str
    bearing_type: str
    bore: float | None
    outside_diameter: float | None
    pitch_diameter: float
    pitch_diameter_source: str
    series: str | None = None
    design_variant: str | None = None
    closures: str = "unknown"
    ball_bearing: object = None
    roller_bearing: object = None

    def __post_init__(self) -> None:
        from ..designation import BEARING_TYPES

        if self.bearing_type not in BEARING_TYPES:
            raise InputError(
                "bearing_type", self.bearing_type, "one of " + ", ".join(BEARING_TYPES)
            )
        d = _length("bore", self.bore, optional=True)
        big_d = _length("outside_diameter", self.outside_diameter, optional=True)
        dm = _length("pitch_diameter", self.pitch_diameter)
        if d is not None and big_d is not None:
            bore_below_outside(d, big_d)
            if not d < dm < big_d:
                raise InputError(
                    "pitch_diameter",
                    dm,
                    "between the bore {d} and the outside diameter {D}",
                    unit="m",
                    numbers={"d": d, "D": big_d},
                )

    @classmethod
    def from_ball_bearing(cls, bearing, designation=None) -> FrictionBearing:
        """A ``bearing`` (:class:`~bearinglab.geometry.BallBearing`; d_m its ball pitch
        diameter) and, optionally, its decoded ``designation``
        (:class:`~bearinglab.designation.Designation`); without one
        the series is read from the bearing's name when that is a designation.

        Parameters
        ----------
        bearing : BallBearing
            The bearing (SI); its pitch diameter is the d_m of the friction model.
        designation : Designation or None
            The bearing's decoded designation (series, design variant, closures); None: read
            from the bearing's name when that is a designation (closures "unknown" otherwise).

        Examples
        --------
        >>> from bearinglab.catalog import bearing_from_designation
        >>> FrictionBearing.from_ball_bearing(*bearing_from_designation("6205-2RS")).closures
        '2seals'
        """
        return cls._from_model(bearing, designation, "ball", ball_bearing=bearing)

    @classmethod
    def from_roller_bearing(cls, bearing, designation=None) -> FrictionBearing:
        """A ``bearing`` (:class:`~bearinglab.roller_geometry.RollerBearing`; d_m its roller
        pitch diameter) and, optionally, its decoded ``designation``.

        Parameters
        ----------
        bearing : RollerBearing
            The roller bearing [-].
        designation : Designation or None
            Its designation (series, design variant, closures) [-].

        Examples
        --------
        >>> from bearinglab.catalog import bearing_from_designation
        >>> b, des = bearing_from_designation("NU205", rollers=True)
        >>> FrictionBearing.from_roller_bearing(b, des).design_variant
        'NU'
        """
        return cls._from_model(
            bearing, designation, "roller", own_design=bearing.design, roller_bearing=bearing
        )

    @classmethod
    def _from_model(
        cls, bearing, designation, element: str, own_design: str | None = None, **model
    ) -> FrictionBearing:
        """A bearing bearinglab models, kept as ``model`` (``ball_bearing=bearing`` or
        ``roller_bearing=bearing``), d_m its ``element``'s (ball, roller) pitch diameter;
        series, design variant and closures from the ``designation``, else from the
        bearing's name when that is one; a roller bearing's ``own_design`` (``"NU"``) when
        the designation gives no design variant."""
        if designation is None:
            designation = _designation_of(bearing.name)
        design_variant = getattr(designation, "design_variant", None)
        if own_design is not None:
            design_variant = design_variant or own_design or None
        return cls(
            name=bearing.name or "bearing",
            bearing_type=bearing.bearing_type,
            bore=bearing.bore,
            outside_diameter=bearing.outside_diameter,
            pitch_diameter=bearing.pitch_diameter,
            pitch_diameter_source=f"{element} pitch diameter ({bearing.geometry_source})",
            series=getattr(designation, "series", None),
            design_variant=design_variant,
            closures=getattr(designation, "closures", "unknown"),
            **model,
        )

    @classmethod
    def from_designation(
        cls,
        text: str,
        system: str | None = None,
        *,
        bore: float | None = None,
        outside_diameter: float | None = None,
        pitch_diameter: float | None = None,
    ) -> FrictionBearing:
        """Any designation through its ISO boundary dimensions (no internal geometry); d,
        D and d_m may be given to replace the table's values and the estimate.

        Parameters
        ----------
        text : str
            The designation (GOST or ISO) [-].
        system : str or None
            ``"gost"`` or ``"iso"`` to read it in one system only [-].
        bore, outside_diameter, pitch_diameter : float or None
            d, D, d_m [m].

        Examples
        --------
        >>> b = FrictionBearing.from_designation("NU205")
        >>> b.bearing_type, round(b.pitch_diameter * 1e3, 3), b.pitch_diameter_source
        ('cylindrical_roller', 38.5, 'estimated as (d + D) / 2')
        """
        from ..catalog import boundary_dimensions
        from ..designation import parse

        des = parse(text, system)
        dims = boundary_dimensions(des)
        given = {
            k for k, v in (("bore", bore), ("outside_diameter", outside_diameter)) if v is not None
        }
        d = dims.bore if bore is None else _length("bore", bore)
        big_d = (
            dims.outside_diameter
            if outside_diameter is None
            else _length("outside_diameter", outside_diameter)
        )
        return cls._with_pitch(
            text,
            des.bearing_type,
            d,
            big_d,
            pitch_diameter,
            given,
            series=des.series,
            design_variant=des.design_variant,
            closures=des.closures,
        )

    @classmethod
    def from_dimensions(
        cls,
        bore: float,
        outside_diameter: float,
        *,
        bearing_type: str | None = None,
        pitch_diameter: float | None = None,
        name: str = "user geometry",
    ) -> FrictionBearing:
        """A bearing known only by d and D (and perhaps d_m).

        Parameters
        ----------
        bore, outside_diameter : float
            d, D [m].
        bearing_type : str or None
            A bearing type, or a seed-003 friction type (which names its bearing type);
            None: a deep-groove ball bearing (``radial_ball``) [-].
        pitch_diameter : float or None
            d_m [m]; None: (d + D) / 2.
        name : str
            Label [-].
        """
        kind = bearing_type or "radial_ball"
        kind = _FRICTION_TYPE_BEARING.get(kind, kind)
        return cls._with_pitch(
            name,
            kind,
            _length("bore", bore),
            _length("outside_diameter", outside_diameter),
            pitch_diameter,
            {"bore", "outside_diameter"},
        )

    @classmethod
    def _with_pitch(cls, name, kind, bore, outside, pitch, given, **kwargs) -> FrictionBearing:
        """The bearing with d_m given or estimated; a mismatch of d, D and d_m is blamed on a
        value that was given rather than one from the table."""
        blame_outside = "outside_diameter" in given or "bore" not in given
        bore_below_outside(bore, outside, "outside_diameter" if blame_outside else "bore")
        if pitch is None:
            return cls(
                name, kind, bore, outside, 0.5 * (bore + outside), MEAN_DIAMETER_ESTIMATE, **kwargs
            )
        pitch = _length("pitch_diameter", pitch)
        if not bore < pitch < outside:
            raise InputError(
                "pitch_diameter",
                pitch,
                "between the bore {d} and the outside diameter {D}",
                unit="m",
                numbers={"d": bore, "D": outside},
            )
        return cls(name, kind, bore, outside, pitch, "given", **kwargs)


def _designation_of(name: str | None):
    """The designation a bearing's name reads as, or None."""
    from ..designation import parse
    from ..errors import DesignationError

    if not name:
        return None
    try:
        return parse(name)
    except (DesignationError, InputError):
        return None


def as_friction_bearing(bearing, designation=None) -> FrictionBearing:
    """A :class:`FrictionBearing` from a BallBearing or a RollerBearing (with its
    designation, if known) or a FrictionBearing."""
    from ..geometry import BallBearing
    from ..roller_geometry import RollerBearing

    if isinstance(bearing, FrictionBearing):
        return bearing
    if isinstance(bearing, BallBearing):
        return FrictionBearing.from_ball_bearing(bearing, designation)
    if isinstance(bearing, RollerBearing):
        return FrictionBearing.from_roller_bearing(bearing, designation)
    raise InputError(
        "bearing", type(bearing).__name__, "a BallBearing, a RollerBearing or a FrictionBearing"
    )
