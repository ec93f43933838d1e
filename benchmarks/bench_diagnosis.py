"""Speed of the diagnosis of one record, as a ratio against a plain SciPy envelope + FFT.

A 10 s record at 12 kHz (the CWRU drive-end record 105 when ../shared/data/real is there,
otherwise synthetic impacts in noise): ``analyze_signal`` with each method and with the
default, against ``np.abs(scipy.signal.hilbert(x))`` and ``np.fft.rfft`` of the same record
(what a user would write by hand), in one run, best of five calls each. Also the Hilbert
transform at an awkward length (480 001 samples) with and without the fast-length padding
of ``bearinglab.signal.spectra.analytic`` (issue 12 item 9).

Run: .venv/bin/python benchmarks/bench_diagnosis.py
"""

import math
import time
from pathlib import Path

import numpy as np
import scipy.signal

from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import analyze_signal
from bearinglab.kinematics import defect_frequencies
from bearinglab.signal.spectra import analytic

REAL = Path(__file__).resolve().parents[2] / "shared" / "data" / "real" / "cwru" / "12k_DE"
FS = 12000.0


def record():
    if (REAL / "105.mat").is_file():
        import scipy.io

        return scipy.io.loadmat(REAL / "105.mat")["X105_DE_time"].ravel()[:int(10 * FS)], "105"
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


def main():
    x, name = record()
    kin = defect_frequencies(bearing_from_designation("6205-2RS")[0], 1797 * math.pi / 30)

    def plain():
        env = np.abs(scipy.signal.hilbert(x - x.mean()))
        return np.abs(np.fft.rfft(env - env.mean()))

    analyze_signal(x, FS, kin)  # warm-up (imports)
    ref = best(plain)
    print(f"record {name}: {x.size} samples at {FS:g} Hz")
    print(f"plain SciPy envelope + FFT: {1e3 * ref:.1f} ms")
    for methods in ("raw", "cpw", "drs-sk", "all"):
        t = best(lambda m=methods: analyze_signal(x, FS, kin, methods=m))
        print(f"analyze_signal(methods={methods!r}): {1e3 * t:.0f} ms, x{t / ref:.1f}")
    odd = np.random.default_rng(1).standard_normal(480_001)
    slow = best(lambda: scipy.signal.hilbert(odd), 3)
    fast = best(lambda: analytic(odd), 3)
    print(f"Hilbert at 480 001 samples: scipy {1e3 * slow:.0f} ms, padded to a fast length "
          f"{1e3 * fast:.0f} ms (x{slow / fast:.1f})")


if __name__ == "__main__":
    main()
