"""Significance of a harmonic series in an envelope spectrum, above its local noise floor.

Layer 1 (NumPy and ``scipy.stats``). The squared envelope spectrum (SES) is estimated by
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

The test of a fault family (outer race, inner race, ball, cage):
1. the noise floor is the running median of the SES over FLOOR_BINS bins, turned into
   the mean of the chi-square law (median / mean = chi2.median(nu) / nu); a few lines
   barely move a median;
2. a line expected at frequency f is read as the largest normalised value z over the
   bin nearest f and its two neighbours (the line's own width under a Hann window); its
   p-value is its rank among the same reading at every other position where a line may
   stand, from the lowest line of any family to the search limit (:func:`line_logp`: an
   empirical null, because the envelope spectrum of a real machine holds far more, and
   larger, lines than the chi-square law of noise allows - on the healthy CWRU record 97
   the chi-square p-values put some family beyond 1e-900);
3. the family's lines are its harmonics n f' (n = 1 .. N), the modulation sidebands
   n f' +- k f_m that the physics puts there, and the modulation's own lines k f_m (the
   sidebands of the 0th harmonic: an impact train whose amplitude varies at f_m has
   envelope lines at k f_m as well as around each harmonic - the envelope spectrum is
   the modulation's spectrum convolved with the train's, whose 0 Hz line is its mean;
   Randall & Antoni 2011, sec. 2); one fundamental f' = (1 + s) f_kin with one
   slip s for all of them (the cage has one mean speed over a record), scanned over the
   family's tolerance window on a grid fine enough to move the N-th harmonic by half a
   bin;
4. the lines' p-values are combined by Fisher's method (-2 sum ln p ~ chi2 with 2L
   degrees of freedom for L independent lines: Fisher R. A., Statistical Methods for
   Research Workers, 1932, sec. 21.1; a line whose three bins overlap an earlier line's
   is read once), the best fundamental is kept, and its p-value is
   multiplied by the number M of distinct line positions the scan tried (a Bonferroni
   bound on the search). The depth of modulation is not known beforehand (an outer-race
   defect under a fixed load is not modulated at all, the same defect under a rotating
   load or away from the load line is; Randall & Antoni 2011, sec. 2 and fig. 4), and
   Fisher's combination is diluted by lines that carry nothing: so the template is tested
   nested - harmonics alone, then with the sidebands up to order 1, 2, ... - and the best
   of the K templates is kept with its p-value multiplied by K too (Bonferroni over the
   templates; on 12 synthetic outer-race faults in the load zone at 0 dB, raw method,
   the +-1 x shaft template scored 10^-1.7 to 10^-7.9, the harmonics alone 10^-4.1 to
   10^-10.9: docs/capabilities/diagnosis.md);
5. the harmonics must be significant by themselves, at SUPPORT_ALPHA (sidebands support a
   series, they do not make one: a flexible template of harmonics and two orders of sidebands fits
   stray lines, e.g. BPFO as a ball line's second cage sideband; the modulation's own
   lines never count here, FTF lines alone are no ball fault) - for ball and inner-race
   faults alone or with their first sidebands, since the load zone modulates those
   defects deeply (:data:`bearinglab.diagnosis.families.GATE_ORDERS`), and for the outer
   race alone or with the first sidebands of the carriers that show (a defect away from
   the load line, or under a rotating load; its load is never negative, so that no
   sideband exceeds its carrier: ``gate_carriers``), by how much is
   not known beforehand: nested as the templates are, at the best fundamental whichever
   template won, the better of the two times 2 (Bonferroni; 1 where no sideband can be
   read, the two sets of lines then being one; CWRU 3005, ball, shows 1, 2, 3 x 2 BSF
   and nearly nothing beside them, and its harmonics with their sidebands fell short:
   docs/capabilities/diagnosis.md);
   and the series must
   not rest on one line: combined again without its strongest line, it must still
   reach SUPPORT_ALPHA (an isolated line is more often a discrete component
   of the machine than a bearing fault; Randall & Antoni 2011, sec. 2: a fault shows as
   a series of harmonics).

Probabilities are carried as logarithms (a strong series has p ~ 1e-1000). Under the
null hypothesis the family's p-value is thus an upper bound of its false-alarm
probability.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: Bins of the running median that estimates the noise floor (odd): wide against the
#: lines (3 bins each) so that even a dense family (harmonics with two orders of
#: sidebands) covers less than half of it.
FLOOR_BINS = 61
#: Bins read around each expected line (the nearest and its two neighbours).
LINE_BINS = 3
#: Level the family must still reach without its strongest line [-].
SUPPORT_ALPHA = 0.01
#: Level at which a single line shows: a line of an accepted family is listed at it, and
#: a carrier must reach it for its sidebands to count in a carrier-gated harmonic test [-].
LINE_ALPHA = 0.01
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
    return p / np.maximum(mean, tiny)


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


@dataclass(frozen=True)
class Line:
    """One line of a family as found: ``kind`` ("harmonic" or "sideband"), harmonic
    ``n`` (0 for the modulation's own lines k f_m), sideband order ``k`` (0 for a
    harmonic), ``expected_hz`` (on the fitted fundamental) and ``frequency_hz`` (bin of
    the largest value read) [Hz], normalised power ``z`` [-] and ``log_p`` (natural log
    of its p-value) [-]."""

    kind: str
    n: int
    k: int
    expected_hz: float
    frequency_hz: float
    z: float
    log_p: float

    @property
    def p_value(self) -> float:
        """p-value of the line [-]."""
        return math.exp(self.log_p)


@dataclass(frozen=True)
class SeriesTest:
    """Result of :func:`series_test` for one fault family.

    ``log_p`` (natural log of the p-value: Fisher's, times ``candidates`` and the number
    of nested templates), ``support_log_p`` (the same without the strongest line),
    ``harmonic_log_p`` (the harmonics alone or with their sidebands up to order
    ``gate_orders``, read at the best fundamental whichever template won, the better
    times the number of distinct sets of lines, and times the factors of
    ``log_p``), ``fundamental_hz`` (the best
    f') and ``slip`` (f'/f_kin - 1) [-], the ``lines`` read, and ``candidates`` (M).
    ``log_p`` is 0 (p = 1) when no line could be read (all masked or above the limit).
    """

    log_p: float
    support_log_p: float
    harmonic_log_p: float
    fundamental_hz: float
    slip: float
    lines: tuple[Line, ...]
    candidates: int

    @property
    def p_value(self) -> float:
        """p-value [-] (0.0 when it underflows; see ``significance``)."""
        return math.exp(self.log_p)

    @property
    def support_p_value(self) -> float:
        """p-value without the strongest line [-]."""
        return math.exp(self.support_log_p)

    @property
    def significance(self) -> float:
        """-log10 of the p-value [-] (10: one chance in 10^10 from noise alone)."""
        return decades(self.log_p)


def _distinct_rows(a: np.ndarray) -> int:
    """Number of distinct rows of the 2-D integer array ``a`` (each row seen as one
    value, so that NumPy's unique compares them at C speed)."""
    rows = np.ascontiguousarray(a).view(np.dtype((np.void, a.dtype.itemsize * a.shape[1])))
    return int(np.unique(rows).size)


def _window_max(z: np.ndarray, valid: np.ndarray):
    """Largest valid z over each bin and its neighbours, the number of valid bins there,
    and the offset (-1, 0, 1) of the largest (the first of equals)."""
    padded = np.pad(np.where(valid, z, -np.inf), 1, constant_values=-np.inf)
    left, mid, right = padded[:-2], padded[1:-1], padded[2:]
    largest = np.maximum(np.maximum(left, mid), right)
    count = np.isfinite(left).astype(int) + np.isfinite(mid) + np.isfinite(right)
    offset = np.where(left == largest, -1, np.where(mid == largest, 0, 1))
    return largest, count, offset


def series_test(
    z: np.ndarray,
    resolution: float,
    nu: float,
    fundamental: float,
    below: float,
    above: float,
    harmonics: int,
    max_frequency: float,
    modulation: float | None = None,
    orders: int = 0,
    valid: np.ndarray | None = None,
    gate_orders: int = 0,
    bottom: float = 0.0,
    gate_carriers: bool = False,
    decoys: tuple | None = None,
    tail: bool = False,
) -> SeriesTest:
    """Significance of the harmonic series n f' (n = 1..``harmonics``) with its sidebands
    n f' +- k ``modulation`` and the modulation's lines k ``modulation``
    (k = 1..``orders``), f' scanned over
    [(1 - below) f, (1 + above) f] (see the module docstring).

    Parameters
    ----------
    z : numpy.ndarray
        Normalised SES (:func:`normalised`), bin k at k x ``resolution`` [Hz].
    resolution : float
        Bin spacing [Hz].
    nu : float
        Degrees of freedom of the SES estimate.
    fundamental : float
        Kinematic fundamental f [Hz].
    below, above : float
        Tolerance window of the fundamental [-, fractions].
    harmonics : int
        Highest harmonic order read.
    max_frequency : float
        No line above this frequency is read [Hz].
    modulation : float, optional
        Modulating frequency of the sidebands [Hz].
    orders : int
        Sideband orders either side.
    valid : numpy.ndarray of bool, optional
        Bins that may be read (False: masked discrete lines or another fault's lines).
    gate_orders : int
        Deepest sideband order counted with the harmonics in ``harmonic_log_p`` (0:
        harmonics alone; 1: alone or with the first sidebands, the better).
    bottom : float
        Lowest frequency at which a line is sought [Hz]: the reference of each line's
        p-value starts there (:func:`line_logp`).
    gate_carriers : bool
        Count a sideband in ``harmonic_log_p`` only where its carrier (the harmonic it
        flanks) shows at LINE_ALPHA.
    decoys : (intervals, intervals), optional
        Calibrate the scan on the record itself (:func:`decoy_centres`,
        :func:`effective_trials`): the same template is scanned over windows of the same
        reach at decoy fundamentals whose windows avoid these intervals [Hz] (the fault
        families' windows, and the harmonics of the shaft, the supply and the mesh:
        what a bearing or machine line explains), and the number of effective
        trials fitted to their best p-values replaces the Bonferroni count. None: the
        Bonferroni count of distinct sets of lines times the templates (also when fewer
        than MIN_DECOYS decoys fit in the spectrum).
    tail : bool
        Read each line with the fitted tail beyond the empirical null
        (:func:`reference_logp`); False (default): the rank alone, floored at
        1 / positions, each candidate's own positions left out of its reference
        (:func:`line_rank_logp`).

    Returns
    -------
    SeriesTest
    """
    valid = np.ones(z.shape, bool) if valid is None else valid
    top = min(max_frequency, (z.size - 2) * resolution)
    # nothing above the limit is read, as a line or as reference: leave those bins out
    # (with a margin: lines beyond the limit are clipped to the last bins)
    keep = int(math.floor(top / resolution)) + 4 + OWN_BINS
    z, valid = z[:keep], valid[:keep]
    n_max = int(min(harmonics, math.floor(top / (fundamental * (1 + above)))))
    if n_max < 1:
        return SeriesTest(0.0, 0.0, 0.0, fundamental, 0.0, (), 0)
    step = resolution / (2.0 * n_max)
    grid = np.arange(fundamental * (1 - below), fundamental * (1 + above) + step / 2, step)
    # expected lines: (kind, n, k) rows, frequencies = n f' + k f_m
    spec = [("harmonic", n, 0) for n in range(1, n_max + 1)]
    if modulation and orders:
        spec += [
            ("sideband", n, s * k)
            for n in range(1, n_max + 1)
            for k in range(1, orders + 1)
            for s in (-1, 1)
        ]
        spec += [("sideband", 0, k) for k in range(1, orders + 1)]
    n_arr = np.array([r[1] for r in spec], float)
    k_arr = np.array([r[2] for r in spec], float)
    zmax, count, offset = _window_max(z, valid)
    table = line_logp(zmax, count, top / resolution, bottom / resolution, tail)
    live = count > 0
    index, readable, logp = _read(grid, n_arr, k_arr, modulation, top, resolution, live, table)
    values = zmax[index]
    if not tail:
        # the rank alone, each candidate's own positions left out of its reference (a
        # strong series, with its leakage, is not measured against itself)
        logp = np.where(
            readable,
            line_rank_logp(
                zmax,
                count,
                top / resolution,
                np.where(readable, values, 0.0),
                index,
                bottom / resolution,
            ),
            0.0,
        )
    if not np.any(readable):
        return SeriesTest(0.0, 0.0, 0.0, fundamental, 0.0, (), 0)
    # nested templates: harmonics alone, then with sidebands up to each order (the depth
    # of modulation is unknown: none for a fixed defect under a fixed load)
    depths = tuple(range(0, int(orders) + 1)) if (modulation and orders) else (0,)
    found = _best_row(logp, readable, k_arr, depths)
    if found is None:
        return SeriesTest(0.0, 0.0, 0.0, fundamental, 0.0, (), 0)
    raw_log_p, best, depth = found
    use = readable & (np.abs(k_arr) <= depth)[None, :]
    candidates = _distinct_rows(np.where(use, index, -1))
    raw_support, raw_harmonic, n_gates = _gates(
        logp[best], use[best], readable[best], n_arr, k_arr, gate_orders, gate_carriers
    )
    # the scan's multiple comparisons: the effective trials fitted to decoy scans of the
    # same spectrum, each statistic on its own decoys; else Bonferroni over the distinct
    # sets of lines x the templates (and x the gate's sets of lines)
    fitted = None
    if decoys is not None:
        fitted = _decoy_trials(
            decoys,
            fundamental,
            grid.size,
            n_max,
            harmonics,
            (below, above),
            (n_arr, k_arr, modulation, depths, gate_orders, gate_carriers),
            top,
            resolution,
            live,
            table,
        )
    if fitted is None:
        # the best template by its Bonferroni-corrected p-value (as before decoys)
        trials = []
        for d in depths:
            u = readable & (np.abs(k_arr) <= d)[None, :]
            if u.any():
                c = _fisher_rows(logp, u)
                r = int(np.argmin(c))
                m = _distinct_rows(np.where(u, index, -1))
                trials.append((float(c[r]) + math.log(m), float(c[r]), r, d, m))
        _, raw_log_p, best, depth, candidates = min(trials)
        use = readable & (np.abs(k_arr) <= depth)[None, :]
        raw_support, raw_harmonic, n_gates = _gates(
            logp[best],
            use[best],
            readable[best],
            n_arr,
            k_arr,
            gate_orders,
            gate_carriers,
            tippett=False,
        )
        # Bonferroni: the scan's distinct sets x the templates (x the gate's sets)
        log_m = math.log(candidates) + math.log(len(trials))
        log_p = min(0.0, raw_log_p + log_m)
        support = min(0.0, raw_support + log_m) if use[best].sum() > 1 else 0.0
        harmonic = min(0.0, raw_harmonic + log_m + math.log(n_gates)) if n_gates else 0.0
    else:
        log_p, support, harmonic = (
            decoy_logp(v, d)
            for v, d in zip((raw_log_p, raw_support, raw_harmonic), fitted, strict=True)
        )
    row = use[best]
    freq = grid[best] * n_arr + k_arr * (modulation or 0.0)
    lines = []
    for j in np.flatnonzero(row):
        kind, n, k = spec[j]
        i = int(index[best, j]) + int(offset[index[best, j]])
        lines.append(
            Line(
                kind,
                n,
                k,
                float(freq[j]),
                i * resolution,
                float(values[best, j]),
                float(logp[best, j]),
            )
        )
    f_best = float(grid[best])
    return SeriesTest(
        log_p, support, harmonic, f_best, f_best / fundamental - 1.0, tuple(lines), candidates
    )


def _best_row(logp, readable, k_arr, depths):
    """(ln p, row, depth) of the best fundamental of a scan and its best nested template
    (Fisher's combination over the readable lines of each), or None when nothing reads."""
    out = None
    for d in depths:
        use = readable & (np.abs(k_arr) <= d)[None, :]
        if not use.any():
            continue
        combined = _fisher_rows(logp, use)
        r = int(np.argmin(combined))
        if out is None or combined[r] < out[0]:
            out = (float(combined[r]), r, d)
    return out


def _gates(logp, use, readable, n_arr, k_arr, gate_orders, gate_carriers, tippett=True):
    """ln p of the support and the harmonic gate at one fundamental, before the scan's
    correction, and the number of sets of lines the harmonic gate tried.

    Support: the series without its strongest line, by Fisher's combination, or with
    ``tippett`` (the decoy-calibrated test) the better of it and the strongest remaining
    line (Tippett's, times the lines left), times 2:
    after a dominant line, a fault's series may show one more clear harmonic and nothing
    else readable (CWRU 222: 2 BSF at z 22.7, 4 BSF at z 5.8), which Fisher's combination
    dilutes in the lines that hold nothing. Harmonic gate: the harmonics alone, then with
    their sidebands up to ``gate_orders`` (nested as the templates are: the depth of
    modulation is unknown), the better; with ``gate_carriers`` a sideband counts only
    beside a carrier that shows at LINE_ALPHA."""
    lps = logp[use]
    support = 0.0
    if lps.size > 1:
        rest = np.delete(lps, int(np.argmin(lps)))
        support = float(fisher_logp(rest))
        if tippett:
            single = min(0.0, float(np.min(rest)) + math.log(rest.size))
            support = min(0.0, min(support, single) + math.log(2.0))
    own = readable & (n_arr >= 1)
    if gate_carriers:
        # a sideband counts only beside a carrier that shows: the load that modulates a
        # fixed defect's impacts is never negative, and the Fourier coefficients of a
        # non-negative function are at most its mean (|c_k| <= c_0), so no sideband of a
        # real series stands without its carrier (stray lines at n f +- k f_m do)
        shown = n_arr[own & (k_arr == 0) & (logp < math.log(LINE_ALPHA))]
        own &= (k_arr == 0) | np.isin(n_arr, shown)
    sets = {tuple(np.flatnonzero(own & (np.abs(k_arr) <= d))) for d in range(int(gate_orders) + 1)}
    sets = [float(fisher_logp(logp[list(g)])) for g in sets if g]
    return support, (min(sets) if sets else 0.0), len(sets)


def decoy_logp(log_p: float, decoys: np.ndarray) -> float:
    """ln p of a scan's statistic ``log_p`` against the same statistic of its decoy scans
    ``decoys`` (ln p each): the larger of their empirical fraction at least as extreme,
    (1 + #decoys <= log_p) / (1 + #decoys) - exact where the family's window is no
    different from a decoy's - and the law fitted to their lower half
    (:func:`effective_trials`); beyond every decoy, that law alone."""
    decoys = np.asarray(decoys, dtype=float)
    fitted = _scan_logp(log_p, *effective_trials(decoys))
    reached = int(np.sum(decoys <= log_p))
    if reached == 0:  # beyond every decoy: the fitted law alone
        return fitted
    return max(math.log((1.0 + reached) / (1.0 + decoys.size)), fitted)


def _scan_logp(log_p: float, log_m: float, beta: float = 1.0) -> float:
    """ln of the chance that the best of a scan's trials reaches e^log_p, for a scan whose
    best p-value follows P(min <= t) = e^log_m t^beta (beta = 1: M = e^log_m trials,
    1 - (1 - p)^M; :func:`effective_trials`), at most 0."""
    if beta == 1.0:
        p = math.exp(log_p)
        if p < 1e-12 or not math.isfinite(log_p):
            return min(0.0, log_p + log_m)
        m = math.exp(log_m)
        return min(0.0, math.log(-math.expm1(m * math.log1p(-min(p, 1 - 1e-16)))))
    return min(0.0, log_m + beta * log_p)


def _read(grid, n_arr, k_arr, modulation, top, resolution, live, table):
    """Bins, readability and ln p of the template's lines (n f' + k f_m) at each
    fundamental of ``grid`` (rows): a line is read where a valid bin lies within one bin
    of it, below ``top`` [Hz], and once (a line whose three bins overlap an earlier line's
    is not read again: Fisher's combination needs independent lines)."""
    freq = grid[:, None] * n_arr[None, :] + k_arr[None, :] * (modulation or 0.0)
    index = np.rint(freq / resolution).astype(int)
    size = live.size
    inside = (freq > 0.5 * resolution) & (freq <= top) & (index >= 1) & (index < size - 1)
    index = np.clip(index, 1, size - 2)
    readable = inside & live[index]
    # (BPFO of a 6203 is 3.053 x shaft: n BPFO + 2 shaft and (n + 1) BPFO - shaft fall in
    # one bin, and white noise then passed the outer race's test 7 x too often)
    # only pairs of lines that come within LINE_BINS of each other somewhere on the grid
    # (their distance is linear in f': its smallest modulus over the grid's range)
    dn = n_arr[None, :] - n_arr[:, None]
    dk = (k_arr[None, :] - k_arr[:, None]) * (modulation or 0.0)
    lo, hi = dn * float(np.min(grid)) + dk, dn * float(np.max(grid)) + dk
    near = np.where(lo * hi <= 0, 0.0, np.minimum(np.abs(lo), np.abs(hi)))
    first, later = np.nonzero(np.triu(near < (LINE_BINS + 1) * resolution, k=1))
    if first.size:
        hit = (np.abs(index[:, first] - index[:, later]) < LINE_BINS) & readable[:, first]
        blocked = np.zeros(readable.shape, bool)
        for j in np.unique(later):
            blocked[:, j] = np.any(hit[:, later == j], axis=1)
        readable &= ~blocked
    logp = np.where(readable, table[index], 0.0)
    return index, readable, logp


#: Fewest decoy windows for a fitted count of effective trials; with fewer the scan is
#: bounded by Bonferroni [-].
MIN_DECOYS = 12
#: Decoy fundamentals farther than this factor from the family's are not used [-]: the
#: template keeps its number of harmonics near its own.
DECOY_SPAN = 3.0
#: Spacing of the decoy windows, as a fraction of their width [-] (below 1 they overlap,
#: as the trials of one scan do; the fitted count is then the same, with more decoys).
DECOY_STEP = 0.5
#: Most decoys per family (evenly chosen among those that fit) [-].
MAX_DECOYS = 48


def decoy_centres(
    fundamental: float,
    width: float,
    harmonics: int,
    top: float,
    families,
    lines,
    lowest: float,
) -> list[float]:
    """Decoy fundamentals [Hz] for a family scanned over ``width`` [Hz] at ``fundamental``
    with up to ``harmonics`` harmonics below ``top``: windows whose reach at their highest
    harmonic equals the family's (the same number of distinct sets of lines), spaced by
    DECOY_STEP of their width, from ``lowest`` [Hz] up to ``top`` / 2 (two harmonics) and
    within DECOY_SPAN of the family's fundamental; none touches an interval of
    ``families`` ((low, high) [Hz]: the fault families' windows), and none is centred in
    one of ``lines`` (the harmonics of the shaft, supply and mesh frequencies, whose lines
    are masked: a decoy there reads little). The family's own lines are not read by its
    decoys (:func:`series_test`); another family's may be, which only makes the test of
    this one more cautious."""
    n_family = max(1, min(harmonics, int(top / (fundamental + width / 2))))
    reach = width * n_family  # how far the highest harmonic moves over the scan [Hz]
    lo = max(lowest, fundamental / DECOY_SPAN)
    hi = min(top / 2.0, fundamental * DECOY_SPAN)
    out, c = [], lo
    while c < hi:
        n = max(1, min(harmonics, int(top / c)))
        half = 0.5 * reach / n
        c0 = c + half
        clear = all(c0 + half < a or c0 - half > b for a, b in families) and all(
            not a <= c0 <= b for a, b in lines
        )
        if clear and n >= 2:
            out.append(c0)
        c = c0 - half + 2 * half * DECOY_STEP
    return out


def effective_trials(decoy_log_p) -> tuple[float, float]:
    """The law of a scan's best p-value fitted to the best ln p of each decoy scan:
    P(min <= t) = A t^beta for small t, returned as (ln A, beta) [-].

    For M independent trials the best p-value is the smallest of M uniform ones,
    P(min <= t) = 1 - (1 - t)^M ~ M t (beta = 1, A = M, a Bonferroni count of effective
    trials). The trials of a scan overlap, and then the count is not one number: it
    grows as t falls (a Monte Carlo count for CWRU 222's ball scan gave 75, 103 and 146
    effective trials at t = 0.05, 0.01 and 0.001: docs/capabilities/diagnosis.md), so
    that a count fitted to the whole of the decoys' law would be too small where the
    verdict's level lies. The law is fitted to the lower half of the decoys' empirical
    distribution (rank i of n at p_(i): ln(i / (n + 1)) = ln A + beta ln p_(i), least
    squares), beta held in [BETA_MIN, 1] and A at least 1, so that it extrapolates no
    faster than the trend of the decoys' own tail. A line statistic whose tail is too
    light or too heavy for the record shows in A and beta too: the law is the record's.

    The minimum of 50 uniform p-values (the decoys of a scan of 50 independent trials):
    the lower half's fit gives about 30 trials and beta 0.9.

    >>> la, b = effective_trials(np.log(np.random.default_rng(0).beta(1, 50, 4000)))
    >>> round(math.exp(la) / 50, 1), round(b, 1)
    (0.6, 0.9)
    """
    lp = np.sort(np.asarray(decoy_log_p, dtype=float))
    n = lp.size
    half = max(n // 2, 3)
    x = lp[:half]
    y = np.log(np.arange(1, half + 1) / (n + 1.0))
    if np.ptp(x) > 0:
        beta = float(np.polyfit(x, y, 1)[0])
    else:
        beta = 1.0
    beta = min(1.0, max(BETA_MIN, beta))
    log_a = max(0.0, float(np.mean(y - beta * x)))
    return log_a, beta


#: Smallest slope of the fitted law of a scan's best p-value [-] (see
#: :func:`effective_trials`).
BETA_MIN = 0.8


def _decoy_trials(
    excluded, fundamental, points, n_max, harmonics, window, template, top, resolution, live, table
):
    """Effective trials (M_p, M_support, M_harmonic) of the family's scan and its two
    gates, each fitted to the same statistic of decoy scans (:func:`effective_trials`),
    or None when fewer than MIN_DECOYS decoys fit (see :func:`series_test`)."""
    below, above = window
    n_arr, k_arr, modulation, depths, gate_orders, gate_carriers = template
    width = fundamental * (below + above)
    own = [(fundamental * (1 - below), fundamental * (1 + above))]
    fams, lines = excluded
    centres = decoy_centres(fundamental, width, harmonics, top, list(fams) + own, lines, 0.0)
    if len(centres) < MIN_DECOYS:
        return None
    if len(centres) > MAX_DECOYS:
        centres = [centres[i] for i in np.linspace(0, len(centres) - 1, MAX_DECOYS).astype(int)]
    # the family's own lines (its harmonics over its window) are not read by a decoy
    free = live.copy()
    for n in range(1, n_max + 1):
        lo = int(math.floor(n * fundamental * (1 - below) / resolution)) - 1
        hi = int(math.ceil(n * fundamental * (1 + above) / resolution)) + 2
        free[max(lo, 0) : max(hi, 0)] = False
    # every decoy's scan in one array: rows = decoys x grid points; harmonics above a
    # decoy's own count (its reach equals the family's) are not read
    c = np.asarray(centres)
    n_d = np.maximum(1, np.minimum(harmonics, (top / c).astype(int)))
    offsets = np.arange(points) - 0.5 * (points - 1)
    grid = (c[:, None] + offsets[None, :] * (resolution / (2.0 * n_d))[:, None]).ravel()
    _, readable, logp = _read(grid, n_arr, k_arr, modulation, top, resolution, free, table)
    readable &= n_arr[None, :] <= np.repeat(n_d, points)[:, None]
    logp = np.where(readable, logp, 0.0)
    rows = readable.reshape(c.size, points, -1)
    enough = (rows[:, :, n_arr >= 1].sum(axis=2) >= 2).any(axis=1)
    best = np.full(c.size, np.inf)
    row_of = np.zeros(c.size, int)
    depth_of = np.zeros(c.size, int)
    for d in depths:
        use = readable & (np.abs(k_arr) <= d)[None, :]
        combined = _fisher_rows(logp, use).reshape(c.size, points)
        r = np.argmin(combined, axis=1)
        v = combined[np.arange(c.size), r]
        better = v < best
        best = np.where(better, v, best)
        row_of = np.where(better, r, row_of)
        depth_of = np.where(better, d, depth_of)
    stats = []
    for j in np.flatnonzero(enough & np.isfinite(best)):
        r = j * points + row_of[j]
        use = readable[r] & (np.abs(k_arr) <= depth_of[j])
        sup, har, _ = _gates(logp[r], use, readable[r], n_arr, k_arr, gate_orders, gate_carriers)
        stats.append((float(best[j]), sup, har))
    if len(stats) < MIN_DECOYS:
        return None
    return tuple(np.array(column) for column in zip(*stats, strict=True))


#: Bins either side of each of a family's own lines kept beyond the search limit [-].
OWN_BINS = 2


def line_logp(
    zmax: np.ndarray,
    count: np.ndarray,
    top_bin: float,
    bottom_bin: float = 1.0,
    tail: bool = True,
) -> np.ndarray:
    """ln p of the reading ``zmax`` (largest z over three bins) at every bin, against the
    same reading at every valid position of the spectrum from ``bottom_bin`` (at least 1)
    to ``top_bin`` (:func:`reference_logp`, its rank alone unless ``tail``); 0 where no
    bin is valid.

    The reference starts where a line may be sought (the analysis passes the lowest
    line of any family, about 0.98 FTF): below it the positions read the main lobe and
    first side lobes of the 0 Hz line (the envelope's mean, the largest value of every
    envelope spectrum), a place no bearing line can stand and which would otherwise
    count against every line of the record.
    """
    stop = int(min(top_bin, zmax.size - 1))
    start = int(min(max(math.floor(bottom_bin), 1), stop))
    live = count[start : stop + 1] > 0
    ref = zmax[start : stop + 1][live]
    out = np.zeros(zmax.size)
    ok = count > 0
    out[ok] = reference_logp(ref, zmax[ok], tail)
    return out


def line_rank_logp(
    zmax: np.ndarray,
    count: np.ndarray,
    top_bin: float,
    values,
    index: np.ndarray,
    bottom_bin: float = 1.0,
) -> np.ndarray:
    """ln p (the rank alone, floored at 1 / positions: ``tail=False``) of lines read as
    ``values`` (largest z over three bins, one row per candidate
    fundamental, at bins ``index``) against the same reading at every other valid
    position of the spectrum from ``bottom_bin`` (at least 1) to ``top_bin``: the
    empirical null (1 + #positions reading at least as much) / (1 + #positions).

    The reference starts where a line may be sought (the analysis passes the lowest
    line of any family, about 0.98 FTF): below it the positions read the main lobe and
    first side lobes of the 0 Hz line (the envelope's mean, the largest value of every
    envelope spectrum), a place no bearing line can stand and which would otherwise
    count against every line of the record.

    The spectrum's own bins are the reference, clutter of unrelated discrete lines
    included: a real machine's envelope spectrum holds many more, and larger, lines than
    the chi-square law of noise allows, and a family must stand out of what this record
    shows elsewhere, not out of an idealised floor. The positions within OWN_BINS of the
    candidate's own lines are left out of its reference, so that a strong series is not
    measured against itself. Exact under the null that the family's line positions are
    no different from any others (exchangeable bins).
    """
    stop = int(min(top_bin, zmax.size - 1))
    start = int(min(max(math.floor(bottom_bin), 1), stop))
    live = count[start : stop + 1] > 0
    ref = np.sort(zmax[start : stop + 1][live])
    values = np.asarray(values, dtype=float)
    above = ref.size - np.searchsorted(ref, values, side="left")
    # the candidate's own positions (deduplicated), and how many of them reach each value
    own = (index[:, :, None] + np.arange(-OWN_BINS, OWN_BINS + 1)).reshape(index.shape[0], -1)
    own = np.sort(own, axis=1)
    fresh = np.ones(own.shape, bool)
    fresh[:, 1:] = own[:, 1:] != own[:, :-1]
    inside = fresh & (own >= start) & (own <= stop)
    own_z = np.where(inside, zmax[np.clip(own, 0, zmax.size - 1)], -np.inf)
    own_live = inside & np.isfinite(own_z)
    own_above = np.sum(own_z[:, None, :] >= values[:, :, None], axis=2)
    n_ref = ref.size - own_live.sum(axis=1)
    return np.log((1.0 + np.maximum(above - own_above, 0)) / (1.0 + np.maximum(n_ref, 0))[:, None])


#: Reference positions beyond the tail's threshold: the largest TAIL_FRACTION of them; the
#: tail is fitted when that is at least TAIL_MIN positions, else the rank alone [-].
TAIL_FRACTION = 0.05
TAIL_MIN = 10


def reference_logp(reference: np.ndarray, values, tail: bool = True) -> np.ndarray:
    """ln p of ``values`` against the readings ``reference`` of the same spectrum at the
    positions where a line may stand: semi-parametric, an empirical null in the body and
    an exponential law fitted to the tail.

    - Up to the k-th largest reading u (k = TAIL_FRACTION of the positions, at least
      TAIL_MIN): the rank, (1 + #positions reading at least as much) / (1 + #positions)
      - exact under the null that a line's position is no different from any other
      (exchangeable positions), whatever the record's clutter of unrelated lines: a real
      machine's envelope spectrum holds far more, and larger, lines than the chi-square
      law of noise allows (on the healthy CWRU record 97 it put some family at 1e-900).
    - Beyond u: p = (1 + k) / (1 + N) exp(-(v - u) / sigma), the exceedances of the top
      k readings over u taken as exponential (the peaks-over-threshold model with shape 0:
      Knijnenburg T. A. et al., Bioinformatics 25 (2009) i161-i168; the chi2_nu / nu law
      of a Welch bin has an exponential tail, and the largest of three bins too), sigma
      from the upper body, (u - u_4k) / ln 4 with u_4k the 4k-th largest reading: the
      few strong lines of a fault, which may make the whole top k, do not move it.
      The rank alone floors at 1 / (1 + N) (10^-2.7 for the ~500 positions of a 6205
      record): a line 20 times the floor scored the same as one at 4.

    On a record whose tail is heavier than exponential (discrete lines of other origin)
    this makes single lines too significant; the scan's count of effective trials, fitted
    to decoy scans of the same spectrum (:func:`effective_trials`), carries that.

    >>> ref = np.random.default_rng(0).exponential(1.0, 2000)
    >>> lp = reference_logp(ref, np.array([0.0, 20.0]))
    >>> round(float(lp[0]), 6), -8.7 < float(lp[1]) / 20 < -0.9
    (0.0, True)
    """
    ref = np.sort(np.asarray(reference, dtype=float))
    values = np.asarray(values, dtype=float)
    n = ref.size
    if n == 0:
        return np.zeros(values.shape)
    above = n - np.searchsorted(ref, values, side="left")
    body = np.log((1.0 + above) / (1.0 + n))
    k = int(math.ceil(TAIL_FRACTION * n))
    if k < TAIL_MIN or not tail:
        return body
    u = ref[n - k - 1]
    # the exponential's scale from the upper body, between the top 4k and the top k
    # readings: a fault's own lines (a few per cent of the positions) do not move it
    sigma = float(u - ref[n - 4 * k - 1]) / math.log(4.0)
    if not sigma > 0:
        return body
    tail = math.log((1.0 + k) / (1.0 + n)) - (values - u) / sigma
    return np.where(values > u, np.minimum(tail, 0.0), body)


def _fisher_rows(logp: np.ndarray, readable: np.ndarray) -> np.ndarray:
    """ln of Fisher's combination, row by row, over the readable entries only."""
    lines = readable.sum(axis=1)
    out = np.zeros(logp.shape[0])
    live = lines > 0
    statistic = -2.0 * np.where(readable, logp, 0.0)[live].sum(axis=1)
    out[live] = chi2_logsf(statistic, 2 * lines[live])
    return out
