"""The shaft speed a vibration record shows.

The shaft turns the rotor's unbalance, misalignment and looseness into lines at the shaft
frequency and its harmonics, in the spectrum of the raw signal (Randall R. B., Vibration-
based Condition Monitoring, Wiley 2011, sec. 2.2.1 and ch. 5). The search is the harmonic
series test of :mod:`bearinglab.diagnosis.series` on the full-resolution power
spectrum (Hann window, one segment, nu = 2), with the fundamental scanned over the range
given: the shaft line and its first harmonics together, each read within one bin, their
p-values combined by Fisher's method and bounded over the scan. When the series is
significant the speed is refined by a least-squares fit through the origin of the lines
found, f_shaft = sum(k f_k) / sum(k^2), which the higher harmonics make k times more
precise than the resolution. A series found at f is also a series at 2f (every other
line); the lowest significant sub-multiple in the range is kept. Over a wide range other
periodic lines (a strong outer-race series in the raw spectrum) can still win: give a
range no wider than about an octave round the expected speed.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError

#: Harmonics of the shaft frequency read [-].
SHAFT_HARMONICS = 5
#: Level at which the shaft series counts as found [-]: the shaft is always there, the
#: test only guards against reading a speed off pure noise.
SPEED_ALPHA = 0.05
#: Half-width of the search round a given speed [-, fraction]: an induction motor runs
#: up to a few per cent below its synchronous speed.
SEARCH = 0.05
#: A shaft series found is unambiguous - enough to overrule a speed or a sample rate
#: given - when it holds this many harmonics or more and is not also a series at a
#: sub-multiple of its frequency (on the CWRU and MFPT records of shared/data/real the
#: shaft series holds 3 to 5 of its first 5 harmonics at p 1e-4 to 0.03).
UNAMBIGUOUS_HARMONICS = 3
#: Speed disagreement that is warned about [-, fraction]: the race lines' tolerance.
SPEED_WARNING = 0.02
#: Faults whose series confirm a speed the shaft series puts in doubt (their lines sit
#: where that speed puts them).
SPEED_CONFIRMING = frozenset({"outer_race", "inner_race", "ball"})
#: Resolution of the raw spectrum, as a fraction of the shaft frequency, at which its
#: shaft series may replace a speed given 2 % off (a bin no wider than that: 50 shaft
#: revolutions or more in the record; a 0.3 s record's 3.3 Hz bins read an 1800 rpm shaft
#: at 1850 rpm), and at which it may put a speed in doubt (the search's own half-width:
#: 20 revolutions or more).
PRECISE = 0.02
RESOLVED = SEARCH
#: Multiples of the given speed searched when no shaft line stands near it (a sample rate
#: given that many times too high, or a speed that many times too low).
MULTIPLES = (2, 3, 4)


@dataclass(frozen=True)
class ShaftEstimate:
    """Shaft frequency found in a record: ``frequency`` [Hz] (None when no significant
    series was found), the search range ``low`` - ``high`` [Hz], the series' ``p_value``
    [-], the number of ``harmonics`` found [-] and ``sub_multiple`` k when the series
    found is also a significant series at frequency / k below the range (a sample rate or
    speed k times too high) [-], and the ``resolution`` of the spectrum searched [Hz]."""

    frequency: float | None
    low: float
    high: float
    p_value: float
    harmonics: int
    sub_multiple: int | None = None
    resolution: float = 0.0

    @property
    def unambiguous(self) -> bool:
        """Whether the series found is strong enough to overrule a speed given:
        UNAMBIGUOUS_HARMONICS harmonics or more, and no sub-multiple."""
        return (
            self.frequency is not None
            and self.harmonics >= UNAMBIGUOUS_HARMONICS
            and self.sub_multiple is None
        )

    def resolves(self, frequency: float, fraction: float) -> bool:
        """Whether the spectrum searched resolves ``fraction`` of ``frequency`` [Hz]."""
        return self.resolution <= fraction * frequency

    def to_dict(self) -> dict:
        """JSON form (Hz and rpm)."""
        f = self.frequency
        return {
            "measured_hz": f,
            "measured_rpm": None if f is None else 60.0 * f,
            "search_rpm": [60.0 * self.low, 60.0 * self.high],
            "p_value": self.p_value,
            "harmonics_found": self.harmonics,
            "sub_multiple": self.sub_multiple,
        }


@functools.lru_cache(maxsize=2)
def periodic_hann(n: int) -> np.ndarray:
    """The periodic Hann window of ``n`` samples (``numpy.hanning(n + 1)[:-1]``), kept
    for the last two record lengths seen (a cosine of 120 000 points costs 0.5 ms a call;
    a long record's window is megabytes, so no more are kept).

    Parameters
    ----------
    n : int
        Samples [-].
    """
    window = np.hanning(n + 1)[:-1]
    window.flags.writeable = False
    return window


def hann_power(x: np.ndarray, n: int, bins: int, spectrum=None) -> np.ndarray:
    """|rfft(y w)|^2 at bins 0 .. ``bins`` - 1 (fewer if the transform has fewer), y the
    first ``n`` samples of ``x`` less their mean and w the periodic Hann window
    (:func:`periodic_hann`).

    ``spectrum``: ``numpy.fft.rfft`` of the whole of ``x`` less its mean, when at hand
    and ``n`` is the record's length; the window is then applied to it - the periodic Hann
    window is 1/2 - (e^(2 pi j i/n) + e^(-2 pi j i/n)) / 4, so that its product's
    spectrum is Y[k] / 2 - (Y[k - 1] + Y[k + 1]) / 4 (Y[-1] = conj Y[1]) - rather than the
    record transformed again (equal to round-off; a test checks it).

    Parameters
    ----------
    x : numpy.ndarray
        Samples (1-D).
    n : int
        Samples transformed, at most ``x.size``.
    bins : int
        Bins wanted.
    spectrum : numpy.ndarray, optional
        ``numpy.fft.rfft(x - x.mean())``.
    """
    if spectrum is not None and n == x.size and len(spectrum) == n // 2 + 1 and bins + 1 < n // 2:
        s = spectrum[: bins + 1]
        before = np.concatenate((np.conj(s[1:2]), s[: bins - 1]))
        windowed = 0.5 * s[:bins] - 0.25 * (before + s[1 : bins + 1])
        return windowed.real**2 + windowed.imag**2
    y = x[:n] - np.mean(x[:n])
    return (np.abs(np.fft.rfft(y * periodic_hann(n))) ** 2)[:bins]


def shaft_frequency(
    x: np.ndarray,
    sample_rate: float,
    low: float,
    high: float,
    harmonics: int = SHAFT_HARMONICS,
    spectrum=None,
) -> ShaftEstimate:
    """Shaft frequency [Hz] in [``low``, ``high``] shown by the record ``x``.

    Parameters
    ----------
    x : numpy.ndarray
        Samples (1-D), any unit.
    sample_rate : float
        Sample rate [Hz].
    low, high : float
        Search range [Hz], 0 < low < high.
    harmonics : int
        Harmonics read.
    spectrum : numpy.ndarray, optional
        ``numpy.fft.rfft(x - x.mean())``, when at hand (:func:`hann_power`).

    Returns
    -------
    ShaftEstimate

    Examples
    --------
    >>> fs = 2000.0
    >>> t = np.arange(20000) / fs
    >>> x = sum(np.sin(2 * np.pi * k * 29.3 * t) / k for k in (1, 2, 3))
    >>> x = x + np.random.default_rng(0).standard_normal(t.size)
    >>> round(shaft_frequency(x, fs, 27.0, 32.0).frequency, 2)
    29.3
    """
    from .methods import segment_length
    from .series import series_test
    from .statistics import FLOOR_BINS, normalised

    n = segment_length(x.size, sample_rate, sample_rate / x.size)
    resolution = sample_rate / n
    centre = 0.5 * (low + high)
    top = min(0.5 * sample_rate, (harmonics + 0.5) * high)
    # only the bins up to the top harmonic are read; the floor's running median there
    # needs FLOOR_BINS beyond it (normalised()'s guard against a zero floor now scales with
    # these bins' largest floor: the same but for records with exact zeros)
    power = hann_power(x, n, int(top / resolution) + FLOOR_BINS + 8, spectrum)
    z = normalised(power, 2.0)
    # the shaft's lines read by their rank (the speed check's levels are set on it)
    test = series_test(
        z,
        resolution,
        2.0,
        centre,
        1.0 - low / centre,
        high / centre - 1.0,
        harmonics,
        top,
        tail=False,
    )
    found = [ln for ln in test.lines if ln.p_value < SPEED_ALPHA]
    if test.p_value >= SPEED_ALPHA or not found:
        return ShaftEstimate(None, low, high, test.p_value, 0, resolution=resolution)
    # a series at f also shows at 2f (every other line): prefer the lowest sub-multiple
    # inside the range whose own series is significant (octave errors of pitch search)
    below = None
    # the sub-series is read off the lines it does not share with the series found
    own = np.ones(z.size, bool)
    for m in range(1, int(top / test.fundamental_hz) + 2):
        i = int(round(m * test.fundamental_hz / resolution))
        own[max(i - 2, 0) : i + 3] = False
    for k in (4, 3, 2):
        sub = test.fundamental_hz / k
        lower = series_test(
            z, resolution, 2.0, sub, 0.01, 0.01, harmonics, top, valid=own, tail=False
        )
        if lower.p_value >= SPEED_ALPHA or sub < 0.5:
            continue
        if sub < low:  # the series found is the k-th harmonic of one below the range
            below = below or k
            continue
        test = series_test(z, resolution, 2.0, sub, 0.01, 0.01, harmonics, top, tail=False)
        found = [ln for ln in test.lines if ln.p_value < SPEED_ALPHA]
        break
    # refine each line by a parabola through its bin and the neighbours (log power)
    refined = []
    for line in found:
        i = int(round(line.frequency_hz / resolution))
        if 1 <= i < power.size - 1 and min(power[i - 1 : i + 2]) > 0:
            a, b, c = np.log(power[i - 1 : i + 2])
            shift = 0.5 * (a - c) / (a - 2 * b + c) if a - 2 * b + c < 0 else 0.0
            refined.append((line.n, (i + max(-0.5, min(0.5, shift))) * resolution))
    k = np.array([r[0] for r in refined], float)
    f = np.array([r[1] for r in refined], float)
    estimate = float(np.sum(k * f) / np.sum(k * k)) if k.size else test.fundamental_hz
    if not math.isfinite(estimate) or not low <= estimate <= high:
        estimate = test.fundamental_hz
    return ShaftEstimate(estimate, low, high, test.p_value, len(found), below, resolution)


#: Supply frequencies [Hz] whose harmonics are never read as a shaft at a multiple of the
#: speed given (the mains of most of the world; `supply_hz` adds the one given).
SUPPLY_HZ = (50.0, 60.0)
#: Supply harmonics so checked [-].
SUPPLY_HARMONICS = 4


def supply_line(frequency: float, supply=None, expected=None) -> bool:
    """Whether ``frequency`` [Hz] lies within SPEED_WARNING of a harmonic (1 ..
    SUPPLY_HARMONICS) of 50 Hz, 60 Hz or the ``supply`` frequency given [Hz], and closer
    to it than to the ``expected`` frequency [Hz] (where the speed given puts a line).

    >>> supply_line(119.97), supply_line(115.0), supply_line(75.5, supply=25.0)
    (True, False, True)
    >>> supply_line(119.97, expected=118.1), supply_line(119.8, expected=119.8)
    (True, False)
    """
    bases = SUPPLY_HZ + ((float(supply),) if supply else ())
    return any(
        abs(frequency / (m * b) - 1.0) <= SPEED_WARNING
        and (expected is None or abs(frequency - m * b) < abs(frequency - expected))
        for b in bases
        for m in range(1, SUPPLY_HARMONICS + 1)
    )


def shaft_multiple(x: np.ndarray, sample_rate: float, nominal: float, supply=None, spectrum=None):
    """(k, frequency [Hz]) of an unambiguous shaft series at k times ``nominal`` [Hz]
    (k in MULTIPLES, the smallest first), or None: asked when no shaft line stands near
    the nominal speed, where a sample rate given k times too high puts the real one.

    A series on the supply's harmonics (:func:`supply_line`: 120 Hz mains read as a shaft
    at 4 x 1772 rpm on CWRU 3006) is the supply's, not a shaft's; and a series at k x f
    whose lines between its own - at f, 2 f, ... - show too (:func:`fundamental_shows`) is
    the harmonics of a shaft at f, near the speed given, whose first line was too weak
    for the search near it (a healthy record of the second laboratory: shaft at 15.23 Hz,
    given 900 rpm, its second harmonic the strongest): neither is a speed error."""
    for k in MULTIPLES:
        low, high = (k * nominal * (1 + s) for s in (-SEARCH, SEARCH))
        if high * UNAMBIGUOUS_HARMONICS >= 0.5 * sample_rate:
            break
        found = shaft_frequency(x, sample_rate, low, high, spectrum=spectrum)
        # Bonferroni over the multiples tried
        if (
            found.unambiguous
            and found.resolves(found.frequency, RESOLVED)
            and found.p_value < SPEED_ALPHA / len(MULTIPLES)
            and not supply_line(found.frequency, supply, k * nominal)
            and not fundamental_shows(x, sample_rate, found.frequency, k, spectrum)
        ):
            return k, found.frequency
    return None


def _periodogram(x: np.ndarray, sample_rate: float, top: float, spectrum=None):
    """z (a Hann periodogram over its running median, chi2_2 / 2 in noise) of the longest
    power-of-two stretch of ``x`` up to ``top`` [Hz], and its resolution [Hz]."""
    from .methods import segment_length
    from .statistics import FLOOR_BINS, normalised

    n = segment_length(x.size, sample_rate, sample_rate / x.size)
    resolution = sample_rate / n
    power = hann_power(x, n, int(top / resolution) + FLOOR_BINS + 8, spectrum)
    return normalised(power, 2.0), resolution


def line_near(
    x: np.ndarray, sample_rate: float, frequency: float, tolerance: float = None, spectrum=None
):
    """The line within ``tolerance`` (default SPEED_WARNING) of ``frequency`` [Hz] that
    stands out of its own neighbourhood: (its frequency [Hz], ln p), the largest reading
    there, when its chance under the chi-square law of a periodogram bin over its running
    median, times the bins read, is below SPEED_ALPHA; else None. A line, not a series:
    the evidence that the shaft turns where the speed given puts it, in a spectrum too
    busy with other lines for the series test near it (HIT-SM Normal_900, below)."""
    from .statistics import bin_logp

    tolerance = SPEED_WARNING if tolerance is None else tolerance
    if not frequency > 0 or frequency * (1 + tolerance) >= 0.5 * sample_rate:
        return None
    z, resolution = _periodogram(x, sample_rate, frequency * (1 + tolerance) * 1.5, spectrum)
    lo = max(int(math.floor(frequency * (1 - tolerance) / resolution)), 1)
    hi = min(int(math.ceil(frequency * (1 + tolerance) / resolution)), z.size - 2)
    if hi < lo:
        return None
    i = lo + int(np.argmax(z[lo : hi + 1]))
    log_p = float(bin_logp(z[i], 2.0)) + math.log(hi - lo + 1)
    return (i * resolution, log_p) if log_p < math.log(SPEED_ALPHA) else None


def fundamental_shows(
    x: np.ndarray, sample_rate: float, frequency: float, k: int, spectrum=None
) -> bool:
    """Whether the lines of a shaft at ``frequency`` / k [Hz] that are not harmonics of
    ``frequency`` (j f / k, j = 1 .. SHAFT_HARMONICS, j not a multiple of k) make a
    series at SPEED_ALPHA in the record ``x``, or its first line stands out of its own
    neighbourhood (:func:`line_near`): then ``frequency`` is the k-th harmonic of that
    shaft, whose series was found."""
    from .series import series_test

    if line_near(x, sample_rate, frequency / k, spectrum=spectrum) is not None:
        return True
    top = min(0.5 * sample_rate, (SHAFT_HARMONICS + 0.5) * frequency / k * 1.01)
    z, resolution = _periodogram(x, sample_rate, top, spectrum)
    own = np.ones(z.size, bool)
    for m in range(1, int(top / frequency) + 2):
        i = int(round(m * frequency / resolution))
        own[max(i - 2, 0) : i + 3] = False
    sub = series_test(
        z, resolution, 2.0, frequency / k, 0.01, 0.01, SHAFT_HARMONICS, top, valid=own, tail=False
    )
    return bool(sub.lines) and sub.p_value < SPEED_ALPHA


def speed_used(
    x, sample_rate, nominal, speed_range, auto: bool, warnings: list, supply=None, spectrum=None
):
    """The speed a diagnosis runs at, and what the record's shaft series says of it.

    The shaft series is searched in ``speed_range`` ((low, high) [rad/s]; default
    +-SEARCH round ``nominal`` [rad/s]). With ``auto`` its speed is used. Otherwise the
    speed given is used, unless the series disagrees by more than SPEED_WARNING and is
    unambiguous and PRECISE (then the signal's, and a warning says so); a series at a
    sub-multiple of it, or none near it but one at k x it (:func:`shaft_multiple`), is a
    doubt that the verdict settles (a sample rate or speed given k times wrong).
    Warnings are appended to ``warnings``; ``supply`` [Hz] is the supply frequency given
    (its harmonics, and 50 and 60 Hz's, are never a shaft at a multiple of the speed);
    ``spectrum``: ``numpy.fft.rfft(x - x.mean())`` when at hand (:func:`hann_power`).

    Returns
    -------
    (speed used [rad/s], the speed record (JSON: given, measured, source, confirmed...),
    the shaft frequency found [Hz] or None, the doubt's warning or None)
    """
    if speed_range is not None:
        try:
            low, high = (float(v) / (2 * math.pi) for v in speed_range)
        except (TypeError, ValueError):
            low = high = math.nan
        if not (0 < low < high):
            raise InputError("speed_range", speed_range, "(low, high) in rad/s, 0 < low < high")
        if not auto and nominal is not None and not low <= nominal / (2 * math.pi) <= high:
            warnings.append(
                f"the given {nominal * 30 / math.pi:.6g} rpm is outside the speed range "
                f"{60 * low:.6g}-{60 * high:.6g} rpm, which then only bounds the search "
                "that checks it"
            )
    elif nominal is not None:
        low, high = (nominal / (2 * math.pi) * (1 + s) for s in (-SEARCH, SEARCH))
    else:
        raise InputError(
            "speed_range",
            None,
            'a (low, high) range in rad/s for shaft_speed="auto" without a nominal speed',
        )
    if high >= sample_rate / 2:
        raise InputError(
            "speed_range", speed_range, f"speeds below Nyquist ({sample_rate / 2:g} Hz)"
        )
    found = shaft_frequency(x, sample_rate, low, high, spectrum=spectrum)
    record = {"given_rpm": None if nominal is None else nominal * 30 / math.pi, **found.to_dict()}
    doubt = None  # why the signal's shaft series points away from the speed given
    if auto:
        if found.frequency is None:
            raise InputError(
                "shaft_speed",
                "auto",
                f"a record whose shaft line stands out between {60 * low:.6g} and "
                f"{60 * high:.6g} rpm, or a speed",
                hint="no shaft line found",
            )
        used, record["source"] = 2 * math.pi * found.frequency, "signal"
    else:
        used, record["source"] = nominal, "given"
        given_rpm = nominal * 30 / math.pi
        nominal_hz = nominal / (2 * math.pi)
        line = (
            None
            if found.frequency is not None
            else line_near(x, sample_rate, nominal_hz, spectrum=spectrum)
        )
        if line is not None:
            # no series stands out near the speed given, but its line does: the speed is
            # where it was given (HIT-SM Normal_900, 900 rpm: its shaft line at 15.23 Hz
            # is 46 x the floor, its 2nd and 4th harmonics 150 x, but a 4.5 Hz line at
            # 690 x with its sidebands and the 50 Hz mains leave the series near 900 rpm at
            # p = 0.28, and "the sample rate given may be 2 times too high" was said)
            found = dataclasses.replace(found, frequency=line[0], harmonics=1)
            record.update(found.to_dict())
        elif found.frequency is None:
            where = (
                f"within {100 * SEARCH:g} % of the given {given_rpm:.6g} rpm"
                if speed_range is None
                else f"between {60 * low:.6g} and {60 * high:.6g} rpm"
            )
            above = shaft_multiple(x, sample_rate, nominal / (2 * math.pi), supply, spectrum)
            if above is None:
                warnings.append(f"no shaft line found {where}: the speed is not checked")
            else:
                k, f = above
                doubt = (
                    f"no shaft line found {where}, but a shaft series at {k} x it "
                    f"({60 * f:.6g} rpm), and no fault's lines confirm the given speed: the "
                    f"sample rate given may be {k} times too high (every frequency then "
                    f"reads {k} times too high) or the speed {k} times too low"
                )
        elif found.sub_multiple and found.resolves(found.frequency / found.sub_multiple, RESOLVED):
            # (only a spectrum that resolves the shaft may put the speed in doubt)
            k = found.sub_multiple
            doubt = (
                f"the shaft series near {given_rpm:.6g} rpm is also a series at 1/{k} of "
                f"it ({60 * found.frequency / k:.6g} rpm), and no fault's lines confirm the "
                f"given speed: the lines may be harmonic {k} of the real shaft - the sample "
                f"rate given may be {k} times too low (every frequency then reads {k} times "
                f"too low) or the speed {k} times too high"
            )
        elif abs(off := found.frequency / (nominal / (2 * math.pi)) - 1) > SPEED_WARNING:
            # an unambiguous, precise shaft series off by more than the race lines'
            # tolerance replaces the speed given: defect lines read at it would be read in
            # the wrong place (a record that stores 1732 rpm but runs at 1774 rpm was
            # called "outer race" from inner-race harmonics)
            replace = found.unambiguous and found.resolves(found.frequency, PRECISE)
            if replace:
                used, record["source"] = 2 * math.pi * found.frequency, "signal"
            warnings.append(
                f"the signal shows the shaft at {60 * found.frequency:.6g} rpm"
                + (f" ({found.harmonics} harmonics)" if replace else "")
                + f", {100 * off:+.1f} % from the given {given_rpm:.6g} rpm (tolerance "
                f"{100 * SPEED_WARNING:g} %): "
                + ("the diagnosis uses the speed the signal shows - " if replace else "")
                + "check the speed and the sample rate"
            )
    record["used_rpm"] = used * 30 / math.pi
    # True: the signal's shaft series confirms the speed used; None: no shaft series to
    # check it; a doubt is settled by the verdict (SPEED_CONFIRMING)
    record["confirmed"] = None if found.frequency is None and doubt is None else doubt is None
    return used, record, found.frequency, doubt
