"""The library's faces (issue 12): the main entry points at top level, imported lazily,
and speeds that cannot silently be rpm where rad/s is meant."""

import math
import subprocess
import sys

import pytest

import bearinglab as bl
from bearinglab.errors import InputError


def test_every_top_level_name_resolves():
    for name in bl.__all__:
        assert getattr(bl, name) is not None, name
    with pytest.raises(AttributeError):
        bl.no_such_name  # noqa: B018


def test_import_bearinglab_is_light():
    code = (
        "import sys, bearinglab; "
        "print(sorted(m for m in sys.modules if m.split('.')[0] in "
        "('numpy', 'scipy', 'pandas', 'numba', 'matplotlib')))"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout.strip()
    assert out == "[]"


def test_speed_in_rpm_by_keyword():
    bearing, _ = bl.bearing_from_designation("6205")
    by_rpm = bl.defect_frequencies(bearing, speed_rpm=1797)
    by_rad = bl.defect_frequencies(bearing, 1797 * math.pi / 30)
    assert by_rpm.hz("bpfo") == pytest.approx(by_rad.hz("bpfo"), rel=1e-14)
    with pytest.raises(InputError):
        bl.defect_frequencies(bearing, 1.0, speed_rpm=1797)  # not both
    with pytest.raises(InputError):
        bl.defect_frequencies(bearing)  # not neither
    condition = bl.OperatingCondition.at_rpm(1797, radial_load=500.0)
    assert condition.speed_rpm == pytest.approx(1797)
    assert bl.rad_s_to_rpm(bl.rpm_to_rad_s(1797)) == pytest.approx(1797)


def test_speed_errors_are_in_rpm():
    """Issue 22: a speed given in rpm was reported back in rad/s (the command line then
    printed `--speed-rpm = -5 ... expected a speed >= 0 [rad/s]`)."""
    from bearinglab.cli._inputs import worded
    from bearinglab.inputs import INPUTS, restate
    from bearinglab.noise import noise_analysis
    from bearinglab.operating import OperatingCondition

    with pytest.raises(InputError) as info:
        OperatingCondition.at_rpm(-5.0, radial_load=100.0)
    assert (info.value.parameter, info.value.value) == ("speed_rpm", -5.0)
    assert "rpm" in info.value.allowed and "rad/s" not in str(info.value)
    bearing, _ = bl.bearing_from_designation("6205")
    stopped = OperatingCondition(radial_load=1000.0)
    checks = [
        lambda: OperatingCondition(shaft_speed=-3 * math.pi),
        lambda: bl.defect_frequencies(bearing, -math.pi),
        lambda: bl.rating_life(bearing, stopped),
        lambda: noise_analysis(bearing, stopped),
    ]
    for check in checks:
        with pytest.raises(InputError) as info:
            check()
        err = info.value
        assert err.parameter == "shaft_speed" and "rad/s" not in str(err), str(err)
        assert err.unit == "rpm" and err.allowed.endswith("rpm")
    # what the command line makes of the first: the option and the range, both in rpm
    with pytest.raises(InputError) as info:
        OperatingCondition(shaft_speed=-3 * math.pi)
    told = str(
        worded(restate(info.value, {"speed_rpm": -90.0}, INPUTS), {"speed_rpm": "--speed-rpm"})
    )
    assert told == "--speed-rpm = -90 is not allowed: expected a finite speed >= 0 rpm"
