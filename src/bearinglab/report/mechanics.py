"""Report sections of the bearing's mechanics: identity and geometry, load distribution,
contact, stiffness and ring resonances. Each function takes the :class:`.Context` and
returns ``(body_html, highlights)``; an exception fails only its own section."""

from __future__ import annotations

import math

import numpy as np

from ..contact.ball_race import SUMMARY as BALL_SUMMARY
from ..contact.ball_race import ball_contacts
from ..contact.roller_race import SUMMARY as ROLLER_SUMMARY
from ..geometry import References
from ..inputs import geometry_rows
from ..operating import OperatingCondition
from ..quasistatic import DOF_NAMES, solve_load_distribution
from ..rings import ring_modes
from .context import Context
from .document import Raw, esc, figure, notes, number, paragraph, table

#: Loads of the stiffness curve, as multiples of the operating load [-].
LOAD_FACTORS = (0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0)
#: Ring modes shown [-].
RING_MODES = range(2, 7)


class _References(References):
    """Source references numbered once, listed under the table."""

    def html(self) -> str:
        if not self.refs:
            return ""
        items = "".join(f"<li>{esc(r)}</li>" for r in self.refs)
        return f'<h3>Sources</h3><ol class="small">{items}</ol>'


def identity(ctx: Context):
    """The designation decoded and every geometry value with where it came from."""
    b, des, parts = ctx.bearing, ctx.designation, []
    if des is not None:
        rows = [["designation", des.text], ["read as", f"{des.system.upper()}: {des.description}"]]
        if des.iso_equivalent:
            rows.append(["ISO equivalent", des.iso_equivalent])
        if des.gost_equivalent:
            rows.append(["GOST equivalent", des.gost_equivalent])
        rows += [[f"part '{text}'", meaning] for text, meaning in des.parts]
        parts.append(table(["", "meaning"], rows, "Designation", numeric=()))
        parts.append(notes(list(des.notes), "About the designation"))
    refs = _References()
    rows = []
    roller = b.rolling_element == "roller"
    for name, label, symbol, value, unit in geometry_rows(b):
        rows.append([label, symbol, value, unit, Raw(esc(refs.cell(b, name)))])
    derived = [
        ("inner raceway diameter", "d_i", b.inner_raceway_diameter * 1e3, "mm"),
        ("outer raceway diameter", "d_o", b.outer_raceway_diameter * 1e3, "mm"),
    ]
    if roller:
        derived.append(("roller mass", "m_r", b.roller_mass * 1e3, "g"))
    else:
        derived += [
            ("free contact angle", "alpha_0", math.degrees(b.free_contact_angle), "deg"),
            ("ball mass", "m_b", b.ball_mass * 1e3, "g"),
        ]
    if not roller and None not in (b.bore, b.outside_diameter, b.width) and not b.is_thrust:
        derived.append(("outer ring mass", "m_k", b.outer_ring_mass * 1e3, "g"))
    rows += [[label, symbol, value, unit, "derived"] for label, symbol, value, unit in derived]
    element = "roller" if roller else "ball"
    for name, label in (
        ("ring_material", "ring material"),
        (f"{element}_material", f"{element} material"),
    ):
        m = getattr(b, name)
        rows.append(
            [
                label,
                "E, nu, rho",
                (
                    f"{m.elastic_modulus / 1e9:.4g} GPa, "
                    f"{m.poisson_ratio:.3g}, {m.density:.5g} kg/m3"
                ),
                "",
                Raw(esc(refs.cell(b, name))),
            ]
        )
    parts.append(
        table(
            ["quantity", "symbol", "value", "unit", "source"],
            rows,
            f"Geometry and materials (geometry source: {b.geometry_source})",
            numeric=(2,),
        )
    )
    parts.append(refs.html())
    label = b.name or (des.text if des is not None else "bearing")
    highlights = [("Bearing", label), ("Geometry", b.geometry_source)]
    return "".join(parts), highlights


