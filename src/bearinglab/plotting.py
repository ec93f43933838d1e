"""Figures for result objects (matplotlib, imported only when a plot is asked for).

Functions here return ``(figure, axes)`` and never call ``show()``; :func:`save_figure`
writes atomically (temporary file, then rename) so a failed write leaves no half file.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from .errors import InputError
from .files import write_atomically


def _pyplot():
    try:
        import matplotlib

        if not os.environ.get("DISPLAY") and matplotlib.get_backend().lower() != "agg":
            matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:  # pragma: no cover - depends on the install
        raise InputError(
            "matplotlib", None, "matplotlib installed (a dependency)", "pip install matplotlib"
        ) from None
    return plt


def figure_axes(ax=None, *args, **kwargs):
    """``(figure, ax)`` for a plot method's ``ax`` argument: the figure that ``ax`` (one
    Axes, or a sequence of them) is on, or, when ``ax`` is None, a new figure and axes
    from ``pyplot.subplots(*args, **kwargs)``."""
    if ax is None:
        return _pyplot().subplots(*args, **kwargs)
    return (ax.figure if hasattr(ax, "figure") else ax[0].figure), ax


def save_figure(fig, path: str | Path) -> Path:
    """Save ``fig`` to ``path`` atomically; the format follows the suffix (.png, .svg, .pdf)."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".png", ".svg", ".pdf"):
        raise InputError("path", str(path), "a file name ending in .png, .svg or .pdf")
    if not path.parent.exists():
        raise InputError("path", str(path), "a path in an existing directory")
    write_atomically(path, lambda tmp: fig.savefig(tmp, dpi=120, bbox_inches="tight"))
    _pyplot().close(fig)
    return path


def ball_contacts_figure(curve, final, axes=None):
    """Max pressure and approach against ball load, and the two contact ellipses at the
    largest load drawn to scale.

    Parameters
    ----------
    curve : bearinglab.contact.ball_race.BallContacts
        Contacts over a range of loads (the curves).
    final : bearinglab.contact.ball_race.BallContacts
        Contacts at the one load whose ellipses are drawn.
    axes : sequence of two matplotlib Axes, optional
        Where to draw; a new figure otherwise.
    """
    fig, axes = figure_axes(axes, 1, 2, figsize=(11, 4.2))
    loads, q_max = np.asarray(curve.load), float(np.max(final.load))
    ax, ax2 = axes[0], axes[0].twinx()
    for race, c, style in (("inner", curve.inner, "-"), ("outer", curve.outer, "--")):
        ax.plot(loads, c.max_pressure / 1e9, "C0" + style, label=f"p_max {race}")
        ax2.plot(loads, c.approach * 1e6, "C1" + style, label=f"approach {race}")
    ax.set_xlabel("ball load Q [N]")
    ax.set_ylabel("max pressure [GPa]", color="C0")
    ax2.set_ylabel("approach [um]", color="C1")
    lines = ax.get_lines() + ax2.get_lines()
    ax.legend(lines, [line.get_label() for line in lines], loc="upper left", fontsize=8)
    ax.set_title(f"{curve.bearing.name or 'bearing'}: Hertz contact vs load")
    t = np.linspace(0, 2 * np.pi, 200)
    for race, c, colour in (("inner", final.inner, "C3"), ("outer", final.outer, "C2")):
        a, b = float(c.semi_major) * 1e3, float(c.semi_minor) * 1e3
        axes[1].fill(b * np.cos(t), a * np.sin(t), color=colour, alpha=0.25)
        axes[1].plot(
            b * np.cos(t),
            a * np.sin(t),
            color=colour,
            label=f"{race}: 2a = {2 * a:.3g} mm, 2b = {2 * b:.3g} mm, "
            f"p_max = {float(c.max_pressure) / 1e9:.3g} GPa",
        )
    # the ellipses are 5-15 times longer than wide: stretch the rolling direction to read them
    axes[1].set_xlabel("rolling direction [mm] (stretched)")
    axes[1].set_ylabel("across the groove [mm]")
    axes[1].set_title(f"contact ellipses at Q = {q_max:g} N")
    axes[1].legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.18))
    fig.tight_layout()
    return fig, axes


