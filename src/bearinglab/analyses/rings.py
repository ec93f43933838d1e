"""The ``ring-modes`` analysis: the outer ring's natural frequencies on the ball springs
(seed 000, :func:`bearinglab.rings.ring_modes`), from a bearing or from the paper's
ring-level inputs alone; its own inputs (``modes``, ``ring_mass_kg``,
``free_frequencies_hz``, ...) are declared here, the only analysis that takes them.
"""

from __future__ import annotations

import math

from ..errors import InputError
from ..inputs import INPUTS, Input, balls_only, bearing_from, bearing_warnings, no_effect, restate
from .base import BEARING_INPUTS, Analysis, Outcome, plot_file

_RING_INPUTS = {
    "axial_load_n": INPUTS["axial_load_n"].with_(
        default=None,
        help="Axial load A [N], for K_x from the bearing (default 200 N).",
        low=0.0,
        low_open=True,
    ),
    "modes": Input("text", "2:6", "Modes FIRST:LAST or m1,m2,...; m = 1 is the rigid-body mode."),
    "ring_mass_kg": Input(
        "number",
        None,
        "Vibrating mass of the outer ring incl. sensors [kg].",
        low=0.0,
        high=1e15,
        low_open=True,
        high_open=True,
    ),
    "radial_stiffness_n_per_m": Input(
        "number",
        None,
        "Radial bearing stiffness K_x [N/m].",
        low=0.0,
        high=1e15,
        low_open=True,
        high_open=True,
    ),
    "rigid_body_frequency_hz": Input(
        "number",
        None,
        "f_1 of the ring on the ball springs [Hz] (instead of sqrt(K_x / ring mass) / 2 pi).",
        low=0.0,
        high=1e15,
        low_open=True,
        high_open=True,
    ),
    "free_frequencies_hz": Input(
        "text",
        None,
        "Measured free-ring frequencies f2,f3,... [Hz], one per flexural mode asked for.",
    ),
    "ball_mass_ratio": Input(
        "number", None, "kappa = n m_b / m_k.", low=0.0, high=1e15, low_open=True, high_open=True
    ),
    "contact_stiffness_ratio": Input(
        "number",
        None,
        "K1/K2 (outer over inner contact stiffness).",
        low=0.0,
        high=1e15,
        low_open=True,
        high_open=True,
    ),
    "stiffness_from": Input(
        "text",
        None,
        "K_x from seed 000's closed form (axial load, contact angle; the default) or from "
        "the load-distribution stiffness at the axial load.",
        choices=("closed-form", "load-distribution"),
    ),
}
#: Axial load for K_x when none is given [N].
DEFAULT_RING_AXIAL_LOAD = 200.0


def _modes(text: str) -> list[int]:
    try:
        if ":" in text:
            a, b = (int(v) for v in text.split(":"))
            ms = list(range(a, b + 1))
        else:
            ms = [int(v) for v in text.split(",")]
    except ValueError:
        ms = []
    if not ms or min(ms) < 1 or max(ms) > 50:
        raise InputError("modes", text, "FIRST:LAST or a list of mode numbers 1..50")
    return ms


def _free_frequencies(text, flexural: list[int]):
    if text is None:
        return None
    try:
        free = [float(v) for v in str(text).split(",")]
    except ValueError:
        free = []
    if not free or not all(math.isfinite(f) and f > 0 for f in free):
        raise InputError("free_frequencies_hz", text, "positive frequencies f2,f3,... [Hz]")
    if len(free) != len(flexural):
        raise InputError(
            "free_frequencies_hz", text, f"{len(flexural)} values, one per flexural mode {flexural}"
        )
    return dict(zip(flexural, free, strict=True))


def _solve_modes(values: dict, bearing, ms, free, ball_count):
    from ..rings import ring_modes as solve

    axial = values.get("axial_load_n")
    source = values.get("stiffness_from")
    return solve(
        bearing,
        axial_load=(DEFAULT_RING_AXIAL_LOAD if axial is None else axial) if bearing else None,
        modes=ms,
        ring_mass=values.get("ring_mass_kg"),
        radial_stiffness=values.get("radial_stiffness_n_per_m"),
        rigid_body_frequency=values.get("rigid_body_frequency_hz"),
        free_frequencies=free,
        ball_mass_ratio=values.get("ball_mass_ratio"),
        contact_stiffness_ratio=values.get("contact_stiffness_ratio"),
        ball_count=ball_count,
        radial_stiffness_from=(source or "closed-form").replace("-", "_"),
    )


