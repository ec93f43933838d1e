"""The dynamic models' compiled kernels against their NumPy twins, and the integrator
against a closed-form solution."""

import math

import numpy as np
import pytest

from bearinglab.dynamics import (
    Defect,
    SlipParameters,
    _integrate,
    _kernels,
    _rosenbrock,
    _slip_kernels,
    rigid,
    slip,
)
from bearinglab.dynamics.defects import edge_drop, pack_defects
from bearinglab.errors import InputError
from bearinglab.operating import OperatingCondition
from bearinglab.validation.dynamics import ER16K
from bearinglab.validation.seed004 import SKF6205

DEFECTS = [
    Defect("outer", 1.2e-3, 0.25e-3),
    Defect("inner", 0.8e-3, 2e-6, angle=1.0),
    Defect("ball", 1.2e-3, ball=3, angle=0.4),
]


def test_edge_drop_matches_the_circle_geometry():
    # ER-16K, 1.2 mm pit: ball sagitta 45.60 um, race sagittas 7.75 (outer), 11.77 (inner)
    r, ro, ri = 3.97e-3, 23.235e-3, 15.295e-3
    assert edge_drop(0.6e-3, r, ro, "outer") == pytest.approx(45.60e-6 - 7.75e-6, abs=0.02e-6)
    assert edge_drop(0.6e-3, r, ri, "inner") == pytest.approx(45.60e-6 + 11.77e-6, abs=0.02e-6)
    assert edge_drop(-1e-3, r, ro, "outer") == 0.0


def test_defect_validation_names_the_parameter():
    with pytest.raises(InputError, match="width"):
        Defect("outer", -1e-3)
    with pytest.raises(InputError, match="location"):
        Defect("cage", 1e-3)
    with pytest.raises(InputError, match="width"):
        pack_defects([Defect("outer", 9e-3)], ER16K)
    with pytest.raises(InputError, match="ball"):
        pack_defects([Defect("ball", 1e-3, ball=9)], ER16K)


def test_surface_deviation_twins_agree():
    rng = np.random.default_rng(1)
    table = pack_defects(DEFECTS, ER16K)
    for _ in range(200):
        psi = rng.uniform(-7, 7, 9)
        spin = rng.uniform(-7, 7, 9)
        spin[3] = 0.4 + rng.uniform(-0.2, 0.2) + rng.integers(0, 2) * math.pi
        shaft = rng.uniform(0, 20)
        psi[0] = -0.5 * math.pi + rng.uniform(-0.03, 0.03)
        psi[1] = 1.0 + shaft + rng.uniform(-0.03, 0.03)
        a = np.empty(9)
        b = np.empty(9)
        _kernels.surface_deviation_numba(psi, spin, shaft, 3.97e-3, 15.3e-3, 23.2e-3, table, a, b)
        na, nb = _kernels.surface_deviation_numpy(
            psi, spin, shaft, 3.97e-3, 15.3e-3, 23.2e-3, table
        )
        np.testing.assert_allclose(a, na, atol=1e-15)
        np.testing.assert_allclose(b, nb, atol=1e-15)
    assert np.any(na > 0) and np.any(nb > 0)  # the sample reached the defects


def _imperfections():
    from bearinglab.imperfections import BallSizeErrors, Imperfections, RandomSurface, Waviness

    return Imperfections(
        [
            Waviness("outer", 10, 0.4e-6, 0.3),
            Waviness("inner", 8, 0.2e-6, -1.0),
            Waviness("ball", 2, 0.1e-6, 0.5, ball=4),
            Waviness("ball", 4, 0.05e-6),
        ],
        ball_size_errors=BallSizeErrors.random(9, 2e-6, seed=3),
        surfaces=[
            RandomSurface.for_bearing(
                ER16K, "outer", 0.1e-6, 5e-3, 0.4e-3, seed=1, points_circumferential=64
            )
        ],
    )


