"""The law of a frequency scan's best p-value: the chain bound on the union of its tests.

Layer 1 (NumPy and ``scipy.special``). A family's test scans its fundamental f' over the
family's tolerance window on a grid fine enough to move the top harmonic by half a bin,
and keeps the best of the Fisher tests of its lines (:mod:`.series`). The chance that
the best of them reaches t on a record without the fault is the probability of the union
of the events A_r = {test r reaches t}. Bonferroni bounds it by the number of distinct
tests times t, but consecutive fundamentals read nearly the same bins - one line moves to
the next bin, or comes in or out of reach - so their events nearly coincide, and the
count of distinct tests overstates the scan by a factor of 2 to 10.

The bound used here is the union bound along a spanning tree of the tests (Hunter D.,
"An upper bound for the probability of a union", J. Appl. Prob. 13 (1976) 597-603;
Worsley K. J., "An improved Bonferroni inequality and applications", Biometrika 69
(1982) 297-302), the tree being the chain of consecutive fundamentals - the discrete form
of Davies' bound by the expected number of up-crossings (Davies R. B., Biometrika 74
(1987) 33-43):

    P(union of A_r) <= P(A_0) + sum_r P(A_r and not A_(r-1)).

Each step between consecutive fundamentals is split into single-line steps (a union of
the intermediate tests only adds events, so the bound stays a bound), and each has a
closed form when the lines' p-values are independent and uniform (the null of
:mod:`.series`) and a line's reading is the largest of three bins:

- a line moves to the next bin (two of its three bins shared): with R ~ chi2(2L - 2) the
  other lines' Fisher statistic, x the level's critical value of chi2(2L) and
  q = e^(-y/2), P(Y_new >= y > Y_old) = (1 - (1 - q)^(1/3)) (1 - q) for independent bins,
  so that P = integral_0^x f_R(x - y) P(Y_new >= y > Y_old) dy (a correlation between
  neighbouring bins, as a Hann window gives, only lowers it);
- a line comes into reach or goes out of it (L - 1 <-> L lines):
  P = e^(-x_L / 2) (x_(L-1) / 2)^(L-1) / Gamma(L), the same both ways.

Measured on noise (tests/unit/test_diagnosis_chain.py, benchmarks/calibration_diagnosis.py):
for harmonics alone the bound is within 10-25 % of the scan's true law where the verdict's
level lies, Bonferroni 2-3 times above it; with two orders of sidebands and three nested
templates the bound is 2-3 times above the truth, Bonferroni 3-5 times.
"""

from __future__ import annotations

import math

import numpy as np

#: Below this ln p a chain is bounded by its count of tests (Bonferroni): far beyond any
#: level, and the quadrature of the moves' terms would underflow.
FAR = -600.0
#: Points of the quadrature of a move's term [-].
QUADRATURE_POINTS = 121
#: Its inner nodes on s in (0, 1) (the ends, where the integrand vanishes, left out) and
#: their spacing.
_NODES = np.linspace(0.0, 1.0, QUADRATURE_POINTS)[None, 1:-1]
_STEP = 1.0 / (QUADRATURE_POINTS - 1)


def _within(counts: np.ndarray) -> np.ndarray:
    """0, 1, .. c - 1 for each count c, concatenated."""
    counts = np.asarray(counts, int)
    return np.arange(int(counts.sum())) - np.repeat(np.cumsum(counts) - counts, counts)


def chain_steps(index: np.ndarray, use: np.ndarray) -> tuple[int, np.ndarray, np.ndarray]:
    """The tests of a scan as a chain, rows in the order of the fundamental.

    Parameters
    ----------
    index : numpy.ndarray of int
        (rows x lines) the bin each line reads at each fundamental.
    use : numpy.ndarray of bool
        (rows x lines) the lines each row's test combines.

    Returns
    -------
    (int, numpy.ndarray, numpy.ndarray)
        The number of lines of the first row; the number of lines L of the test in which
        each single-line move happens; and the larger of L - 1 and L for each line that
        comes in or goes out (a step's moves first, then the lines that go, then those
        that come).

    Examples
    --------
    >>> first, moves, pairs = chain_steps(np.array([[1, 4], [2, 4], [2, 5]]),
    ...                                   np.array([[True, True], [True, True], [True, False]]))
    >>> first, moves.tolist(), pairs.tolist()
    (2, [2], [2])
    """
    use = np.asarray(use, bool)
    lines = use.sum(axis=1)
    if lines.size < 2:
        return (int(lines[0]) if lines.size else 0), np.zeros(0, int), np.zeros(0, int)
    prev, cur = use[:-1], use[1:]
    moved = (prev & cur & (index[:-1] != index[1:])).sum(axis=1)
    gone = (prev & ~cur).sum(axis=1)
    come = (~prev & cur).sum(axis=1)
    old = lines[:-1]
    moves = np.repeat(old, moved)
    pairs = np.concatenate(
        [np.repeat(old, gone) - _within(gone), np.repeat(old - gone, come) + 1 + _within(come)]
    )
    return int(lines[0]), moves[moves >= 1], pairs[pairs >= 1]


