"""Compiled code compiles once: a new process loads every numba kernel from the on-disk
cache (issue 12). Each workload runs in two fresh processes; the second must find every
kernel it used in the cache (numba's own cache statistics) and compile nothing."""

import json
import subprocess
import sys

import pytest

#: Short runs that reach every compiled kernel: the rigid and slip integrators and their
#: accelerations, the surface function, the quasi-static ball and roller kernels.
WORKLOAD = """
import math
from bearinglab.catalog import bearing_from_designation
from bearinglab.dynamics import Defect, simulate
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution

bearing, _ = bearing_from_designation("6205")
condition = OperatingCondition(radial_load=500.0, shaft_speed=1800 * math.pi / 30)
solve_load_distribution(bearing, condition)
# the roller kernels: the rollers' equilibrium (tapered) and the series shortcut (at rest)
taper, _ = bearing_from_designation("30205", rollers=True)
solve_load_distribution(taper, OperatingCondition(radial_load=500.0, axial_load=800.0))
cylinder, _ = bearing_from_designation("NU205", rollers=True)
solve_load_distribution(cylinder, OperatingCondition(radial_load=500.0))
for model in ("rigid", "slip"):
    simulate(bearing, condition, [Defect("outer", width=1e-3, depth=1e-4)], model=model,
             duration=0.002, sample_rate=40e3, settle=0.0)
"""

REPORT = """
import json, sys
from numba.core.registry import CPUDispatcher
out = {}
for name, module in list(sys.modules.items()):
    if not name.startswith("bearinglab"):
        continue
    for attr, value in vars(module).items():
        if isinstance(value, CPUDispatcher):
            stats = value.stats
            out[f"{name}.{attr}"] = {
                "cache": type(value._cache).__name__ != "NullCache",
                "compiled": len(value.signatures),
                "hits": sum(stats.cache_hits.values()),
                "misses": sum(stats.cache_misses.values())}
print(json.dumps(out))
"""


def _run() -> dict:
    done = subprocess.run(
        [sys.executable, "-c", WORKLOAD + REPORT], capture_output=True, text=True, check=True
    )
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.fixture(scope="module")
def second_run() -> dict:
    _run()  # the first process may compile (a fresh checkout)
    return _run()


def test_every_kernel_is_cacheable(second_run):
    assert second_run, "no compiled kernels were found"
    assert [name for name, s in second_run.items() if not s["cache"]] == []


def test_a_new_process_compiles_nothing(second_run):
    used = {name: s for name, s in second_run.items() if s["compiled"]}
    assert any("dopri_chunk_rigid" in name for name in used)
    assert any("rosenbrock_chunk" in name for name in used)
    assert any("_roller_compiled.ring_newton" in name for name in used)
    assert {name: s["misses"] for name, s in used.items() if s["misses"]} == {}
    assert all(s["hits"] >= s["compiled"] for s in used.values())


@pytest.mark.slow
def test_cache_directory_for_read_only_installs(tmp_path):
    """With NUMBA_CACHE_DIR (what a read-only site-packages install uses when numba cannot
    fall back to its per-user directory) the cache lives there and a second process loads
    from it."""
    import os

    code = (
        WORKLOAD.split("for model")[0]
        + "simulate(bearing, condition, [Defect('outer', width=1e-3, depth=1e-4)], "
        "duration=0.002, sample_rate=40e3, settle=0.0)\n" + REPORT
    )
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    for _ in range(2):
        done = subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env
        )
    stats = json.loads(done.stdout.strip().splitlines()[-1])
    rigid = next(s for name, s in stats.items() if name.endswith("dopri_chunk_rigid"))
    assert rigid["hits"] >= 1 and rigid["misses"] == 0
    assert list(tmp_path.rglob("*dopri_chunk_rigid*.nbi"))
