"""Speed of the diagnosis of one record, as a ratio against a plain SciPy envelope + FFT.

A 10 s record at 12 kHz (the CWRU drive-end record 105 when ../shared/data/real is there,
otherwise synthetic impacts in noise): ``analyze_signal`` with each method and with the
default, against ``np.abs(scipy.signal.hilbert(x))`` and ``np.fft.rfft`` of the same record
(what a user would write by hand), in one run, best of five calls each. The default is
timed as ``bearinglab analyze`` runs it: ``analyze_signal`` and then its ``defect_sizes``
(the width of a race defect found, issue 29, read lazily and printed by the command), and
also without the sizing, as the methods are (before 2026-11-28 the default's line left
the sizing out). Also the Hilbert
transform at an awkward length (480 001 samples) with and without the fast-length padding
of ``bearinglab.signal.spectra.analytic`` (issue 12 item 9).

With ``--synthetic``: the synthetic validation table of docs/capabilities/diagnosis.md -
detections per fault family, SNR and method on rigid-model records (``dynamics.simulate``)
with slip, a random-walk time warp (random slip), a transfer-path resonance, shaft
harmonics and white noise.

Run: .venv/bin/python benchmarks/bench_diagnosis.py [--synthetic [SEEDS]] [--methods M,...]
(``--methods``: the synthetic table's columns, comma-separated, a set joining methods
with "+"; default raw,cpw,drs-sk,all).
"""

import math
import sys
import time
from pathlib import Path

import numpy as np
import scipy.signal

from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import NO_FAULT, analyze_signal
from bearinglab.kinematics import defect_frequencies
from bearinglab.signal.spectra import analytic

REAL = Path(__file__).resolve().parents[2] / "shared" / "data" / "real" / "cwru" / "12k_DE"
FS = 12000.0


def record():
    if (REAL / "105.mat").is_file():
        import scipy.io

        return scipy.io.loadmat(REAL / "105.mat")["X105_DE_time"].ravel()[: int(10 * FS)], "105"
    rng = np.random.default_rng(0)
    t = np.arange(int(10 * FS)) / FS
    x = np.exp(-(t % (1 / 162.0)) / 1e-3) * np.sin(2 * np.pi * 3000 * t)
    return x + rng.standard_normal(t.size), "synthetic"


def best(fn, repeat=5):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def steady_allocator() -> bool:
    """Keep freed memory in the process (glibc's mallopt: no mmap below 256 MB, no trim),
    so that a large array is not page-faulted afresh at every call. Under the default
    allocator the plain SciPy reference's own time depends on what ran before it in the
    process (3.8-6.5 ms for record 105: its 1.9 MB complex arrays come page-faulted from
    the system, or recycled when an earlier call freed as large a block); the ratios are
    also given with this set, where both sides compute without those page faults."""
    import ctypes
    import ctypes.util

    name = ctypes.util.find_library("c")
    if not name:
        return False
    try:
        libc = ctypes.CDLL(name)
        # M_TRIM_THRESHOLD -1, M_MMAP_THRESHOLD -3 (malloc.h)
        return bool(libc.mallopt(-1, 1 << 28)) and bool(libc.mallopt(-3, 1 << 28))
    except (OSError, AttributeError):
        return False


def main():
    x, name = record()
    kin = defect_frequencies(bearing_from_designation("6205-2RS")[0], 1797 * math.pi / 30)

    def plain():
        env = np.abs(scipy.signal.hilbert(x - x.mean()))
        return np.abs(np.fft.rfft(env - env.mean()))

    assert analyze_signal(x, FS, kin).defect_sizes is not None  # warm-up (imports)
    ref = best(plain)
    print(f"record {name}: {x.size} samples at {FS:g} Hz")
    print(f"plain SciPy envelope + FFT: {1e3 * ref:.1f} ms")
    t = best(lambda: analyze_signal(x, FS, kin).defect_sizes)
    print(
        f"analyze_signal() and its defect_sizes (as `bearinglab analyze`): {1e3 * t:.0f} ms, "
        f"x{t / ref:.1f}"
    )
    for methods in ("raw", "cpw", "drs-sk", "all", "ies", "cpw,ies"):
        t = best(lambda m=methods: analyze_signal(x, FS, kin, methods=m))
        sized = best(lambda m=methods: analyze_signal(x, FS, kin, methods=m).defect_sizes)
        print(
            f"analyze_signal(methods={methods!r}): {1e3 * t:.0f} ms, x{t / ref:.1f}; "
            f"with its defect_sizes {1e3 * sized:.0f} ms, x{sized / ref:.1f}"
        )
    if steady_allocator():
        ref = best(plain)
        t = best(lambda: analyze_signal(x, FS, kin).defect_sizes)
        bare = best(lambda: analyze_signal(x, FS, kin))
        print(
            f"without the allocator's page faults (steady_allocator): plain {1e3 * ref:.1f} ms; "
            f"analyze_signal() and its defect_sizes {1e3 * t:.0f} ms, x{t / ref:.1f}; without "
            f"the sizing {1e3 * bare:.0f} ms, x{bare / ref:.1f}"
        )
    odd = np.random.default_rng(1).standard_normal(480_001)
    slow = best(lambda: scipy.signal.hilbert(odd), 3)
    fast = best(lambda: analytic(odd), 3)
    print(
        f"Hilbert at 480 001 samples: scipy {1e3 * slow:.0f} ms, padded to a fast length "
        f"{1e3 * fast:.0f} ms (x{slow / fast:.1f})"
    )