def load_distribution(ctx: Context):
    """Quasi-static load distribution at the operating point (polar plot of ball loads)."""
    r = solve_load_distribution(ctx.bearing, ctx.condition)
    ctx.results["load"] = r
    if ctx.bearing.rolling_element == "roller":
        return _roller_load_distribution(ctx, r)
    d = r.to_dict()
    balls = r.ball_table()
    loaded = int((balls["inner_load_n"] > 0).sum())
    summary = [
        ["radial displacement S_r", d["radial_displacement_um"], "um"],
        ["axial displacement S_a", d["axial_displacement_um"], "um"],
        ["largest ball load Q_max", d["max_ball_load_n"], "N"],
        ["balls loaded at the inner ring", loaded, f"of {ctx.bearing.ball_count}"],
        ["radial stiffness C_r = dF_r/dS_r", d["radial_stiffness_n_per_um"], "N/um"],
        ["axial stiffness C_a = dF_a/dS_a", d["axial_stiffness_n_per_um"], "N/um"],
        ["diametral clearance P_d", d["diametral_clearance_um"], "um"],
        ["equilibrium residual", d["equilibrium_residual_n"], "N"],
    ]
    rows = [
        [
            int(row.ball),
            row.angle_deg,
            row.inner_load_n,
            row.outer_load_n,
            row.inner_contact_angle_deg,
            row.inner_max_pressure_gpa,
            row.outer_max_pressure_gpa,
        ]
        for row in balls.itertuples(index=False)
    ]
    body = [
        paragraph(
            "Quasi-static equilibrium of the inner ring under the applied loads, "
            "with clearance and the balls' centrifugal force (seed 001's model; "
            "bearinglab.quasistatic.solve_load_distribution). Ball 1 sits under "
            "the radial load, which acts downwards (-y)."
        ),
        table(["quantity", "value", "unit"], [*summary], "Operating point", numeric=(1,)),
        figure(
            r.plot()[0],
            "Ball loads at their angular positions (polar) and the contact angle of each ball",
        ),
        table(
            [
                "ball",
                "angle [deg]",
                "inner load [N]",
                "outer load [N]",
                "inner contact angle [deg]",
                "inner p_max [GPa]",
                "outer p_max [GPa]",
            ],
            rows,
            "Per ball",
        ),
        notes(list(r.warnings), "Warnings"),
    ]
    highlights = [
        ("Largest ball load", f"{number(d['max_ball_load_n'], 3)} N"),
        ("Radial stiffness", f"{number(d['radial_stiffness_n_per_um'], 3)} N/um"),
    ]
    return "".join(body), highlights


def _roller_load_distribution(ctx: Context, r):
    """The roller bearing's load distribution by slices (its summary and one row per
    roller)."""
    d = r.to_dict()
    summary = [
        ["radial displacement S_r", d["radial_displacement_um"], "um"],
        ["axial displacement S_a", d["axial_displacement_um"], "um"],
        ["largest roller load Q_max", d["max_roller_load_n"], "N"],
        ["largest slice pressure p_max", d["max_pressure_gpa"], "GPa"],
        ["rollers loaded at the inner ring", d["loaded_rollers"], f"of {d['roller_count']}"],
        ["radial stiffness C_r = dF_r/dS_r", d["radial_stiffness_n_per_um"], "N/um"],
        ["axial stiffness C_a = dF_a/dS_a", d["axial_stiffness_n_per_um"], "N/um"],
        ["diametral clearance P_d", d["diametral_clearance_um"], "um"],
        ["equilibrium residual", d["equilibrium_residual_n"], "N"],
    ]
    if "max_flange_load_n" in d:
        summary.insert(3, ["largest rib load", d["max_flange_load_n"], "N"])
    rows = [
        [
            row["roller"],
            row["angle_deg"],
            row["inner_load_n"],
            row["outer_load_n"],
            row["inner_max_pressure_gpa"],
            row["outer_max_pressure_gpa"],
            row["end_load_ratio"],
        ]
        for row in d["rollers"]
    ]
    body = [
        paragraph(
            "Quasi-static equilibrium of the inner ring with each roller's line contacts cut "
            f"into {d['slices']} slices (Harris & Kotzalas, Advanced Concepts, ch. 1; "
            "Palmgren's slice stiffness; the roller's profile drop in each slice; "
            "bearinglab.quasistatic.solve_load_distribution). Roller 1 sits under the "
            "radial load, which acts downwards (-y)."
        ),
        table(["quantity", "value", "unit"], summary, "Operating point", numeric=(1,)),
        figure(r.plot()[0], "Roller loads at their angular positions and the slice loads"),
        table(
            [
                "roller",
                "angle [deg]",
                "inner load [N]",
                "outer load [N]",
                "inner p_max [GPa]",
                "outer p_max [GPa]",
                "end / mean slice load",
            ],
            rows,
            "Per roller",
        ),
        notes(list(r.warnings), "Warnings"),
    ]
    highlights = [
        ("Largest roller load", f"{number(d['max_roller_load_n'], 3)} N"),
        ("Radial stiffness", f"{number(d['radial_stiffness_n_per_um'], 3)} N/um"),
    ]
    return "".join(body), highlights


