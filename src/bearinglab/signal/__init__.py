"""Signal analysis for bearing diagnostics: records and their files, spectra, envelope
analysis with a spectral-kurtosis band, peak matching to defect frequencies, coherence,
and cyclic spectral analysis (:mod:`.cyclic`: the fast spectral correlation and the
improved envelope spectrum).

Sources are cited in each module: Randall & Antoni 2011 (envelope analysis), Antoni 2006
and 2007 (spectral kurtosis, kurtogram), Antoni, Xin & Hamzaoui 2017 and Mauricio et al.
2020 (cyclic spectral analysis), SciPy (scipy.signal, scipy.io) and numpy.fft.
"""

from .bands import ISO15242_BANDS, VelocityBands, iso15242_bands, velocity_bands
from .coherence import Coherence, coherence
from .io import SUFFIXES, read_signal, write_signal
from .peaks import find_peaks, match_peaks, peak_label
from .record import Signal
from .spectra import (
    EnvelopeSpectrum,
    KurtogramBand,
    Spectrum,
    amplitude_spectrum,
    envelope,
    envelope_spectrum,
    spectral_kurtosis,
    spectral_kurtosis_band,
)

__all__ = [
    "ISO15242_BANDS",
    "SUFFIXES",
    "Coherence",
    "EnvelopeSpectrum",
    "KurtogramBand",
    "Signal",
    "Spectrum",
    "VelocityBands",
    "amplitude_spectrum",
    "coherence",
    "envelope",
    "envelope_spectrum",
    "find_peaks",
    "iso15242_bands",
    "match_peaks",
    "peak_label",
    "read_signal",
    "spectral_kurtosis",
    "spectral_kurtosis_band",
    "velocity_bands",
    "write_signal",
]
