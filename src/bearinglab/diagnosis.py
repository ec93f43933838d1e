"""Bearing fault diagnosis of a vibration record by envelope analysis.

Layer 3 (see docs/architecture.md): :func:`analyze_signal` takes a record (a
:class:`~bearinglab.signal.Signal` or an array with its sample rate) and the kinematic
frequencies of the bearing (:class:`~bearinglab.kinematics.DefectFrequencies`) and
returns a :class:`Diagnosis`: the envelope spectrum, its largest lines labelled as
harmonics or sidebands of the shaft and defect frequencies, the likely fault, and the
ball-defect frequency measured from the signal.

The method is the benchmark procedure of Randall R. B., Antoni J., "Rolling element
bearing diagnostics - A tutorial", Mech. Syst. Signal Process. 25(2) (2011) 485-520:
band-pass the signal where the impacts excite the structure (the band of largest
spectral kurtosis, sec. 3.3, found with the STFT kurtogram of Antoni J., "Fast
computation of the kurtogram for the detection of transient faults", MSSP 21 (2007)
108-124), demodulate it (Hilbert-transform envelope, sec. 3.1) and read the
envelope spectrum for the defect frequencies and their harmonics and modulation
sidebands (sec. 2). The lines of the frequencies carried by the cage sit below their
kinematic values because the balls slip (Randall & Antoni sec. 2.1: 1-2 %); seed 004
(Hou X. et al., J. Mech. & Electr. Eng. 2024 no. 2) measures a ball-defect line at
93.6 % of the kinematic value, hence the default one-sided ``slip_tolerance`` of 8 %.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import InputError
from .kinematics import DefectFrequencies
from .signal import (
    EnvelopeSpectrum,
    KurtogramBand,
    Signal,
    diagnose,
    envelope_spectrum,
    find_peaks,
    match_peaks,
    spectral_kurtosis_band,
)
from .signal.peaks import NAMES

#: Channels preferred when none is named: the vertical (load-direction) acceleration of
#: a simulated record, the drive-end accelerometer of a CWRU record.
PREFERRED_CHANNELS = ("acc_y", "DE")
#: Default search range of the envelope lines, in multiples of the largest defect
#: frequency: room for the 5th harmonic of every defect frequency with its slip.
MAX_FREQUENCY_FACTOR = 5.5
#: Narrowest automatic demodulation band, in multiples of the largest defect frequency:
#: the band must pass the defect's modulation sidebands (Randall & Antoni 2011, sec. 3.3).
MIN_BAND_FACTOR = 3.0
#: Envelope lines kept by default: room for the 8 harmonics of one fault with their
#: sidebands and for the lines of a second fault (a compound fault).
COUNT = 24
#: Highest harmonic order matched by default: BPFO is about 0.6-0.7 BPFI in ball
#: bearings, so its 8th harmonic reaches the default search limit (5.5 x BPFI); with
#: fewer orders 6-8 x BPFO would take the label of a BPFI line or stay unlabelled.
HARMONICS = 8


@dataclass(frozen=True)
class Diagnosis:
    """What envelope analysis finds in a vibration record.

    Attributes
    ----------
    spectrum : EnvelopeSpectrum
        Envelope spectrum: ``frequency`` [Hz], ``amplitude`` (unit of the samples, e.g.
        m/s^2) and the demodulation ``band`` [Hz] (None: no band-pass).
    band : tuple of float or None
        Demodulation band (low, high) [Hz].
    kurtogram : KurtogramBand or None
        The spectral-kurtosis band search, when the band was chosen automatically.
    peaks : tuple of dict
        The largest envelope lines, largest first, labelled by
        :func:`bearinglab.signal.match_peaks`: ``frequency_hz``, ``amplitude``,
        ``prominence``, ``matched`` (``shaft``, ``ftf``, ``bpfo``, ``bpfi``, ``bsf``,
        ``ball_defect`` or None), ``harmonic`` (n or None), ``deviation``
        ((f - n f_kin)/(n f_kin), or None) and, for sidebands, ``sideband_of``,
        ``sideband_harmonic``, ``sideband_order`` and ``modulation``.
    diagnosis : dict
        :func:`bearinglab.signal.diagnose`'s ``likely_fault``, ``primary_fault``,
        ``faults``, ``scores``, ``lines`` and ``reason``.
    frequencies : DefectFrequencies
        The kinematic frequencies the lines were matched to.
    sample_rate : float
        Sample rate of the record [Hz].
    channel : str or None
        Channel analysed (None for a bare array).
    max_frequency : float
        Upper end of the line search [Hz].
    slip_tolerance : float
        How far below n f_kin a slip-affected line was allowed to sit [-].
    harmonics : int
        Highest harmonic order matched.
    ball_defect_frequency_hz : float or None
        Ball-defect frequency measured from the signal [Hz]: the strongest line matched
        to ``ball_defect`` at harmonic 1, else half the strongest matched at harmonic 2,
        else None.
    """

    spectrum: EnvelopeSpectrum
    band: tuple[float, float] | None
    kurtogram: KurtogramBand | None
    peaks: tuple
    diagnosis: dict
    frequencies: DefectFrequencies
    sample_rate: float
    channel: str | None
    max_frequency: float
    slip_tolerance: float
    harmonics: int
    ball_defect_frequency_hz: float | None

    @property
    def likely_fault(self) -> str | None:
        """"outer race", "inner race", "ball", "cage", "compound: ..." or None."""
        return self.diagnosis["likely_fault"]

    @property
    def primary_fault(self) -> str | None:
        """The best-supported fault: "outer race", "inner race", "ball", "cage" or None."""
        return self.diagnosis["primary_fault"]

    @property
    def faults(self) -> list[str]:
        """Every fault found, the primary first (see ``diagnose``)."""
        return list(self.diagnosis["faults"])

    @property
    def scores(self) -> dict:
        """Score of each fault (sum of A/n over its lines; see ``diagnose``)."""
        return self.diagnosis["scores"]

    @property
    def reason(self) -> str:
        """One line: the lines that support the diagnosis."""
        return self.diagnosis["reason"]

    @property
    def resolution(self) -> float:
        """Bin spacing of the envelope spectrum [Hz]."""
        return self.spectrum.resolution

    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units (Hz; amplitudes in the samples' unit)."""
        return {
            "channel": self.channel,
            "sample_rate_hz": self.sample_rate,
            "band_hz": None if self.band is None else [float(b) for b in self.band],
            "band_kurtosis": None if self.kurtogram is None else self.kurtogram.kurtosis,
            "resolution_hz": self.resolution,
            "max_frequency_hz": self.max_frequency,
            "slip_tolerance": self.slip_tolerance,
            "harmonics": self.harmonics,
            "kinematic": self.frequencies.to_dict(),
            "peaks": [dict(p) for p in self.peaks],
            "likely_fault": self.likely_fault,
            "primary_fault": self.primary_fault,
            "faults": self.faults,
            "scores": dict(self.scores),
            "lines": dict(self.diagnosis["lines"]),
            "reason": self.reason,
            "ball_defect_frequency_hz": self.ball_defect_frequency_hz,
        }

    def to_pandas(self):
        """Table of the envelope lines (one row per peak, largest first)."""
        import pandas as pd

        columns = ["frequency_hz", "amplitude", "prominence", "matched", "harmonic",
                   "deviation", "sideband_of", "sideband_harmonic", "sideband_order",
                   "modulation"]
        return pd.DataFrame([{c: p.get(c) for c in columns} for p in self.peaks],
                            columns=columns)

    def plot(self, path=None, ax=None):
        """Envelope spectrum with the kinematic lines and their harmonics marked.

        Parameters
        ----------
        path : str or Path, optional
            Also save the figure there (.png, .svg or .pdf; written atomically, and the
            figure is closed).
        ax : matplotlib Axes, optional
            Where to draw; a new figure otherwise.

        Returns
        -------
        (figure, axes)
        """
        from .plotting import _pyplot, save_figure

        plt = _pyplot()
        if ax is None:
            fig, ax = plt.subplots(figsize=(11, 4.5))
        else:
            fig = ax.figure
        f, a = self.spectrum.frequency, self.spectrum.amplitude
        shown = f <= self.max_frequency
        ax.plot(f[shown], a[shown], color="0.3", lw=0.8, label="envelope spectrum")
        top = float(np.max(a[shown])) if np.any(shown) else 1.0
        for i, name in enumerate(("shaft", "ftf", "bpfo", "bpfi", "ball_defect")):
            base = self.frequencies.hz(name)
            orders = np.arange(1, self.harmonics + 1)
            lines = orders * base
            lines = lines[lines <= self.max_frequency]
            if lines.size:
                ax.vlines(lines, 0, 1.05 * top, colors=f"C{i}", linestyles="--", lw=0.8,
                          alpha=0.7, label=f"{name.upper()} {base:.2f} Hz and harmonics")
        for p in self.peaks:
            label = peak_label(p)
            colour = "k" if label == "-" else "C3"
            ax.plot(p["frequency_hz"], p["amplitude"], "o", ms=4, color=colour)
            ax.annotate(label, (p["frequency_hz"], p["amplitude"]), textcoords="offset points",
                        xytext=(2, 4), fontsize=7, rotation=60)
        band = ("no band-pass" if self.band is None
                else f"band {self.band[0]:.0f}-{self.band[1]:.0f} Hz")
        fault = self.likely_fault or "no fault found"
        ax.set_title(f"{self.frequencies.bearing.name or 'bearing'} at "
                     f"{self.frequencies.shaft_hz * 60:g} rpm, channel {self.channel or '-'}, "
                     f"{band}: {fault}")
        ax.set_xlabel("frequency [Hz]")
        ax.set_ylabel("envelope amplitude")
        ax.set_xlim(0, self.max_frequency)
        ax.set_ylim(0, 1.25 * top)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
        fig.tight_layout()
        if path is not None:
            try:
                save_figure(fig, path)  # closes the figure
            except Exception:
                plt.close(fig)
                raise
        return fig, ax


