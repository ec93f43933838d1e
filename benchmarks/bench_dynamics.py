"""Speed of the dynamic models (issue 4), as ratios against straightforward
implementations measured in the same run, on one core.

1. Rigid-ring model (seed 003): ER-16K at 1750 rpm, 50 N, an outer-race defect
   (1.2 mm wide, 0.25 mm deep) and a ball defect (1.2 mm), 50 kHz output.
   ``simulate(..., model="rigid")`` (compiled Dormand-Prince 5(4)) records 1 s of signal
   after a warm-up call (numba compilation excluded); the reference is
   ``scipy.integrate.solve_ivp(method="RK45")`` -- the same Dormand-Prince pair -- with the
   same rtol, atol, maximum step and output times, on the NumPy twin of the right-hand
   side (``_kernels.rigid_rhs_numpy``), over a shorter span from the same initial state and
   scaled. Both answers are compared over the common span.
2. Slip model (seed 004): the 6205 of seed 004 at 2400 rpm, a 0.267 mm ball defect,
   20 kHz output: ``simulate(..., model="slip")`` (compiled Rosenbrock 2(3) with an
   arrow-structured Jacobian) records 1 s of signal at 500 N and at 1000 N, after the
   default settling (detected by cage turns, at least four; its steps are counted in the
   steps per simulated second); at 500 N it
   is compared with SciPy's stiff integrators (``BDF`` and ``Radau``,
   each as ``solve_ivp`` runs it: the solver class stepped to the end, with a wall-time
   cap) on ``_slip_kernels.slip_rhs_numpy``, same rtol, atol and maximum step.

Speeds are compared per second of *simulated* time (``simulate`` also integrates its
settling time, which it discards); "signal s per wall s" counts only the recorded signal,
with the settling time's cost included in the wall time, which is what a user waits for.
Everything runs on one core: numba, OpenMP and BLAS get one thread each (set before they
are imported) and nothing is run in parallel. The process is not pinned to a CPU: on a
shared machine the scheduler then finds the idler core; ours are the best of three runs.

Run: .venv/bin/python benchmarks/bench_dynamics.py [--quick]
"""

import os