def frequencies_figure(freqs, names, harmonics: int = 3, ax=None):
    """Stem chart of the defect frequencies and their harmonics, for reading spectra.

    Parameters
    ----------
    freqs : bearinglab.kinematics.DefectFrequencies
        The frequencies.
    names : sequence of str
        Which of them to draw (``freqs.hz(name)``), e.g. shaft, ftf, bpfo [-].
    harmonics : int
        How many harmonics of each to draw (>= 1).
    ax : matplotlib Axes, optional
        Where to draw.
    """
    fig, ax = figure_axes(ax, figsize=(10, 4))
    for i, name in enumerate(names):
        base = freqs.hz(name)
        h = np.arange(1, harmonics + 1) * base
        ax.vlines(
            h,
            0,
            1.0 / np.arange(1, harmonics + 1),
            color=f"C{i}",
            label=f"{name.upper()} {base:.2f} Hz",
        )
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("harmonic (1/n)")
    ax.set_ylim(0, 1.1)
    ax.set_title(
        f"{freqs.bearing.name or 'bearing'} at {freqs.shaft_hz * 60:g} rpm: "
        f"defect frequencies and harmonics"
    )
    ax.legend(fontsize=8, ncol=3)
    fig.tight_layout()
    return fig, ax


def load_distribution_figure(result, axes=None):
    """Polar load distribution (ball loads at their azimuths, inner and outer) and the
    contact angles of every ball.

    Parameters
    ----------
    result : bearinglab.quasistatic.LoadDistribution
        A solved load distribution.
    axes : pair of matplotlib Axes (the first polar), optional
        Where to draw.
    """
    plt = _pyplot()
    if axes is None:
        fig = plt.figure(figsize=(11, 4.6))
        axes = (fig.add_subplot(1, 2, 1, projection="polar"), fig.add_subplot(1, 2, 2))
    fig = axes[0].figure
    table = result.ball_table()
    angles = np.radians(table["angle_deg"].to_numpy())
    width = 2 * np.pi / len(angles) * 0.35
    axes[0].bar(angles - width / 2, table["inner_load_n"], width=width, color="C0", label="inner")
    axes[0].bar(angles + width / 2, table["outer_load_n"], width=width, color="C1", label="outer")
    axes[0].set_title("ball loads [N] at their angles", fontsize=10)
    axes[0].legend(loc="lower left", fontsize=8, bbox_to_anchor=(-0.15, -0.12))
    order = np.argsort(table["angle_deg"].to_numpy())
    for name, colour in (("inner", "C0"), ("outer", "C1")):
        axes[1].plot(
            table["angle_deg"].to_numpy()[order],
            table[f"{name}_contact_angle_deg"].to_numpy()[order],
            "o-",
            color=colour,
            label=f"{name} contact angle",
        )
    axes[1].set_xlabel("ball angle [deg]")
    axes[1].set_ylabel("contact angle [deg]")
    d = result.to_dict()
    axes[1].set_title(
        f"S_r = {d['radial_displacement_um']:.3g} um, S_a = "
        f"{d['axial_displacement_um']:.3g} um, C_r = "
        f"{d['radial_stiffness_n_per_um']:.3g} N/um",
        fontsize=10,
    )
    axes[1].legend(fontsize=8)
    fig.suptitle(
        f"{result.bearing.name or 'bearing'}: F_r = {result.condition.radial_load:g} N, "
        f"F_a = {result.condition.axial_load:g} N, "
        f"{result.condition.shaft_speed * 30 / np.pi:g} rpm"
    )
    fig.tight_layout()
    return fig, axes


