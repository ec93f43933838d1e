"""The figure of a trend: the indicators over time with the baseline, the limits and the
alarm (matplotlib, imported when a figure is asked for)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .indicators import INDICATORS


def time_axis(times) -> tuple[np.ndarray, str, float]:
    """Times [s] in the unit that suits their span: (values, label, seconds per unit)."""
    span = float(times[-1])
    if span > 3 * 3600:
        return times / 3600.0, "time [h]", 3600.0
    if span > 180:
        return times / 60.0, "time [min]", 60.0
    return times, "time [s]", 1.0


def trend_figure(result, ax=None):
    """The indicators over time (one panel each; all channels), the baseline shaded,
    each test's limit dashed, the alarm as a red line; the velocity with its ISO zones
    and the family significance when computed. Returns (figure, axes)."""
    from matplotlib.ticker import FormatStrFormatter, LogLocator, NullFormatter

    from ..plotting import figure_axes

    panels = list(INDICATORS)
    if result.velocity is not None:
        panels.append("velocity")
    if result.diagnosis is not None:
        panels.append("families")
    fig, axes = figure_axes(
        ax, len(panels), 1, sharex=True, figsize=(10, 1.9 * len(panels) + 0.8), squeeze=False
    )
    axes = np.asarray(axes).ravel()
    t, label, scale = time_axis(result.times)
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:purple"]
    base = (
        result.times[result.settle_records] / scale,
        result.times[result.baseline_stop - 1] / scale,
    )
    for k, (ax_, panel) in enumerate(zip(axes, panels, strict=True)):
        ax_.axvspan(*base, color="0.85", lw=0, label="baseline" if k == 0 else None)
        if result.alarm is not None:
            ax_.axvline(
                t[result.alarm.record], color="red", lw=1.2, label="alarm" if k == 0 else None
            )
        if panel in INDICATORS:
            for c, ch in enumerate(result.channels):
                colour = colours[c % len(colours)]
                ax_.plot(t, result.values[panel][:, c], lw=0.8, color=colour, label=ch)
                j = result.tests.index((panel, c))
                ax_.axhline(result.limit(j), color=colour, ls="--", lw=0.8)
            ax_.set_ylabel(panel.replace("_", " "))
            if panel == "spectral_kurtosis":
                ax_.set_yscale("symlog", linthresh=1.0)
            else:
                ax_.set_yscale("log")
                ax_.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
                ax_.yaxis.set_minor_formatter(NullFormatter())
            ax_.yaxis.set_major_formatter(FormatStrFormatter("%g"))
        elif panel == "velocity":
            for c, ch in enumerate(result.channels):
                ax_.plot(t, result.velocity[:, c] * 1e3, lw=0.8, color=colours[c % 4], label=ch)
            if result.zones is not None:
                for name, v in (
                    ("A/B", result.zones.a_b),
                    ("B/C", result.zones.b_c),
                    ("C/D", result.zones.c_d),
                ):
                    ax_.axhline(v * 1e3, color="0.4", ls=":", lw=0.8)
                    ax_.annotate(name, (t[0], v * 1e3), fontsize=7, color="0.3", va="bottom")
            ax_.set_ylabel("velocity rms\n10-1000 Hz [mm/s]")
            ax_.set_yscale("log")
        else:
            d = result.diagnosis
            for fam in ("outer_race", "inner_race", "ball", "cage"):
                y = [np.nan if s is None else s.get(fam, np.nan) for s in d.significance]
                ax_.plot(t, y, lw=0.8, label=fam)
            if d.threshold is not None:
                ax_.axhline(d.threshold, color="0.3", ls="--", lw=0.8)
            ax_.set_ylabel("family signif.\n-log10 p")
            ax_.legend(fontsize=7, loc="upper left", ncol=4)
    axes[0].legend(fontsize=7, loc="upper left", ncol=4)
    axes[-1].set_xlabel(label)
    title = Path(result.folder).name or result.folder
    if result.alarm is not None:
        a = result.alarm
        title += (
            f": alarm at {t[a.record]:.4g} {label.split('[')[1].rstrip(']')} "
            f"({a.indicator.replace('_', ' ')}, {a.channel})"
        )
    else:
        title += ": no alarm"
    axes[0].set_title(title)
    fig.tight_layout()
    return fig, axes


def life_figure(result, ax=None):
    """The remaining useful life estimated at records over the series, with its 80 %
    interval (shaded), the alarm (red) and the basis of each estimate; returns (figure,
    axes)."""
    from ..plotting import figure_axes

    life = result.remaining_life
    fig, ax_ = figure_axes(ax, figsize=(10, 3.2))
    # (estimates of 0 s, at a failure, are drawn at 10 s on the log scale)
    times = np.asarray(life.history[0], dtype=float)
    est, low, high = (np.maximum(np.asarray(v, dtype=float), 10.0) for v in life.history[1:])
    t, label, scale = time_axis(result.times)
    x = times / scale
    ax_.fill_between(
        x, low / 3600.0, high / 3600.0, color="tab:blue", alpha=0.2, lw=0, label="80 % interval"
    )
    ax_.plot(x, est / 3600.0, color="tab:blue", lw=1.2, marker=".", ms=3, label="estimate")
    if result.alarm is not None:
        ax_.axvline(t[result.alarm.record], color="red", lw=1.2, label="alarm")
    ax_.set_yscale("log")
    ax_.set_xlabel(label)
    ax_.set_ylabel("remaining life [h]")
    ax_.set_title(
        f"remaining life at the last record: {life.estimate / 3600.0:.3g} h "
        f"({life.low / 3600.0:.3g} to {life.high / 3600.0:.3g} h), from {life.basis}"
    )
    ax_.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    return fig, ax_
