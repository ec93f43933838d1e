"""Stiffness export: CSV table and the ROSS bearing element."""

import sys
import types

import numpy as np
import pytest

from bearinglab.cli import main
from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution

R = solve_load_distribution(
    BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3,
                diametral_clearance=15e-6, name="6205"),
    OperatingCondition(radial_load=500.0, axial_load=100.0, shaft_speed=3000 * np.pi / 30))


def test_stiffness_frame_names_rows_and_columns():
    f = R.stiffness_frame()
    assert list(f.index) == list(f.columns) == ["x", "y", "z", "tilt_x", "tilt_y"]
    assert f.loc["y", "y"] == R.stiffness_matrix[1, 1]


def test_to_ross_maps_the_matrix(monkeypatch):
    calls = {}
    fake = types.ModuleType("ross")
    fake.BearingElement = lambda **kw: calls.update(kw) or "element"
    monkeypatch.setitem(sys.modules, "ross", fake)
    assert R.to_ross(n=3, damping=50.0) == "element"
    k = R.stiffness_matrix
    assert calls["n"] == 3 and calls["tag"] == "6205"
    assert (calls["kxx"], calls["kyy"], calls["kxy"], calls["kyx"], calls["kzz"]) == (
        k[0, 0], k[1, 1], k[0, 1], k[1, 0], k[2, 2])
    assert calls["cxx"] == calls["cyy"] == 50.0
    assert calls["frequency"] == [pytest.approx(3000 * np.pi / 30)]


def test_to_ross_with_the_real_package():
    ross = pytest.importorskip("ross")
    element = R.to_ross(n=0)
    assert isinstance(element, ross.BearingElement)


def test_to_ross_without_ross_says_how_to_get_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "ross", None)
    with pytest.raises(ImportError, match="pip install ross-rotordynamics"):
        R.to_ross(n=0)


def test_static_writes_the_stiffness_csv(tmp_path, capsys):
    out = tmp_path / "k.csv"
    assert main(["static", "6205", "--radial-load-n", "500", "--stiffness-csv", str(out),
                 "--json"]) == 0
    capsys.readouterr()
    lines = out.read_text().splitlines()
    assert lines[0] == ",x,y,z,tilt_x,tilt_y" and len(lines) == 6


def test_one_line_from_a_designation(monkeypatch):
    from bearinglab.rotordynamics import ross_bearing

    calls = {}
    fake = types.ModuleType("ross")
    fake.BearingElement = lambda **kw: calls.update(kw) or "element"
    monkeypatch.setitem(sys.modules, "ross", fake)
    assert ross_bearing("6205", n=2, radial_load=500.0, speed_rpm=3000.0) == "element"
    assert calls["n"] == 2 and 50e6 < calls["kyy"] < 300e6      # about 100 N/um