def _chi2_isf(log_t, dof) -> np.ndarray:
    """The critical value x with P(chi2_dof > x) = e^log_t (``log_t`` a float, or one per
    ``dof``)."""
    import scipy.special

    if np.ndim(log_t):  # each level's e^log_t by math.exp, as for one level
        t = np.array([math.exp(v) for v in np.asarray(log_t, float).ravel()])
    else:
        t = math.exp(log_t)
    return np.asarray(scipy.special.chdtri(np.asarray(dof, float), t), float)


def log_move(log_t, lines) -> np.ndarray:
    """ln P(A_new and not A_old) when one of the L ``lines`` of a Fisher test at level
    e^``log_t`` (a float, or one per L) moves to the next bin (see the module docstring):
    the integral over y = x s^2 (points crowded where the line's term rises), all L at
    once."""
    import scipy.special

    lines = np.atleast_1d(np.asarray(lines, float))
    x = _chi2_isf(log_t, 2.0 * lines)[:, None]
    s = _NODES
    y = x * s * s
    q = np.exp(-y / 2.0)
    log_h = np.log(-np.expm1(np.log1p(-q) / 3.0)) + np.log1p(-q) + y / 2.0
    many = lines[:, None] >= 2
    f = np.where(many, (lines[:, None] - 2.0) * np.log(np.maximum(x - y, 1e-300)), 0.0)
    f = f + log_h + np.log(2.0 * x * s)  # dy = 2 x s ds
    peak = np.max(f, axis=1, keepdims=True)
    # the trapezoidal rule on the equally spaced nodes: h (sum - half the end values)
    g = np.exp(f - peak)
    area = _STEP * (g.sum(axis=1) - 0.5 * (g[:, 0] + g[:, -1]))
    integral = np.log(area) + peak[:, 0]
    out = (
        -x[:, 0] / 2.0
        - (lines - 1.0) * math.log(2.0)
        - scipy.special.gammaln(np.maximum(lines - 1.0, 1.0))
        + integral
    )
    # one line alone: its term is P(Y_new >= x > Y_old) itself
    q1 = np.exp(-x[:, 0] / 2.0)
    single = np.log(np.maximum(-np.expm1(np.log1p(-q1) / 3.0) * (1.0 - q1), 1e-300))
    return np.where(lines >= 2, out, single)


def log_pair(log_t, lines) -> np.ndarray:
    """ln P(A_L and not A_(L-1)) for Fisher tests of L ``lines`` and of L - 1 of them at
    level e^``log_t`` (a float, or one per L; = P(A_(L-1) and not A_L)):
    e^(-x_L/2) (x_(L-1)/2)^(L-1) / Gamma(L)."""
    import scipy.special

    lines = np.atleast_1d(np.asarray(lines, float))
    x_l = _chi2_isf(log_t, 2.0 * lines)
    x_m = np.where(lines > 1, _chi2_isf(log_t, np.maximum(2.0 * lines - 2.0, 1.0)), 2.0)
    return -x_l / 2.0 + (lines - 1.0) * np.log(x_m / 2.0) - scipy.special.gammaln(lines)


def chain_counts(index: np.ndarray, uses: np.ndarray) -> tuple[int, np.ndarray, np.ndarray]:
    """What :func:`chain_logp` needs of one or several scans over the same fundamentals, as
    counts: :func:`chain_steps` of each scan, its moves and pairs counted by their number
    of lines and summed over the scans (the chain bound is a sum over single-line steps:
    their order does not matter).

    Parameters
    ----------
    index : numpy.ndarray of int
        (rows x lines) the bin each line reads at each fundamental.
    uses : numpy.ndarray of bool
        (rows x lines) the lines one scan's test combines at each fundamental, or
        (scans x rows x lines) several scans' at once.

    Returns
    -------
    (int, numpy.ndarray, numpy.ndarray)
        The number of scans whose first row reads a line; the count of single-line moves
        at L lines and of lines coming in or going out with the larger count L, at
        position L (integer arrays).

    Examples
    --------
    >>> first, moves, pairs = chain_counts(np.array([[1, 4], [2, 4], [2, 5]]),
    ...                                    np.array([[True, True], [True, True], [True, False]]))
    >>> first, moves.tolist(), pairs.tolist()
    (1, [0, 0, 1, 0], [0, 0, 1, 0])
    """
    use = np.asarray(uses, bool)
    if use.ndim == 2:
        use = use[None]
    lines = use.sum(axis=2)  # scans x rows
    if lines.shape[1] == 0:
        return 0, np.zeros(1, int), np.zeros(1, int)
    firsts = int(np.count_nonzero(lines[:, 0] >= 1))
    size = int(lines.max()) + 2
    if lines.shape[1] < 2:
        return firsts, np.zeros(size, int), np.zeros(size, int)
    prev, cur = use[:, :-1], use[:, 1:]
    moved = (prev & cur & (index[:-1] != index[1:])[None]).sum(axis=2).ravel()
    gone = (prev & ~cur).sum(axis=2).ravel()
    come = (~prev & cur).sum(axis=2).ravel()
    old = lines[:, :-1].ravel()
    moves = np.bincount(np.repeat(old, moved), minlength=size)
    moves[0] = 0  # a test of no lines moves none
    # a step's lines that go count L, L - 1, .., L - gone + 1; those that come then count
    # L - gone + 1, .., L - gone + come: two runs of consecutive counts, summed as the
    # differences of their ends
    starts = np.concatenate([old - gone + 1, old - gone + 1])
    lengths = np.concatenate([gone, come])
    some = lengths > 0
    edges = np.bincount(starts[some], minlength=size + 1) - np.bincount(
        (starts + lengths)[some], minlength=size + 1
    )
    pairs = np.cumsum(edges)[:size]
    return firsts, moves, pairs


