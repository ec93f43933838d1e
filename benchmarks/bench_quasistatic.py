"""Speed of the quasi-static solver, as ratios against straightforward implementations
and against the code as it was before the ring iteration was compiled, measured in the
same run.

1. One combined-load, high-speed solve (6205, F_r = 1000 N, F_a = 300 N, 10 000 rpm):
   bearinglab (compiled ball kernel, condensed analytic Jacobian) against
   (a) its own NumPy twin and (b) seed 001's scheme written with scipy.optimize.fsolve
   (every ball by fsolve inside an outer fsolve on the ring; finite-difference
   Jacobians), with the same contact law, and (c) one flat fsolve over all unknowns.
   The answers are compared.
2. A 10 000-case stiffness map (100 radial x 10 axial loads x 10 speeds) with
   bearinglab.quasistatic.study.stiffness_map on all cores, against the fsolve
   implementation timed on a sample of the same cases and scaled to 10 000.
3. Per-case cost of a stiffness map in one process (issue 12, item 9): the same 400-case
   map (20 radial x 5 axial loads x 4 speeds, workers=1) with (a) this checkout, (b) this
   checkout with the ring iteration in Python (``solver.COMPILED_RING = False``, the kept
   reference) and (c) the code of commit REFERENCE_COMMIT (before the change), checked out
   with ``git worktree`` into a temporary folder and run in a subprocess. CPU seconds per
   case, best of three passes after a warm-up pass (numba compilation excluded). At 0 rpm
   the answers of (a) and (c) are compared (at speed the model changed: Jones's cage
   speed).

Run: .venv/bin/python benchmarks/bench_quasistatic.py [--quick] (--quick: part 3 only)
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np
from scipy import optimize

from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import _kernels, solve_load_distribution, solver
from bearinglab.quasistatic.solver import _Problem, initial_ring_guess
from bearinglab.quasistatic.study import stiffness_map

#: The code before the ring iteration was compiled (issue 12 item 9's "today").
REFERENCE_COMMIT = "8cf1c511e3d2b51a7ddd7f60dd496f23f76a47be"
ROOT = Path(__file__).resolve().parents[1]

BEARING = BallBearing(
    ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3, diametral_clearance=15e-6
)


def _contact_state(p, b, c_rho, c_z, balls=slice(None)):
    """The compiled contact state of ``balls`` at centres ``b`` (rho, z), with the
    problem's contact constants."""
    cs = p.contacts
    return _kernels.contact_state(
        b[:, 0],
        b[:, 1],
        c_rho[balls],
        c_z[balls],
        p.free[balls],
        cs.groove_radius,
        cs.side,
        cs.z0,
        cs.k_poly,
        p.film[balls],
    )


def fsolve_reference(bearing, condition):
    """Seed 001's scheme with SciPy: for trial ring displacements (x, y, z), solve every
    ball's equilibrium with scipy.optimize.fsolve, and the ring's with an outer fsolve
    (finite-difference Jacobians in both), with the same contact law."""
    p = _Problem(bearing, condition, condition.radial_load_angle, None, None)
    balls = {"b": None}

    def ring_force(q, n_rho, n_z):
        inner = p.inner
        g = np.stack([q[:, inner] * n_rho[:, inner], q[:, inner] * n_z[:, inner]], axis=-1)
        return np.einsum("jkab,jka->b", p.t[:, inner], g)

    def ball_forces(b, c_rho, c_z, j):
        q, n_rho, n_z, _, _ = _contact_state(p, np.array([b]), c_rho, c_z, slice(j, j + 1))
        return q, n_rho, n_z

    def ring_residual(x):
        u = np.zeros(5)
        u[:3] = x
        c_rho, c_z = p.centres(u)
        b = balls["b"].copy()
        for j in range(bearing.ball_count):

            def f(bj, j=j):
                q, n_rho, n_z = ball_forces(bj, c_rho, c_z, j)
                return [p.fc - np.sum(q * n_rho), -np.sum(q * n_z)]

            b[j] = optimize.fsolve(f, b[j], xtol=1e-12)
        balls["b"] = b
        state = _contact_state(p, b, c_rho, c_z)
        return (p.load + ring_force(*state[:3]))[:3]

    u0 = initial_ring_guess(p)
    c_rho, c_z = p.centres(u0)
    inner = p.inner
    # each ball starts between its groove centres, sharing the overlap
    mid_rho = 0.5 * (c_rho[:, inner].mean(1) + c_rho[:, ~inner].mean(1))
    mid_z = 0.5 * (c_z[:, inner].mean(1) + c_z[:, ~inner].mean(1))
    balls["b"] = np.stack([mid_rho, mid_z], 1)
    x, _info, ier, _msg = optimize.fsolve(ring_residual, u0[:3], full_output=True, xtol=1e-9)
    return x, ier == 1