def peak_label(p: dict) -> str:
    """Short label of a labelled line: "2x bpfo", "1x bpfi -1 shaft" or "-" (no match).

    >>> peak_label({"matched": "bpfo", "harmonic": 2})
    '2x bpfo'
    """
    if p.get("matched"):
        return f"{p['harmonic']}x {p['matched']}"
    if p.get("sideband_of"):
        return (f"{p['sideband_harmonic']}x {p['sideband_of']} {p['sideband_order']:+d} "
                f"{p['modulation']}")
    return "-"


def _samples(signal_or_array, sample_rate, channel):
    """(samples, sample rate [Hz], channel name or None) from a Signal or an array."""
    if isinstance(signal_or_array, Signal):
        signal = signal_or_array
        if sample_rate is not None:
            try:
                fs = float(sample_rate)
            except (TypeError, ValueError):
                fs = math.nan
            if not math.isclose(fs, signal.sample_rate, rel_tol=1e-9):
                raise InputError("sample_rate", sample_rate,
                                 f"None or the record's own rate {signal.sample_rate:g} Hz")
        if channel is None:
            channel = next((c for c in PREFERRED_CHANNELS if c in signal.channels),
                           signal.names[0])
        return signal.channel(channel), signal.sample_rate, channel
    if channel is not None:
        raise InputError("channel", channel, "None for a bare array (name channels of a "
                         "Signal)")
    if sample_rate is None:
        raise InputError("sample_rate", None, "the sample rate in Hz of the array")
    from .signal.spectra import rate, samples

    return samples(signal_or_array, "signal_or_array"), rate(sample_rate), None