def _as_counts(chains) -> tuple[int, np.ndarray, np.ndarray]:
    """The steps of ``chains`` (each :func:`chain_steps`) as :func:`chain_counts`."""
    firsts = sum(1 for first, _, _ in chains if first >= 1)
    moves = np.concatenate([m for _, m, _ in chains]) if chains else np.zeros(0, int)
    pairs = np.concatenate([p for _, _, p in chains]) if chains else np.zeros(0, int)
    size = int(max(moves.max(initial=0), pairs.max(initial=0))) + 2
    return firsts, np.bincount(moves, minlength=size), np.bincount(pairs, minlength=size)


def chain_logp(log_t: float, chains) -> float:
    """ln of the chain bound on the chance that some test of the scans ``chains`` (each
    :func:`chain_steps`) reaches e^``log_t``, at most 0.

    >>> import math
    >>> steps = chain_steps(np.arange(10)[:, None], np.ones((10, 1), bool))
    >>> round(math.exp(chain_logp(math.log(1e-4), [steps])) / 1e-4, 2)  # 1 + 9 x ~1/3
    4.0
    """
    return chain_bounds([log_t], [_as_counts(chains)])[0]


def chain_bounds(log_ts, counts) -> list[float]:
    """:func:`chain_logp` of several levels at once, each of its scans given as counts
    (:func:`chain_counts`): the moves' and pairs' terms of all of them computed together,
    as they are one level at a time.

    Parameters
    ----------
    log_ts : sequence of float
        ln of each level.
    counts : sequence of tuple
        For each level, :func:`chain_counts` of its scans (summed over them).

    Returns
    -------
    list of float
        ln of each level's bound, at most 0.

    >>> import math
    >>> c = chain_counts(np.arange(10)[:, None], np.ones((10, 1), bool))
    >>> round(math.exp(chain_bounds([math.log(1e-4)], [c])[0]) / 1e-4, 2)
    4.0
    """
    out: list[float] = [0.0] * len(log_ts)
    work = []  # (query, level's ln, firsts, count, L of moves, their counts, L of pairs, ...)
    for q, (log_t, (firsts, moves, pairs)) in enumerate(zip(log_ts, counts, strict=True)):
        log_t = float(log_t)
        count = firsts + int(moves[1:].sum()) + int(pairs[1:].sum())
        if not log_t < 0.0 or count == 0:
            continue
        if log_t < FAR:
            out[q] = min(0.0, log_t + math.log(count))
            continue
        lm, lp = np.flatnonzero(moves[1:]) + 1, np.flatnonzero(pairs[1:]) + 1
        work.append((q, log_t, firsts, count, lm, moves[lm], lp, pairs[lp]))
    if not work:
        return out
    # every level's terms at once: one row per (level, L), the level's probability as
    # math.exp gives it (as one level at a time does)
    terms = {}
    for which, term, lines_at, counts_at in ((0, log_move, 4, 5), (1, log_pair, 6, 7)):
        rows = [w for w in work if w[lines_at].size]
        if rows:
            t = np.concatenate([np.full(w[lines_at].size, w[1]) for w in rows])
            values = term(t, np.concatenate([w[lines_at] for w in rows]))
            values = values + np.log(np.concatenate([w[counts_at] for w in rows]))
            ends = np.cumsum([w[lines_at].size for w in rows])
            for w, part in zip(rows, np.split(values, ends[:-1]), strict=True):
                terms[which, w[0]] = part
    for q, log_t, firsts, count, *_ in work:
        parts = [np.array([log_t + math.log(firsts)])] if firsts else []
        parts += [terms[k, q] for k in (0, 1) if (k, q) in terms]
        total = float(np.logaddexp.reduce(np.concatenate(parts)))
        out[q] = min(0.0, total, log_t + math.log(count))
    return out
