"""Coherence and cross-spectral phase between two channels.

Layer 1: ``scipy.signal.coherence`` (magnitude-squared coherence
gamma^2(f) = |P_xy|^2 / (P_xx P_yy), Welch-averaged) and ``scipy.signal.csd`` (the phase of
P_xy = <conj(X) Y>). Seed 000 (Balmont & Varlamov 1986) used the coherence and phase
between two accelerometers on the bearing housing to tell the outer ring's modes apart;
Bendat J. S., Piersol A. G., *Random Data*, 4th ed., Wiley 2010, ch. 9, give the estimators
and why they need averaging (one segment gives gamma^2 = 1 at every frequency).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..errors import InputError
from .spectra import check_window, overlapping, rate, samples, segment


class Coherence(NamedTuple):
    """``frequency`` [Hz], magnitude-squared ``coherence`` [-, 0..1] and ``phase_deg``, the
    phase of y relative to x [deg, (-180, 180]; negative when y lags x]."""

    frequency: np.ndarray
    coherence: np.ndarray
    phase_deg: np.ndarray


def coherence(x, y, sample_rate, segment_length=None, overlap=0.5, window="hann") -> Coherence:
    """Coherence and cross-spectral phase of ``y`` relative to ``x``.

    Parameters
    ----------
    x, y : array_like
        Equal-length 1-D records (any units), sampled together.
    sample_rate : float
        Sample rate [Hz].
    segment_length : int, optional
        Samples per segment; default the largest power of two <= n/8 (at least 16), so
        that ~15 half-overlapping segments are averaged.
    overlap : float
        Fraction of a segment shared with the next one, in [0, 1).
    window : str or tuple
        Any window ``scipy.signal.get_window`` accepts.

    Returns
    -------
    Coherence
        ``frequency`` [Hz], ``coherence`` [-], ``phase_deg`` [deg]. A copy of x delayed
        by tau has phase -360 f tau (wrapped).

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> x = rng.standard_normal(4096)
    >>> c = coherence(x, 2.0 * x, 1000.0)
    >>> bool(np.allclose(c.coherence, 1.0)), bool(np.allclose(c.phase_deg, 0.0))
    (True, True)
    """
    import scipy.signal  # imported here: it costs ~0.5 s at start-up

    x = samples(x, "x")
    y = samples(y, "y")
    if y.size != x.size:
        raise InputError("y", f"{y.size} samples", f"{x.size} samples, as x")
    fs = rate(sample_rate)
    default = max(16, 2 ** int(np.floor(np.log2(max(x.size // 8, 1)))))
    nperseg = segment(segment_length, x.size, default=min(default, x.size))
    noverlap = overlapping(overlap, nperseg)
    check_window(window, nperseg)
    options = {"fs": fs, "window": window, "nperseg": nperseg, "noverlap": noverlap}
    frequency, gamma2 = scipy.signal.coherence(x, y, **options)
    _, pxy = scipy.signal.csd(x, y, **options)
    return Coherence(frequency, gamma2, np.degrees(np.angle(pxy)))
