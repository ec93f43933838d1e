"""The friction command: torque and power loss by seed 003's constant coefficient or by
the SKF four-component model (bearinglab.friction)."""

import math
from enum import Enum
from typing import Annotated

import typer
from rich.markup import escape

from ..catalog import boundary_dimensions
from ..designation import parse
from ..errors import BearinglabError, CatalogError, InputError
from ..friction import (
    DEEP_GROOVE_CONSTANTS,
    SEED003_COEFFICIENTS,
    SKF_BEARING_TYPES,
    SkfGeometryConstants,
    constant_friction,
    deep_groove_constants,
    friction_type_of,
    seal_moment,
    skf_friction,
)
from ..life import equivalent_dynamic_load, load_ratings
from ..lubrication import LUBRICANTS, ZERO_CELSIUS
from ._app import command_app, console
from ._inputs import (
    MAX_LOAD_N,
    JsonOpt,
    OptionError,
    _geometry_warnings,
    _print_warnings,
    load_n,
    resolve_bearing,
    speed_rad_s,
    with_geometry,
)
from ._output import _emit_json, _table

app = command_app()

DesignationArg = Annotated[str | None, typer.Argument(
    help="Bearing designation or catalogue name; optional with --bore-mm and "
         "--outside-diameter-mm.", show_default=False)]
#: Types with an internal-geometry model (resolved as a BallBearing, pitch diameter known).
_BALL_TYPES = ("radial_ball", "angular_contact_ball", "four_point_contact_ball")


class FrictionModel(str, Enum):
    constant = "constant"
    skf = "skf"


class Seals(str, Enum):
    none = "none"
    shields = "shields"
    contact = "contact"


class Lubrication(str, Enum):
    grease = "grease"
    oil_air = "oil-air"
    oil_jet = "oil-jet"
    low_oil_bath = "low-oil-bath"


class OilKind(str, Enum):
    mineral = "mineral"
    synthetic = "synthetic"
    transmission_fluid = "transmission-fluid"


def _finite(flag: str, value: float, low: float, high: float, what: str,
            low_open: bool = False) -> float:
    ok = math.isfinite(value) and (low < value if low_open else low <= value) and value <= high
    if not ok:
        raise OptionError(flag, value, what)
    return float(value)


def _numbers(flag: str, text: str, counts: tuple, what: str) -> list[float]:
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) not in counts or not all(math.isfinite(v) and v >= 0 for v in values):
        raise OptionError(flag, text, what)
    return values


class _Bearing:
    """What the friction models need of the bearing, and where each value came from."""

    def __init__(self, name, bearing_type, design_variant, series, closures, bore,
                 outside_diameter, pitch_diameter, pitch_source, warnings, ball_bearing=None):
        self.name = name
        self.ball_bearing = ball_bearing
        self.bearing_type = bearing_type
        self.design_variant = design_variant
        self.series = series
        self.closures = closures
        self.bore = bore
        self.outside_diameter = outside_diameter
        self.pitch_diameter = pitch_diameter
        self.pitch_source = pitch_source
        self.warnings = warnings


def _mm_option(geometry: dict, name: str, flag: str) -> float | None:
    value = geometry.get(name)
    if value is None:
        return None
    return _finite(flag, value, 0.0, 1e5, "a length in (0, 100000] mm", low_open=True) * 1e-3


def _from_dimensions(name, bearing_type, des, bore, outside, geometry) -> _Bearing:
    if outside <= bore:
        raise OptionError("--outside-diameter-mm", outside * 1e3,
                          f"more than the bore {bore * 1e3:.6g} mm")
    pitch = _mm_option(geometry, "pitch_diameter_mm", "--pitch-diameter-mm")
    source = "given" if pitch is not None else "estimated as (d + D) / 2"
    if pitch is None:
        pitch = 0.5 * (bore + outside)
    return _Bearing(name, bearing_type, getattr(des, "design_variant", None),
                    getattr(des, "series", None), getattr(des, "closures", "unknown"),
                    bore, outside, pitch, source, [])