def _band(x, fs, band, fmax):
    """(band or None, KurtogramBand or None) for ``band`` = (lo, hi), "auto" or None."""
    if isinstance(band, str):
        if band != "auto":
            raise InputError("band", band, '(low, high) in Hz, "auto" or None')
        if x.size < 64:
            raise InputError("signal_or_array", f"{x.size} samples",
                             'at least 64 samples for band="auto" (a kurtogram)')
        # the widest band the kurtogram tries is f_s/8 (16-sample windows)
        min_bw = min(MIN_BAND_FACTOR * fmax, fs / 8.0)
        found = spectral_kurtosis_band(x, fs, min_bandwidth=min_bw)
        return found.band, found
    return band, None


def analyze_signal(signal_or_array, sample_rate, frequencies: DefectFrequencies, *,
                   channel: str | None = None, band="auto", count: int = COUNT,
                   slip_tolerance: float = 0.08, max_frequency: float | None = None,
                   tolerance: float = 0.02, harmonics: int = HARMONICS) -> Diagnosis:
    """Envelope analysis of a vibration record: lines, their labels, the likely fault.

    Steps (Randall & Antoni 2011; see the module docstring): choose the demodulation
    band (``"auto"``: the STFT kurtogram's band of largest spectral kurtosis, at least
    3 x the largest defect frequency wide so that the modulation sidebands pass, at most
    f_s/8); take the envelope spectrum over the whole record (resolution f_s/n = 1/T);
    pick the ``count`` largest lines up to ``max_frequency``
    (:func:`bearinglab.signal.find_peaks`); label them as harmonics n = 1..8 of the shaft
    and defect frequencies or as modulation sidebands, within a window of at least one
    bin of the spectrum (:func:`bearinglab.signal.match_peaks`); find the faults
    (:func:`bearinglab.signal.diagnose`): the primary one and every other one whose
    lines stand on their own (a compound fault).

    Parameters
    ----------
    signal_or_array : Signal or array_like
        The record; an array is one channel of samples (any unit, e.g. m/s^2 or g).
    sample_rate : float or None
        Sample rate [Hz]; required for an array; None (or the same rate) for a Signal.
    frequencies : DefectFrequencies
        Kinematic frequencies of the bearing at the record's speed
        (:func:`bearinglab.kinematics.defect_frequencies`).
    channel : str, optional
        Channel of a Signal; default ``acc_y`` (simulated records: the load direction) or
        ``DE`` (CWRU drive end) if present, else the first channel.
    band : (float, float) or "auto" or None
        Demodulation band (low, high) [Hz], ``"auto"`` or None (no band-pass).
    count : int
        Most envelope lines kept (24 by default: a strong fault's harmonics and
        sidebands fill a dozen, and a second fault's lines must still find room).
    slip_tolerance : float
        How far below n f_kin the line of a slip-affected frequency may sit [-, fraction];
        8 % by default after seed 004 (module docstring).
    max_frequency : float, optional
        Upper end of the line search [Hz]; default 5.5 x the largest defect frequency
        (ftf, bpfo, bpfi, bsf, ball defect, shaft), at most the Nyquist frequency.
    tolerance : float
        Relative match tolerance either side of n f_kin [-].
    harmonics : int
        Highest harmonic order n matched (8 by default: room for the BPFO harmonics
        below the default ``max_frequency``).

    Returns
    -------
    Diagnosis

    Examples
    --------
    >>> from bearinglab.catalog import bearing_from_designation
    >>> from bearinglab.kinematics import defect_frequencies
    >>> bearing, _ = bearing_from_designation("ER-16K")
    >>> kin = defect_frequencies(bearing, 1750 * math.pi / 30)
    >>> fs = 20000.0
    >>> t = np.arange(int(fs)) / fs                      # 1 s
    >>> since = t % (1.0 / kin.hz("bpfo"))               # time since the last impact [s]
    >>> x = np.exp(-since / 2e-3) * np.sin(2 * np.pi * 4e3 * t)  # ringing at 4 kHz
    >>> x = x + 0.2 * np.random.default_rng(0).standard_normal(t.size)
    >>> d = analyze_signal(x, fs, kin)
    >>> d.likely_fault, [peak_label(p) for p in d.peaks[:3]]
    ('outer race', ['1x bpfo', '2x bpfo', '3x bpfo'])
    """
    if not isinstance(frequencies, DefectFrequencies):
        raise InputError("frequencies", type(frequencies).__name__,
                         "bearinglab.kinematics.DefectFrequencies (defect_frequencies())")
    x, fs, channel = _samples(signal_or_array, sample_rate, channel)
    freqs = {name: frequencies.hz(name) for name in NAMES}
    fmax = max(freqs.values())
    nyquist = fs / 2.0
    if max_frequency is None:
        max_frequency = min(MAX_FREQUENCY_FACTOR * fmax, nyquist)
    else:
        try:
            max_frequency = float(max_frequency)
        except (TypeError, ValueError):
            max_frequency = math.nan
        if not 0.0 < max_frequency <= nyquist:
            raise InputError("max_frequency", max_frequency,
                             f"a frequency in (0, {nyquist:g}] Hz (Nyquist)")
    used_band, kurtogram = _band(x, fs, band, fmax)
    spectrum = envelope_spectrum(x, fs, band=used_band)
    peaks = find_peaks(spectrum, count=count, max_frequency=max_frequency)
    # the resolution widens the match window to a bin on short records (the FTF line)
    matched = match_peaks(peaks, freqs, harmonics=harmonics, tolerance=tolerance,
                          slip_tolerance=slip_tolerance, resolution=spectrum.resolution)
    return Diagnosis(spectrum=spectrum, band=spectrum.band, kurtogram=kurtogram,
                     peaks=tuple(matched),
                     diagnosis=diagnose(matched, tolerance=tolerance,
                                        resolution=spectrum.resolution),
                     frequencies=frequencies, sample_rate=fs, channel=channel,
                     max_frequency=max_frequency, slip_tolerance=float(slip_tolerance),
                     harmonics=int(harmonics),
                     ball_defect_frequency_hz=measured_ball_defect_frequency(matched))


def measured_ball_defect_frequency(matched_peaks) -> float | None:
    """Ball-defect frequency read off labelled envelope lines [Hz].

    The strongest line matched to ``ball_defect`` at harmonic 1; if there is none, half
    the strongest matched at harmonic 2; else None. Sidebands are not used.

    >>> measured_ball_defect_frequency([
    ...     {"frequency_hz": 270.0, "amplitude": 1.0, "matched": "ball_defect", "harmonic": 2}])
    135.0
    """
    for n in (1, 2):
        lines = [p for p in matched_peaks
                 if p.get("matched") == "ball_defect" and p.get("harmonic") == n]
        if lines:
            return float(max(lines, key=lambda p: p["amplitude"])["frequency_hz"]) / n
    return None


__all__ = ["Diagnosis", "analyze_signal", "measured_ball_defect_frequency", "peak_label"]