def roller_distribution_figure(
    angles, inner, outer, positions, inner_slices, outer_slices, name="", axes=None
):
    """Roller loads at their azimuths (inner and outer raceway) and the slice loads along
    the heaviest roller.

    Parameters
    ----------
    angles : array (N,)
        Roller azimuths [rad].
    inner, outer : arrays (N,)
        Roller loads on the inner and outer raceway [N].
    positions : array (n_s,)
        Slice centres along the roller [m].
    inner_slices, outer_slices : arrays (n_s,)
        Slice loads of the heaviest roller [N].
    name : str
        Bearing label for the title [-].
    axes : pair of matplotlib Axes (the first polar), optional
        Where to draw.
    """
    plt = _pyplot()
    if axes is None:
        fig = plt.figure(figsize=(11, 4.6))
        axes = (fig.add_subplot(1, 2, 1, projection="polar"), fig.add_subplot(1, 2, 2))
    fig = axes[0].figure
    angles = np.asarray(angles, float)
    width = 2 * np.pi / max(len(angles), 1) * 0.35
    axes[0].bar(angles - width / 2, inner, width=width, color="C0", label="inner")
    axes[0].bar(angles + width / 2, outer, width=width, color="C1", label="outer")
    axes[0].set_title(f"{name} roller loads [N] at their angles".strip(), fontsize=10)
    axes[0].legend(loc="lower left", fontsize=8, bbox_to_anchor=(-0.15, -0.12))
    x = np.asarray(positions, float) * 1e3
    axes[1].step(x, inner_slices, where="mid", color="C0", label="inner slices")
    axes[1].step(x, outer_slices, where="mid", color="C1", label="outer slices")
    axes[1].set_xlabel("position along the roller [mm]")
    axes[1].set_ylabel("slice load [N]")
    axes[1].set_title("heaviest roller", fontsize=10)
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    return fig, axes


def roller_pressure_figure(curves, name="", ax=None):
    """The pressure along a roller on each raceway.

    Parameters
    ----------
    curves : dict
        Raceway -> (positions [m], pressures [Pa]).
    name : str
        Bearing label [-].
    ax : matplotlib Axes, optional
        Where to draw.
    """
    fig, ax = figure_axes(ax, figsize=(8, 4))
    for race, (x, p) in curves.items():
        ax.plot(np.asarray(x) * 1e3, np.asarray(p) / 1e6, "o-", ms=3, label=race)
    ax.axhline(4000.0, color="0.5", ls="--", lw=0.8, label="ISO 76: 4000 MPa")
    ax.set_xlabel("position along the roller [mm]")
    ax.set_ylabel("pressure [MPa]")
    ax.set_title(f"{name} pressure along the roller".strip(), fontsize=10)
    ax.legend(fontsize=8)
    return fig, ax


def stiffness_map_figure(table, ax=None):
    """Radial and axial stiffness over the radial load, one line per (axial load, speed).

    Parameters
    ----------
    table : pandas.DataFrame
        Rows with radial_load_n, axial_load_n, speed_rpm, radial_stiffness_n_per_um,
        axial_stiffness_n_per_um.
    ax : pair of matplotlib Axes, optional
        Where to draw.
    """
    fig, ax = figure_axes(ax, 1, 2, figsize=(11, 4.2))
    for (fa, rpm), group in table.groupby(["axial_load_n", "speed_rpm"]):
        label = f"F_a = {fa:g} N, {rpm:g} rpm"
        ax[0].plot(group["radial_load_n"], group["radial_stiffness_n_per_um"], ".-", label=label)
        ax[1].plot(group["radial_load_n"], group["axial_stiffness_n_per_um"], ".-", label=label)
    for a, name in zip(ax, ("radial C_r", "axial C_a"), strict=False):
        a.set_xlabel("radial load F_r [N]")
        a.set_ylabel(f"{name} [N/um]")
        a.legend(fontsize=7)
    fig.tight_layout()
    return fig, ax