def _resolve(designation: str | None, geometry: dict, type_option: str | None) -> _Bearing:
    """The bearing from a designation (ball bearings through the catalogue's full model,
    other types through their ISO boundary dimensions) or from --bore-mm and
    --outside-diameter-mm."""
    if designation is not None and not designation.strip():
        raise OptionError("DESIGNATION", designation, "a bearing designation (e.g. 6205, NU205)")
    if designation is None:
        bore = _mm_option(geometry, "bore_mm", "--bore-mm")
        outside = _mm_option(geometry, "outside_diameter_mm", "--outside-diameter-mm")
        if bore is None or outside is None:
            if geometry.get("balls") is not None or geometry.get("geometry") is not None:
                bearing, _ = resolve_bearing(None, geometry)
                return _from_ball_bearing(bearing, None)
            raise OptionError("DESIGNATION", None, "a designation, or --bore-mm and "
                              "--outside-diameter-mm (with --type)")
        kind = type_option if type_option in _BALL_TYPES else "radial_ball"
        return _from_dimensions("user geometry", kind, None, bore, outside, geometry)
    try:
        bearing, des = resolve_bearing(designation, geometry)
        return _from_ball_bearing(bearing, des)
    except CatalogError as first:
        system = geometry.get("system")
        try:
            des = parse(designation, system.value if system is not None else None)
            dims = boundary_dimensions(des)
        except BearinglabError:
            raise first from None
        bore = _mm_option(geometry, "bore_mm", "--bore-mm") or dims.bore
        outside = _mm_option(geometry, "outside_diameter_mm",
                             "--outside-diameter-mm") or dims.outside_diameter
        return _from_dimensions(designation, des.bearing_type, des, bore, outside, geometry)


def _from_ball_bearing(bearing, des) -> _Bearing:
    return _Bearing(bearing.name or "bearing", bearing.bearing_type,
                    getattr(des, "design_variant", None), getattr(des, "series", None),
                    getattr(des, "closures", "unknown"), bearing.bore, bearing.outside_diameter,
                    bearing.pitch_diameter, f"ball pitch diameter ({bearing.geometry_source})",
                    _geometry_warnings(bearing), bearing)


def _seals_of(b: _Bearing, option: Seals | None) -> Seals:
    if option is not None:
        return option
    if b.closures in ("seal", "2seals"):
        return Seals.contact
    if b.closures in ("shield", "2shields"):
        return Seals.shields
    return Seals.none


def _viscosity(lubricant: str, viscosity_mm2_s, temperature_c) -> tuple[float, str]:
    """Operating kinematic viscosity [m^2/s] and how it was found."""
    if viscosity_mm2_s is not None:
        if temperature_c is not None:
            raise OptionError("--temperature-c", temperature_c,
                              "no temperature with --viscosity-mm2-s (that is already the "
                              "viscosity at the operating temperature)")
        nu = _finite("--viscosity-mm2-s", viscosity_mm2_s, 0.0, 1e6,
                     "a viscosity in (0, 1000000] mm^2/s", low_open=True)
        return nu * 1e-6, "given (--viscosity-mm2-s)"
    if lubricant not in LUBRICANTS:
        raise OptionError("--lubricant", lubricant, f"one of {', '.join(LUBRICANTS)}")
    oil = LUBRICANTS[lubricant]
    if temperature_c is None:
        t = oil.reference_temperature
        how = f"{oil.name} at its reference temperature {t - ZERO_CELSIUS:.4g} degC"
    else:
        t = _finite("--temperature-c", temperature_c, -60.0, 300.0,
                    "a temperature in [-60, 300] degC") + ZERO_CELSIUS
        how = (f"{oil.name} at {temperature_c:.4g} degC (Reynolds' exponential law from "
               f"{oil.reference_temperature - ZERO_CELSIUS:.4g} degC)")
    return float(oil.kinematic_viscosity(t)), how


