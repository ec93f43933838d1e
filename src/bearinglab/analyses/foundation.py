"""The foundation's requests: what a designation or a geometry is (``info``), the
Hertz contact of one rolling element with both raceways (``contact``) and the kinematic
defect frequencies (``frequencies``, pure rolling). Each builds the models from the
request (:mod:`bearinglab.inputs`), calls the library once and keeps the result."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..errors import CatalogError, DesignationError, InputError
from ..inputs import INPUTS, Input, bearing_from, bearing_warnings, no_effect, si, speed_from
from .base import BEARING_INPUTS, Analysis, Outcome, inputs, plot_file


@dataclass(frozen=True)
class InfoResult:
    """What a request names: the designation as typed (``text``), its reading
    (``decoded``, a :class:`~bearinglab.designation.Designation` or None), the bearing
    (a :class:`~bearinglab.geometry.BallBearing`, or None when there is no internal
    geometry model for it, ``why_no_geometry`` saying why), its boundary dimensions
    (``dimensions``, when the bearing is None; ``why_no_dimensions`` otherwise) and the
    ``warnings``."""

    text: str | None
    decoded: object = None
    bearing: object = None
    dimensions: object = None
    why_no_geometry: str | None = None
    why_no_dimensions: str | None = None
    warnings: tuple = field(default_factory=tuple)

    def to_dict(self) -> dict:
        """The designation read, the geometry with its sources and the frequency factors
        (per shaft revolution), or the boundary dimensions and why there is no geometry."""
        from ..kinematics import FREQUENCY_NAMES, defect_frequencies

        decoded, bearing, dims = self.decoded, self.bearing, self.dimensions
        out = {
            "designation": self.text,
            "system": decoded.system if decoded else None,
            "bearing_type": (decoded.bearing_type if decoded else bearing.bearing_type),
        }
        if bearing is not None:
            out.update(bearing.to_dict())
            out["designation"] = self.text
            f = defect_frequencies(bearing, 2 * math.pi)
            out["frequency_factors"] = {f"{n}_order": f.orders[n] for n in FREQUENCY_NAMES}
        else:
            out.update(
                {
                    "bore_mm": decoded.bore_mm if dims is None else dims.bore * 1e3,
                    "outside_diameter_mm": None if dims is None else dims.outside_diameter * 1e3,
                    "width_mm": None if dims is None else dims.width * 1e3,
                    "ball_count": None,
                    "ball_diameter_mm": None,
                    "pitch_diameter_mm": None,
                    "contact_angle_deg": decoded.contact_angle_deg,
                    "geometry_source": None,
                    "dimensions": None if dims is None else dims.to_dict(),
                    "dimensions_standard": None if dims is None else dims.standard,
                    "no_dimensions_reason": self.why_no_dimensions,
                    "no_geometry_reason": self.why_no_geometry,
                }
            )
        out["warnings"] = list(self.warnings)
        if decoded is not None:
            out["decoded"] = decoded.to_dict()
        return out


def info(values: dict) -> InfoResult:
    """The ``info`` request: the designation decoded and the bearing's geometry with its
    sources; for a designation without an internal-geometry model (a roller bearing, a
    size not in the catalogue), its boundary dimensions and why there is no geometry."""
    from ..catalog import boundary_dimensions, published_geometry
    from ..designation import parse

    designation = values.get("designation")
    decoded = None
    try:
        bearing, from_catalog = bearing_from(values)
    except CatalogError as exc:  # roller bearings, sizes not in the catalogue...
        bearing, from_catalog, why_no_geometry = None, None, str(exc)
    else:
        why_no_geometry = None
    if designation:
        try:
            decoded = from_catalog or parse(designation, system=values.get("system"))
        except DesignationError:
            if published_geometry(designation) is None:  # not a catalogue name either
                raise
    if bearing is None and decoded is None:
        raise CatalogError(why_no_geometry)
    dims = why_no_dims = None
    if bearing is None:
        try:
            dims = boundary_dimensions(decoded)
        except CatalogError as exc:
            why_no_dims = str(exc)
    warnings = () if bearing is None else tuple(bearing_warnings(bearing))
    return InfoResult(designation, decoded, bearing, dims, why_no_geometry, why_no_dims, warnings)


INFO = Analysis(
    "info",
    "The designation decoded, boundary dimensions and internal geometry with their sources.",
    BEARING_INPUTS,
    run=info,
)


def contact(values: dict) -> Outcome:
    """The ``contact`` request: the Hertz contact of one ball with the inner and outer
    raceway under `ball_load_n` (:func:`bearinglab.contact.ball_race.ball_contacts`), or
    the line contact of one roller under `roller_load_n` by slices, with the tilt
    `misalignment_mrad` between the rings
    (:func:`bearinglab.contact.roller_race.roller_contacts`)."""
    bearing, decoded = bearing_from(values)
    roller = bearing.rolling_element == "roller"
    own, other = ("roller_load_n", "ball_load_n") if roller else ("ball_load_n", "roller_load_n")
    if values.get(other) is not None:
        raise InputError(
            other,
            values[other],
            f"no value for a {bearing.rolling_element} bearing: give `{own}`",
        )
    if values.get(own) is None:
        raise InputError(own, None, f"the load on one {bearing.rolling_element} [N]")
    if roller:
        from ..contact.roller_race import roller_contacts

        result = roller_contacts(
            bearing,
            values[own],
            tilt=si(values, "misalignment_mrad", 0.0),
            slices=values.get("slices") or 30,
        )
        method = values.get("hertz_method")
        unused = no_effect(
            [("hertz_method", method not in (None, "exact"))],
            "for a roller (a line contact, by slices)",
        )
    else:
        from ..contact.ball_race import ball_contacts  # scipy.special: only this request

        method = (values.get("hertz_method") or "exact").replace("-", "_")
        result = ball_contacts(bearing, values[own], method=method)
        given = [(n, bool(values.get(n))) for n in ("misalignment_mrad",)]
        unused = no_effect(given, "on a ball's contact") + no_effect(
            [("slices", values.get("slices") not in (None, 30))], "for a ball (a point contact)"
        )
    warnings = bearing_warnings(bearing, decoded) + list(result.to_dict()["warnings"]) + unused
    return Outcome(result, values.get("designation"), tuple(warnings), bearing)


CONTACT = Analysis(
    "contact",
    "Hertz contact of one ball with both raceways (ball_contacts).",
    {
        **BEARING_INPUTS,
        "ball_load_n": Input(
            "number",
            None,
            "Normal load on one ball [N] (a ball bearing).",
            low=0.0,
            high=1e7,
            low_open=True,
            what="a load",
        ),
        "roller_load_n": Input(
            "number",
            None,
            "Normal load on one roller [N] (a roller bearing).",
            low=0.0,
            high=1e7,
            low_open=True,
            what="a load",
        ),
        "misalignment_mrad": INPUTS["misalignment_mrad"].with_(
            help="Tilt between the rings in the roller's plane [mrad] (a roller bearing)."
        ),
        **inputs("slices"),
        "hertz_method": Input(
            "text",
            "exact",
            "Ellipticity and elliptic integrals: exact or Hamrock-Brewe.",
            choices=("exact", "hamrock-brewe"),
            aliases=("method",),
            sets="method",
        ),
    },
    run=contact,
    files=plot_file("the contact ellipses and pressures"),
)

__all__ = ["CONTACT", "INFO", "InfoResult", "contact", "info"]


# ------------------------------------------------------------------ kinematics
def frequencies(values: dict) -> Outcome:
    """The ``frequencies`` request: kinematic defect frequencies (pure rolling)."""
    from ..inputs import given_fields
    from ..kinematics import defect_frequencies, geometry_inputs
    from ..plausibility import speed_factor_warnings

    shaft_speed = speed_from(values, positive=False)
    bearing, decoded = bearing_from(values)
    f = defect_frequencies(bearing, shaft_speed, outer_rotating=bool(values.get("outer_rotating")))
    used = geometry_inputs(bearing)
    unused = [(name, field not in used) for name, field in given_fields(values).items()]
    warnings = (
        bearing_warnings(bearing, decoded)
        + speed_factor_warnings(bearing, shaft_speed)
        + no_effect(unused, "on the defect frequencies (pure rolling: Z, D_w, d_m, contact angle)")
    )
    return Outcome(f, values.get("designation"), tuple(warnings), bearing)


_FREQ_OUT = {
    f"{n}_{u}": "f" for u in ("hz", "order") for n in ("ftf", "bpfo", "bpfi", "bsf", "ball_defect")
}
_FREQ_OUT["shaft_hz"] = "f"

FREQUENCIES = Analysis(
    "frequencies",
    "Kinematic defect frequencies (defect_frequencies).",
    {
        **BEARING_INPUTS,
        "speed_rpm": INPUTS["speed_rpm"].with_(default=...),
        **inputs("outer_rotating"),
    },
    run=frequencies,
    outputs=_FREQ_OUT,
    largest=20000,
    files=plot_file("the defect frequencies"),
)
