"""The lines of a plain spectrum matched to a bearing's kinematic frequencies.

The same matching as the envelope analysis (:func:`bearinglab.signal.find_peaks` and
:func:`bearinglab.signal.match_peaks`, after Randall & Antoni 2011), applied to the plain
spectrum: the form-error lines of a simulated displacement (seed 003 part 4 selection
rules) and the ball-pass lines of a sound pressure (seed 002) are read this way.
"""

from __future__ import annotations

from .peaks import NAMES, find_peaks, match_peaks
from .spectra import amplitude_spectrum

#: Lines listed and harmonics matched by default (those of the envelope analysis).
COUNT = 24
HARMONICS = 8


def spectrum_lines(
    x,
    sample_rate: float,
    kin,
    max_frequency: float,
    *,
    count: int = COUNT,
    harmonics: int = HARMONICS,
    prominence: float = 4.0,
    slip_tolerance: float = 0.08,
):
    """The plain (Hann, whole-record) amplitude spectrum of ``x`` and its largest lines up
    to ``max_frequency`` matched to the shaft and defect frequencies of ``kin``.

    Parameters
    ----------
    x : array_like
        The record [any unit].
    sample_rate : float
        Its sample rate [Hz].
    kin : DefectFrequencies
        The kinematic frequencies to match (:func:`bearinglab.kinematics.defect_frequencies`).
    max_frequency : float
        Highest frequency searched [Hz].
    count, harmonics : int
        Lines kept, harmonics matched [-].
    prominence : float
        Least height of a line above its neighbourhood, as a ratio [-].
    slip_tolerance : float
        Relative window of a match [-] (at least one bin wide).

    Returns
    -------
    (Spectrum, list of dict)
        The spectrum and its labelled lines.
    """
    spec = amplitude_spectrum(x, sample_rate)
    lines = find_peaks(spec, count=count, max_frequency=max_frequency, prominence=prominence)
    matched = match_peaks(
        lines,
        {name: kin.hz(name) for name in NAMES},
        harmonics=harmonics,
        slip_tolerance=slip_tolerance,
        resolution=spec.resolution,
    )
    return spec, matched


#: The keys a labelled line carries in JSON.
LINE_KEYS = (
    "frequency_hz",
    "amplitude",
    "matched",
    "harmonic",
    "deviation",
    "sideband_of",
    "sideband_harmonic",
    "sideband_order",
    "modulation",
)


def lines_to_dict(lines) -> list[dict]:
    """Labelled lines (:func:`bearinglab.signal.match_peaks`) in their JSON form: frequency,
    amplitude, the family matched, harmonic, deviation and sideband keys."""
    return [{k: p[k] for k in LINE_KEYS if k in p} for p in lines]