def _constant(b: _Bearing, omega, fr, fa, type_option, equivalent_load_n):
    try:
        kind = type_option or friction_type_of(b.bearing_type, b.design_variant)
    except InputError:
        raise OptionError("--type", None, f"a friction type for this {b.bearing_type} bearing, "
                          "one of " + ", ".join(SEED003_COEFFICIENTS),
                          "seed 003's Table III has no row for it") from None
    if kind not in SEED003_COEFFICIENTS:
        raise OptionError("--type", kind, "for the constant model one of "
                          + ", ".join(SEED003_COEFFICIENTS))
    if equivalent_load_n is not None:
        p = load_n("--equivalent-load-n", equivalent_load_n)
        how = "given (--equivalent-load-n)"
    elif fa == 0.0:
        p, how = fr, "P = F_r (no axial load)"
    elif b.ball_bearing is not None and b.bearing_type in ("radial_ball", "angular_contact_ball"):
        p, factors = equivalent_dynamic_load(b.ball_bearing, fr, fa)
        how = (f"ISO 281 Table 3 from the geometry (bearinglab.life): X = {factors.x:.4g}, "
               f"Y = {factors.y:.4g}, e = {factors.e:.4g}")
    elif kind == "thrust_ball" and fr == 0.0:
        p, how = fa, "ISO 281 thrust ball bearing: P_a = F_a"
    else:
        raise OptionError("--axial-load-n", fa, f"0, or give --equivalent-load-n (no "
                          f"equivalent-load rule is built in here for {kind} under this load)")
    result = constant_friction(p, b.pitch_diameter, omega, kind, name=b.name, radial_load=fr,
                               axial_load=fa)
    return result, {"equivalent_load_source": how}


def _skf(b: _Bearing, omega, fr, fa, type_option, c0_kn, nu, lubrication, oil, constants_text,
         seals, seal_text, seal_diameter_mm):
    kind = type_option or b.bearing_type
    if kind not in SKF_BEARING_TYPES:
        raise OptionError("--type" if type_option else "DESIGNATION", type_option or b.name,
                          "for the SKF model a ball bearing: " + ", ".join(SKF_BEARING_TYPES),
                          f"this bearing is {b.bearing_type}; use --model constant")
    if constants_text is not None:
        v = _numbers("--skf-constants", constants_text, (4, 6),
                     "R1,R2,S1,S2 (deep-groove) or R1,R2,S1,S2,R3,S3 (angular contact), "
                     "numbers >= 0 in SKF units")
        constants = SkfGeometryConstants(*v[:4], *(v[4:] or (None, None)),
                                         source="user (--skf-constants)")
    elif kind == "radial_ball":
        if b.series not in DEEP_GROOVE_CONSTANTS:
            raise OptionError("DESIGNATION", b.name, "a deep-groove series with shipped SKF "
                              "constants (" + ", ".join(DEEP_GROOVE_CONSTANTS) + ")",
                              "or give --skf-constants R1,R2,S1,S2")
        constants = deep_groove_constants(b.series)
    else:
        raise OptionError("--skf-constants", None, "R1,R2,S1,S2,R3,S3 for an "
                          f"{kind.replace('_', '-')} bearing (SKF's table is not shipped)")
    if b.bore is None or b.outside_diameter is None:
        raise OptionError("--bore-mm", None, "the bore and outside diameter (give --bore-mm and "
                          "--outside-diameter-mm): the SKF model uses d_m = 0.5 (d + D)")
    c0 = None
    if c0_kn is not None:
        c0 = _finite("--static-load-rating-kn", c0_kn, 0.0, 1e5, "a rating in (0, 100000] kN",
                     low_open=True) * 1e3
    notes, seal = [], 0.0
    if kind == "radial_ball" and fa > 0 and c0 is None:
        if b.ball_bearing is None or b.ball_bearing.bearing_type != "radial_ball":
            raise OptionError("--static-load-rating-kn", None, "the basic static load rating "
                              "C_0 when there is an axial load (SKF: alpha_F = 24.6 "
                              "(F_a/C_0)^0.24)")
        c0 = load_ratings(b.ball_bearing).static
        notes.append(f"C_0 = {c0:.5g} N from ISO 76 and the internal geometry "
                     "(bearinglab.life); give --static-load-rating-kn for the maker's value")
    if c0 is not None and fa > c0:
        raise OptionError("--axial-load-n", fa, f"at most C_0 = {c0:g} N")
    if seals is Seals.contact:
        if seal_text is None:
            notes.append("contact seals: M_seal is not included (SKF's seal constants are not "
                         "shipped; give --seal-constants K_S1,K_S2,BETA and --seal-diameter-mm)")
        else:
            ks1, ks2, beta = _numbers("--seal-constants", seal_text, (3,),
                                      "K_S1,K_S2,BETA, numbers >= 0 in SKF units")
            if seal_diameter_mm is None:
                raise OptionError("--seal-diameter-mm", None, "the seal counterface diameter "
                                  "d_s [mm] with --seal-constants")
            ds = _finite("--seal-diameter-mm", seal_diameter_mm, 0.0, 1e5,
                         "a diameter in (0, 100000] mm", low_open=True)
            seal = seal_moment(ks1, ks2, beta, ds * 1e-3)
    result = skf_friction(kind, b.bore, b.outside_diameter, fr, fa, omega, nu, constants,
                          name=b.name, static_load_rating=c0, lubrication=lubrication.value,
                          lubricant_kind=oil.value, seal=seal, notes=tuple(notes))
    return result, {}


