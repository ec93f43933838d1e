"""The entry and exit events of a defect's passages in a record: whitening, the passages
tracked and aligned, and the test of a second event separate from the first.

Layer 1 (samples in, samples and numbers out). :func:`event_envelope` whitens the record
by its linear prediction error (an autoregressive model fitted by the Levinson-Durbin
recursion, :func:`levinson`: Makhoul J., "Linear prediction: a tutorial review", Proc.
IEEE 63 (1975) 561-580; the pre-whitening Sawalhi & Randall, MSSP 25 (2011) 846-870, use to
see the entry beside the exit); :func:`track_passages` follows the fault's bursts from
period to period; :func:`align_passages` aligns them on their average (Woody 1967);
:func:`separate_events` and :func:`find_pair` find the partner of the tracked burst, tested
across passages by Wilcoxon's signed-rank test (:func:`signed_rank_p`).
"""

from __future__ import annotations

import math

import numpy as np

#: Largest change of the fault period from one passage to the next that the tracking
#: follows (random slip: 1-2 % per period; Randall & Antoni, MSSP 25 (2011) 485-520) [-].
ALIGN_TOLERANCE = 0.03
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
#: Level of the test of a separate event (before the Bonferroni factor) [-].
EVENT_ALPHA = 0.01


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

    Examples
    --------
    >>> [abs(round(float(c), 6)) for c in levinson([1.0, 0.5, 0.25], 2)]   # AR(1), 0.5
    [1.0, 0.5, 0.0]
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
    from ..signal.spectra import analytic_power

    x = np.asarray(x, dtype=float)
    x = x - x.mean()
    n = x.size
    order = min(int(order), n - 1)
    # the biased autocorrelation r_0 .. r_p (positive definite), and the prediction error
    # e[i] = sum_k a_k x[i - k], causal: direct sums, p being short (einsum, not BLAS's
    # dot, whose threads wake slowly on a busy machine: 20 ms a lag measured)
    r = np.array([np.einsum("i,i->", x[: n - k], x[k:]) for k in range(order + 1)]) / n
    if not r[0] > 0.0:
        return np.zeros(n)
    error = np.convolve(x, levinson(r, order))[:n]
    error[:order] = 0.0  # the filter's start, predicted from samples before the record
    return analytic_power(error)


def median(x) -> float:
    """``numpy.median`` of a 1-D array, by one partition: numpy partitions an even-length
    array at both middle positions at once, which costs eight times one (1.1 against
    0.14 ms for 120 000 samples); the lower middle value is the largest below the upper.

    Parameters
    ----------
    x : array_like
        Values (1-D, at least one, no NaN).

    >>> median([3.0, 1.0, 2.0]), median([4.0, 1.0, 3.0, 2.0])
    (2.0, 2.5)
    """
    v = np.asarray(x, dtype=float)
    k = v.size // 2
    part = np.partition(v, k)
    if v.size % 2:
        return float(part[k])
    return float(np.mean(np.array([part[:k].max(), part[k]])))


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
    n, half = x.size, length // 2
    c = np.concatenate(([0.0], np.cumsum(x)))
    out = np.empty(n)
    # the full windows by slices, the ends (windows cut by the record) by index
    first, last = half, n - length + half  # i with 0 <= i - half and i - half + length <= n
    if first <= last:
        out[first : last + 1] = (c[length:] - c[: n - length + 1]) / length
    ends = np.r_[0 : min(first, n), max(last + 1, first) : n]
    lo = np.clip(ends - half, 0, n)
    hi = np.clip(ends - half + length, 0, n)
    out[ends] = (c[hi] - c[lo]) / (hi - lo)
    return out


