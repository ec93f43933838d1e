"""Spectral peaks, their match to bearing defect frequencies, and a diagnosis.

Layer 3 (see docs/architecture.md): :func:`find_peaks` picks the lines of a spectrum
(``scipy.signal.find_peaks`` with a prominence relative to the median level, a robust
estimate of the noise floor); :func:`match_peaks` labels each line as a harmonic n f of
a shaft or defect frequency (names as in :data:`bearinglab.kinematics.FREQUENCY_NAMES`,
values in Hz from :func:`bearinglab.kinematics.defect_frequencies`) or as a modulation
sideband n f_d +- k f_m; :func:`diagnose` turns the labels into the likely fault.

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
import scipy.signal

from ..errors import InputError

#: Frequency names ``match_peaks`` understands (kinematics' names plus the shaft).
NAMES = ("shaft", "ftf", "bpfo", "bpfi", "bsf", "ball_defect")
#: Frequencies carried by the cage, which slips: their lines run slow.
SLIP_AFFECTED = ("ftf", "bpfo", "bpfi", "bsf", "ball_defect")
#: Defect -> the frequency that modulates it (the load zone seen by the defect turns
#: with the shaft for an inner-race defect, with the cage for a ball defect).
MODULATION = {"bpfi": "shaft", "ball_defect": "ftf", "bsf": "ftf"}
#: Sideband orders k looked for in n f_d +- k f_m.
SIDEBAND_ORDERS = 2
#: Defect frequency name -> fault.
FAULTS = {"bpfo": "outer race", "bpfi": "inner race", "bsf": "ball", "ball_defect": "ball",
          "ftf": "cage"}
_FAULT_ORDER = ("outer race", "inner race", "ball", "cage")
_SIDEBAND_WEIGHT = 0.5  # a sideband supports its carrier's fault, less than a harmonic does


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


def find_peaks(spectrum, count: int = 10, min_frequency: float = 0.0,
               max_frequency: float | None = None, prominence: float = 4.0) -> list[dict]:
    """The ``count`` largest lines of a spectrum that stand out of its noise floor.

    A line is a local maximum (``scipy.signal.find_peaks``) whose prominence is at least
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
        raise InputError("spectrum", type(spectrum).__name__,
                         "a Spectrum or (frequency, amplitude) arrays") from None
    if (frequency.ndim != 1 or frequency.shape != amplitude.shape or frequency.size < 3
            or not np.all(np.isfinite(amplitude))):
        raise InputError("spectrum", f"arrays of shapes {frequency.shape}, {amplitude.shape}",
                         "equal-length 1-D frequency and finite amplitude arrays (>= 3)")
    count = _positive_int("count", count)
    prominence = _fraction("prominence", prominence, 0.0, math.inf, closed_low=False)
    high = frequency[-1] if max_frequency is None else max_frequency
    try:
        low, high = float(min_frequency), float(high)
    except (TypeError, ValueError):
        low = high = math.nan
    if not low < high:
        raise InputError("max_frequency", max_frequency,
                         f"a frequency above min_frequency = {min_frequency!r} Hz")
    inside = np.flatnonzero((frequency >= low) & (frequency <= high))
    if inside.size < 3:
        return []
    a = amplitude[inside]
    # the 1e-9 x max floor keeps the rounding noise of noiseless synthetic spectra out
    floor = max(float(np.median(a)), 1e-9 * float(np.max(np.abs(a))))
    index, props = scipy.signal.find_peaks(a, prominence=prominence * floor)
    top = index[np.argsort(a[index], kind="stable")[::-1][:count]]
    prom = dict(zip(index.tolist(), props["prominences"].tolist(), strict=True))
    return [{"frequency_hz": float(frequency[inside[i]]), "amplitude": float(a[i]),
             "prominence": prom[int(i)]} for i in top]


def _peak(p) -> dict:
    if isinstance(p, dict):
        out = dict(p)
    else:
        try:
            f, a = p
        except (TypeError, ValueError):
            raise InputError("peaks", p, "dicts with frequency_hz and amplitude, "
                             "or (frequency, amplitude) pairs") from None
        out = {"frequency_hz": f, "amplitude": a}
    try:
        out["frequency_hz"], out["amplitude"] = float(out["frequency_hz"]), float(out["amplitude"])
    except (KeyError, TypeError, ValueError):
        raise InputError("peaks", p, "dicts with numeric frequency_hz and amplitude") from None
    if not (math.isfinite(out["frequency_hz"]) and out["frequency_hz"] > 0):
        raise InputError("peaks", p, "frequencies > 0 Hz")
    return out


