"""Speed of the vectorised exact Hertz solution, as a ratio against a scalar reference.

The reference solves the exact ellipticity relation one contact at a time with
scipy.optimize.brentq (what a straightforward implementation would do); bearinglab solves
all contacts at once with a vectorised Newton iteration. Both are timed in this run on the
same inputs, and their answers are compared.

Run: .venv/bin/python benchmarks/bench_hertz.py [N]
"""

import sys
import time

import numpy as np
from scipy import optimize, special

from bearinglab.contact import hertz


def reference_ellipticity(ratio: float) -> float:
    def f(k):
        m = 1 - 1 / k**2
        kk, ee = special.ellipk(m), special.ellipe(m)
        return (k**2 * ee - kk) / (kk - ee) - ratio

    return optimize.brentq(f, 1 + 1e-9, 2 * ratio + 2, xtol=1e-14)


def main(n: int = 20000) -> None:
    ratios = np.random.default_rng(1).uniform(2.0, 60.0, n)
    t0 = time.perf_counter()
    ref = np.array([reference_ellipticity(r) for r in ratios])
    t1 = time.perf_counter()
    ours = hertz.ellipticity(ratios)
    t2 = time.perf_counter()
    err = np.max(np.abs(ours / ref - 1))
    print(
        f"{n} contacts: scalar brentq {t1 - t0:.3f} s, vectorised {t2 - t1:.4f} s, "
        f"speed-up x{(t1 - t0) / (t2 - t1):.0f}, max relative difference {err:.1e}"
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 20000)