def track_passages(envelope, period: float, tolerance: float = ALIGN_TOLERANCE):
    """(sample of the largest value of ``envelope`` in each fault period, whether it is
    clear) [-].

    The passages are followed from the largest value of the first three periods, forwards
    and backwards: each next one is the largest sample within +-``tolerance`` x ``period``
    of one period from the last clear one (a weak passage - the defect out of the load
    zone - does not move the tracking). A passage is clear when that sample reaches
    TRACK_LEVEL times the envelope's median.

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
    if e.size < period:
        return np.zeros(0, dtype=int), np.zeros(0, dtype=bool)
    level = TRACK_LEVEL * median(e)
    anchor = int(np.argmax(e[: int(min(3 * period, e.size))]))
    half = max(tolerance * period, 1.0)
    clear = e >= level
    found = {anchor: bool(clear[anchor])}
    size = e.size
    for step in (period, -period):
        last, gap = float(anchor), 0
        while True:  # a loop of a thousand steps: each as few NumPy calls as it can be
            centre = last + (gap + 1) * step
            lo, hi = int(round(centre - half)), int(round(centre + half)) + 1
            if hi > size or lo < 0:
                break
            i = lo + int(e[lo:hi].argmax())
            found[i] = is_clear = bool(clear[i])
            if is_clear:
                last, gap = float(i), 0
            else:
                gap += 1
    times = np.array(sorted(found), dtype=int)
    return times, np.array([found[i] for i in times], dtype=bool)


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
    length = 2 * margin + 1
    # the correlation of each passage with the template at shifts -reach .. +reach is
    # the whole envelope's correlation with the template, read at each passage; it is
    # computed by overlap-save (blocks of `block` samples, `hop` outputs each, no wrap),
    # the blocks transformed once for every round and the template at the blocks' length
    block = 1024
    while block < 4 * length:
        block *= 2
    hop = block - length + 1
    count = max(-(-(e.size - length + 1) // hop), 1)
    padded = np.zeros((count - 1) * hop + block)
    padded[: e.size] = e
    blocks = np.fft.rfft(
        np.lib.stride_tricks.sliding_window_view(padded, block)[::hop][:count], axis=1
    )
    shifts_read = np.arange(2 * reach + 1)
    for _ in range(iterations):
        template = e[t[:, None] + np.arange(-margin, margin + 1)].mean(axis=0)
        template = template - template.mean()
        c = np.fft.irfft(blocks * np.conj(np.fft.rfft(template, block)), block, axis=1)
        c = c[:, :hop].ravel()  # c[p] = sum_j e[p + j] template[j]
        shifts = np.argmax(c[(t - margin - reach)[:, None] + shifts_read], axis=1) - reach
        if not np.any(shifts):
            break
        t = t + shifts
    return t


def align_passages_rows(envelope, times, margin: int, reach: int, iterations: int = 2):
    """:func:`align_passages` passage by passage (each row of samples transformed on its
    own): the plain form a test checks the whole-record correlation against.

    Parameters
    ----------
    envelope, times, margin, reach, iterations :
        As for :func:`align_passages`.
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

    Examples
    --------
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


def refine_peak(row, i: int) -> float:
    """Position of the maximum near sample ``i`` of ``row``, by a parabola through it and
    its neighbours [samples].

    Parameters
    ----------
    row : array_like
        Samples.
    i : int
        The largest sample near the maximum.
    """
    if 0 < i < row.size - 1:
        a, b, c = row[i - 1], row[i], row[i + 1]
        denominator = a - 2.0 * b + c
        if denominator < 0.0:
            return i + 0.5 * (a - c) / denominator
    return float(i)


def refine_peaks(rows, i) -> np.ndarray:
    """:func:`refine_peak` of each row of ``rows`` at its sample ``i`` (one per row), all
    rows at once (the same arithmetic) [samples].

    Parameters
    ----------
    rows : numpy.ndarray
        Samples (rows x samples).
    i : numpy.ndarray of int
        The largest sample near each row's maximum.
    """
    rows = np.asarray(rows, dtype=float)
    i = np.asarray(i, dtype=int)
    out = i.astype(float)
    inner = (i > 0) & (i < rows.shape[1] - 1)
    r = np.flatnonzero(inner)
    a, b, c = rows[r, i[r] - 1], rows[r, i[r]], rows[r, i[r] + 1]
    denominator = a - 2.0 * b + c
    bent = denominator < 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        shift = 0.5 * (a - c) / denominator
    out[r[bent]] = i[r[bent]] + shift[bent]
    return out


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