def match_peaks(peaks, frequencies: dict[str, float], harmonics: int = 5,
                tolerance: float = 0.02, slip_tolerance: float = 0.08,
                sidebands: bool = True) -> list[dict]:
    """Label each peak as a harmonic n f of a shaft or defect frequency, or a sideband.

    A peak at f_p matches n f (n = 1 .. ``harmonics``) when
    -tolerance <= (f_p - n f)/(n f) <= tolerance, and, for the frequencies the slip of
    the rolling elements lowers (ftf, bpfo, bpfi, bsf, ball_defect), also when
    -slip_tolerance <= (f_p - n f)/(n f) <= tolerance. Of several matches the smallest
    relative distance wins, then the lowest harmonic (so 2 bsf is labelled
    ``ball_defect`` 1x).

    With ``sidebands``, a peak is labelled a sideband n f_d +- k f_m (k = 1, 2) of an
    inner-race line (f_m = shaft) or a ball line (f_m = ftf) when it lies within
    ``tolerance`` x (n f_d +- k f_m) and f_m/4 of it, relatively nearer than to any
    harmonic. The carrier n f_d must be among the peaks (matched as a harmonic; the
    largest if several), and its measured frequency is used, so the slip is accounted
    for.

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

    Returns
    -------
    list of dict
        One per peak, in the order given: the peak's keys plus ``matched`` (a name or
        None), ``harmonic`` (n or None), ``deviation`` ((f_p - n f)/(n f) or None) and,
        for sidebands, ``sideband_of`` (the defect's name), ``sideband_harmonic`` (n),
        ``sideband_order`` (+-k) and ``modulation`` (the modulating frequency's name).

    Examples
    --------
    >>> m = match_peaks([(215.0, 1.0), (201.0, 0.5)], {"bpfo": 107.4})
    >>> [(p["matched"], p["harmonic"]) for p in m]
    [('bpfo', 2), ('bpfo', 2)]
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
    out = [_peak(p) for p in peaks]

    # pass 1: harmonics; key (|deviation|, n, name order) so ties go to the lowest n
    order = {name: i for i, name in enumerate(NAMES)}
    for p in out:
        fp, best = p["frequency_hz"], None
        for name, f in freqs.items():
            lower = -max(tolerance, slip_tolerance) if name in SLIP_AFFECTED else -tolerance
            for n in range(1, harmonics + 1):
                deviation = (fp - n * f) / (n * f)
                if lower <= deviation <= tolerance:
                    key = (abs(deviation), n, order[name])
                    if best is None or key < best[0]:
                        best = (key, name, n, deviation)
        p["matched"], p["harmonic"], p["deviation"] = (best[1], best[2], best[3]) if best \
            else (None, None, None)
    if sidebands:
        _label_sidebands(out, freqs, harmonics, tolerance)
    return out


def _label_sidebands(out: list[dict], freqs: dict, harmonics: int, tolerance: float) -> None:
    """Pass 2 of :func:`match_peaks`: relabel peaks that are nearer a sideband."""
    carriers = []  # (defect, n, carrier frequency [Hz], modulation name, f_m [Hz])
    for defect, modulation in MODULATION.items():
        if defect not in freqs or modulation not in freqs:
            continue
        for n in range(1, harmonics + 1):
            seen = [p for p in out if p["matched"] == defect and p["harmonic"] == n]
            if seen:  # a sideband without its carrier line is too weak a clue
                fc = max(seen, key=lambda p: p["amplitude"])["frequency_hz"]
                carriers.append((defect, n, fc, modulation, freqs[modulation]))
    for p in out:
        fp, best = p["frequency_hz"], None
        for defect, n, fc, modulation, fm in carriers:
            for k in range(1, SIDEBAND_ORDERS + 1):
                for sign in (-1, 1):
                    target = fc + sign * k * fm
                    if target <= 0:
                        continue
                    distance = abs(fp - target)
                    if distance <= min(tolerance * target, 0.25 * fm):
                        key = (distance / target, k, n)
                        if best is None or key < best[0]:
                            best = (key, defect, n, sign * k, modulation)
        if best is not None and (p["deviation"] is None or best[0][0] < abs(p["deviation"])):
            p.update(matched=None, harmonic=None, deviation=None, sideband_of=best[1],
                     sideband_harmonic=best[2], sideband_order=best[3], modulation=best[4])


def diagnose(matched_peaks, min_lines: int = 2, compound_ratio: float = 0.5) -> dict:
    """The likely bearing fault from peaks labelled by :func:`match_peaks`.

    Each fault scores sum(A / n) over its harmonic lines (amplitude A, order n: high
    orders are likelier coincidences, as the match window widens with n) plus
    0.5 sum(A / n) over its sidebands. A fault needs at least ``min_lines`` lines; the
    best-scoring one is reported, or ``"compound: a + b"`` when another also qualifies
    with at least ``compound_ratio`` times its score. Shaft lines make no fault (they
    point to unbalance, misalignment or looseness).

    Parameters
    ----------
    matched_peaks : list of dict
        Output of :func:`match_peaks`.
    min_lines : int
        Fewest lines (harmonics and sidebands) that make a fault.
    compound_ratio : float
        Score ratio, in (0, 1], above which a second fault is reported too.

    Returns
    -------
    dict
        ``likely_fault`` ("outer race", "inner race", "ball", "cage", "compound: ..." or
        None), ``scores`` and ``lines`` per fault, and a one-line ``reason``.

    Examples
    --------
    >>> peaks = match_peaks([(107.0, 1.0), (214.5, 0.6), (322.0, 0.3)], {"bpfo": 107.4})
    >>> diagnose(peaks)["likely_fault"]
    'outer race'
    """
    min_lines = _positive_int("min_lines", min_lines)
    try:
        ratio = float(compound_ratio)
    except (TypeError, ValueError):
        ratio = math.nan
    if not 0.0 < ratio <= 1.0:
        raise InputError("compound_ratio", compound_ratio, "a number in (0, 1]")
    scores = dict.fromkeys(_FAULT_ORDER, 0.0)
    lines = dict.fromkeys(_FAULT_ORDER, 0)
    evidence: dict[str, list[str]] = {f: [] for f in _FAULT_ORDER}
    shaft = 0
    for p in matched_peaks:
        try:
            amplitude = float(p["amplitude"])
            name, sideband_of = p.get("matched"), p.get("sideband_of")
            if name in FAULTS:
                fault = FAULTS[name]
                scores[fault] += amplitude / p["harmonic"]
                evidence[fault].append(f"{p['harmonic']}x {name}")
            elif sideband_of in FAULTS:
                fault = FAULTS[sideband_of]
                scores[fault] += _SIDEBAND_WEIGHT * amplitude / p["sideband_harmonic"]
                evidence[fault].append(f"{p['sideband_harmonic']}x {sideband_of} "
                                       f"{p['sideband_order']:+d} {p['modulation']}")
            else:
                shaft += name == "shaft"
                continue
        except (AttributeError, KeyError, TypeError, ValueError, ZeroDivisionError):
            raise InputError("matched_peaks", p, "dicts from match_peaks") from None
        lines[fault] += 1
    ranked = sorted((f for f in _FAULT_ORDER if lines[f] >= min_lines and scores[f] > 0),
                    key=lambda f: -scores[f])
    if ranked:
        chosen = [f for f in ranked if scores[f] >= ratio * scores[ranked[0]]]
        likely = chosen[0] if len(chosen) == 1 else "compound: " + " + ".join(chosen)
        reason = "; ".join(f"{f}: {', '.join(evidence[f])} (score {scores[f]:.3g})"
                           for f in chosen)
    else:
        likely = None
        if any(lines.values()):
            reason = (f"fewer than {min_lines} defect lines for any fault: "
                      + "; ".join(f"{f}: {', '.join(e)}" for f, e in evidence.items() if e))
        elif shaft:
            reason = (f"only shaft lines ({shaft}): unbalance, misalignment or looseness, "
                      "not a bearing defect")
        else:
            reason = "no line matches a defect frequency"
    return {"likely_fault": likely, "scores": scores, "lines": lines, "reason": reason}