def flat_fsolve_reference(bearing, condition):
    """The most straightforward form: every unknown (ring x, y, z in um, each ball's rho, z
    offset in um) in one scipy.optimize.fsolve from the same start as ours."""
    p = _Problem(bearing, condition, condition.radial_load_angle, None, None)
    z = bearing.ball_count

    def residual(x):
        u = np.zeros(5)
        u[:3] = x[:3] * 1e-6
        b = x[3:].reshape(z, 2) * 1e-6 + np.array([0.5 * bearing.pitch_diameter, 0.0])
        c_rho, c_z = p.centres(u)
        q, n_rho, n_z, _, _ = _contact_state(p, b, c_rho, c_z)
        balls = np.stack([p.fc - np.sum(q * n_rho, 1), -np.sum(q * n_z, 1)], 1)
        force = np.einsum(
            "jkab,jka->b",
            p.t[:, p.inner],
            np.stack([q[:, p.inner] * n_rho[:, p.inner], q[:, p.inner] * n_z[:, p.inner]], axis=-1),
        )
        return np.concatenate([(p.load + force)[:3], balls.ravel()])

    u0 = initial_ring_guess(p)[:3]
    c_rho, c_z = p.centres(np.r_[u0, 0.0, 0.0])
    inner = p.inner
    mid = np.stack(
        [
            0.5 * (c_rho[:, inner].mean(1) + c_rho[:, ~inner].mean(1))
            - 0.5 * bearing.pitch_diameter,
            0.5 * (c_z[:, inner].mean(1) + c_z[:, ~inner].mean(1)),
        ],
        1,
    )
    x, _, ier, _ = optimize.fsolve(
        residual, np.concatenate([u0 * 1e6, mid.ravel() * 1e6]), full_output=True, xtol=1e-10
    )
    return x[:3] * 1e-6, ier == 1 and np.max(np.abs(residual(x))) < 1e-3


def timed(fn, repeat):
    fn()
    t = time.perf_counter()
    for _ in range(repeat):
        out = fn()
    return (time.perf_counter() - t) / repeat, out


MAP_GRID = {
    "radial": np.linspace(0.0, 2000.0, 20).tolist(),
    "axial": np.linspace(-500.0, 500.0, 5).tolist(),
    "speeds": [0.0, 5000.0, 10000.0, 15000.0],
}

_MAP_SNIPPET = """
import json, sys, time, numpy as np
from bearinglab.geometry import BallBearing
from bearinglab.quasistatic.study import stiffness_map
grid = json.loads(sys.argv[1])
b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3,
                diametral_clearance=15e-6)
def run():
    return stiffness_map(b, grid["radial"], grid["axial"], grid["speeds"], workers=1)
run()
best = []
for _ in range(3):
    t = time.process_time()
    table = run()
    best.append((time.process_time() - t) / len(table))
zero = table[table.speed_rpm == 0]
print(json.dumps({"per_case_s": min(best), "cases": len(table),
                  "ok": int((table.status == "ok").sum()),
                  "zero_rpm_um": zero.radial_displacement_um.fillna(0).tolist()}))
"""


def map_per_case(src: Path | None, compiled_ring: bool = True) -> dict:
    """Run _MAP_SNIPPET with the package from ``src`` (None: this checkout) in a
    subprocess, one thread each."""
    env = {
        **os.environ,
        "OMP_NUM_THREADS": "1",
        "NUMBA_NUM_THREADS": "1",
        "OPENBLAS_NUM_THREADS": "1",
    }
    snippet = _MAP_SNIPPET
    if src is not None:
        env["PYTHONPATH"] = str(src)
    if not compiled_ring:
        snippet = snippet.replace(
            "def run():",
            "from bearinglab.quasistatic import solver\nsolver.COMPILED_RING = False\ndef run():",
        )
    out = subprocess.run(
        [sys.executable, "-c", snippet, json.dumps(MAP_GRID)],
        env=env,
        capture_output=True,
        text=True,
        check=True,
        cwd=tempfile.gettempdir(),
    )
    return json.loads(out.stdout.splitlines()[-1])