for _var in ("NUMBA_NUM_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse
import math
import time

import numpy as np
from scipy import integrate

from bearinglab.catalog.build import bearing_from_designation
from bearinglab.dynamics import Defect, _kernels, _slip_kernels, rigid, simulate, slip
from bearinglab.dynamics.defects import pack_defects
from bearinglab.operating import OperatingCondition
from bearinglab.validation.seed004 import SKF6205

RIGID_RATE = 50e3
SLIP_RATE = 20e3
# seed 004's 6205, the slip model's reference case
SLIP_BEARING = SKF6205
SLIP_DEFECT_WIDTH = 0.267e-3


def best_of(fn, repeat):
    """Smallest wall time of ``repeat`` calls (the machine is shared) and the last result."""
    best = math.inf
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def reference_run(method, fun, y0, t_eval, cap, **options):
    """What ``solve_ivp(fun, (0, t_eval[-1]), y0, method=method, t_eval=t_eval, ...)``
    does -- step the solver to the end, evaluate its dense output at ``t_eval`` -- but
    stopping after ``cap`` seconds of wall time. Returns (states at the reached output
    times, time reached, wall time, accepted steps, finished)."""
    t0 = time.perf_counter()
    solver = method(fun, 0.0, y0, t_eval[-1], **options)
    out = [y0[None, :]] if t_eval[0] == 0.0 else []
    i = len(out)
    steps = 0
    while solver.status == "running":
        if time.perf_counter() - t0 > cap:
            break
        solver.step()
        if solver.status == "failed":
            break
        steps += 1
        j = np.searchsorted(t_eval, solver.t, side="right")
        if j > i:
            out.append(solver.dense_output()(t_eval[i:j]).T)
            i = j
    wall = time.perf_counter() - t0
    states = np.concatenate(out) if out else np.empty((0, y0.size))
    return states, solver.t, wall, steps, solver.status == "finished"


def relative_difference(ours, ref):
    """max |ours - ref| over the range of ref."""
    return float(np.max(np.abs(ours - ref)) / np.ptp(ref))


def rigid_benchmark(duration, ref_span, repeat):
    bearing, _ = bearing_from_designation("ER-16K")
    condition = OperatingCondition(radial_load=50.0, shaft_speed=1750 * math.pi / 30)
    defects = (Defect("outer", width=1.2e-3, depth=0.25e-3), Defect("ball", width=1.2e-3))

    def run(length, settle=None):
        return simulate(
            bearing,
            condition,
            defects,
            model="rigid",
            duration=length,
            sample_rate=RIGID_RATE,
            settle=settle,
        )

    run(0.01)  # warm-up: numba compilation
    wall, sim = best_of(lambda: run(duration), repeat)
    simulated = duration + sim.stats["settle_s"]

    table = pack_defects(defects, bearing)
    p = rigid.pack(bearing, condition, rigid.RigidParameters(), table)
    y0 = rigid.static_state(p)
    t_eval = np.arange(round(ref_span * RIGID_RATE)) / RIGID_RATE
    states, reached, ref_wall, ref_steps, done = reference_run(
        integrate.RK45,
        lambda t, y: _kernels.rigid_rhs_numpy(t, y, p, table),
        y0,
        t_eval,
        cap=600.0,
        rtol=1e-6,
        atol=rigid.ATOL,
        max_step=1.0 / RIGID_RATE,
    )
    if not done:
        raise RuntimeError(f"RK45 reference stopped at t = {reached:.4g} s")

    # ours over the same span from the same state (no settling), for the comparison
    same_wall, same = best_of(lambda: run(ref_span, settle=0.0), repeat)
    ch = same.signal.channels
    acc_ref = _kernels.rigid_accelerations(p, table, t_eval, np.ascontiguousarray(states))
    disp_ref = states[:, 0:2] - states[:, 2:4]
    rms, rms_ref = (float(np.sqrt(np.mean(a**2))) for a in (ch["acc_y"], acc_ref[:, 1]))
    return {
        "wall": wall,
        "duration": duration,
        "simulated": simulated,
        "steps": sim.stats["steps"],
        "rejected": sim.stats["rejected_steps"],
        "ref_wall": ref_wall,
        "ref_span": reached,
        "ref_steps": ref_steps,
        "same_wall": same_wall,
        "same_steps": same.stats["steps"],
        "disp_x": relative_difference(ch["disp_x"], disp_ref[:, 0]),
        "disp_y": relative_difference(ch["disp_y"], disp_ref[:, 1]),
        "rms": rms,
        "rms_ref": rms_ref,
    }


def slip_record(load, duration, repeat):
    """Best wall time of a ``duration`` s record at ``load`` N (after a warm-up call)."""
    condition = OperatingCondition(radial_load=load, shaft_speed=2400 * math.pi / 30)
    defects = (Defect("ball", width=SLIP_DEFECT_WIDTH),)
    simulate(
        SLIP_BEARING,
        condition,
        defects,
        model="slip",
        duration=64 / SLIP_RATE,
        sample_rate=SLIP_RATE,
        settle=0.0,
    )  # warm-up: numba compilation
    wall, sim = best_of(
        lambda: simulate(
            SLIP_BEARING, condition, defects, model="slip", duration=duration, sample_rate=SLIP_RATE
        ),
        repeat,
    )
    simulated = duration + sim.stats["settle_s"]
    return {
        "load": load,
        "wall": wall,
        "duration": duration,
        "simulated": simulated,
        "settle": sim.stats["settle_s"],
        "turns": sim.stats.get("settle_turns"),
        "steps": sim.stats["steps"],
        "rejected": sim.stats["rejected_steps"],
        "cage_ratio": sim.cage_speed_ratio,
        "spin_ratio": sim.spin_speed_ratio,
    }


def slip_benchmark(ref_span, repeat, cap):
    condition = OperatingCondition(radial_load=500.0, shaft_speed=2400 * math.pi / 30)
    defects = (Defect("ball", width=SLIP_DEFECT_WIDTH),)

    def run(length, settle=None):
        return simulate(
            SLIP_BEARING,
            condition,
            defects,
            model="slip",
            duration=length,
            sample_rate=SLIP_RATE,
            settle=settle,
        )

    run(64 / SLIP_RATE, settle=0.0)  # warm-up: numba compilation

    table = pack_defects(defects, SLIP_BEARING)
    p = slip.pack(SLIP_BEARING, condition, slip.SlipParameters(), table, None, SLIP_DEFECT_WIDTH)
    y0 = slip.initial_state(p)
    z = SLIP_BEARING.ball_count
    t_eval = np.arange(round(ref_span * SLIP_RATE)) / SLIP_RATE
    same_wall, same = best_of(lambda: run(ref_span, settle=0.0), repeat)
    ch = same.signal.channels
    refs = {}
    for name in ("BDF", "Radau"):
        states, reached, ref_wall, ref_steps, done = reference_run(
            getattr(integrate, name),
            lambda t, y: _slip_kernels.slip_rhs_numpy(t, y, p, table),
            y0,
            t_eval,
            cap=cap,
            rtol=1e-3,
            atol=slip.atol(z),
            max_step=1.0 / SLIP_RATE,
        )
        n = states.shape[0]
        disp_y = states[:, 1] - states[:, 3]
        orbital = states[:, _slip_kernels.NG + 3 :: _slip_kernels.NB].mean(1)
        ours_orbital = same.ball_orbital_speed.mean(0)[:n]
        refs[name] = {
            "wall": ref_wall,
            "span": reached,
            "steps": ref_steps,
            "finished": done,
            "samples": n,
            "disp_y": relative_difference(ch["disp_y"][:n], disp_y) if n > 1 else math.nan,
            "cage": float(abs(ch["cage_speed"][:n].mean() / states[:, 9].mean() - 1))
            if n
            else math.nan,
            "orbital": float(np.max(np.abs(ours_orbital / orbital - 1))) if n else math.nan,
        }
    return {
        "same_wall": same_wall,
        "ref_span": ref_span,
        "same_steps": same.stats["steps"],
        "same_rejected": same.stats["rejected_steps"],
        "refs": refs,
    }


def verdict(value, target):
    return "met" if value >= target else "NOT met"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--quick", action="store_true", help="shorter records and reference spans (a smoke run)"
    )
    args = parser.parse_args()
    quick = args.quick
    print(
        "one core: one thread each for numba, OpenMP and BLAS; load average "
        f"{os.getloadavg()[0]:.2f} (machine has {os.cpu_count()} CPUs)"
    )

    r = rigid_benchmark(
        duration=0.2 if quick else 1.0, ref_span=0.01 if quick else 0.05, repeat=1 if quick else 3
    )
    records = [
        slip_record(load, duration=0.05 if quick else 1.0, repeat=1 if quick else 3)
        for load in (500.0, 1000.0)
    ]
    s = slip_benchmark(
        ref_span=0.0032 if quick else 0.01, repeat=1 if quick else 3, cap=30.0 if quick else 300.0
    )

    # rigid
    r_rate = r["duration"] / r["wall"]
    r_per_sim = r["wall"] / r["simulated"]
    r_ref_per_sim = r["ref_wall"] / r["ref_span"]
    r_ratio = r_ref_per_sim / r_per_sim
    print("\nrigid (ER-16K, 1750 rpm, 50 N, outer 1.2x0.25 mm + ball 1.2 mm, 50 kHz)")
    print(
        f"  simulate: {r['duration']:g} s of signal (+{r['simulated'] - r['duration']:g} s "
        f"settling) in {r['wall']:.3f} s, {r['steps']} steps ({r['rejected']} rejected, "
        f"{r['steps'] / r['simulated']:.0f} per simulated s)"
    )
    print(
        f"  RK45 + NumPy twin: {r['ref_span']:g} s in {r['ref_wall']:.2f} s "
        f"({r['ref_steps']} steps), {r_ref_per_sim:.1f} s per simulated s; "
        f"same span ours {r['same_wall'] * 1e3:.1f} ms ({r['same_steps']} steps)"
    )
    print(
        f"  agreement over {r['ref_span']:g} s: max |disp diff| / range "
        f"x {r['disp_x']:.2e}, y {r['disp_y']:.2e}; RMS acc_y {r['rms']:.2f} vs "
        f"{r['rms_ref']:.2f} m/s^2 ({abs(r['rms'] / r['rms_ref'] - 1) * 100:.3f} %)"
    )

    # slip
    print("\nslip (seed-004 6205, 2400 rpm, ball defect 0.267 mm, 20 kHz)")
    for rec in records:
        print(
            f"  simulate, {rec['load']:g} N: {rec['duration']:g} s of signal "
            f"(+{rec['settle']:.4f} s settling, {rec['turns']} cage turns by slip.settle's "
            f"rule) in {rec['wall']:.3f} s, {rec['steps']} steps "
            f"({rec['rejected']} rejected): {rec['steps'] / rec['simulated']:.0f} steps per "
            f"simulated s; cage speed ratio {rec['cage_ratio']:.5f}, spin speed ratio "
            f"{rec['spin_ratio']:.5f}"
        )
    s_per_sim = records[0]["wall"] / records[0]["simulated"]
    s_same_per_sim = s["same_wall"] / s["ref_span"]
    print(
        f"  500 N, same span as the references ({s['ref_span']:g} s from the initial state): "
        f"{s['same_wall'] * 1e3:.1f} ms, {s['same_steps']} steps "
        f"({s['same_rejected']} rejected)"
    )
    ratios = {}
    for name, ref in s["refs"].items():
        per_sim = ref["wall"] / ref["span"] if ref["span"] > 0 else math.inf
        ratios[name] = (per_sim / s_per_sim, per_sim / s_same_per_sim)
        print(
            f"  {name} + NumPy twin: reached {ref['span']:.4g} s "
            f"({'finished' if ref['finished'] else 'stopped by the time cap'}) in "
            f"{ref['wall']:.2f} s, {ref['steps']} steps, {per_sim:.0f} s per simulated s: "
            f"x{ratios[name][0]:.0f} (long run), x{ratios[name][1]:.0f} (same span); "
            f"vs ours over {ref['samples']} samples: max |disp_y diff| / range "
            f"{ref['disp_y']:.2e}, relative difference of the mean cage speed "
            f"{ref['cage']:.1e}, of the balls' mean orbital speed (max) {ref['orbital']:.1e}"
        )

    best = min(ratios, key=lambda k: ratios[k][0])
    rows = [
        ("rigid: signal s per wall s", f"{r_rate:.2f}", ">= 1", verdict(r_rate, 1.0)),
        ("rigid: vs RK45 + NumPy twin", f"x{r_ratio:.0f}", ">= x50", verdict(r_ratio, 50)),
    ]
    for rec in records:
        rate = rec["duration"] / rec["wall"]
        rows += [
            (
                f"slip {rec['load']:g} N: signal s per wall s",
                f"{rate:.3f} ({rec['simulated'] / rec['wall']:.3f} per simulated s)",
                ">= 0.2",
                verdict(rate, 0.2),
            ),
            (
                f"slip {rec['load']:g} N: steps per simulated s",
                f"{rec['steps'] / rec['simulated']:.0f}",
                "-",
                "-",
            ),
        ]
    rows.append(
        (
            f"slip 500 N: vs {best} + NumPy twin (fastest ref.)",
            f"x{ratios[best][0]:.0f} (same span x{ratios[best][1]:.0f})",
            "-",
            "-",
        )
    )
    widths = [
        max(len(row[i]) for row in rows + [("what", "result", "target", "verdict")])
        for i in range(4)
    ]
    print()
    for row in [("what", "result", "target", "verdict"), tuple("-" * w for w in widths)] + rows:
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths, strict=False)))


if __name__ == "__main__":
    main()
