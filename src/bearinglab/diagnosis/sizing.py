"""The width of a race defect from the entry and exit events of its passages.

A rolling element that rolls over a spall long enough to drop into it makes two events per
passage: the entry, as it leaves the near edge and unloads, and the exit, as it strikes
the far edge and is loaded again; their spacing in time with the element's speed over the
race gives the defect's extent along the rolling direction (Sawalhi N., Randall R. B.,
"Vibration response of spalled rolling element bearings: observations, simulations and
signal processing techniques to track the spall size", MSSP 25 (2011) 846-870; Epps I. K.,
McCallion H., "An investigation into the characteristic vibration excited by discrete
faults in rolling element bearings", Proc. 9th Int. Congress on Condition Monitoring and
Diagnostic Engineering Management, 1994). Here:

1. **Events**: the squared envelope of the cepstrum-prewhitened record (Borghesani et al.,
   MSSP 36 (2013) 370-384; Sawalhi & Randall 2011 pre-whiten to bring the entry's step
   response and the exit's impulse response to comparable levels), in which each passage
   of the defect shows as a burst (:func:`event_envelope`).
2. **Passages**: the strongest burst of each fault period is tracked from period to
   period within +-ALIGN_TOLERANCE of the period (the fault frequency measured by the
   diagnosis, which carries the slip) (:func:`track_passages`), and the passages are
   averaged aligned on it (the event-aligned average).
3. **A separate second event**: a local maximum of the average, one to ``smax`` samples
   from the tracked burst, that is separate from it - between the two the average falls
   back to within SEPARATION of the weaker one's height above the record's floor - and
   that rises above that valley passage by passage (Wilcoxon's signed-rank test across
   passages, Bonferroni over the maxima tried) (:func:`separate_events`). The nearest such
   event pairs with the tracked one; the earlier of the two is the entry.
4. **Width**: the spacing of entry and exit in each passage (median and the central 80 %
   over passages) times the speed of the contact point over the race,
   v = 2 pi f R / Z (f the measured fault frequency, R the raceway radius, Z the balls:
   f / Z is the rate at which one ball's contact point crosses the race; no tachometer is
   needed), plus the distances the ball bridges at each edge (:func:`bridged_distance`):
   its contacts are compressed by their approach delta, so it loses contact only where
   the pit has opened that much clearance, a distance x0 past the near edge, and it is
   loaded again x1 before the far edge, where the clearance has closed to delta1, the
   approach on the load line once the other balls have taken that ball's load (the rings
   close up) (:func:`ball_approaches`). The clearance a pit opens is the circle-chord
   geometry of :func:`bearinglab.dynamics.defects.edge_drop` (seed 003's rigid model).

A defect shorter than x0 + x1 unloads the ball without letting it drop: there is one
event per passage, not two (:func:`shortest_sizable`); so does a defect whose events lie
closer than their own bursts last. Then the entry is not separate from the exit, and the
answer is "too small to size" - if the exit bursts stand clearly enough above the noise
(MEASURABLE) that a separate entry would have shown; otherwise "not sized", with the reason.

The ball's load is the radial load given, or, when none is, ASSUMED_LOAD x the bearing's
dynamic rating C (the middle, on a log scale, of the loads a ball bearing runs at: from
SKF's minimum load 0.01 C to the top of its "normal" loads 0.1 C); the interval then
spans LOAD_RANGE as well as the spread over passages.

Layer 1 (the functions, SI) and layer 3 (:func:`size_defect`, :class:`DefectSize`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError

#: The fault families whose defects are sized, and their race.
RACES = {"outer_race": "outer", "inner_race": "inner"}
#: Largest change of the fault period from one passage to the next that the tracking
#: follows (random slip: 1-2 % per period; Randall & Antoni, MSSP 25 (2011) 485-520) [-].
ALIGN_TOLERANCE = 0.03
#: Length of the moving average that smooths the envelope for reading the average's
#: maxima and each passage's events [s].
SMOOTHING = 1e-4
#: Length of the moving average over which passages are tracked: about a burst [s].
TRACK_SMOOTHING = 1e-3
#: A passage is tracked as clear when its burst, smoothed over TRACK_SMOOTHING, reaches
#: this many times the median [-].
TRACK_LEVEL = 3.0
#: Two events are separate when the averaged envelope between them falls to within this
#: fraction of the weaker one's height above the floor: the first has died out before the
#: second begins [-].
SEPARATION = 0.05
#: ... and the interval between them is quiet: over its middle half the averaged envelope's
#: median stays within this fraction of the weaker one's height above the floor (nothing
#: else happens while the ball crosses the defect) [-].
QUIET = 0.1
#: A second event counts when it reaches this fraction of the tracked burst's height above
#: the floor [-] ...
ENTRY_FRACTION = 0.05
#: ... and stands this many floors above the floor: the averaged envelope of a real record
#: wanders by about a floor between events, so only an event 1 / SEPARATION floors high can
#: show its valley within SEPARATION of its height [-].
MEASURABLE = 1.0 / SEPARATION
#: Fewest passages averaged [-].
MIN_PASSAGES = 20
#: Level of the test of a separate event (before the Bonferroni factor) [-].
EVENT_ALPHA = 0.01
#: Quantiles of the per-passage spacing that bound the interval [-].
QUANTILES = (0.1, 0.9)
#: Radial load assumed when none is given, and the range the interval then spans, as
#: fractions of the dynamic load rating C (SKF rolling bearings catalogue: minimum load
#: of a ball bearing about 0.01 C; light loads P <= 0.05 C, normal 0.05 C < P <= 0.1 C).
ASSUMED_LOAD = math.sqrt(0.01 * 0.1)
LOAD_RANGE = (0.01, 0.1)
#: Largest event spacing searched, as a fraction of the fault period (a pair further
#: apart would be nearer the next passage's event than its own) [-].
MAX_PERIOD_FRACTION = 0.45
#: Length of the linear predictor that whitens the record [s].
PREDICTOR_LENGTH = 1e-3
STATUSES = ("sized", "too small to size", "not sized")


# ----------------------------------------------------------------- physics (layer 1, SI)
def raceway_radius(bearing, race: str) -> float:
    """Radius of the ``race``'s groove bottom ("inner" or "outer"), along which the
    defect's width is measured [m] (the raceway diameters of
    :class:`~bearinglab.geometry.BallBearing`)."""
    if race == "outer":
        return 0.5 * bearing.outer_raceway_diameter
    if race == "inner":
        return 0.5 * bearing.inner_raceway_diameter
    raise InputError("race", race, "inner or outer")


def contact_speed(fault_frequency, ball_count, race_radius):
    """Speed of a ball's contact point over the defective race [m/s].

    A defect on a race is passed Z times for each revolution of the balls relative to
    that race, so f / Z is one ball's rate over it and v = 2 pi f R / Z, with the fault
    frequency f as measured (BPFO for the outer race, BPFI for the inner; slip included).

    Parameters
    ----------
    fault_frequency : float or array
        f, the fault frequency [Hz].
    ball_count : int
        Z [-].
    race_radius : float
        R, the raceway radius [m].

    >>> round(contact_speed(107.36, 9, 23.49e-3), 3)   # 6205 outer race at 1797 rpm
    1.761
    """
    return 2.0 * math.pi * np.asarray(fault_frequency, dtype=float) * race_radius / ball_count


def _drop(distance, ball_radius, race_radius, race):
    """lambda(d) of :func:`bearinglab.dynamics.defects.edge_drop` (circle-chord geometry,
    the race concave for the outer race, convex for the inner) [m]."""
    d = np.minimum(distance, ball_radius)
    ball = ball_radius - np.sqrt(ball_radius**2 - d**2)
    ring = race_radius - np.sqrt(np.maximum(race_radius**2 - d**2, 0.0))
    return ball - ring if race == "outer" else ball + ring


def bridged_distance(approach, ball_radius, race_radius, race: str):
    """Distance from a pit's edge at which a loaded ball loses (or regains) contact [m].

    A ball whose contacts are compressed by ``approach`` delta keeps its load over a pit
    until the pit has opened that much clearance under it: the distance d past the edge
    where lambda(d) = delta, lambda being the drop of the ball's centre into a pit whose
    edge is d away (:func:`bearinglab.dynamics.defects.edge_drop`, seed 003's geometry);
    about sqrt(2 delta r_e) with 1/r_e = 1/r -+ 1/R. Found by bisection (lambda rises
    monotonically with d). A ``approach`` beyond the deepest drop, at d = r, gives r.

    Parameters
    ----------
    approach : float or array
        delta, the approach of the ball's contacts [m], >= 0.
    ball_radius : float
        r [m].
    race_radius : float
        R, the raceway radius [m].
    race : {"inner", "outer"}
        The race with the pit.

    >>> round(float(bridged_distance(10e-6, 3.97e-3, 23.49e-3, "outer")) * 1e3, 3)
    0.309
    """
    delta = np.asarray(approach, dtype=float)
    lo = np.zeros_like(delta)
    hi = np.full_like(delta, ball_radius)
    for _ in range(60):  # 2^-60 of r: far below a nanometre
        mid = 0.5 * (lo + hi)
        above = _drop(mid, ball_radius, race_radius, race) >= delta
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    return (0.5 * (lo + hi))[()]


def ball_series_constant(bearing) -> float:
    """Load-deflection constant K of one ball between both races, Q = K delta^1.5
    [N/m^1.5] (Hertz, :func:`bearinglab.contact.hertz.series_constant`)."""
    from ..contact import hertz
    from ..materials import effective_modulus

    e = effective_modulus(bearing.ball_material, bearing.ring_material)
    inner = hertz.load_deflection_constant(*bearing.contact_radii("inner"), e)
    outer = hertz.load_deflection_constant(*bearing.contact_radii("outer"), e)
    return float(hertz.series_constant(inner, outer))


def _ring_approach(k: float, cosines: np.ndarray, load: float, half_clearance: float) -> float:
    """u with load = sum K [u cos(psi) - P_d/2]_+^1.5 cos(psi), by bisection [m]."""

    def force(u):
        return k * float(np.sum(np.clip(u * cosines - half_clearance, 0.0, None) ** 1.5 * cosines))

    lo = min(half_clearance, 0.0)
    while force(lo) > load:  # a preload: the rings are pressed together at u = 0
        lo -= 1e-6
    hi = max(half_clearance, 0.0) + 1e-6
    while force(hi) < load:
        hi *= 2.0
    while hi - lo > 1e-13:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if force(mid) < load else (lo, mid)
    return 0.5 * (lo + hi)


def ball_approaches(bearing, radial_load: float) -> tuple[float, float]:
    """Approaches (delta0, delta1) of the ball on the load line [m]: carrying its load with
    every ball in place, and once it has lost contact over a defect and the others carry
    the whole load (the rings close up by delta1 - delta0).

    Rigid rings, balls equally spaced with one on the load line, Hertz contacts in series
    Q = K delta^1.5 (:func:`ball_series_constant`), the clearance P_d / 2:
    F_r = sum_j K [u cos(psi_j) - P_d/2]_+^1.5 cos(psi_j) (Stribeck's equilibrium, Harris &
    Kotzalas, *Essential Concepts of Bearing Technology*, 2007, ch. 7; the static state
    of seed 003's rigid model, :func:`bearinglab.dynamics.rigid.static_offset`).

    Parameters
    ----------
    bearing : BallBearing
        The bearing.
    radial_load : float
        F_r [N], > 0.

    >>> from bearinglab.catalog import bearing_from_designation
    >>> b, _ = bearing_from_designation("6205")
    >>> [round(d * 1e6, 1) for d in ball_approaches(b, 500.0)]
    [9.8, 15.8]
    """
    k = ball_series_constant(bearing)
    z = bearing.ball_count
    cosines = np.cos(2.0 * np.pi * np.arange(z) / z)
    half = 0.5 * bearing.diametral_clearance
    u0 = _ring_approach(k, cosines, radial_load, half)
    u1 = _ring_approach(k, cosines[1:], radial_load, half)
    return u0 - half, u1 - half


def bridged_width(bearing, race: str, radial_load: float) -> float:
    """x0 + x1: what the ball bridges at both edges of a pit on ``race`` under
    ``radial_load`` [N] - the event spacing times the contact speed falls short of the
    defect's width by this much, and a defect shorter than it never lets the ball drop
    (:func:`bridged_distance` of :func:`ball_approaches`) [m]."""
    r = 0.5 * bearing.ball_diameter
    radius = raceway_radius(bearing, race)
    d0, d1 = ball_approaches(bearing, radial_load)
    return float(np.sum(bridged_distance(np.array([d0, d1]), r, radius, race)))


def assumed_loads(bearing) -> tuple[float, float, float]:
    """(assumed, lowest, highest) radial load [N] when none is given: ASSUMED_LOAD and
    LOAD_RANGE times the dynamic load rating C (ISO 281 from the internal geometry,
    :func:`bearinglab.ratings.load_ratings`)."""
    from ..ratings import load_ratings

    c = load_ratings(bearing).dynamic
    return ASSUMED_LOAD * c, LOAD_RANGE[0] * c, LOAD_RANGE[1] * c


# ----------------------------------------------------------- signal processing (layer 1)
def levinson(autocorrelation, order: int) -> np.ndarray:
    """Coefficients [1, a_1 .. a_p] of the order-p linear predictor of a stationary series
    with the given autocorrelation r_0 .. r_p, by the Levinson-Durbin recursion (the
    Yule-Walker equations; Makhoul J., "Linear prediction: a tutorial review", Proc. IEEE
    63 (1975) 561-580, eqs. 38a-e).

    Parameters
    ----------
    autocorrelation : array_like
        r_0 .. r_p (at least ``order`` + 1 values), r_0 > 0.
    order : int
        p, >= 1.

    >>> np.round(levinson([1.0, 0.5, 0.25], 2), 6)   # AR(1) with coefficient 0.5
    array([ 1. , -0.5,  0. ])
    """
    r = np.asarray(autocorrelation, dtype=float)
    a = np.zeros(order + 1)
    a[0] = 1.0
    error = r[0]
    for k in range(1, order + 1):
        reflection = -(r[k] + np.dot(a[1:k], r[k - 1 : 0 : -1])) / error
        a[1:k] = a[1:k] + reflection * a[k - 1 : 0 : -1]
        a[k] = reflection
        error *= 1.0 - reflection * reflection
        if error <= 0.0:  # a perfectly predictable series: keep the predictor found
            break
    return a


def event_envelope(x, order: int) -> np.ndarray:
    """Squared envelope of the record whitened by its linear prediction error: each passage
    of a defect is a burst in it [unit-free].

    The order-p linear predictor (:func:`levinson`) models what is predictable from the
    last p samples - the structure's resonances, its echoes, the machine's tones; its
    error is what is new at each instant, the impacts and unloadings, each at the time it
    happens (the prediction error filter is causal and minimum-phase, so no burst is
    smeared before its start, as a zero-phase whitening such as cepstral pre-whitening
    does). Sawalhi & Randall (2011) whiten so for the same purpose: the entry's step
    response and the exit's impulse response then stand out alike. A periodic train of
    bursts is not predicted from the last p samples when p is shorter than its period.

    Parameters
    ----------
    x : array_like
        The record's samples (1-D), any unit.
    order : int
        p, the predictor's length [samples].
    """
    from ..signal.spectra import analytic, fast_length

    x = np.asarray(x, dtype=float)
    x = x - x.mean()
    m = fast_length(2 * x.size)
    spectrum = np.fft.rfft(x, m)
    r = np.fft.irfft(np.abs(spectrum) ** 2, m)[: order + 1] / x.size
    if not r[0] > 0.0:
        return np.zeros(x.size)
    a = levinson(r, order)
    error = np.fft.irfft(spectrum * np.fft.rfft(a, m), m)[: x.size]
    return np.abs(analytic(error)) ** 2


def moving_average(x, length: int) -> np.ndarray:
    """Centred moving average of ``x`` over ``length`` samples (the ends averaged over what
    there is).

    Parameters
    ----------
    x : array_like
        Samples (1-D).
    length : int
        Samples averaged, >= 1.
    """
    x = np.asarray(x, dtype=float)
    if length <= 1:
        return x.copy()
    c = np.concatenate(([0.0], np.cumsum(x)))
    i = np.arange(x.size)
    lo = np.clip(i - length // 2, 0, x.size)
    hi = np.clip(i - length // 2 + length, 0, x.size)
    return (c[hi] - c[lo]) / (hi - lo)


def track_passages(envelope, period: float, tolerance: float = ALIGN_TOLERANCE):
    """(sample of the largest value of ``envelope`` in each fault period, whether it is
    clear) [-].

    The first passage is at the phase where ``envelope`` folded at ``period`` is largest;
    each next one is its largest sample within +-``tolerance`` x ``period`` of one period
    after the last clear one (a weak passage - the defect out of the load zone - does not
    move the tracking). A passage is clear when that sample reaches TRACK_LEVEL times the
    envelope's median.

    Parameters
    ----------
    envelope : array_like
        The event envelope, smoothed over about a burst.
    period : float
        The fault period [samples], > 2.
    tolerance : float
        Largest change of the period followed from one passage to the next [-].
    """
    e = np.asarray(envelope, dtype=float)
    n = e.size
    cycles = int(n // period)
    if cycles < 1:
        return np.zeros(0, dtype=int), np.zeros(0, dtype=bool)
    level = TRACK_LEVEL * float(np.median(e))
    bins = max(int(period), 1)
    phase = ((np.arange(int(cycles * period)) % period) / period * bins).astype(int)
    folded = np.bincount(phase, weights=e[: phase.size], minlength=bins)
    start = float(np.argmax(folded)) * period / bins
    half = max(tolerance * period, 1.0)
    times, clear = [], []
    last, gap = start, 0
    while True:
        centre = last + (gap + (1 if times else 0)) * period
        lo, hi = int(round(centre - half)), int(round(centre + half)) + 1
        if hi > n:
            break
        lo = max(lo, 0)
        i = lo + int(np.argmax(e[lo:hi]))
        good = bool(e[i] >= level)
        times.append(i)
        clear.append(good)
        if good:
            last, gap = float(i), 0
        else:
            gap += 1
    return np.array(times, dtype=int), np.array(clear, dtype=bool)


def align_passages(envelope, times, margin: int, reach: int, iterations: int = 2):
    """The passages' samples realigned on their average (Woody's adaptive alignment:
    each passage shifted by up to +-``reach`` samples to the best cross-correlation with
    the average of all, twice; Woody C. D., "Characterization of an adaptive filter for
    the analysis of variable latency neuroelectric signals", Med. Biol. Eng. 5 (1967)
    539-554): both events of a pair keep their places in every passage whichever of the
    two is the larger in it [samples].

    Parameters
    ----------
    envelope : array_like
        The event envelope.
    times : array_like
        A sample of each passage (its largest burst), ``margin`` + ``reach`` from the ends.
    margin : int
        Samples compared either side of the passage's sample.
    reach : int
        Largest shift [samples].
    iterations : int
        Rounds of alignment.
    """
    e = np.asarray(envelope, dtype=float)
    t = np.asarray(times, dtype=int).copy()
    span = np.arange(-margin - reach, margin + reach + 1)
    length = 2 * margin + 1
    m = 1
    while m < span.size + length:
        m *= 2
    for _ in range(iterations):
        rows = e[t[:, None] + span]
        template = rows[:, reach : reach + length].mean(axis=0)
        template = template - template.mean()
        # correlation of each row with the template at shifts -reach .. +reach
        c = np.fft.irfft(np.fft.rfft(rows, m) * np.conj(np.fft.rfft(template, m)), m)
        shifts = np.argmax(c[:, : 2 * reach + 1], axis=1) - reach
        if not np.any(shifts):
            break
        t = t + shifts
    return t


def signed_rank_p(differences) -> float:
    """One-sided p-value of Wilcoxon's signed-rank test that ``differences`` are centred
    above zero (normal approximation, ties given their mean rank, zeros dropped; Wilcoxon,
    Biometrics Bull. 1 (1945) 80-83) [-].

    Parameters
    ----------
    differences : array_like
        Paired differences, one per passage.

    >>> signed_rank_p([1.0] * 30) < 1e-5, signed_rank_p([-1.0] * 30) > 0.99
    (True, True)
    """
    d = np.asarray(differences, dtype=float)
    d = d[d != 0.0]
    n = d.size
    if n == 0:
        return 1.0
    order = np.argsort(np.abs(d), kind="stable")
    ranks = np.empty(n)
    ranks[order] = np.arange(1, n + 1)
    magnitudes = np.abs(d)[order]
    start = 0
    for i in range(1, n + 1):  # mean ranks of ties
        if i == n or magnitudes[i] != magnitudes[start]:
            if i - start > 1:
                ranks[order[start:i]] = 0.5 * (start + 1 + i)
            start = i
    w = float(np.sum(ranks[d > 0]))
    mean = n * (n + 1) / 4.0
    sd = math.sqrt(n * (n + 1) * (2 * n + 1) / 24.0)
    return 0.5 * math.erfc((w - mean) / sd / math.sqrt(2.0))


def separate_events(average, passages, floor: float, shortest: int, longest: int, width: int):
    """The events of the aligned average that are separate from the burst at its centre.

    Parameters
    ----------
    average : array_like
        The smoothed aligned average, 2 ``longest`` + 1 samples or more, centred on the
        burst.
    passages : array_like
        The smoothed envelope of each passage (rows), aligned as ``average``.
    floor : float
        The envelope's floor.
    shortest, longest : int
        Nearest and farthest lag searched [samples].
    width : int
        Half-width of the windows compared passage by passage [samples].

    Returns
    -------
    list of (lag [samples], p-value with the Bonferroni factor, valley lag [samples])
        Every local maximum between ``shortest`` and ``longest`` from the centre that is an
        event of its own - at least ENTRY_FRACTION of the centre's height above ``floor``,
        and separate from it: the average falls between them to within SEPARATION of the
        weaker one's height above ``floor`` - with the p-value of its rise above that
        valley across passages (:func:`signed_rank_p`), the largest first.
    """
    a = np.asarray(average, dtype=float)
    rows = np.asarray(passages, dtype=float)
    centre = (a.size - 1) // 2
    top = a[centre] - floor
    found = []
    for lag in range(-longest, longest + 1):
        i = centre + lag
        if abs(lag) < shortest or i <= width or i >= a.size - 1 - width:
            continue
        if not (a[i] > a[i - 1] and a[i] >= a[i + 1]):
            continue
        if a[i] - floor < max(ENTRY_FRACTION * top, MEASURABLE * floor):
            continue
        lo, hi = sorted((centre, i))
        v = lo + int(np.argmin(a[lo : hi + 1]))
        weaker = min(a[i], a[centre]) - floor
        if a[v] - floor > SEPARATION * weaker:
            continue
        quarter = (hi - lo) // 4
        if np.median(a[lo + quarter : hi - quarter + 1]) - floor > QUIET * weaker:
            continue  # something else happens between them
        if abs(v - i) <= width or abs(v - centre) <= width:
            continue
        peak = rows[:, i - width : i + width + 1].mean(axis=1)
        valley = rows[:, v - width : v + width + 1].mean(axis=1)
        found.append([lag, signed_rank_p(peak - valley), v - centre])
    for item in found:
        item[1] = min(1.0, item[1] * len(found))
    return sorted((tuple(f) for f in found), key=lambda f: -a[centre + f[0]])


def _refine(row, i: int) -> float:
    """Position of the maximum near sample ``i`` of ``row``, by a parabola through it and
    its neighbours [samples]."""
    if 0 < i < row.size - 1:
        a, b, c = row[i - 1], row[i], row[i + 1]
        denominator = a - 2.0 * b + c
        if denominator < 0.0:
            return i + 0.5 * (a - c) / denominator
    return float(i)


# ------------------------------------------------------------------------ the result
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


# ------------------------------------------------------------------- the analysis (3)
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
    >>> x = 0.05 * rng.standard_normal(int(2 * fs))
    >>> for t0 in np.arange(0.004, 1.99, 1 / f):
    ...     for t1, a in ((t0, 0.5), (t0 + 1e-3, 1.0)):
    ...         i = int(t1 * fs)
    ...         x[i:i + 40] += a * np.exp(-np.arange(40) / 8) * np.sin(np.arange(40) * 2)
    >>> s = size_defect(x, fs, b, "outer_race", f, radial_load=500.0)
    >>> s.status, round(s.spacing * 1e3, 2), round(s.width * 1e3, 2)
    ('sized', 1.0, 2.46)
    """
    if fault not in RACES:
        raise InputError("fault", fault, f"one of {sorted(RACES)}")
    race = RACES[fault]
    fs = _number("sample_rate", sample_rate, "a sample rate > 0 Hz")
    f = _number("fault_frequency", fault_frequency, "a frequency > 0 Hz")
    x = np.asarray(x, dtype=float)
    radius = raceway_radius(bearing, race)
    v = float(contact_speed(f, bearing.ball_count, radius))
    if radial_load is None:
        load, light, heavy = assumed_loads(bearing)
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
    floor = float(np.median(es))
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
    spacings = []
    for row in rows:
        positions = []
        for at in (entry_at, exit_at):
            lo = max(centre + at - reach, 0)
            i = lo + int(np.argmax(row[lo : centre + at + reach + 1]))
            positions.append(_refine(row, i))
        spacings.append((positions[1] - positions[0]) / fs)
    spacings = np.array(spacings)
    spacing = float(np.median(spacings))
    q_low, q_high = (float(q) for q in np.quantile(spacings, QUANTILES))
    bridged = bridged_width(bearing, race, load)
    low = v * max(q_low, 0.0) + bridged_width(bearing, race, light)
    high = v * q_high + bridged_width(bearing, race, heavy)
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


def ring_down(average, floor: float, at: int, fraction: float, horizon: int) -> int:
    """How long the burst at sample ``at`` of ``average`` rings: the last sample within
    ``horizon`` after it still above ``floor`` + ``fraction`` of its height above
    ``floor`` [samples from ``at``].

    Parameters
    ----------
    average : array_like
        The aligned average.
    floor : float
        Its floor.
    at : int
        The burst's sample.
    fraction : float
        Of the burst's height above the floor [-].
    horizon : int
        Samples after ``at`` looked at.
    """
    a = np.asarray(average, dtype=float)
    level = floor + fraction * (a[at] - floor)
    above = np.nonzero(a[at : at + horizon + 1] > level)[0]
    return int(above[-1]) if above.size else 0


def find_pair(envelope, times, window, floor: float, shortest: int, longest: int, width: int):
    """The entry and exit of each passage: (lag of the partner from the tracked burst
    [samples], the passages' samples with each pair oriented alike), or None.

    The candidates are :func:`separate_events` of the passages' average that rise above
    their valleys passage by passage (level EVENT_ALPHA), the largest first. Each passage
    is tracked at its larger burst, which may be the entry in some and the exit in others:
    a passage whose partner stands at -lag rather than +lag is moved by lag, so that
    every passage has its earlier event at the same sample. A candidate is kept when the
    oriented average then shows it as a pair - no event as large at the mirrored lag (a
    burst with events at both sides is one burst's modulation, the beating of two modes,
    not an entry and an exit) - and resolved: the later burst rings down (below
    ENTRY_FRACTION of its height, :func:`ring_down`) in less than the spacing, so the
    earlier one has died out before the later one begins.

    Parameters
    ----------
    envelope : array_like
        The smoothed event envelope.
    times : array_like
        Each passage's sample, aligned (:func:`align_passages`).
    window : array_like
        The samples of a passage around its sample, symmetric, at least 2 ``longest``
        either side.
    floor : float
        The envelope's floor.
    shortest, longest : int
        Nearest and farthest lag searched [samples].
    width : int
        Half-width of the windows compared passage by passage [samples].
    """
    e = np.asarray(envelope, dtype=float)
    t = np.asarray(times, dtype=int)
    centre = (len(window) - 1) // 2
    rows = e[t[:, None] + window]
    average = rows.mean(axis=0)
    for lag, p, _ in separate_events(average, rows, floor, shortest, longest, width):
        if p >= EVENT_ALPHA:
            continue
        side = rows[:, centre + lag - width : centre + lag + width + 1].max(axis=1)
        other = rows[:, centre - lag - width : centre - lag + width + 1].max(axis=1)
        oriented = t - lag * (other > side)
        a = e[oriented[:, None] + window].mean(axis=0)
        top = max(a[centre], a[centre + lag]) - floor
        mirror = a[centre - lag - width : centre - lag + width + 1].max() - floor
        if mirror >= ENTRY_FRACTION * top:
            continue
        return int(lag), oriented
    return None