def test_imperfection_rows_twins_agree_and_equal_the_approach_changes():
    """Waviness, ball-size and sampled-track rows: the kernel equals its twin, and both
    equal minus the approach changes of Imperfections (written independently)."""
    imp = _imperfections()
    table = pack_defects(DEFECTS[:1], ER16K, imp)
    bare = pack_defects(DEFECTS[:1], ER16K)
    r_b, r_i, r_o = (
        0.5 * ER16K.ball_diameter,
        0.5 * ER16K.inner_raceway_diameter,
        0.5 * ER16K.outer_raceway_diameter,
    )
    rng = np.random.default_rng(2)
    for _ in range(100):
        psi, spin, shaft = rng.uniform(-7, 7, 9), rng.uniform(-7, 7, 9), rng.uniform(0, 20)
        a, b = np.empty(9), np.empty(9)
        _kernels.surface_deviation_numba(psi, spin, shaft, r_b, r_i, r_o, table, a, b)
        na, nb = _kernels.surface_deviation_numpy(psi, spin, shaft, r_b, r_i, r_o, table)
        np.testing.assert_allclose(a, na, atol=1e-18)
        np.testing.assert_allclose(b, nb, atol=1e-18)
        pit_in, pit_out = _kernels.surface_deviation_numpy(psi, spin, shaft, r_b, r_i, r_o, bare)
        change = imp.approach_change(ER16K, psi, shaft, spin)
        np.testing.assert_allclose(a - pit_in, -change.inner, atol=1e-18)
        np.testing.assert_allclose(b - pit_out, -change.outer, atol=1e-18)


def test_imperfections_are_checked_against_the_bearing():
    from bearinglab.imperfections import Imperfections, Waviness

    with pytest.raises(InputError, match="ball"):
        pack_defects([], ER16K, Imperfections([Waviness("ball", 2, 1e-7, ball=9)]))
    with pytest.raises(InputError, match="imperfections"):
        pack_defects([], ER16K, [Waviness("outer", 2, 1e-7)])


def test_rigid_rhs_twins_agree():
    table = pack_defects(DEFECTS, ER16K)
    cond = OperatingCondition(radial_load=50.0, shaft_speed=183.0)
    p = rigid.pack(ER16K, cond, rigid.RigidParameters(unbalance=1e-4), table)
    rng = np.random.default_rng(2)
    out = np.empty(8)
    for _ in range(100):
        y = rigid.static_state(p) + rng.normal(0, 2e-6, 8) * np.r_[np.ones(4), 1e3 * np.ones(4)]
        t = rng.uniform(0, 1)
        _kernels.rigid_rhs_numba(t, y, p, table, out)
        np.testing.assert_allclose(
            out, _kernels.rigid_rhs_numpy(t, y, p, table), rtol=1e-10, atol=1e-9
        )


@pytest.mark.parametrize("traction", ["seed004", "bair_winer"])
def test_slip_rhs_twins_agree(traction):
    table = pack_defects([Defect("ball", 0.3e-3, ball=2), Defect("outer", 0.5e-3)], SKF6205)
    cond = OperatingCondition(radial_load=500.0, shaft_speed=251.3)
    p = slip.pack(
        SKF6205, cond, SlipParameters(traction=traction, pocket_clearance=1e-5), table, None, 0.3e-3
    )
    y0 = slip.initial_state(p)
    rng = np.random.default_rng(3)
    out = np.empty_like(y0)
    parts = np.empty((9, _slip_kernels.NG))
    scale = slip.atol(9) * 1e4
    for _ in range(100):
        y = y0 + rng.normal(0, 1, y0.size) * scale
        t = rng.uniform(0, 0.1)
        _slip_kernels.slip_rhs(t, y, p, table, out, parts)
        twin = _slip_kernels.slip_rhs_numpy(t, y, p, table)
        np.testing.assert_allclose(out, twin, rtol=1e-9, atol=1e-6)