@app.command("friction")
@with_geometry
def friction_command(
        designation: DesignationArg = None,
        speed_rpm: Annotated[float, typer.Option("--speed-rpm", help="Speed of the rotating "
                                                 "ring [rpm].")] = ...,
        radial_load_n: Annotated[float, typer.Option("--radial-load-n",
                                                     help="Radial load F_r [N].")] = 0.0,
        axial_load_n: Annotated[float, typer.Option("--axial-load-n",
                                                    help="Axial load F_a [N].")] = 0.0,
        model: Annotated[FrictionModel, typer.Option(
            "--model", help="constant: seed 003's M = mu P d_m / 2; skf: SKF's rolling + "
            "sliding + seal (+ drag) model.")] = FrictionModel.constant,
        type_option: Annotated[str | None, typer.Option(
            "--type", help="Friction type (constant model: " + ", ".join(SEED003_COEFFICIENTS)
            + "; skf: " + ", ".join(SKF_BEARING_TYPES) + "). Default: from the designation.",
            show_default=False)] = None,
        equivalent_load_n: Annotated[float | None, typer.Option(
            "--equivalent-load-n", help="Equivalent load P [N] (constant model).",
            show_default=False)] = None,
        static_load_rating_kn: Annotated[float | None, typer.Option(
            "--static-load-rating-kn", help="Basic static load rating C_0 [kN] for the SKF "
            "model with an axial load on a deep-groove bearing (default: ISO 76 from the "
            "geometry).", show_default=False)] = None,
        lubricant: Annotated[str, typer.Option(
            "--lubricant", help="Lubricant for the viscosity: " + ", ".join(LUBRICANTS))]
        = "iso-vg68",
        viscosity_mm2_s: Annotated[float | None, typer.Option(
            "--viscosity-mm2-s", help="Operating kinematic viscosity of the oil or the "
            "grease's base oil [mm^2/s] (instead of --lubricant/--temperature-c).",
            show_default=False)] = None,
        temperature_c: Annotated[float | None, typer.Option(
            "--temperature-c", help="Operating temperature of the lubricant [degC] (default: "
            "its reference).", show_default=False)] = None,
        lubrication: Annotated[Lubrication | None, typer.Option(
            "--lubrication", help="Lubrication method, sets K_rs (default: grease for a "
            "grease, oil-jet for an oil).", show_default=False)] = None,
        oil: Annotated[OilKind, typer.Option(
            "--oil", help="Kind of oil, sets mu_EHL.")] = OilKind.mineral,
        skf_constants: Annotated[str | None, typer.Option(
            "--skf-constants", help="SKF geometry constants R1,R2,S1,S2 (deep groove) or "
            "R1,R2,S1,S2,R3,S3 (angular contact).", show_default=False)] = None,
        seals: Annotated[Seals | None, typer.Option(
            "--seals", help="Seals (default: from the designation's suffix).",
            show_default=False)] = None,
        seal_constants: Annotated[str | None, typer.Option(
            "--seal-constants", help="SKF seal constants K_S1,K_S2,BETA (M_seal = K_S1 "
            "d_s^BETA + K_S2 in N mm, d_s in mm).", show_default=False)] = None,
        seal_diameter_mm: Annotated[float | None, typer.Option(
            "--seal-diameter-mm", help="Seal counterface diameter d_s [mm].",
            show_default=False)] = None,
        json_output: JsonOpt = False, *, geometry):
    """Friction torque and power loss: seed 003's constant coefficient or the SKF model."""
    omega = speed_rad_s(speed_rpm, zero=True)
    fr = load_n("--radial-load-n", radial_load_n)
    fa = _finite("--axial-load-n", axial_load_n, 0.0, MAX_LOAD_N,
                 f"a load in [0, {MAX_LOAD_N:g}] N (a magnitude)")
    if static_load_rating_kn is not None:
        _finite("--static-load-rating-kn", static_load_rating_kn, 0.0, 1e5,
                "a rating in (0, 100000] kN", low_open=True)
    bearing = _resolve(designation, geometry, type_option)
    seal_kind = _seals_of(bearing, seals)
    extra: dict = {"designation": designation, "bearing_type": bearing.bearing_type,
                   "seals": seal_kind.value}
    if model is FrictionModel.constant:
        result, more = _constant(bearing, omega, fr, fa, type_option, equivalent_load_n)
        extra["pitch_diameter_source"] = bearing.pitch_source
        if seal_kind is Seals.contact:
            more["note"] = "contact seals add friction that the constant model leaves out"
    else:
        nu, how = _viscosity(lubricant, viscosity_mm2_s, temperature_c)
        method = lubrication or (Lubrication.grease if "grease" in lubricant
                                 else Lubrication.oil_jet)
        result, more = _skf(bearing, omega, fr, fa, type_option, static_load_rating_kn, nu,
                            method, oil, skf_constants, seal_kind, seal_constants,
                            seal_diameter_mm)
        more["viscosity_source"] = how
    d = result.to_dict()
    warnings = bearing.warnings + d.pop("warnings") + ([more.pop("note")] if "note" in more
                                                         else [])
    out = {**extra, **d, **more, "warnings": warnings}
    if json_output:
        _emit_json(out)
        return
    _print(out)
    _print_warnings(warnings)