def contact(ctx: Context):
    """Hertz contact of the most loaded ball with both raceways."""
    r = ctx.need("load", "load distribution")
    if ctx.bearing.rolling_element == "roller":
        return _roller_contact(ctx, r)
    q = float(np.max(r.load))
    if q <= 0:
        raise ValueError("no ball carries load at this operating point")
    c = ball_contacts(ctx.bearing, q)
    d = c.to_dict()
    rows = [[label, d["inner"][k], d["outer"][k], unit] for k, label, unit in BALL_SUMMARY]
    body = [
        paragraph(
            f"Hertz point contact of the most loaded ball (Q = {q:.4g} N) with the "
            f"inner and outer raceways at the nominal contact angle "
            f"{d['contact_angle_deg']:.3g} deg (exact elliptic integrals; "
            "bearinglab.contact.ball_contacts)."
        ),
        table(
            ["quantity", "inner", "outer", "unit"],
            rows,
            f"Contacts at Q = {q:.4g} N",
            numeric=(1, 2),
        ),
        figure(
            c.plot()[0],
            "Maximum pressure and approach against ball load, and the "
            "contact ellipses at the largest ball load",
        ),
        notes(list(c.warnings), "Warnings"),
    ]
    p = max(d["inner"]["max_pressure_gpa"], d["outer"]["max_pressure_gpa"])
    return "".join(body), [("Max contact pressure", f"{number(p, 3)} GPa")]


def _roller_contact(ctx: Context, r):
    """The line contacts of the most loaded roller, by slices and by the half-space."""
    from ..contact.roller_race import roller_contacts

    q = float(r.max_roller_load)
    if q <= 0:
        raise ValueError("no roller carries load at this operating point")
    c = roller_contacts(ctx.bearing, q)
    d = c.to_dict()
    rows = [[label, d["inner"][k], d["outer"][k], unit] for k, label, unit in ROLLER_SUMMARY]
    body = [
        paragraph(
            f"Line contacts of the most loaded roller (Q = {q:.4g} N) with both raceways: "
            "the pressure along the roller from the elastic half-space (the profile's "
            "crowning and the edges included) against Hertz's line contact of the same "
            "length (bearinglab.contact.roller_contacts)."
        ),
        table(
            ["quantity", "inner", "outer", "unit"],
            rows,
            f"Contacts at Q = {q:.4g} N",
            numeric=(1, 2),
        ),
        figure(c.plot()[0], "Pressure along the roller at the largest roller load"),
        notes(list(c.warnings), "Warnings"),
    ]
    return "".join(body), [("Max contact pressure", f"{number(d['max_pressure_gpa'], 3)} GPa")]


def _condition(ctx: Context, factor: float, along: str) -> OperatingCondition:
    c = ctx.condition
    kwargs = {
        "radial_load": c.radial_load,
        "axial_load": c.axial_load,
        "shaft_speed": c.shaft_speed,
        "radial_load_angle": c.radial_load_angle,
    }
    kwargs[along] = factor * kwargs[along]
    return OperatingCondition(**kwargs)


