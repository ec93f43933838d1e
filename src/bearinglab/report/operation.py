"""Report sections of running the bearing: friction torque and power loss, rating life.
Each function takes the :class:`.Context` and returns ``(body_html, highlights)``."""

from __future__ import annotations

from ..engine import reraise_interrupt
from ..friction import bearing_friction
from ..life import rating_life
from ..plausibility import operating_warnings
from ..units import UNITS, label
from .context import Context
from .document import figure, notes, number, paragraph, table

_N_MM = UNITS["n_mm"].from_si(1.0)  # N m -> N mm


def friction_inputs(ctx: Context) -> dict:
    """The keyword arguments of :func:`bearinglab.friction.bearing_friction` that the
    report's inputs give: the designation (series, seals) and the lubricant as it was
    given (a lubricant, read at its reference temperature, or a viscosity) -- what the
    ``friction`` command passes for the same options, so both give the same numbers."""
    out = {"designation": ctx.designation}
    if ctx.lubricant is not None:
        out["lubricant"] = ctx.lubricant
    elif ctx.viscosity is not None:
        out["viscosity"] = ctx.viscosity
    return out


def friction(ctx: Context):
    """Friction torque and power loss: seed 003's constant coefficient and the SKF model."""
    c, b = ctx.condition, ctx.bearing
    fa = abs(c.axial_load)
    inputs = friction_inputs(ctx)
    constant = bearing_friction(
        b, c.shaft_speed, c.radial_load, fa, model="constant", designation=ctx.designation
    )
    rows = [
        [
            "constant coefficient (seed 003, M = mu P d_m / 2)",
            constant.torque * _N_MM,
            constant.power_loss,
        ]
    ]
    said, skf = list(constant.warnings), None
    if len(inputs) == 1:
        said.append("SKF model not run: no lubricant viscosity.")
    else:
        try:
            skf = bearing_friction(b, c.shaft_speed, c.radial_load, fa, model="skf", **inputs)
        except Exception as exc:  # noqa: BLE001 - e.g. no SKF constants for this type: keep the other
            reraise_interrupt(exc)
            said.append(f"SKF model not run: {type(exc).__name__}: {exc}")
    body = [
        paragraph(
            f"Friction at {ctx.speed_rpm:g} rpm, F_r = {c.radial_load:g} N, "
            f"F_a = {c.axial_load:g} N (bearinglab.friction.bearing_friction)."
        )
    ]
    columns = ["model", label("friction torque", "n_mm"), label("power loss", "w")]
    if skf is not None:
        d = skf.to_dict()
        rows.append(["SKF four-component model", skf.torque * _N_MM, skf.power_loss])
        said += list(skf.warnings)
        parts = [
            [k.replace("_", " "), v * _N_MM, 100.0 * v / skf.torque if skf.torque else None]
            for k, v in skf.components.items()
        ]
        body.append(table(columns, rows, "Friction torque and power loss"))
        body.append(
            paragraph(
                f"SKF model with the viscosity {d['viscosity_mm2_s']:.4g} mm²/s "
                f"({d['viscosity_source']}): viscosity ratio kappa = "
                f"{d['kappa']:.3g}; lubrication {d['lubrication']} "
                f"({d['lubrication_source']})."
            )
        )
        body.append(
            '<div class="two">'
            + table(
                ["SKF component", label("torque", "n_mm"), label("share", "percent")],
                parts,
                "SKF model components",
            )
            + figure(skf.plot()[0], "SKF friction torque by component")
            + "</div>"
        )
    else:
        body.append(table(columns, rows, "Friction torque and power loss"))
    # the load and speed checks stand at the report's head: not again under each model
    head = set(operating_warnings(ctx.bearing, c))
    body.append(notes([w for w in dict.fromkeys(said) if w not in head], "Notes"))
    best = skf or constant
    return "".join(body), [
        ("Friction torque", f"{number(best.torque * _N_MM, 3)} N·mm"),
        ("Power loss", f"{number(best.power_loss, 3)} W"),
    ]


def life(ctx: Context):
    """Load ratings and rating life (ISO 281, modified with a_ISO when the viscosity is
    known)."""
    r = rating_life(ctx.bearing, ctx.condition, viscosity=ctx.viscosity)
    table_ = r.to_pandas()
    rows = [[q, v, u] for q, v, u in table_[["quantity", "value", "unit"]].itertuples(index=False)]
    d = r.to_dict()
    said = list(r.warnings)
    if ctx.viscosity is not None:
        said.append(f"Viscosity {ctx.viscosity * 1e6:.4g} mm2/s: {ctx.viscosity_source}.")
    body = [
        paragraph(
            "Basic dynamic and static load ratings from the internal geometry "
            "(ISO 281:2007, ISO 76:2006), the equivalent loads with ISO 281's X "
            "and Y, the basic rating life L10 = (C/P)^3 and, with the lubricant's "
            "viscosity, the modified life a_1 a_ISO L10 (bearinglab.life)."
        ),
        '<div class="two">'
        + table(["quantity", "value", "unit"], rows, "Rating life", numeric=(1,))
        + figure(r.plot()[0], "Basic rating life against the equivalent load")
        + "</div>",
        notes(said, "Notes"),
    ]
    out = [("L10 life", f"{number(d['l10_hours'], 3)} h")]
    if d.get("l10m_hours") is not None:
        out.append(("Modified life L10m", f"{number(d['l10m_hours'], 3)} h"))
    out.append(("Static safety s0", number(d["static_safety_factor"], 3)))
    return "".join(body), out
