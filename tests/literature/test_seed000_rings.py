"""Seed 000 (Balmont & Varlamov 1986): outer-ring natural frequencies of loaded bearings.

The published numbers (the closing table, the text's values, the epsilon roots of sec. 3,
the computed free-ring frequencies), each with its tolerance and the reason for it, and
the five known non-reproductions with theirs, live in
:mod:`bearinglab.validation.seed000` and run in tests/literature/test_published_cases.py
(and in ``bearinglab validate``). This file checks what is not a single published number:
that every table cell has a case, how the tolerances are built, and the consistency of
the printed epsilon pairs.
"""

import pytest

from bearinglab.validation import all_cases, seed000


def _case(quantity_start: str):
    found = [c for c in seed000.CASES if c.quantity.startswith(quantity_start)]
    assert len(found) == 1, quantity_start
    return found[0]


def test_every_table_cell_has_a_case():
    # closing table: 8 columns (106: m = 2, 3; 310: m = 2, 3, 4, 4, 4, 5) x 2 computed rows
    # (f' refined, f'' approximate) = 16 cells, 2 of them dashes: 14 printed numbers
    assert len([c for c in seed000.CASES if "table" in c.quantity]) == 14


def test_seed000_is_in_the_registry():
    ids = {c.id for c in all_cases()}
    assert {c.id for c in seed000.CASES} <= ids
    known = [c for c in seed000.CASES if c.known_failure]
    assert len(known) == 5  # 11.0, 5.07, 16.2 (from the computed 10.49), 3.9, 7.6


def test_tolerance_is_printed_half_unit_plus_input_rounding():
    # 106 m=2, text 7.31: eq. (1.9) moves by ~0.008 kHz over f_1 +-0.005 and f*_2 +-0.005
    value, allowance = seed000.tolerance(
        lambda p: seed000.modes_106(p).mode(2).approximate[0] / seed000.KHZ, seed000.P106, 0.005
    )
    case = _case("m=2 approx, text 7.31")
    assert case.rel_tol * abs(case.published) == pytest.approx(allowance, rel=1e-12)
    assert 0.005 < allowance < 0.05
    assert case.compute() == pytest.approx(value, rel=1e-12)


@pytest.mark.parametrize(
    "m, lam, first, second",
    [
        (5, 1, "m=5 epsilon_1", "m=5 epsilon_2"),
        (4, 2, "m=4 antinodes epsilon_1", "m=4 antinodes epsilon_2"),
    ],
)
def test_epsilon_pairs_imply_kappa(m, lam, first, second):
    # Vieta on (3.5) / (3.10): e1 e2 = -(1 + m^-2) / (lam kappa), whatever f_1 and f*_m are;
    # the printed pair (each root +- half a unit of its last printed place) must allow a
    # kappa that rounds to 0.33
    e1, e2 = _case(first).published, _case(second).published
    h1, h2 = (0.5 * 10.0 ** -len(repr(abs(e)).split(".")[1]) for e in (e1, e2))
    lo, hi = (abs(e1) - h1) * (abs(e2) - h2), (abs(e1) + h1) * (abs(e2) + h2)
    kappa_min, kappa_max = (1 + m**-2) / (lam * hi), (1 + m**-2) / (lam * lo)
    assert kappa_min <= 0.335 and kappa_max >= 0.325