def ring_modes(values: dict) -> Outcome:
    """The ``ring-modes`` request: from a bearing, or from the paper's ring-level inputs
    alone (balls, ring_mass_kg with radial_stiffness_n_per_m or rigid_body_frequency_hz,
    free_frequencies_hz, ball_mass_ratio)."""
    ms = _modes(values.get("modes") or "2:6")
    free = _free_frequencies(values.get("free_frequencies_hz"), [m for m in ms if m >= 2])
    ring_level = values.get("designation") is None and all(
        values.get(k) is None for k in ("ball_diameter_mm", "pitch_diameter_mm", "geometry")
    )
    bearing = decoded = ball_count = None
    if ring_level:
        ball_count = values.get("balls")
        if ball_count is None:
            raise InputError(
                "designation",
                None,
                "a designation, explicit geometry, or the ring-level inputs `balls`, "
                "`ring_mass_kg` with `radial_stiffness_n_per_m` (or `rigid_body_frequency_hz`), "
                "`free_frequencies_hz` and `ball_mass_ratio`",
            )
    else:
        bearing, decoded = bearing_from(values)
        balls_only(
            bearing, values, "the outer-ring modes of seed 000 are those of a ring on ball springs"
        )
    try:
        r = _solve_modes(values, bearing, ms, free, ball_count)
    except InputError as exc:
        raise restate(exc, values, RING_MODES.options) from None
    # the axial load gives K_x, from a bearing, when K_x is not given; given f1, K_x is
    # only reported (f1 fixes the contact stiffness)
    if r.to_dict()["axial_load_n"] is None:
        why = (
            "with `radial_stiffness_n_per_m` (K_x is given)"
            if values.get("radial_stiffness_n_per_m") is not None
            else "without a bearing (K_x from the axial load needs the bearing's contacts)"
        )
    elif values.get("rigid_body_frequency_hz") is not None:
        why = "on the frequencies with `rigid_body_frequency_hz` (only on the K_x reported)"
    else:
        why = None
    given = [
        (n, why is not None and values.get(n) is not None)
        for n in ("axial_load_n", "stiffness_from")
    ]
    warnings = (bearing_warnings(bearing, decoded) if bearing is not None else []) + list(
        r.warnings
    )
    warnings += no_effect(given, why or "")
    return Outcome(r, values.get("designation"), tuple(warnings), bearing)


_MODES = (2, 3, 4, 5, 6)


def _ring_columns(r: Outcome) -> dict:
    d = r.to_dict()
    for m in d["modes"]:
        k = m["m"]
        if k not in _MODES:
            continue
        d[f"m{k}_free_hz"] = m["free_hz"]
        d[f"m{k}_approx_low_hz"], d[f"m{k}_approx_high_hz"] = (
            min(m["approx_hz"]),
            max(m["approx_hz"]),
        )
        refined = [f for f in m["refined_hz"] if f is not None]
        if refined:
            d[f"m{k}_refined_low_hz"], d[f"m{k}_refined_high_hz"] = min(refined), max(refined)
    return d


_RING_OUT = {
    "rigid_body_frequency_hz": "f",
    "radial_stiffness_n_per_um": "f",
    "ring_mass_kg": "f",
    "ball_mass_ratio": "f",
    "contact_stiffness_ratio": "f",
}
for _m in _MODES:
    for _k in ("free", "approx_low", "approx_high", "refined_low", "refined_high"):
        _RING_OUT[f"m{_m}_{_k}_hz"] = "f"

RING_MODES = Analysis(
    "ring-modes",
    "Outer-ring natural frequencies (ring_modes, seed 000).",
    {**BEARING_INPUTS, **_RING_INPUTS},
    run=ring_modes,
    outputs=_RING_OUT,
    largest=2000,
    columns=_ring_columns,
    warm=("bearinglab.rings",),
    probe={"modes": "2:6"},
    files=plot_file("the frequencies"),
)
