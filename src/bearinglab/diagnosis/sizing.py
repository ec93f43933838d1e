"""The width of a race defect from the entry and exit events of its passages.

A rolling element that rolls over a spall long enough to drop into it makes two events per
passage: the entry, a low-frequency unloading as it leaves the near edge, and the exit, a
high-frequency impact as it strikes the far edge; their spacing in time, with the
element's speed over the race, gives the defect's extent along the rolling direction
(Sawalhi N., Randall R. B., "Vibration response of spalled rolling element bearings:
observations, simulations and signal processing techniques to track the spall size",
MSSP 25 (2011) 846-870; Epps I. K., McCallion H., "An investigation into the
characteristic vibration excited by discrete faults in rolling element bearings", 1994).
From one record, without a tachometer:

1. **Events** (:func:`.events.event_envelope`): the record whitened by its linear prediction
   error - an order-p autoregressive model of the record (PREDICTOR_LENGTH), fitted by
   the Levinson-Durbin recursion (:func:`.events.levinson`, Makhoul 1975) - as Sawalhi & Randall
   (2011) whiten it, so that the entry's step response and the exit's impulse response
   stand out alike; the prediction error filter is causal, so each burst stays where it
   starts. The squared envelope shows each passage of the defect as a burst.
2. **Passages**: the largest burst of each fault period (the fault frequency the
   diagnosis measured, slip included) is tracked from period to period; weak passages
   (the defect out of the load zone) are left out (:func:`.events.track_passages`). The passages
   are aligned on their average (Woody 1967, :func:`.events.align_passages`): the event-aligned
   average.
3. **The pair** (:func:`.events.find_pair`): the second event of the average, at most one ball
   diameter's travel away, that is an event of its own - MEASURABLE floors high and at
   least ENTRY_FRACTION of the tracked burst - separate from it (the average falls back
   to within SEPARATION of the weaker one's height between them) with a quiet interval
   between them (QUIET), that rises above that valley passage by passage (Wilcoxon's
   signed-rank test across passages, Bonferroni over the maxima tried,
   :func:`.events.separate_events`), and that makes a pair: once each passage is oriented alike,
   no event as large stands at the mirrored lag (a burst with events at both sides is
   one burst modulated by the beating of two modes). The earlier of the two is the entry.
4. **Width**: the spacing of entry and exit in each passage (median and the central 80 %
   over passages) times the speed of the contact point over the race,
   v = 2 pi f R / Z (:func:`.spall.contact_speed`: f the measured fault frequency, R the
   raceway radius, Z the balls), plus what the ball bridges at the two edges
   (:func:`.spall.bridged_width`): its contacts are compressed by their approach delta0, so it
   loses contact only where the pit has opened that much clearance under it, x0 past the
   near edge, and it is loaded again x1 before the far edge, where the clearance has
   closed to delta1, the approach on the load line once the other balls carry its load
   (:func:`.spall.ball_approaches`, :func:`.spall.bridged_distance`; the circle-chord
   geometry of seed 003's rigid model, :func:`bearinglab.dynamics.defects.edge_drop`).

A defect shorter than x0 + x1 unloads the ball without letting it drop, and a defect
whose two events lie closer than their bursts ring shows them merged: either way there is
no separate entry, and the answer is "too small to size" - when the exit bursts stand
MEASURABLE floors high, so that a separate entry would have shown; otherwise "not sized",
with the reason.

The ball's load is the radial load given, or, when none is, ASSUMED_LOAD x the bearing's
dynamic rating C (the middle, on a log scale, of 0.01-0.1 C, the loads a ball bearing runs
at in ordinary service); the interval then spans LOAD_RANGE as well as the spread over
passages.

Layer 3 (:func:`size_defect`, :class:`DefectSize`) on the functions of :mod:`.spall` (the
geometry, SI; ASSUMED_LOAD, LOAD_RANGE) and :mod:`.events` (the signal processing;
SEPARATION, QUIET, ENTRY_FRACTION, MEASURABLE); docs/capabilities/defect_size.md has what
was measured.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from .events import (
    ENTRY_FRACTION,
    MEASURABLE,
    align_passages,
    event_envelope,
    find_pair,
    median,
    moving_average,
    refine_peaks,
    ring_down,
    track_passages,
)
from .spall import (
    ASSUMED_LOAD,
    LOAD_RANGE,
    assumed_loads,
    bridged_width,
    bridged_widths,
    contact_speed,
    raceway_radius,
)

#: The fault families whose defects are sized, and their race.
RACES = {"outer_race": "outer", "inner_race": "inner"}
#: Length of the moving average that smooths the envelope for reading the average's
#: maxima and each passage's events [s].
SMOOTHING = 1e-4
#: Length of the moving average over which passages are tracked: about a burst [s].
TRACK_SMOOTHING = 1e-3
#: Fewest passages averaged [-].
MIN_PASSAGES = 20
#: Quantiles of the per-passage spacing that bound the interval [-].
QUANTILES = (0.1, 0.9)
#: Largest event spacing searched, as a fraction of the fault period (a pair further
#: apart would be nearer the next passage's event than its own) [-].
MAX_PERIOD_FRACTION = 0.45
#: Length of the linear predictor that whitens the record [s].
PREDICTOR_LENGTH = 1e-3
STATUSES = ("sized", "too small to size", "not sized")


@dataclass(frozen=True)
class DefectSize:
    """The width of a race defect read from its entry and exit events.

    Attributes
    ----------
    race : str
        ``outer_race`` or ``inner_race``.
    status : str
        ``sized``, ``too small to size`` (the exit bursts are clear, no separate entry
        precedes them) or ``not sized`` (the record cannot tell; ``reason`` says why).
    reason : str
        What was found, in words.
    width, low, high : float or None
        The width along the rolling direction and its interval [m] (sized only).
    extent : float or None
        The angular extent on the raceway, ``width`` / raceway radius [rad].
    spacing : float or None
        Median spacing of entry and exit over the passages [s].
    passages : int
        Passages averaged.
    fault_frequency : float
        The measured fault frequency [Hz].
    speed : float
        The contact point's speed over the race [m/s].
    bridged : float or None
        What the ball bridges at both edges at the load used [m].
    radial_load : float or None
        The radial load used [N]; ``load_given`` says whether it was given.
    lag, envelope, waveform : numpy.ndarray
        The event-aligned average: time from the exit (or from the tracked burst when
        there is no exit) [s], the averaged event envelope over its floor [-] and the
        averaged record (aligned on the same samples) [unit of the record].
    entry_lag : float or None
        Time of the entry before the exit (negative) [s].
    """

    race: str
    status: str
    reason: str
    fault_frequency: float
    speed: float
    passages: int = 0
    width: float | None = None
    low: float | None = None
    high: float | None = None
    extent: float | None = None
    spacing: float | None = None
    bridged: float | None = None
    radial_load: float | None = None
    load_given: bool = False
    lag: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)
    envelope: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)
    waveform: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)
    entry_lag: float | None = None

    @property
    def sized(self) -> bool:
        """True when a width was read."""
        return self.status == "sized"

    def to_dict(self) -> dict:
        """JSON-ready: ``race``, ``status``, ``width_mm``, ``extent_deg``, ``low_mm``,
        ``high_mm``, ``reason`` (null where not sized), and ``event_spacing_s``,
        ``passages``, ``radial_load_n``."""

        def mm(value):
            return None if value is None else value * 1e3

        return {
            "race": self.race,
            "status": self.status,
            "width_mm": mm(self.width),
            "extent_deg": None if self.extent is None else math.degrees(self.extent),
            "low_mm": mm(self.low),
            "high_mm": mm(self.high),
            "reason": self.reason,
            "event_spacing_s": self.spacing,
            "passages": self.passages,
            "radial_load_n": self.radial_load,
        }

    def to_pandas(self):
        """The event-aligned average as a table: ``time_from_exit_s``, ``record`` (the
        averaged record, its unit) and ``envelope`` (the averaged event envelope over its
        floor); empty when no passages were averaged."""
        import pandas as pd

        return pd.DataFrame(
            {"time_from_exit_s": self.lag, "record": self.waveform, "envelope": self.envelope}
        )

    def plot(self, ax=None, path=None):
        """The event-aligned average: the averaged record (top) and event envelope
        (bottom, over its floor) against the time from the exit, entry and exit marked.

        Parameters
        ----------
        ax : sequence of two matplotlib Axes, optional
            Where to draw; a new figure otherwise.
        path : str or Path, optional
            Also save the figure there (.png, .svg or .pdf; the figure is closed).

        Returns
        -------
        (figure, axes)
        """
        from ..plotting import draw_aligned_events, figure_axes, save_figure

        fig, axes = figure_axes(ax, 2, 1, figsize=(10, 6), sharex=True)
        draw_aligned_events(
            axes,
            self.lag,
            self.waveform,
            self.envelope,
            self.entry_lag,
            f"{self.race.replace('_', ' ')}: {self.status}"
            + (f", {self.width * 1e3:.2f} mm" if self.sized else "")
            + f" ({self.passages} passages)",
            speed=self.speed,
        )
        fig.tight_layout()
        if path is not None:
            save_figure(fig, path)
        return fig, axes


#: The fault frequency of each race, as the reason names it.
_FREQUENCY = {"outer": "BPFO", "inner": "BPFI"}


def _number(name: str, value, allowed: str) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = math.nan
    if isinstance(value, bool) or not (math.isfinite(v) and v > 0):
        raise InputError(name, value, allowed)
    return v


def size_defect(
    x,
    sample_rate: float,
    bearing,
    fault: str,
    fault_frequency: float,
    *,
    radial_load: float | None = None,
) -> DefectSize:
    """The width of the defect on a race from the entry and exit events of its passages.

    See the module docstring for the method and its sources.

    Parameters
    ----------
    x : array_like
        The record's samples (1-D), any unit.
    sample_rate : float
        Sample rate [Hz].
    bearing : BallBearing
        The bearing.
    fault : {"outer_race", "inner_race"}
        The fault family the diagnosis found.
    fault_frequency : float
        Its fundamental as measured (BPFO or BPFI, slip included) [Hz].
    radial_load : float, optional
        Radial load on the bearing [N]; default ASSUMED_LOAD x the dynamic rating C, with
        LOAD_RANGE in the interval.

    Returns
    -------
    DefectSize

    Examples
    --------
    Two bursts 1 ms apart at each passage of an outer-race defect of a 6205 (BPFO
    107.4 Hz, the contact point at 1.76 m/s), in noise:

    >>> from bearinglab.catalog import bearing_from_designation
    >>> b, _ = bearing_from_designation("6205")
    >>> fs, f = 51200.0, 107.4
    >>> rng = np.random.default_rng(0)
    >>> x = 0.02 * rng.standard_normal(int(2 * fs))
    >>> for t0 in np.arange(0.004, 1.99, 1 / f):
    ...     for t1, a in ((t0, 0.5), (t0 + 1e-3, 1.0)):
    ...         i = int(t1 * fs)
    ...         x[i:i + 40] += a * np.exp(-np.arange(40) / 8) * np.sin(np.arange(40) * 2)
    >>> s = size_defect(x, fs, b, "outer_race", f, radial_load=500.0)
    >>> s.status, round(s.spacing * 1e3, 2), round(s.width * 1e3, 2)
    ('sized', 1.0, 2.45)
    """
    if fault not in RACES:
        raise InputError("fault", fault, f"one of {sorted(RACES)}")
    race = RACES[fault]
    fs = _number("sample_rate", sample_rate, "a sample rate > 0 Hz")
    f = _number("fault_frequency", fault_frequency, "a frequency > 0 Hz")
    from ..signal.spectra import samples

    x = samples(x, "x")
    if bearing.rolling_element == "roller":  # the spall geometry here is a ball's
        return DefectSize(
            race=fault,
            status="not sized",
            reason="sizing models a ball rolling over a spall (its drop and the bridging at "
            "the edges); a roller's line contact is not modelled",
            fault_frequency=f,
            speed=float(contact_speed(f, bearing.roller_count, raceway_radius(bearing, race))),
        )
    radius = raceway_radius(bearing, race)
    v = float(contact_speed(f, bearing.ball_count, radius))
    if radial_load is None:
        try:
            load, light, heavy = assumed_loads(bearing)
        except (InputError, ValueError, ArithmeticError) as exc:
            return DefectSize(
                race=fault,
                status="not sized",
                reason="no radial load given, and the bearing's dynamic load rating, to "
                f"assume one from, could not be computed ({exc}): give the radial load",
                fault_frequency=f,
                speed=v,
            )
        given = False
    else:
        load = light = heavy = _number("radial_load", radial_load, "a radial load > 0 N")
        given = True
    common = {"race": fault, "fault_frequency": f, "speed": v, "radial_load": load}
    common["load_given"] = given
    period = fs / f
    k = max(1, int(round(SMOOTHING * fs)))
    longest = int(min(bearing.ball_diameter / v * fs, MAX_PERIOD_FRACTION * period))
    shortest = max(2 * k, 3)
    if longest < 2 * shortest:
        return DefectSize(
            status="not sized",
            reason=f"at {fs:g} Hz a defect as long as the ball ({bearing.ball_diameter * 1e3:.3g}"
            f" mm) passes in {longest} samples, too few to time its entry and exit",
            **common,
        )
    order = max(4, int(round(PREDICTOR_LENGTH * fs)))
    e = event_envelope(x, order)
    es = moving_average(e, k)
    floor = median(es)
    reach = max(k, int(round(TRACK_SMOOTHING * fs)))
    times, clear = track_passages(moving_average(e, reach), period)
    margin = 2 * longest + k
    edge = margin + longest + 4 * reach
    keep = clear & (times >= edge) & (times + edge < es.size)
    t = times[keep]
    if t.size < MIN_PASSAGES:
        return DefectSize(
            status="not sized",
            reason=f"{t.size} passages of the defect stand clearly above the noise (of "
            f"{times.size}); at least {MIN_PASSAGES} are averaged",
            passages=int(t.size),
            **common,
        )
    # each passage at its largest burst, then all aligned on their average
    near = es[t[:, None] + np.arange(-reach, reach + 1)]
    t = t - reach + np.argmax(near, axis=1)
    t = align_passages(es, t, margin, reach)
    window = np.arange(-margin, margin + 1)
    centre = margin
    pair = find_pair(es, t, window, floor, shortest, longest, max(k // 2, 1))
    if pair is not None:
        lag, t = pair
    rows = es[t[:, None] + window]
    average = rows.mean(axis=0)
    waveform = x[t[:, None] + window].mean(axis=0)
    height = float(average[centre] / floor)
    if pair is None:
        lag = window / fs
        plot = {"lag": lag, "envelope": average / floor, "waveform": waveform}
        if height - 1.0 < MEASURABLE:
            return DefectSize(
                status="not sized",
                reason=f"the defect's bursts stand {height:.3g} times above the envelope's "
                f"floor (averaged over {t.size} passages): an entry, weaker than the exit, "
                f"would not show as a separate event ({MEASURABLE:g} floors above the floor)",
                passages=int(t.size),
                **plot,
                **common,
            )
        bridged = bridged_width(bearing, race, load)
        burst = ring_down(average, floor, centre, ENTRY_FRACTION, longest)
        return DefectSize(
            status="too small to size",
            reason=f"no entry event separate from the exit bursts ({t.size} passages, "
            f"{height:.3g} times the envelope's floor): the defect is too short for the "
            f"ball to drop into it, or its entry lies within the exit's burst - the ball "
            f"bridges {bridged * 1e3:.2g} mm of it under {load:.4g} N"
            f"{'' if given else ' (assumed)'}, and the bursts ring for {burst / fs * 1e3:.2g} "
            f"ms ({v * burst / fs * 1e3:.2g} mm at this speed), so a defect under about "
            f"{(bridged + v * burst / fs) * 1e3:.2g} mm shows no two separate events here",
            passages=int(t.size),
            bridged=bridged,
            **plot,
            **common,
        )
    entry_at, exit_at = (lag, 0) if lag < 0 else (0, lag)
    reach = max(k, int(round(0.2 * abs(lag))))
    # each passage's entry and exit: the largest sample near each, refined by a parabola
    # (refine_peaks: refine_peak of all passages at once)
    positions = []
    for at in (entry_at, exit_at):
        lo = max(centre + at - reach, 0)
        positions.append(
            refine_peaks(rows, lo + np.argmax(rows[:, lo : centre + at + reach + 1], axis=1))
        )
    spacings = (positions[1] - positions[0]) / fs
    spacing = float(np.median(spacings))
    q_low, q_high = (float(q) for q in np.quantile(spacings, QUANTILES))
    # the three loads' bridged widths at once (one Hertz constant, one bisection)
    bridged, at_light, at_heavy = bridged_widths(bearing, race, (load, light, heavy))
    low = v * max(q_low, 0.0) + at_light
    high = v * q_high + at_heavy
    width = v * spacing + bridged
    load_words = (
        f"under {load:.4g} N"
        if given
        else f"under {load:.4g} N assumed ({ASSUMED_LOAD:.2g} C; the interval spans "
        f"{LOAD_RANGE[0]:g}-{LOAD_RANGE[1]:g} C)"
    )
    reason = (
        f"entry and exit {spacing * 1e3:.3g} ms apart (median of {t.size} passages, 80 % "
        f"within {q_low * 1e3:.3g}-{q_high * 1e3:.3g} ms) at {v:.3g} m/s over the {race} race "
        f"({_FREQUENCY[race]} {f:.5g} Hz as measured): {v * spacing * 1e3:.3g} mm, and "
        f"{bridged * 1e3:.2g} mm the ball bridges at the edges {load_words}"
    )
    return DefectSize(
        status="sized",
        reason=reason,
        passages=int(t.size),
        width=width,
        low=min(low, width),
        high=max(high, width),
        extent=width / radius,
        spacing=spacing,
        bridged=bridged,
        lag=(window - exit_at) / fs,
        envelope=average / floor,
        waveform=waveform,
        entry_lag=(entry_at - exit_at) / fs,
        **common,
    )
