"""The diagnosis' fast paths against the plain computations they replace (2026-11-28,
branch diag-speed2): the same numbers, to the bit where the arithmetic is the same.
Cost: well under a second."""

import math

import numpy as np
import pytest

from bearinglab.diagnosis.chain import (
    chain_bounds,
    chain_counts,
    chain_logp,
    chain_steps,
    log_move,
    log_pair,
)


def _scan(rng, rows=40, lines=12):
    """A scan's bins (rising with the fundamental, some lines moving at each row) and
    its readable lines (some coming in and going out)."""
    index = np.cumsum(rng.integers(0, 2, size=(rows, lines)), axis=0) + np.arange(lines) * 50
    use = rng.random((rows, lines)) < 0.8
    return index, use


def _plain_chain_logp(log_t, chains):
    """The chain bound as it was computed before the counts (one level, np.unique)."""
    firsts = sum(1 for first, _, _ in chains if first >= 1)
    moves = np.concatenate([m for _, m, _ in chains])
    pairs = np.concatenate([p for _, _, p in chains])
    count = firsts + moves.size + pairs.size
    if not log_t < 0.0 or count == 0:
        return 0.0
    terms = [log_t + math.log(firsts)] if firsts else []
    for values, term in ((moves, log_move), (pairs, log_pair)):
        if values.size:
            unique, counts = np.unique(values, return_counts=True)
            terms += list(term(log_t, unique) + np.log(counts))
    return min(0.0, float(np.logaddexp.reduce(np.array(terms))), log_t + math.log(count))


@pytest.mark.parametrize("seed", range(5))
def test_chain_counts_are_the_steps_counted(seed):
    rng = np.random.default_rng(seed)
    index, use = _scan(rng)
    uses = np.stack([use, use & (rng.random(use.shape) < 0.7), use[:, ::-1]])
    firsts, moves, pairs = chain_counts(index, uses)
    steps = [chain_steps(index, u) for u in uses]
    assert firsts == sum(1 for f, _, _ in steps if f >= 1)
    all_moves = np.concatenate([m for _, m, _ in steps])
    all_pairs = np.concatenate([p for _, _, p in steps])
    assert moves.tolist() == np.bincount(all_moves, minlength=moves.size).tolist()
    assert pairs.tolist() == np.bincount(all_pairs, minlength=pairs.size).tolist()


@pytest.mark.parametrize("seed", range(5))
def test_chain_bounds_together_equal_each_alone(seed):
    rng = np.random.default_rng(10 + seed)
    index, use = _scan(rng)
    scans = [np.stack([use, use & (rng.random(use.shape) < 0.5)]), use[:7], use & False]
    levels = [math.log(1e-3), math.log(10 ** -rng.uniform(2, 30)), math.log(0.2)]
    counts = [chain_counts(index[: s.shape[-2]], s) for s in scans]
    together = chain_bounds(levels, counts)
    for level, scan, bound in zip(levels, scans, together, strict=True):
        chains = [
            chain_steps(index[: s.shape[0]], s) for s in np.reshape(scan, (-1, *scan.shape[-2:]))
        ]
        assert bound == _plain_chain_logp(level, chains)  # to the bit
        assert bound == chain_logp(level, chains)
    # far beyond any level: the count of tests (Bonferroni)
    far = chain_bounds([-700.0], counts[:1])[0]
    assert far == pytest.approx(
        -700.0 + math.log(counts[0][0] + counts[0][1].sum() + counts[0][2].sum())
    )
