"""The noise floor of an envelope spectrum and its chi-square law: the scale on which the
diagnosis reads every line.

Layer 1 (NumPy and ``scipy.special``). The squared envelope spectrum (SES) is estimated by
Welch averaging (Hann segments, 50 % overlap). Where the signal holds no periodic
modulation - noise, or a healthy machine away from its discrete lines - the SES at a
non-zero frequency is the estimate of a spectral density, and its value in each bin
follows a scaled chi-square law with nu equivalent degrees of freedom (the spectral
correlation at cyclic frequency alpha != 0 of a stationary signal is zero, and its
estimate is asymptotically complex Gaussian: Antoni J., "Cyclic spectral analysis in
practice", MSSP 21 (2007) 597-630, sec. 4; Antoni J., "Cyclic spectral analysis of
rolling-element bearing signals: facts and fictions", JSV 304 (2007) 497-529). nu follows
from the window and the overlap (Percival D. B., Walden A. T., Spectral Analysis for
Physical Applications, Cambridge 1993, eq. 292b; Welch P. D., IEEE Trans. Audio
Electroacoust. 15 (1967) 70-73).

- :func:`welch_dof`: nu of a Welch average;
- :func:`normalised`: the noise floor, the running median of the SES over FLOOR_BINS bins
  turned into the mean of the chi-square law (median / mean = chi2.median(nu) / nu; a few
  lines barely move a median), and the SES over it; :func:`standardised`, the same on
  the chi2_nu / nu scale for a spectrum whose spread is not proportional to its level
  (the improved envelope spectrum);
- :func:`chi2_logsf`, :func:`bin_logp`: the chi-square tail as a logarithm, finite far
  into it (Abramowitz & Stegun 6.5.32); :func:`fisher_logp`: Fisher's combination of
  independent p-values (-2 sum ln p ~ chi2 with 2L degrees of freedom for L lines:
  Fisher R. A., Statistical Methods for Research Workers, 1932, sec. 21.1).

What is read on this scale: a line's p-value against the spectrum's own positions
(:mod:`.tail`) and a fault family's harmonic series (:mod:`.series`). Probabilities are
carried as logarithms (a strong series has p ~ 1e-1000).
"""

from __future__ import annotations

import math

import numpy as np

#: Bins of the running median that estimates the noise floor (odd): wide against the
#: lines (3 bins each) so that even a dense family (harmonics with two orders of
#: sidebands) covers less than half of it.
FLOOR_BINS = 61
#: Smallest p-value carried in the arithmetic (keeps logarithms finite).
TINY = 1e-300


