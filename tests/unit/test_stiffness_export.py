"""Stiffness export: CSV table and the ROSS bearing element (stand-ins for the mapping and
the keyword ROSS wants; the real package for a two-bearing rotor and its modes)."""

import math
import sys
import types

import numpy as np
import pytest
from conftest import in_ci

from bearinglab.catalog import bearing_from_designation
from bearinglab.cli import main
from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution
from bearinglab.rotordynamics import KRAMER_FACTOR, bearing_element, ross_bearing, ross_element

BEARING = BallBearing(
    ball_count=9,
    ball_diameter=7.94e-3,
    pitch_diameter=39.04e-3,
    diametral_clearance=15e-6,
    name="6205",
)
R = solve_load_distribution(
    BEARING, OperatingCondition(radial_load=500.0, axial_load=100.0, shaft_speed=3000 * np.pi / 30)
)


def _fake_ross(monkeypatch, speed_keyword):
    """A stand-in ross module whose BearingElement takes the speed as ``speed_keyword``
    (ROSS 2: frequency=; ROSS 3: speed=, with frequency= for the whirl frequency)."""
    calls = {}

    class Ross2Element:
        def __init__(
            self,
            n,
            kxx,
            cxx,
            kyy=None,
            kxy=0,
            kyx=0,
            cyy=None,
            kzz=0,
            frequency=None,
            tag=None,
            **kwargs,
        ):
            calls.update({k: v for k, v in locals().items() if k not in ("self", "kwargs")})
            calls.update(kwargs)

    class Ross3Element:
        def __init__(
            self,
            n,
            kxx,
            cxx,
            kyy=None,
            kxy=0,
            kyx=0,
            cyy=None,
            kzz=0,
            frequency=None,
            speed=None,
            tag=None,
            **kwargs,
        ):
            calls.update({k: v for k, v in locals().items() if k not in ("self", "kwargs")})
            calls.update(kwargs)

    fake = types.ModuleType("ross")
    fake.BearingElement = Ross3Element if speed_keyword == "speed" else Ross2Element
    monkeypatch.setitem(sys.modules, "ross", fake)
    return calls


def test_stiffness_frame_names_rows_and_columns():
    f = R.stiffness_frame()
    assert list(f.index) == list(f.columns) == ["x", "y", "z", "tilt_x", "tilt_y"]
    assert f.loc["y", "y"] == R.stiffness_matrix[1, 1]


def test_ross_element_maps_the_matrix(monkeypatch):
    calls = _fake_ross(monkeypatch, "frequency")
    ross_element(R, 3, damping=50.0)
    k = R.stiffness_matrix
    assert calls["n"] == 3 and calls["tag"] == "6205 n3"  # the node in the tag
    assert (calls["kxx"], calls["kyy"], calls["kxy"], calls["kyx"], calls["kzz"]) == (
        k[0, 0],
        k[1, 1],
        k[0, 1],
        k[1, 0],
        k[2, 2],
    )
    assert calls["cxx"] == calls["cyy"] == 50.0
    assert calls["frequency"] == [pytest.approx(3000 * np.pi / 30)]  # ROSS 2: the speed


def test_ross_3_gets_the_speed_as_speed(monkeypatch):
    calls = _fake_ross(monkeypatch, "speed")
    ross_element(R, 1, tag="front")
    assert calls["speed"] == [pytest.approx(3000 * np.pi / 30)]
    assert calls["frequency"] is None  # ROSS 3's whirl-frequency axis
    assert calls["tag"] == "front"
    # default damping: Kramer's rule c = 1e-5 s x k
    assert calls["cxx"] == pytest.approx(KRAMER_FACTOR * R.stiffness_matrix[0, 0])
    assert calls["cyy"] == pytest.approx(KRAMER_FACTOR * R.stiffness_matrix[1, 1])


def test_coefficients_at_several_speeds(monkeypatch):
    calls = _fake_ross(monkeypatch, "frequency")
    speeds = [0.0, 6000.0, 12000.0, 18000.0]
    bearing_element(BEARING, 2, speeds_rpm=speeds, radial_load=500.0, axial_load=100.0)
    assert calls["frequency"] == pytest.approx([s * math.pi / 30 for s in speeds])
    assert len(calls["kxx"]) == len(calls["cyy"]) == 4
    for rpm, kyy in zip(speeds, calls["kyy"], strict=True):
        r = solve_load_distribution(
            BEARING,
            OperatingCondition(radial_load=500.0, axial_load=100.0, shaft_speed=rpm * math.pi / 30),
        )
        assert kyy == pytest.approx(r.stiffness_matrix[1, 1], rel=1e-6)
    assert calls["kyy"][0] != pytest.approx(calls["kyy"][-1], rel=1e-3)  # speed matters