def stiffness(ctx: Context):
    """Stiffness at the operating point (5x5) and its variation with the load."""
    r = ctx.need("load", "load distribution")
    along = "radial_load" if ctx.condition.radial_load > 0 else "axial_load"
    symbol = "F_r" if along == "radial_load" else "F_a"
    rows, loads, cr, ca, sr = [], [], [], [], []
    guess = None
    for k in LOAD_FACTORS:
        cond = _condition(ctx, k, along)
        s = r if k == 1.0 else solve_load_distribution(ctx.bearing, cond, initial=guess)
        guess = s.displacement
        d = s.to_dict()
        load = getattr(cond, along)
        loads.append(load)
        cr.append(d["radial_stiffness_n_per_um"])
        ca.append(d["axial_stiffness_n_per_um"])
        sr.append(
            d["radial_displacement_um"] if along == "radial_load" else d["axial_displacement_um"]
        )
        rows.append(
            [k, load, sr[-1], cr[-1], ca[-1], d.get("max_ball_load_n", d.get("max_roller_load_n"))]
        )
    from ..plotting import _pyplot

    fig, ax = _pyplot().subplots(1, 2, figsize=(11, 3.8))
    ax[0].plot(loads, cr, "o-", label="radial C_r")
    ax[0].plot(loads, ca, "s--", label="axial C_a")
    ax[0].set_ylabel("stiffness [N/um]")
    ax[1].plot(loads, sr, "o-", color="C2")
    ax[1].set_ylabel(f"{'radial S_r' if along == 'radial_load' else 'axial S_a'} [um]")
    for a in ax:
        a.axvline(getattr(ctx.condition, along), color="0.6", ls=":", lw=1)
        a.set_xlabel(f"{symbol} [N] (dotted: operating load)")
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    fig.tight_layout()
    names = list(DOF_NAMES)
    k = r.stiffness_matrix_shown()
    matrix = [[n, *[float(v) for v in row]] for n, row in zip(names, k, strict=False)]
    body = [
        paragraph(
            f"Tangent stiffness of the bearing at {symbol} from "
            f"{LOAD_FACTORS[0]:g} to {LOAD_FACTORS[-1]:g} times the operating load "
            "(other loads and the speed held). Bearings stiffen as the load grows "
            "(Q ~ delta^1.5 for a ball, about delta^1.1 for a roller) and more "
            "rolling elements take load."
        ),
        figure(fig, f"Stiffness and displacement against {symbol}"),
        table(
            [
                "x operating load",
                f"{symbol} [N]",
                "S_r [um]" if along == "radial_load" else "S_a [um]",
                "C_r [N/um]",
                "C_a [N/um]",
                "Q_max [N]",
            ],
            rows,
            "Stiffness against load",
        ),
        table(
            ["", *names],
            matrix,
            "5x5 tangent stiffness matrix at the operating point (SI: N/m, N/rad, N m/m, N m/rad)",
        ),
    ]
    return "".join(body), []


def rings(ctx: Context):
    """Natural frequencies of the outer ring in the loaded bearing (seed 000)."""
    r = ctx.need("load", "load distribution")
    k = float(r.radial_stiffness)
    if not k > 0:
        raise ValueError(
            f"the radial stiffness at the operating point is {k:g} N/m: the ring "
            "is not supported by the balls in the radial direction"
        )
    m = ring_modes(ctx.bearing, radial_stiffness=k, modes=(1, *RING_MODES))
    d = m.to_dict()
    rows = []
    for mode in d["modes"]:
        rows.append(
            [
                mode["m"],
                mode["free_hz"] / 1e3 if mode["m"] > 1 else None,
                ", ".join(f"{f / 1e3:.4g}" for f in mode["approx_hz"]),
                ", ".join(f"{f / 1e3:.4g}" for f in mode["refined_hz"]) or None,
                "ring as a rigid body on the ball springs"
                if mode["m"] == 1
                else "balls at nodes / antinodes"
                if mode["split"]
                else "",
            ]
        )
    body = [
        paragraph(
            "Flexural modes of the outer ring supported by the loaded balls "
            "(seed 000, Balmont & Varlamov 1986): the free-ring frequency f*_m of "
            "our ring section, eq. (1.9)'s approximate loaded frequency and the "
            "refined solution with the balls' mass (eqs. 3.3-3.10). The ball "
            f"springs' radial stiffness K_x = {k / 1e6:.4g} N/um is the tangent "
            "radial stiffness of the load distribution at the operating point; the "
            f"vibrating mass is the bare outer ring ({d['ring_mass_kg'] * 1e3:.4g} "
            f"g, no housing or sensors), kappa = {d['ball_mass_ratio']:.3g}."
        ),
        table(
            ["mode m", "free f*_m [kHz]", "approximate [kHz]", "refined [kHz]", "note"],
            rows,
            "Outer-ring natural frequencies",
            numeric=(1, 2, 3),
        ),
        figure(m.plot()[0], "Ring natural frequencies by mode number", 80),
        notes(
            [
                (
                    "The outer ring vibrates on the balls alone, as in the paper's test (a "
                    "ring hung free): a ring pressed into a housing vibrates with the housing, "
                    "and its resonances are then those of the assembly."
                )
            ],
            "Assumptions",
        ),
    ]
    m2 = next(mode for mode in d["modes"] if mode["m"] == 2)
    return "".join(body), [("Ring mode m=2", f"{number(m2['approx_hz'][0] / 1e3, 3)} kHz")]