def per_case_comparison() -> None:
    """Part 3: this checkout, its Python ring reference and REFERENCE_COMMIT, one run."""
    with tempfile.TemporaryDirectory() as tmp:
        tree = Path(tmp) / "reference"
        subprocess.run(
            ["git", "-C", str(ROOT), "worktree", "add", "--detach", str(tree), REFERENCE_COMMIT],
            check=True,
            capture_output=True,
        )
        try:
            before = map_per_case(tree / "src")
            now = map_per_case(ROOT / "src")
            python_ring = map_per_case(ROOT / "src", compiled_ring=False)
        finally:
            subprocess.run(
                ["git", "-C", str(ROOT), "worktree", "remove", "--force", str(tree)],
                check=False,
                capture_output=True,
            )
    diff = np.max(np.abs(np.array(now["zero_rpm_um"]) - np.array(before["zero_rpm_um"])))
    print(
        f"stiffness map, {now['cases']} cases, one process: "
        f"{now['per_case_s'] * 1e3:.3f} ms CPU per case now ({now['ok']} solved), "
        f"{before['per_case_s'] * 1e3:.3f} ms at {REFERENCE_COMMIT[:7]} ({before['ok']} "
        f"solved): x{before['per_case_s'] / now['per_case_s']:.1f} fewer seconds per case; "
        f"Python ring reference {python_ring['per_case_s'] * 1e3:.3f} ms "
        f"(x{python_ring['per_case_s'] / now['per_case_s']:.1f}); "
        f"at 0 rpm S_r differs from {REFERENCE_COMMIT[:7]} by {diff * 1e3:.2g} nm at most"
    )


def main() -> None:
    if "--quick" in sys.argv:
        per_case_comparison()
        return
    c = OperatingCondition(radial_load=1000.0, axial_load=300.0, shaft_speed=10000 * math.pi / 30)
    t_ours, r = timed(lambda: solve_load_distribution(BEARING, c), 50)
    original = solver._solve_balls_compiled
    solver._solve_balls_compiled = lambda: _kernels.solve_balls_numpy
    solver.COMPILED_RING = False
    try:
        t_numpy, _ = timed(lambda: solve_load_distribution(BEARING, c), 10)
    finally:
        solver._solve_balls_compiled = original
        solver.COMPILED_RING = True
    t_ref, (x, ok) = timed(lambda: fsolve_reference(BEARING, c), 3)
    diff = np.max(np.abs(x - r.displacement[:3]))
    t_flat, (x_flat, ok_flat) = timed(lambda: flat_fsolve_reference(BEARING, c), 3)
    print(
        f"flat fsolve over all unknowns: {t_flat * 1e3:.1f} ms, converged: {ok_flat} "
        f"(off by {np.max(np.abs(x_flat - r.displacement[:3])) * 1e6:.3g} um)"
    )
    print(
        f"single solve: bearinglab {t_ours * 1e3:.2f} ms, NumPy twin {t_numpy * 1e3:.1f} ms "
        f"(x{t_numpy / t_ours:.1f}), fsolve {t_ref * 1e3:.1f} ms (x{t_ref / t_ours:.1f}, "
        f"converged: {ok}); displacement difference {diff * 1e9:.3g} nm"
    )

    radial, axial, speeds = (
        np.linspace(0, 2000, 100),
        np.linspace(-500, 500, 10),
        np.linspace(0, 15000, 10),
    )
    t = time.perf_counter()
    table = stiffness_map(BEARING, radial, axial, speeds)
    t_map = time.perf_counter() - t
    sample = [(fr, fa, n) for fr in radial[5::30] for fa in axial[::4] for n in speeds[::5]]
    t = time.perf_counter()
    failures = 0
    for fr, fa, n in sample:
        failures += not fsolve_reference(
            BEARING, OperatingCondition(radial_load=fr, axial_load=fa, shaft_speed=n * math.pi / 30)
        )[1]
    t_ref_map = (time.perf_counter() - t) / len(sample) * len(table)
    print(
        f"{len(table)}-case map: bearinglab {t_map:.1f} s on all cores "
        f"({(table.status == 'ok').sum()} solved); fsolve scaled from {len(sample)} cases "
        f"{t_ref_map:.0f} s (x{t_ref_map / t_map:.0f}; {failures} of the sample did not "
        f"converge)"
    )
    per_case_comparison()


if __name__ == "__main__":
    with warnings.catch_warnings():  # fsolve's "not making good progress" notes
        warnings.simplefilter("ignore", RuntimeWarning)
        main()