def test_bad_damping_and_speeds_are_refused(monkeypatch):
    _fake_ross(monkeypatch, "frequency")
    with pytest.raises(InputError, match="damping"):
        ross_element(R, 0, damping=-1.0)
    with pytest.raises(InputError, match="speeds_rpm"):
        bearing_element(BEARING, 0, speeds_rpm=[-5.0], radial_load=100.0)
    with pytest.raises(InputError, match="speeds"):
        bearing_element(BEARING, 0, speeds_rpm=[3000.0, 1000.0], radial_load=100.0)


def test_ross_element_without_ross_says_how_to_get_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "ross", None)
    with pytest.raises(ImportError, match="pip install ross-rotordynamics"):
        ross_element(R, 0)


def test_static_writes_the_stiffness_csv(tmp_path, capsys):
    out = tmp_path / "k.csv"
    assert (
        main(["static", "6205", "--radial-load-n", "500", "--stiffness-csv", str(out), "--json"])
        == 0
    )
    capsys.readouterr()
    lines = out.read_text().splitlines()
    assert lines[0] == ",x,y,z,tilt_x,tilt_y" and len(lines) == 6


def test_one_line_from_a_designation(monkeypatch):
    calls = _fake_ross(monkeypatch, "frequency")
    ross_bearing("6205", n=2, radial_load=500.0, speed_rpm=3000.0)
    assert calls["n"] == 2 and 50e6 < calls["kyy"] < 300e6  # about 100 N/um
    assert calls["tag"].endswith("n2")


# ------------------------------------------------------------------ the real ROSS


@pytest.fixture(scope="module")
def ross():
    import importlib.util

    from bearinglab.rotordynamics import import_ross

    if importlib.util.find_spec("ross") is None and not in_ci():
        pytest.skip("ROSS is not installed (CI installs it: .ci/run)")
    return import_ross()  # quietly: ROSS warns at import about an optional library


def test_two_bearing_rotor_with_the_real_ross(ross):
    # a 25 mm steel shaft, 0.6 m between two 6205 bearings, a disk of ~10 kg in the middle;
    # both bearings from one designation (unique tags by node), coefficients at four speeds;
    # ROSS assembles the rotor and runs a modal analysis at 3000 rpm
    steel = ross.materials.steel
    shaft = [ross.ShaftElement(L=0.1, idl=0.0, odl=0.025, material=steel) for _ in range(6)]
    disk = ross.DiskElement.from_geometry(n=3, material=steel, width=0.05, i_d=0.025, o_d=0.18)
    speeds = [0.0, 2000.0, 4000.0, 6000.0]
    bearings = [ross_bearing("6205", n=node, radial_load=60.0, speed_rpm=speeds) for node in (0, 6)]
    assert bearings[0].tag != bearings[1].tag
    rotor = ross.Rotor(shaft, [disk], bearings)
    omega = 3000 * math.pi / 30
    modal = rotor.run_modal(speed=omega)
    wn = np.sort(np.asarray(modal.wn))
    assert np.all(np.isfinite(wn)) and wn[0] > 0
    # the first bending pair: the disk (plus half the shaft) on the shaft's midspan
    # stiffness 48 E I / L^3 in series with the two bearings, once with kxx, once with kyy
    b6205 = bearing_from_designation("6205")[0]
    r = solve_load_distribution(b6205, OperatingCondition(radial_load=60.0, shaft_speed=omega))
    e_i = steel.E * math.pi * 0.025**4 / 64
    k_shaft = 48 * e_i / 0.6**3
    mass = disk.m + 0.5 * steel.rho * math.pi * 0.0125**2 * 0.6
    for k_b in (r.stiffness_matrix[0, 0], r.stiffness_matrix[1, 1]):
        estimate = math.sqrt(1.0 / (1.0 / k_shaft + 1.0 / (2.0 * k_b)) / mass)
        assert np.min(np.abs(wn / estimate - 1.0)) < 0.03, (estimate, wn[:6])
    # the element holds bearinglab's stiffness at the speeds ROSS interpolates between
    r4 = solve_load_distribution(
        b6205, OperatingCondition(radial_load=60.0, shaft_speed=4000 * math.pi / 30)
    )
    kyy = float(np.asarray(bearings[0].kyy_interpolated(4000 * math.pi / 30)))
    assert kyy == pytest.approx(r4.stiffness_matrix[1, 1], rel=1e-6)