def test_grouped_jacobian_equals_a_dense_difference():
    """The arrow-structured Jacobian (16 grouped calls) against column-by-column central
    differences of the NumPy twin."""
    table = pack_defects([], SKF6205)
    cond = OperatingCondition(radial_load=500.0, shaft_speed=251.3)
    p = slip.pack(SKF6205, cond, SlipParameters(traction="bair_winer"), table)
    y = slip.initial_state(p)
    y[8:] += np.random.default_rng(4).normal(0, 1, y.size - 8) * slip.atol(9)[8:] * 10
    n, ng, nb = y.size, _slip_kernels.NG, _slip_kernels.NB
    dense = np.empty((n, n))
    for col in range(n):
        eps = 1e-6 * max(
            abs(y[col]), 1e-5 if col < 4 or (col >= ng and (col - ng) % nb == 0) else 1e-2
        )
        yp, ym = y.copy(), y.copy()
        yp[col] += eps
        ym[col] -= eps
        dense[:, col] = (
            _slip_kernels.slip_rhs_numpy(0.0, yp, p, table)
            - _slip_kernels.slip_rhs_numpy(0.0, ym, p, table)
        ) / (2 * eps)
    f0 = np.empty(n)
    parts0 = np.empty((9, ng))
    _slip_kernels.slip_rhs(0.0, y, p, table, f0, parts0)
    jg, jgb = np.empty((ng, ng)), np.empty((9, ng, nb))
    jbg, jb = np.empty((9, nb, ng)), np.empty((9, nb, nb))
    _rosenbrock._jacobian(0.0, y, f0, parts0, p, table, jg, jgb, jbg, jb)
    grouped = np.zeros((n, n))
    grouped[:ng, :ng] = jg
    for j in range(9):
        cols = slice(ng + nb * j, ng + nb * (j + 1))
        grouped[:ng, cols] = jgb[j]
        grouped[cols, :ng] = jbg[j]
        grouped[cols, cols] = jb[j]
    scale = np.abs(dense).max(axis=1, keepdims=True) + 1e-30
    assert np.max(np.abs(grouped - dense) / scale) < 1e-3


def _arrow_blocks(n, ng, nb, z, rng):
    blocks = (
        rng.normal(size=(ng, ng)),
        rng.normal(size=(z, ng, nb)),
        rng.normal(size=(z, nb, ng)),
        rng.normal(size=(z, nb, nb)),
    )
    dense = np.zeros((n, n))
    dense[:ng, :ng] = blocks[0]
    for j in range(z):
        cols = slice(ng + nb * j, ng + nb * (j + 1))
        dense[:ng, cols], dense[cols, :ng], dense[cols, cols] = (
            blocks[1][j],
            blocks[2][j],
            blocks[3][j],
        )
    return blocks, dense


@pytest.mark.parametrize("gh", [1e-3, 0.3, 40.0])
def test_block_elimination_solves_the_dense_system(gh):
    """W = I - gh J solved by the hand-written block LU equals a dense solve, also when
    gh J dominates the identity (pivoting needed)."""
    ng, nb, z = _slip_kernels.NG, _slip_kernels.NB, 9
    n = ng + nb * z
    rng = np.random.default_rng(7)
    (jg, jgb, jbg, jb), dense = _arrow_blocks(n, ng, nb, z, rng)
    lu_b, piv_b = np.empty((z, nb, nb)), np.empty((z, nb), dtype=np.int64)
    m_bg, lu_s, piv_s = np.empty((z, nb, ng)), np.empty((ng, ng)), np.empty(ng, dtype=np.int64)
    _rosenbrock._factor(gh, jg, jgb, jbg, jb, lu_b, piv_b, m_bg, lu_s, piv_s)
    rhs = rng.normal(size=n)
    out = np.empty(n)
    _rosenbrock._solve(gh, jgb, lu_b, piv_b, m_bg, lu_s, piv_s, rhs, out)
    expected = np.linalg.solve(np.eye(n) - gh * dense, rhs)
    np.testing.assert_allclose(out, expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max())


def test_dopri_matches_a_damped_oscillator():
    # x'' + 2 z w x' + w^2 x = 0 through the rigid kernel's signature
    import numba

    @numba.njit
    def oscillator(t, y, p, table, dydt):
        dydt[0] = y[1]
        dydt[1] = -(p[0] ** 2) * y[0] - 2 * p[1] * p[0] * y[1]

    w, z = 2 * math.pi * 500.0, 0.05
    t_out = np.linspace(0, 0.02, 401)
    out, *_rest, status = _integrate.dopri_chunk(
        oscillator,
        np.array([w, z]),
        np.zeros((0, 5)),
        0.0,
        np.array([1.0, 0.0]),
        1e-6,
        t_out,
        1e-9,
        np.array([1e-12, 1e-9]),
        5e-5,
        100000,
    )
    assert status == _integrate.OK
    wd = w * math.sqrt(1 - z * z)
    exact = np.exp(-z * w * t_out) * (np.cos(wd * t_out) + z * w / wd * np.sin(wd * t_out))
    assert np.max(np.abs(out[:, 0] - exact)) < 1e-6