def _print(out: dict) -> None:
    title = (f"{out['name']}: {out['speed_rpm']:g} rpm, F_r = {out['radial_load_n']:g} N, "
             f"F_a = {out['axial_load_n']:g} N ({out['model']} model)")
    rows = [["friction torque M", out["friction_torque_nmm"], "N mm"],
            ["power loss N", out["power_loss_w"], "W"]]
    if out["model"] == "constant":
        rows += [["friction type", out["friction_type"], ""],
                 ["coefficient mu (seed 003)", out["friction_coefficient"], "-"],
                 ["equivalent load P", out["equivalent_load_n"], "N"],
                 ["pitch diameter d_m", out["pitch_diameter_mm"], "mm"]]
        note = f"P: {out['equivalent_load_source']}; d_m: {out['pitch_diameter_source']}"
    else:
        rows += [["rolling phi_ish phi_rs M_rr", out["rolling_torque_nmm"], "N mm"],
                 ["sliding M_sl", out["sliding_torque_nmm"], "N mm"],
                 ["seals M_seal", out["seal_torque_nmm"], "N mm"],
                 ["drag M_drag (not modelled)", out["drag_torque_nmm"], "N mm"],
                 ["mean diameter d_m = (d + D)/2", out["mean_diameter_mm"], "mm"],
                 ["viscosity nu", out["viscosity_mm2_s"], "mm^2/s"],
                 ["rated viscosity nu_1 (ISO 281)", out["rated_viscosity_mm2_s"], "mm^2/s"],
                 ["viscosity ratio kappa", out["viscosity_ratio"], "-"],
                 ["inlet shear factor phi_ish", out["inlet_shear_factor"], "-"],
                 ["replenishment factor phi_rs", out["replenishment_factor"], "-"],
                 ["weighting factor phi_bl", out["sliding_weighting_factor"], "-"],
                 ["sliding coefficient mu_sl", out["sliding_friction_coefficient"], "-"]]
        c = out["geometry_constants"]
        note = (f"viscosity: {out['viscosity_source']}; lubrication {out['lubrication']} "
                f"(K_rs {out['k_rs']:g}), K_Z {out['k_z']:g}; R1 {c['r1']:g}, R2 {c['r2']:g}, "
                f"S1 {c['s1']:g}, S2 {c['s2']:g}")
    console.print(_table(title, ["quantity", "value", "unit"], rows))
    console.print(escape(note))
    for source in out["sources"]:
        console.print(f"[dim]source: {escape(source)}[/dim]")