SLIP = {
    "outer": (-0.015, 0.015),
    "inner": (-0.015, 0.015),
    "ball": (-0.04, 0.01),
    "none": (0.0, 0.0),
}
WANT = {"outer": "outer_race", "inner": "inner_race", "ball": "ball", "none": "no fault detected"}


def synthetic_base(fault, seed, duration=4.0):
    """Noise-free rigid-model record of a 6205 with ``fault`` and its random inputs."""
    from bearinglab.dynamics import Defect, simulate
    from bearinglab.operating import OperatingCondition

    bearing = bearing_from_designation("6205")[0]
    rng = np.random.default_rng(1000 + seed + 100 * ["none", "outer", "inner", "ball"].index(fault))
    rpm, load, slip = rng.uniform(1700, 1800), rng.uniform(300, 2000), rng.uniform(*SLIP[fault])
    defects = (
        []
        if fault == "none"
        else [
            Defect(
                fault,
                rng.uniform(0.3e-3, 1.5e-3),
                rng.uniform(0.1e-3, 0.3e-3),
                angle=rng.uniform(-0.75 * math.pi, -0.25 * math.pi)
                if fault == "outer"
                else rng.uniform(0, 2 * math.pi),
                ball=int(rng.integers(9)) if fault == "ball" else 0,
            )
        ]
    )
    # slip s: the defect lines at (1 + s) x their kinematic value
    condition = OperatingCondition(radial_load=load, shaft_speed=rpm * (1 + slip) * math.pi / 30)
    sim = simulate(bearing, condition, defects, model="rigid", duration=duration, sample_rate=FS)
    resonance = (rng.uniform(2500, 4500), rng.uniform(0.02, 0.08))
    return np.asarray(sim.signal.channels["acc_y"]), rpm, resonance, bearing


def synthetic_record(base, seed, snr_db, fault, jitter=0.01, shaft_amp=2.0):
    """(samples, kinematics given to the analysis) of one synthetic record."""
    from bearinglab.dataset.path import TransferPath

    x, rpm, resonance, bearing = base
    rng = np.random.default_rng(seed * 7 + 13)
    x = x - x.mean()
    t = np.arange(x.size) / FS
    kin = defect_frequencies(bearing, rpm * math.pi / 30)
    # random slip: a random-walk time warp, spread `jitter` of a BPFO period per period
    period, step = 1 / kin.hz("bpfo"), 1e-3
    m = int(t[-1] / step) + 3
    walk = np.cumsum(rng.standard_normal(m)) * jitter * period * math.sqrt(step / period)
    x = np.interp(t + np.interp(t, np.arange(m) * step, walk - walk[0]), t, x)
    x = TransferPath((resonance,)).apply(x, FS)
    rms = float(np.std(x))
    if fault == "none":  # healthy: its own lines at -20 dB of a unit fault signal
        x, rms = x / max(rms, 1e-30) * 0.1, 1.0
    for k in range(1, 6):  # shaft harmonics (unbalance, misalignment)
        x = x + shaft_amp * rms / k * np.sin(
            2 * np.pi * k * rpm / 60 * t + rng.uniform(0, 2 * np.pi)
        )
    return x + rms * 10 ** (-snr_db / 20) * rng.standard_normal(x.size), kin


def synthetic(seeds=12, snrs=(0, -5, -10, -15), methods=("raw", "cpw", "drs-sk", "all")):
    """Right verdicts of ``seeds`` per cell, and in brackets the wrong faults (neither the
    right family nor "no fault detected")."""
    print("fault  SNR_dB " + " ".join(f"{m:>13}" for m in methods))
    for fault in SLIP:
        bases = [synthetic_base(fault, s) for s in range(seeds)]
        for snr in snrs:
            cells = []
            for m in methods:
                hits = wrong = 0
                for s, base in enumerate(bases):
                    x, kin = synthetic_record(base, s, snr, fault)
                    verdict = analyze_signal(x, FS, kin, methods=m.split("+")).verdict
                    hits += verdict == WANT[fault]
                    wrong += verdict not in (WANT[fault], NO_FAULT)
                cells.append(f"{hits:>5}/{seeds} ({wrong})")
            print(f"{fault:6} {snr:6g} " + " ".join(cells), flush=True)


if __name__ == "__main__":
    args = sys.argv[1:]
    chosen = ("raw", "cpw", "drs-sk", "all")
    if "--methods" in args:
        i = args.index("--methods")
        chosen = tuple(m for m in args[i + 1].split(",") if m)
        del args[i : i + 2]
    if "--synthetic" in args:
        rest = args[args.index("--synthetic") + 1 :]
        synthetic(int(rest[0]) if rest else 12, methods=chosen)
    else:
        main()