def draw_spectrum(
    ax,
    spec,
    lines,
    kin,
    max_frequency: float,
    *,
    title: str,
    ylabel: str,
    names=("shaft", "ftf", "bpfo", "bpfi", "ball_defect"),
    harmonics: int = 8,
    trace: str = "spectrum",
    highlight=None,
) -> None:
    """A spectrum (or envelope spectrum) up to ``max_frequency`` with the kinematic
    lines and their harmonics marked and the labelled peaks annotated (the lines of
    :func:`bearinglab.signal.lines.spectrum_lines` or of a diagnosis). ``highlight(line)``
    says which peaks to draw in colour; by default those matched to any line."""
    from .signal.peaks import peak_label

    f, a = spec.frequency, spec.amplitude
    shown = (f > 0) & (f <= max_frequency)  # a DC offset (or envelope mean) would set the scale
    ax.plot(f[shown], a[shown], color="0.3", lw=0.8, label=trace)
    top = float(np.max(a[shown])) if np.any(shown) else 1.0
    for i, name in enumerate(names):
        base = kin.hz(name)
        marks = np.arange(1, harmonics + 1) * base
        marks = marks[marks <= max_frequency]
        if marks.size:
            ax.vlines(
                marks,
                0,
                1.05 * top,
                colors=f"C{i}",
                linestyles="--",
                lw=0.8,
                alpha=0.7,
                label=f"{name.upper()} {base:.2f} Hz and harmonics",
            )
    for p in lines:
        label = peak_label(p)
        coloured = label != "-" if highlight is None else highlight(p)
        ax.plot(p["frequency_hz"], p["amplitude"], "o", ms=4, color="C3" if coloured else "k")
        ax.annotate(
            label,
            (p["frequency_hz"], p["amplitude"]),
            textcoords="offset points",
            xytext=(2, 4),
            fontsize=7,
            rotation=60,
        )
    ax.set_title(title)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel(ylabel)
    ax.set_xlim(0, max_frequency)
    ax.set_ylim(0, 1.25 * top)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))


def draw_aligned_events(axes, lag, waveform, envelope, entry_lag, title: str, speed=None) -> None:
    """An event-aligned average: the averaged record (``axes[0]``) and its event envelope
    over its floor on a log scale (``axes[1]``) against the time from the exit [ms], the
    exit (at 0) and the entry (``entry_lag`` [s], None: no entry) marked, around them.

    Parameters
    ----------
    axes : sequence of two matplotlib Axes
        Where to draw.
    lag : array_like
        Time of each sample from the exit (or from the burst tracked) [s].
    waveform, envelope : array_like
        The averaged record [its unit] and event envelope over its floor [-].
    entry_lag : float or None
        The entry's time from the exit [s].
    title : str
        The title of the upper plot.
    speed : float, optional
        The contact point's speed over the race [m/s]: the distance it travels is shown
        on a second axis [mm].
    """
    ms = np.asarray(lag, dtype=float) * 1e3
    top, bottom = axes
    if ms.size == 0:
        top.text(0.5, 0.5, "no passages to average", ha="center", transform=top.transAxes)
        top.set_title(title)
        return
    spacing = 0.0 if entry_lag is None else -entry_lag * 1e3
    margin = max(spacing, 1.0)
    shown = (ms >= -spacing - margin) & (ms <= margin)
    top.plot(ms[shown], np.asarray(waveform)[shown], color="0.3", lw=0.7)
    top.set_ylabel("averaged record")
    top.tick_params(labelbottom=False)
    bottom.semilogy(ms[shown], np.maximum(np.asarray(envelope)[shown], 1e-3), color="0.3", lw=0.8)
    bottom.set_ylabel("event envelope / floor")
    bottom.set_xlabel("time from the exit [ms]" if entry_lag is not None else "time [ms]")
    marks = [(0.0, "exit" if entry_lag is not None else "burst", "C3")]
    if entry_lag is not None:
        marks.append((entry_lag * 1e3, "entry", "C0"))
    for ax in axes:
        for at, label, colour in marks:
            ax.axvline(at, color=colour, ls="--", lw=1.0, label=label)
    bottom.legend(fontsize=8, loc="upper right")
    if speed:
        v = float(speed)
        top.secondary_xaxis("top", functions=(lambda t: t * v, lambda x: x / v)).set_xlabel(
            "distance the contact point travels over the race [mm]"
        )
    top.set_title(title)
