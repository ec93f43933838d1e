"""The HTML page of ``bearinglab trend --html``: the summary, the rule, the figure, the
tests and the records around the alarm (the report's style, self-contained). The page takes
the :class:`bearinglab.trend.TrendResult` as data; the trend analysis does not render pages.
"""

from __future__ import annotations

from pathlib import Path

from ..files import write_atomically
from .document import figure, key_figures, notes, page, paragraph, table


def trend_page(result) -> str:
    """The page of a trend analysis.

    Parameters
    ----------
    result : bearinglab.trend.TrendResult
        What :func:`bearinglab.trend.trend_records` returned.
    """
    d = result.to_dict()
    alarm = d["alarm"]
    cards = [
        ("records", f"{len(result.files)}"),
        ("span", f"{result.times[-1] / 3600:.3g} h"),
        ("baseline", f"{result.baseline_records} records"),
        ("alarm", "none" if alarm is None else f"{alarm['time_s']:.6g} s"),
    ]
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
    body.append(notes(d["warnings"], "Warnings"))
    return page("bearinglab trend", [result.folder], "".join(body))


def write_trend_page(result, path) -> Path:
    """Write :func:`trend_page` of ``result`` atomically to ``path`` (UTF-8)."""
    text = trend_page(result)
    return write_atomically(path, lambda tmp: Path(tmp).write_text(text, encoding="utf-8"))
