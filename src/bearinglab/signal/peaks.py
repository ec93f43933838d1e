"""Spectral peaks and their match to bearing defect frequencies.

Layer 3 (see docs/architecture.md): :func:`find_peaks` picks the lines of a spectrum
(``scipy.signal.find_peaks`` with a prominence relative to the median level, a robust
estimate of the noise floor); :func:`match_peaks` labels each line as a harmonic n f of
a shaft or defect frequency (names as in :data:`bearinglab.kinematics.FREQUENCY_NAMES`,
values in Hz from :func:`bearinglab.kinematics.defect_frequencies`) or as a modulation
sideband n f_d +- k f_m. The rules are in those functions' docstrings and in
docs/capabilities/signal.md; the diagnosis itself (a statistical test of each fault family
against the noise floor) is :mod:`bearinglab.diagnosis`.

Sources: the fault signatures (outer race: harmonics of BPFO; inner race: harmonics of
BPFI with shaft-rate sidebands; ball: harmonics of the ball defect rate 2 BSF with cage-
rate sidebands; cage: FTF) are those of Randall R. B., Antoni J., "Rolling element
bearing diagnostics - A tutorial", MSSP 25(2) (2011) 485-520, sec. 2. Rolling elements
slip, so the measured lines of the cage and of everything carried by it sit up to a few
per cent below the kinematic value (Randall & Antoni, sec. 2.1: 1-2 %); seed 004 (Hou X.
et al., J. Mech. & Electr. Eng. 2024 no. 2) measures a ball-defect line at 93.6 % of the
kinematic value, hence the one-sided ``slip_tolerance`` window (8 % by default).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

#: Frequency names ``match_peaks`` understands (kinematics' names plus the shaft).
NAMES = ("shaft", "ftf", "bpfo", "bpfi", "bsf", "ball_defect")
#: Frequencies carried by the cage, which slips: their lines run slow.
SLIP_AFFECTED = ("ftf", "bpfo", "bpfi", "bsf", "ball_defect")
#: Defect -> the frequency that modulates it (the load zone seen by the defect turns
#: with the shaft for an inner-race defect, with the cage for a ball defect).
MODULATION = {"bpfi": "shaft", "ball_defect": "ftf", "bsf": "ftf"}
#: Frequencies that are harmonics of another (name -> (family, multiple)): the
#: ball-defect rate is 2 BSF, so both are one family with one slip.
FAMILIES = {"ball_defect": ("bsf", 2)}
#: Sideband orders k looked for in n f_d +- k f_m.
SIDEBAND_ORDERS = 2
#: Least match window, in bins of the spectrum: the bin holding a line is within half a
#: bin of it, and noise can tip the maximum into the next bin.
RESOLUTION_BINS = 1.0


def _positive_int(name: str, value, minimum: int = 1) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise InputError(name, value, f"an integer >= {minimum}")
    return int(value)


def _fraction(name: str, value, low: float, high: float, closed_low: bool) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = math.nan
    if not (low <= v < high if closed_low else low < v < high):
        raise InputError(name, value, f"a number in {'[' if closed_low else '('}{low}, {high})")
    return v


def find_peaks(
    spectrum,
    count: int = 10,
    min_frequency: float = 0.0,
    max_frequency: float | None = None,
    prominence: float = 4.0,
) -> list[dict]:
    """The ``count`` largest lines of a spectrum that stand out of its noise floor.

    A line is a local maximum (:func:`local_maxima`) whose prominence
    (:func:`peak_prominences`) is at least
    ``prominence`` times the median amplitude in [min_frequency, max_frequency]; the
    median is a noise floor that the lines themselves barely move.

    Parameters
    ----------
    spectrum : Spectrum or EnvelopeSpectrum or (frequency, amplitude)
        Frequencies [Hz] and amplitudes.
    count : int
        Most lines returned.
    min_frequency, max_frequency : float
        Search range [Hz]; default 0 to the last frequency.
    prominence : float
        Least prominence, in multiples of the median amplitude [-].

    Returns
    -------
    list of dict
        ``{"frequency_hz", "amplitude", "prominence"}`` per line, largest amplitude first.

    Examples
    --------
    >>> f = np.arange(0.0, 100.0)
    >>> a = np.ones(100); a[30] = 10.0; a[70] = 5.0
    >>> [p["frequency_hz"] for p in find_peaks((f, a))]
    [30.0, 70.0]
    """
    try:
        frequency = np.asarray(spectrum[0], dtype=float)
        amplitude = np.asarray(spectrum[1], dtype=float)
    except (TypeError, ValueError, IndexError, KeyError):
        raise InputError(
            "spectrum", type(spectrum).__name__, "a Spectrum or (frequency, amplitude) arrays"
        ) from None
    if (
        frequency.ndim != 1
        or frequency.shape != amplitude.shape
        or frequency.size < 3
        or not np.all(np.isfinite(amplitude))
    ):
        raise InputError(
            "spectrum",
            f"arrays of shapes {frequency.shape}, {amplitude.shape}",
            "equal-length 1-D frequency and finite amplitude arrays (>= 3)",
        )
    count = _positive_int("count", count)
    prominence = _fraction("prominence", prominence, 0.0, math.inf, closed_low=False)
    high = frequency[-1] if max_frequency is None else max_frequency
    try:
        low, high = float(min_frequency), float(high)
    except (TypeError, ValueError):
        low = high = math.nan
    if not low < high:
        raise InputError(
            "max_frequency",
            max_frequency,
            f"a frequency above min_frequency = {min_frequency!r} Hz",
        )
    inside = np.flatnonzero((frequency >= low) & (frequency <= high))
    if inside.size < 3:
        return []
    a = amplitude[inside]
    # the 1e-9 x max floor keeps the rounding noise of noiseless synthetic spectra out
    floor = max(float(np.median(a)), 1e-9 * float(np.max(np.abs(a))))
    index = local_maxima(a)
    prominences = peak_prominences(a, index)
    keep = prominences >= prominence * floor
    index, prominences = index[keep], prominences[keep]
    top = index[np.argsort(a[index], kind="stable")[::-1][:count]]
    prom = dict(zip(index.tolist(), prominences.tolist(), strict=True))
    return [
        {
            "frequency_hz": float(frequency[inside[i]]),
            "amplitude": float(a[i]),
            "prominence": prom[int(i)],
        }
        for i in top
    ]


def local_maxima(x) -> np.ndarray:
    """Indices of the local maxima of ``x``: samples higher than both neighbours, a flat
    top counted once at its middle; the ends are not maxima. What
    ``scipy.signal.find_peaks(x)`` returns with no conditions (scipy.signal is not imported
    here: it costs ~0.5 s at start-up); a test checks the two agree.

    >>> local_maxima([0, 2, 1, 3, 3, 3, 0, 5]).tolist()
    [1, 4]
    """
    x = np.asarray(x, dtype=float)
    if x.size < 3:
        return np.zeros(0, dtype=int)
    change = np.flatnonzero(np.diff(x))  # x[i] != x[i + 1]
    starts = np.concatenate(([0], change + 1))  # runs of equal values
    ends = np.concatenate((change, [x.size - 1]))
    v = x[starts]
    peak = np.zeros(v.size, dtype=bool)
    peak[1:-1] = (v[1:-1] > v[:-2]) & (v[1:-1] > v[2:])
    return (starts[peak] + ends[peak]) // 2


def _base_minima(x: np.ndarray) -> np.ndarray:
    """For every sample j, the least value over (L, j], where L is the nearest sample to
    the left higher than x[j] (or the start): one pass with a stack of (value, least value
    since the entry below it)."""
    out = np.empty(x.size)
    stack: list[tuple[float, float]] = []
    for j, value in enumerate(x.tolist()):
        least = value
        while stack and stack[-1][0] <= value:
            least = min(least, stack.pop()[1])
        out[j] = least
        stack.append((value, least))
    return out


def peak_prominences(x, peaks) -> np.ndarray:
    """Prominence of each peak: its height over the higher of the lowest points between it
    and the nearest higher sample on either side (or the end). What
    ``scipy.signal.peak_prominences(x, peaks)`` returns (a test checks the two agree),
    computed in one pass each way.

    >>> peak_prominences([0, 3, 1, 2, 0], [1, 3]).tolist()
    [3.0, 1.0]
    """
    x = np.asarray(x, dtype=float)
    peaks = np.asarray(peaks, dtype=int)
    if peaks.size == 0:
        return np.zeros(0)
    left = _base_minima(x)
    right = _base_minima(x[::-1])[::-1]
    return x[peaks] - np.maximum(left[peaks], right[peaks])


def _peak(p) -> dict:
    if isinstance(p, dict):
        out = dict(p)
    else:
        try:
            f, a = p
        except (TypeError, ValueError):
            raise InputError(
                "peaks", p, "dicts with frequency_hz and amplitude, or (frequency, amplitude) pairs"
            ) from None
        out = {"frequency_hz": f, "amplitude": a}
    try:
        out["frequency_hz"], out["amplitude"] = float(out["frequency_hz"]), float(out["amplitude"])
    except (KeyError, TypeError, ValueError):
        raise InputError("peaks", p, "dicts with numeric frequency_hz and amplitude") from None
    if not (math.isfinite(out["frequency_hz"]) and out["frequency_hz"] > 0):
        raise InputError("peaks", p, "frequencies > 0 Hz")
    return out


def match_peaks(
    peaks,
    frequencies: dict[str, float],
    harmonics: int = 5,
    tolerance: float = 0.02,
    slip_tolerance: float = 0.08,
    sidebands: bool = True,
    resolution: float = 0.0,
) -> list[dict]:
    """Label each peak as a harmonic n f of a shaft or defect frequency, or a sideband.

    Window: a peak at f_p is a candidate for n f (n = 1 .. ``harmonics``) when
    -below <= f_p - n f <= above, with above = max(``tolerance`` n f, RESOLUTION_BINS x
    ``resolution``) and below the same, but with ``slip_tolerance`` instead of
    ``tolerance`` (if larger) for the frequencies the slip of the rolling elements
    lowers (ftf, bpfo, bpfi, bsf, ball_defect). The resolution term keeps low lines (the
    cage's) matchable on coarse spectra, where the bin holding a line can be a bin off.

    Harmonics (pass 1), strongest peak first:

    1. one slip per family: once a family (a frequency; bsf and ball_defect = 2 bsf are
       one) labels a line, a weaker candidate must imply the same fundamental, f_p / n
       within max(``tolerance`` f, one bin) of the strongest line's;
    2. a candidate whose family already labels a stronger line, or with n = 1, beats an
       unsupported higher harmonic (so 6 x BPFO in a BPFO series is not a lone 4 x BPFI);
    3. then the smallest n |deviation| = |f_p - n f| / f, the distance in units of the
       fundamental: it favours low orders, whose windows are narrower and catch
       unrelated lines less often;
    4. then the lowest n (so 2 bsf is labelled ``ball_defect`` 1x).

    Sidebands (pass 2, with ``sidebands``), strongest peak first: a peak becomes a
    sideband n f_d +- k f_m (k = 1, 2) of an inner-race line (f_m = shaft) or a ball
    line (f_m = ftf) when

    - the carrier is a peak labelled n f_d (its measured frequency is used, so the slip
      is accounted for), and stronger than the peak if the peak matches a harmonic well
      (within max(``tolerance`` n f, one bin), without the slip allowance): a weak line
      never claims a well-matched stronger one; a carrier keeps its label;
    - the peak lies within max(min(``tolerance`` x target, f_m/4), one bin) of the
      target n f_d +- k f_m, relatively nearer than to its own harmonic, if any.

    Parameters
    ----------
    peaks : list of dict or (frequency, amplitude) pairs
        E.g. from :func:`find_peaks`; frequencies [Hz].
    frequencies : dict
        Some of ``shaft, ftf, bpfo, bpfi, bsf, ball_defect`` -> frequency [Hz].
    harmonics : int
        Highest harmonic order n.
    tolerance : float
        Relative tolerance either side of n f [-], in (0, 0.5).
    slip_tolerance : float
        How far below n f a slip-affected line may sit [-, fraction], in [0, 0.5).
    sidebands : bool
        Look for modulation sidebands.
    resolution : float
        Bin spacing of the spectrum the peaks come from [Hz] (0: ignore).

    Returns
    -------
    list of dict
        One per peak, in the order given: the peak's keys plus ``matched`` (a name or
        None), ``harmonic`` (n or None), ``deviation`` ((f_p - n f)/(n f) or None) and,
        for sidebands, ``sideband_of`` (the defect's name), ``sideband_harmonic`` (n),
        ``sideband_order`` (+-k) and ``modulation`` (the modulating frequency's name).

    Examples
    --------
    >>> m = match_peaks([(201.0, 1.0), (301.5, 0.5)], {"bpfo": 107.4})  # 6.4 % slip
    >>> [(p["matched"], p["harmonic"]) for p in m]
    [('bpfo', 2), ('bpfo', 3)]
    >>> m = match_peaks([(215.0, 1.0), (201.0, 0.5)], {"bpfo": 107.4})  # two slips
    >>> [(p["matched"], p["harmonic"]) for p in m]
    [('bpfo', 2), (None, None)]
    >>> m = match_peaks([(12.0, 1.0)], {"ftf": 11.58}, resolution=2.0)  # 3.6 %: one bin
    >>> (m[0]["matched"], m[0]["harmonic"])
    ('ftf', 1)
    """
    if not isinstance(frequencies, dict) or not frequencies:
        raise InputError("frequencies", frequencies, f"a dict with keys among {list(NAMES)}")
    freqs = {}
    for name, value in frequencies.items():
        if name not in NAMES:
            raise InputError("frequencies", name, f"keys among {list(NAMES)}")
        try:
            f = float(value)
        except (TypeError, ValueError):
            f = math.nan
        if not (math.isfinite(f) and f > 0):
            raise InputError(f"frequencies[{name!r}]", value, "a frequency > 0 Hz")
        freqs[name] = f
    harmonics = _positive_int("harmonics", harmonics)
    tolerance = _fraction("tolerance", tolerance, 0.0, 0.5, closed_low=False)
    slip_tolerance = _fraction("slip_tolerance", slip_tolerance, 0.0, 0.5, closed_low=True)
    resolution = _fraction("resolution", resolution, 0.0, math.inf, closed_low=True)
    out = [_peak(p) for p in peaks]
    slack = RESOLUTION_BINS * resolution  # [Hz]

    # pass 1: harmonics, strongest peak first: a family's strongest line fixes its slip
    order = {name: i for i, name in enumerate(NAMES)}
    fundamentals: dict[str, float] = {}  # family -> f_p / order of its strongest line [Hz]
    for p in sorted(out, key=lambda p: -p["amplitude"]):
        fp, best = p["frequency_hz"], None
        for name, f in freqs.items():
            family, multiple = FAMILIES.get(name, (name, 1))
            below = max(tolerance, slip_tolerance) if name in SLIP_AFFECTED else tolerance
            for n in range(1, harmonics + 1):
                line = n * f
                if not -max(below * line, slack) <= fp - line <= max(tolerance * line, slack):
                    continue
                # one slip per family: the fundamental this line implies must agree
                reference = fundamentals.get(family)
                implied = fp / (n * multiple)
                if reference is not None and abs(implied - reference) > max(
                    tolerance * f / multiple, slack
                ):
                    continue
                deviation = (fp - line) / line
                key = (n > 1 and reference is None, n * abs(deviation), n, order[name])
                if best is None or key < best[0]:
                    best = (key, name, n, deviation)
        p["matched"], p["harmonic"], p["deviation"] = (
            (best[1], best[2], best[3]) if best else (None, None, None)
        )
        if best:
            family, multiple = FAMILIES.get(best[1], (best[1], 1))
            fundamentals.setdefault(family, fp / (best[2] * multiple))
    if sidebands:
        _label_sidebands(out, freqs, tolerance, slack)
    return out


def peak_label(p: dict) -> str:
    """Short label of a labelled line ``p`` (a dict of :func:`match_peaks`): "2x bpfo",
    "1x bpfi -1 shaft", "10x shaft" or "-".

    Parameters
    ----------
    p : dict
        One labelled peak of :func:`match_peaks`: ``matched`` and ``harmonic`` for a
        harmonic, ``sideband_of``, ``sideband_harmonic``, ``sideband_order`` and
        ``modulation`` for a sideband.

    Examples
    --------
    >>> peak_label({"matched": "bpfo", "harmonic": 2})
    '2x bpfo'
    """
    if p.get("matched"):
        return f"{p['harmonic']}x {p['matched']}"
    if p.get("sideband_of"):
        return (
            f"{p['sideband_harmonic']}x {p['sideband_of']} {p['sideband_order']:+d} "
            f"{p['modulation']}"
        )
    return "-"


def _well_matched(p: dict, tolerance: float, slack: float) -> bool:
    """Whether a labelled peak lies within +-max(tolerance n f, slack) of its harmonic
    n f: inside the match window without the slip allowance."""
    if p.get("deviation") is None:
        return False
    line = p["frequency_hz"] / (1.0 + p["deviation"])
    return abs(p["frequency_hz"] - line) <= max(tolerance * line, slack)


def _label_sidebands(out: list[dict], freqs: dict, tolerance: float, slack: float) -> None:
    """Pass 2 of :func:`match_peaks`: relabel peaks that are nearer a sideband."""
    carriers: set[int] = set()  # ids of the lines sidebands were given to: they stay
    for p in sorted(out, key=lambda p: -p["amplitude"]):  # strongest first
        if id(p) in carriers:
            continue
        fp, best = p["frequency_hz"], None
        good = _well_matched(p, tolerance, slack)
        for c in out:
            modulation = MODULATION.get(c["matched"])
            if modulation not in freqs or c is p or (good and c["amplitude"] <= p["amplitude"]):
                continue  # a line that matches well is claimed by a stronger line only
            fm = freqs[modulation]
            for k in range(1, SIDEBAND_ORDERS + 1):
                for sign in (-1, 1):
                    target = c["frequency_hz"] + sign * k * fm
                    if target <= 0:
                        continue
                    distance = abs(fp - target)
                    if distance <= max(min(tolerance * target, 0.25 * fm), slack):
                        key = (distance / target, k, c["harmonic"])
                        if best is None or key < best[0]:
                            best = (key, c, sign * k, modulation)
        if best is not None and (p["deviation"] is None or best[0][0] < abs(p["deviation"])):
            c = best[1]
            carriers.add(id(c))
            p.update(
                matched=None,
                harmonic=None,
                deviation=None,
                sideband_of=c["matched"],
                sideband_harmonic=c["harmonic"],
                sideband_order=best[2],
                modulation=best[3],
            )