def welch_dof(nperseg: int, noverlap: int, n: int, window: np.ndarray | None = None) -> float:
    """Equivalent degrees of freedom nu of a Welch average (Percival & Walden eq. 292b).

    nu = 2 K / (1 + 2 sum_{m=1}^{K-1} (1 - m/K) rho(m)^2), rho(m) = sum_t h_t h_{t+m D}
    the overlap correlation of the window normalised to sum_t h_t^2 = 1 with itself
    shifted by m hops D, K the segments (Hann at 50 % overlap: rho(1) = 1/6).

    >>> round(welch_dof(256, 0, 256), 6)                  # one segment: chi-square 2
    2.0
    >>> round(welch_dof(256, 128, 256 * 10), 2)           # 19 Hann segments, 50 % overlap
    36.1
    """
    if window is None:
        window = np.hanning(nperseg + 1)[:-1] if nperseg > 1 else np.ones(1)  # periodic Hann
    hop = max(nperseg - noverlap, 1)
    k = max(1 + (n - nperseg) // hop, 1)
    total = float(np.sum(window**2))
    rho = [
        float(np.sum(window[m * hop :] * window[: nperseg - m * hop])) / total
        if m * hop < nperseg
        else 0.0
        for m in range(1, k)
    ]
    correction = 1.0 + 2.0 * sum((1.0 - m / k) * r**2 for m, r in enumerate(rho, start=1))
    return 2.0 * k / correction


def normalised(power: np.ndarray, nu: float, floor_bins: int = FLOOR_BINS) -> np.ndarray:
    """Power over its local mean noise level, from a running median [-].

    The running median (``scipy.ndimage.median_filter``, reflected at the ends) of a
    scaled chi2_nu variable is scaled to its mean by nu / chi2.median(nu). The 0 Hz bin,
    which holds the record's mean, gets the value of its neighbour.
    """
    import scipy.ndimage
    import scipy.special

    p = np.asarray(power, dtype=float).copy()
    if p.size > 1:
        p[0] = p[1]
    size = min(floor_bins, p.size - (1 - p.size % 2))
    median = scipy.ndimage.median_filter(p, size=max(size, 1), mode="reflect")
    chi2_median = 2.0 * float(scipy.special.gammaincinv(nu / 2.0, 0.5))  # = chi2(nu).median()
    mean = median * nu / chi2_median
    tiny = 1e-300 + 1e-12 * float(np.max(mean)) if mean.size else 1e-300
    # divided by the median first: a bin that is its own window's median reads exactly
    # chi2_median / nu, so that such bins tie exactly whatever the round-off of the FFTs
    # before (a rank among them must not depend on the last bit of each bin's power)
    return p / np.maximum(median, tiny * chi2_median / nu) * (chi2_median / nu)


def standardised(power: np.ndarray, nu: float, floor_bins: int = FLOOR_BINS) -> np.ndarray:
    """Power standardised against its local median and spread, on the scale of a
    chi2_nu / nu variable [-]: z = 1 + sqrt(2 / nu) (P - m) / s, m the running median over
    ``floor_bins`` bins and s = 1.4826 x the running median of |P - m| (the spread a
    Gaussian's median absolute deviation estimates), floored at 0.

    For a spectrum whose spread is proportional to its level - a Welch estimate,
    chi-square - this orders the bins as :func:`normalised` does. The improved envelope
    spectrum averages a hundred spectral frequencies, so that its estimation noise is a
    few percent of its level, and what spreads it is the record's own weak cyclic
    content, more of it at some cyclic frequencies than at others (the low ones): its
    spread is not proportional to its level, and the ratio to the local median alone
    reads a bin of a busy stretch as a line (on CWRU 197 and 198, "cage" from FTF lines
    of z 1.1). Putting z on the chi2_nu / nu scale keeps the masks of discrete lines
    (:func:`bearinglab.diagnosis.verdict.leakage_halfwidth`) and the peaks' reading as
    they are for the Welch spectra of the other methods.
    """
    import scipy.ndimage

    p = np.asarray(power, dtype=float).copy()
    if p.size > 1:
        p[0] = p[1]
    size = max(min(floor_bins, p.size - (1 - p.size % 2)), 1)
    median = scipy.ndimage.median_filter(p, size=size, mode="reflect")
    spread = 1.4826 * scipy.ndimage.median_filter(np.abs(p - median), size=size, mode="reflect")
    tiny = 1e-300 + 1e-12 * float(np.max(np.abs(p))) if p.size else 1e-300
    z = 1.0 + math.sqrt(2.0 / nu) * (p - median) / np.maximum(spread, tiny)
    return np.maximum(z, 0.0)


def chi2_logsf(x, dof) -> np.ndarray:
    """ln P(chi2_dof > x), finite far into the tail.

    ln of the regularised upper incomplete gamma function Q(dof/2, x/2)
    (``scipy.special.chdtrc``, what ``scipy.stats.chi2.sf`` computes; scipy.stats is not
    imported, it costs ~0.5 s at start-up). It underflows to -inf beyond ~700 nats; there
    the leading term of the upper incomplete gamma function, Gamma(s, y) ~ y^(s-1) e^-y
    (s = dof/2, y = x/2; Abramowitz & Stegun 6.5.32), takes over.

    >>> float(np.round(chi2_logsf(4.0, 2), 12)), bool(np.isfinite(chi2_logsf(1e6, 20)))
    (-2.0, True)
    """
    import scipy.special

    x = np.asarray(x, dtype=float)
    dof = np.asarray(dof, dtype=float)
    with np.errstate(divide="ignore"):
        out = np.asarray(np.log(scipy.special.chdtrc(dof, x)), dtype=float)
    far = ~np.isfinite(out)
    if np.any(far):
        s, y = np.broadcast_to(dof / 2.0, x.shape)[far], x[far] / 2.0
        out = out.copy()
        out[far] = (s - 1.0) * np.log(y) - y - scipy.special.gammaln(s)
    return out


def decades(log_p: float) -> float:
    """-log10 p from ln p [-] (0.0, not -0.0, for p = 1).

    >>> round(decades(math.log(1e-3)), 12), decades(0.0)
    (3.0, 0.0)
    """
    return 0.0 - float(log_p) / math.log(10.0)


def bin_logp(z, nu: float) -> np.ndarray:
    """ln P(chi2_nu / nu > z): the chance that noise alone reaches z in one bin."""
    return chi2_logsf(np.asarray(z, dtype=float) * nu, nu)


def bin_pvalue(z, nu: float) -> np.ndarray:
    """P(chi2_nu / nu > z) [-] (may underflow to 0; see :func:`bin_logp`)."""
    return np.exp(bin_logp(z, nu))


def fisher_logp(logps, axis=-1):
    """ln of Fisher's combined p-value P(chi2_2L > -2 sum ln p) of L p-values."""
    logps = np.asarray(logps, dtype=float)
    return chi2_logsf(-2.0 * np.sum(logps, axis=axis), 2 * logps.shape[axis])
