"""The HTML page of ``bearinglab trend --html``: the summary, the rule, the figure, the
tests and the records around the alarm (the report's style, self-contained). The page takes
the :class:`bearinglab.trend.TrendResult` as data; the trend analysis does not render pages.
"""

from __future__ import annotations

from pathlib import Path

from ..files import write_text_atomically
from ..trend.result import life_text, measured_text
from .document import figure, key_figures, notes, number, page, paragraph, table

#: What the ISO 20816 zones can and cannot say about a bearing (issue 27).
ISO_NOTE = (
    "The zones judge the broadband r.m.s. velocity over 10-1000 Hz (ISO 20816-1 and -3), "
    "the measure of a machine's overall vibration. That band misses most of the energy of "
    "a bearing defect, whose impacts ring the structure at kilohertz frequencies (here the "
    "indicators' band reaches {top} Hz): a failing bearing can stay in zone A until late, "
    "and the alarm above does not use the zones."
)


def trend_page(result) -> str:
    """The page of a trend analysis.

    Parameters
    ----------
    result : bearinglab.trend.TrendResult
        What :func:`bearinglab.trend.trend_records` returned.
    """
    d = result.to_dict()
    alarm = d["alarm"]
    measured = d["rule"]["measured_false_alarm"]
    cards = [
        ("records", f"{len(result.files)}"),
        ("span", f"{result.times[-1] / 3600:.3g} h"),
        ("baseline", f"{result.baseline_records} records"),
        ("alarm", "none" if alarm is None else f"{alarm['time_s']:.6g} s"),
        ("false alarms stated", f"{number(d['rule']['false_alarm_per_hour'], 3)} per hour"),
        ("false alarms measured", _measured_card(measured)),
    ]
    life = d.get("remaining_life")
    if life is not None:
        cards.append(("remaining life", _hours(life["estimate_s"])))
    if alarm is not None:
        cards.append(("raised by", f"{alarm['indicator']} ({alarm['channel']})"))
        cards.append(("before the last record", f"{alarm['time_to_last_record_s']:.6g} s"))
        if alarm["verdict"] is not None:
            cards.append(("diagnosis at the alarm", alarm["verdict"]))
    rows = [
        [
            t["indicator"],
            t["channel"],
            t["baseline_median"],
            t["limit"],
            "-" if t["first_alarm_s"] is None else t["first_alarm_s"],
        ]
        for t in d["tests"]
    ]
    body = [
        key_figures(cards),
        paragraph(d["rule"]["description"]),
        paragraph(
            f"False alarms measured: {measured_text(measured)}. "
            f"Documentation: {d['rule']['documentation']}."
        ),
        figure(
            result.plot()[0],
            "Indicators over time: baseline (grey), limits (dashed), alarm (red)",
        ),
        table(
            ["indicator", "channel", "baseline median", "limit", "first alarm [s]"],
            rows,
            "Tests",
            numeric=(2, 3, 4),
        ),
    ]
    if result.diagnosis is not None and alarm is not None:
        after = d["diagnosis"]["after_alarm"] or {}
        body.append(
            paragraph(
                f"Diagnosis ({result.diagnosis.block_records} consecutive records joined, "
                f"channel {result.diagnosis.channel}): at the alarm "
                f"{alarm['verdict'] or 'not computed'}; after it "
                + (", ".join(f"{k}: {v} blocks" for k, v in after.items()) or "no block")
                + "."
            )
        )
    if alarm is not None:
        lo, hi = max(0, alarm["record"] - 5), min(len(result.files), alarm["record"] + 6)
        near = [
            [
                r["time_s"],
                r["file"],
                ", ".join(r["above_limit"]) or "-",
                r["verdict"] or "-",
            ]
            for r in d["records"][lo:hi]
        ]
        body.append(
            table(
                ["time [s]", "file", "above limit", "diagnosis"],
                near,
                "Records near the alarm",
                numeric=(0,),
            )
        )
    if d["short_crossings"]:
        shown = d["short_crossings"][:20]
        body.append(
            table(
                ["from [s]", "to [s]", "indicator", "channel"],
                [[c["time_s"], c["end_s"], c["indicator"], c["channel"]] for c in shown],
                f"Short crossings: records above a limit that did not persist "
                f"({len(d['short_crossings'])}, the first {len(shown)} shown)",
                numeric=(0, 1),
            )
        )
    if d["severity"] is not None:
        body.append(_zones(d["severity"], result.max_frequency))
    if life is not None:
        body.append(_life(result, life))
    body.append(notes(d["warnings"], "Warnings"))
    return page("bearinglab trend", [result.folder], "".join(body))


def _hours(seconds: float) -> str:
    return f"{seconds:.4g} s" if seconds < 3600 else f"{seconds / 3600:.3g} h"


def _measured_card(m: dict) -> str:
    if m["per_hour"] is None:
        return "not measured"
    if m["upper_per_hour"] is not None:
        return f"0 in {number(m['monitored_hours'], 3)} h (< {number(m['upper_per_hour'], 2)}/h)"
    return f"{number(m['per_hour'], 3)} per hour"


def _zones(severity: dict, top: float) -> str:
    """The ISO 20816 zones: the machine's boundaries, when each zone was first reached, and
    what the velocity band cannot see."""
    b = severity["boundaries_mm_s"]
    first = severity["first_zone_s"]
    rows = [
        ["A/B", b["a_b"], first.get("B")],
        ["B/C", b["b_c"], first.get("C")],
        ["C/D", b["c_d"], first.get("D")],
    ]
    return table(
        ["boundary", "velocity r.m.s. [mm/s]", "first reached [s]"],
        rows,
        f"ISO 20816 zones of {severity['machine']} ({severity['source']})",
        numeric=(1, 2),
    ) + paragraph(ISO_NOTE.format(top=number(top, 4)))


def _life(result, life: dict) -> str:
    """The remaining-life estimate, its basis and its figure over time."""
    out = paragraph(
        f"Remaining useful life: {life_text(life)}. Learned from {life['learned_from']}."
    )
    history = getattr(result.remaining_life, "history", None)
    if history is not None and len(history[0]):
        out += figure(
            result.plot_life()[0],
            "Remaining useful life estimated at each record, with its 80 % interval",
        )
    return out


def write_trend_page(result, path) -> Path:
    """Write :func:`trend_page` of ``result`` atomically to ``path`` (UTF-8).

    Parameters
    ----------
    result : TrendResult
        What :func:`bearinglab.trend.trend_records` returned.
    path : str or Path
        The HTML file to write; its directory must exist.

    Returns
    -------
    Path
        The file written.
    """
    text = trend_page(result)
    return write_text_atomically(path, text)
