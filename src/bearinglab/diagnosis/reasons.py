"""The verdict in words: the one-line reason of a diagnosis, and the warning for a harmonic
series that none of the bearing's frequencies explains (:func:`.verdict.stray_series`).

What each line says follows the tests it reports (:mod:`.series`, :mod:`.verdict`).
"""

from __future__ import annotations

import math

from .families import FAMILIES, FREQUENCY, GATE_CARRIERS, GATE_ORDERS, SIDEBANDS
from .methods import DESCRIPTIONS
from .series import LINE_ALPHA, SUPPORT_ALPHA
from .statistics import decades
from .verdict import series_shape, significance, stray_series


def _gated(family: str) -> str:
    """What the family's harmonic test counts with the harmonics (GATE_ORDERS,
    GATE_CARRIERS)."""
    if not GATE_ORDERS[family]:
        return "alone"
    if GATE_CARRIERS[family]:
        return "alone or with the first sidebands of those that show"
    return "alone or with their first sidebands"


def verdict_reason(faults, table, decision, pfa) -> str:
    """One line: what the verdict rests on."""
    threshold = significance(decision["alpha"])
    if not faults:
        best = max(FAMILIES, key=lambda f: table[f]["significance"])
        t = table[best]
        # above the threshold but stopped by a gate: say which, or the table reads wrong
        gate = significance(SUPPORT_ALPHA)
        short = []
        if t["harmonic_significance"] < gate:
            short.append(
                f"its harmonics {_gated(best)} reach only {t['harmonic_significance']:.3g}"
            )
        if t["support_significance"] < gate:
            short.append(f"without its strongest line it reaches {t['support_significance']:.3g}")
        test = decision.get("tests", {}).get(best)
        shape = series_shape(test[1].lines) if test else None
        if shape and not short:
            short.append(shape)
        if t["significance"] > threshold and short:
            needed = f" (at least {gate:.3g} needed)" if not shape or len(short) > 1 else ""
            return (
                f"no fault called at a false-alarm probability of {pfa:g}: {best} reaches "
                f"{t['significance']:.3g} > {threshold:.3g} by {t['method']}, but a fault "
                f"shows as a series, and {' and '.join(short)}{needed}"
            )
        return (
            f"no family's harmonic series stands out of the noise floor at a false-alarm "
            f"probability of {pfa:g} (threshold {threshold:.3g}; best: {best} "
            f"{t['significance']:.3g} by {t['method']})"
        )
    parts = []
    look = decision.get("second_look") or {}
    for f in faults:
        t = table[f]
        found = t["lines"]
        harm = sorted({ln["n"] for ln in found if ln["kind"] == "harmonic"})
        side = sum(ln["kind"] == "sideband" and ln["n"] > 0 for ln in found)
        own = sum(ln["n"] == 0 for ln in found)  # the modulation's own lines
        rate = {"ftf": "FTF"}.get(SIDEBANDS[f][0], SIDEBANDS[f][0])
        parts.append(
            f"{f}: {FREQUENCY[f]} {t['fundamental_hz']:.5g} Hz ({100 * t['slip']:+.2f} %), "
            f"series significance {t['significance']:.3g} > {threshold:.3g}, its harmonics "
            f"{_gated(f)} {t['harmonic_significance']:.3g} ({t['method']}, "
            f"{DESCRIPTIONS[t['method']].split(' (')[0]}); lines at {100 * LINE_ALPHA:g} % "
            f"each: harmonics {harm or 'none'}, sidebands {side}"
            + (f", k x {rate} {own}" if own else "")
            + (
                f"; read once the {look['removed'].replace('_', ' ')}'s impacts recurring at "
                f"{look['rate_hz']:.6g} Hz were removed from the squared envelope"
                if f in look.get("added", ())
                else ""
            )
        )
    if decision["modulation"]:
        parts.append("FTF lines counted as the cage-rate modulation of the fault")
    # a second series above the threshold beside the fault, not named: say so (a compound
    # fault is reported whole, or its second part is said to be short of the gates)
    gate = significance(SUPPORT_ALPHA)
    for f in FAMILIES:
        t = table[f]
        if f in faults or f in decision["modulation"] or t["significance"] <= threshold:
            continue
        short = [
            f"{what} {value:.3g}"
            for what, value in (
                (f"its harmonics {_gated(f)}", t["harmonic_significance"]),
                ("without its strongest line", t["support_significance"]),
            )
            if value < gate
        ]
        parts.append(
            f"{f} also reaches {t['significance']:.3g} > {threshold:.3g} by {t['method']} "
            "beside it, not named a second fault"
            + (f": {' and '.join(short)} (at least {gate:.3g} needed)" if short else "")
        )
    return "; ".join(parts)


def doubt_reason(withdrawn, table) -> str:
    """The reason when the signal's shaft series puts the speed given in doubt and no race
    or ball series confirms it: no fault named, and the families ``withdrawn`` said."""
    return (
        "no fault named: the signal's shaft series does not confirm the speed given, "
        "and no race or ball series sits where that speed puts it (see the warnings)"
        + "".join(
            f"; {f} passed at that speed ({table[f]['significance']:.3g} by "
            f"{table[f]['method']}), not called"
            for f in withdrawn
        )
    )


def stray_warning(spectra, fams, valid, max_frequency, pfa, freqs, shaft, supply=None) -> list[str]:
    """A warning for the strongest harmonic series that no family explains (the bearing
    or the speed given may be wrong), at the verdict's false-alarm probability."""
    level = pfa / len(spectra)
    found = [
        (s, hit)
        for s in spectra
        if (hit := stray_series(s, fams, valid[s.method], max_frequency, level, shaft, supply))
    ]
    if not found:
        return []
    spec, (f, test, log_p) = min(found, key=lambda sh: sh[1][2])
    shown = sorted(ln.n for ln in test.lines if ln.log_p < math.log(LINE_ALPHA))
    kinematic = ", ".join(
        f"{name.upper()} {freqs[name]:.5g} Hz" for name in ("bpfo", "bpfi", "ball_defect", "ftf")
    )
    return [
        f"a harmonic series at {f:.5g} Hz (harmonics {shown}, significance "
        f"{decades(log_p):.3g} by {spec.method}) stands in the envelope spectrum, and none of "
        f"the bearing's frequencies at the speed used explains it ({kinematic}): check the "
        "bearing and the speed"
    ]
