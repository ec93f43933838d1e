"""simulate and analyze on the command line (rigid model, 0.5 s at 20 kHz: fast)."""

import math

import pytest
from conftest import run_error, run_json

from bearinglab.cli import main
from bearinglab.errors import InputError
from bearinglab.inputs import parse_defect

SIM = [
    "simulate",
    "ER-16K",
    "--speed-rpm",
    "1750",
    "--radial-load-n",
    "50",
    "--duration-s",
    "0.5",
    "--sample-rate-hz",
    "20000",
]
OUTER = ["--defect", "outer:width_mm=1.2,depth_mm=0.25"]
ANALYZE = ["--designation", "ER-16K", "--speed-rpm", "1750"]
BPFO_HZ = 104.19


def test_simulate_outer_race_json(capsys):
    d = run_json(capsys, *SIM, *OUTER)
    for key in (
        "model",
        "sample_rate_hz",
        "duration_s",
        "kinematic",
        "likely_fault",
        "faults",
        "diagnosis",
        "spectrum",
        "cage_speed_ratio",
        "spin_speed_ratio",
        "defects",
        "output",
        "stats",
        "parameters",
        "warnings",
    ):
        assert key in d, key
    diag = d["diagnosis"]
    assert d["model"] == "rigid" and d["sample_rate_hz"] == 20000.0 and d["duration_s"] == 0.5
    assert d["kinematic"]["bpfo_hz"] == pytest.approx(BPFO_HZ, abs=0.01)
    assert d["likely_fault"] == "outer_race" and d["faults"] == ["outer_race"]
    bpfo = [p for p in diag["peaks"] if p["matched"] == "bpfo" and p["harmonic"] == 1]
    assert bpfo and bpfo[0]["frequency_hz"] == pytest.approx(BPFO_HZ, abs=2.0)  # 2 Hz bins
    assert {"frequency_hz", "amplitude", "matched", "harmonic"} <= diag["peaks"][0].keys()
    assert d["cage_speed_ratio"] is None and d["spin_speed_ratio"] is None  # rigid: no slip
    assert d["defects"] == [
        {"location": "outer", "width_mm": 1.2, "depth_mm": 0.25, "angle_deg": -90.0}
    ]
    assert d["output"] is None and d["stats"]["steps"] > 0
    # a bearinglab simulation is read by the raw and pre-whitened envelopes, whole band
    # (issue 11; cpw beside raw since issue 27 item 10)
    assert diag["band_hz"] is None and diag["methods"] == ["raw", "cpw"]


@pytest.mark.parametrize(
    "suffix, extra",
    [
        (".npz", []),
        (".wav", ["--channel", "channel_1", "--sample-rate-hz", "20000"]),  # WAV: no names
        (".mat", []),
        (".csv", []),
    ],
)
def test_simulate_output_then_analyze(tmp_path, capsys, suffix, extra):
    path = tmp_path / f"signal{suffix}"
    d = run_json(capsys, *SIM, *OUTER, "-o", str(path))
    assert d["output"] == str(path) and path.is_file()
    a = run_json(capsys, "analyze", str(path), *ANALYZE, *extra)
    for key in (
        "file",
        "channel",
        "sample_rate_hz",
        "kinematic",
        "peaks",
        "likely_fault",
        "scores",
        "band_hz",
        "ball_defect_frequency_hz",
    ):
        assert key in a, key
    assert a["file"] == str(path)
    assert a["channel"] == ("channel_1" if suffix == ".wav" else "acc_y")
    assert a["sample_rate_hz"] == pytest.approx(20000.0)
    assert a["likely_fault"] == "outer_race"
    assert a["scores"]["outer_race"] > a["scores"]["inner_race"]
    assert any(
        p["matched"] == "bpfo" and abs(p["frequency_hz"] - BPFO_HZ) <= 2.0 for p in a["peaks"]
    )


def test_analyze_reads_the_speed_from_the_file(tmp_path, capsys):
    path = tmp_path / "s.npz"
    run_json(capsys, *SIM, *OUTER, "-o", str(path))
    a = run_json(capsys, "analyze", str(path), "--designation", "ER-16K")
    assert a["kinematic"]["speed_rpm"] == pytest.approx(1750.0)
    assert a["likely_fault"] == "outer_race"
    # a WAV file records no speed
    wav = tmp_path / "s.wav"
    run_json(capsys, *SIM, *OUTER, "-o", str(wav))
    assert "--speed-rpm" in run_error(capsys, "analyze", str(wav), "--designation", "ER-16K")


def test_inner_race_is_diagnosed(capsys):
    d = run_json(capsys, *SIM, "--defect", "inner:width_mm=1.2,depth_mm=0.25")
    assert d["likely_fault"] == "inner_race"
    assert any(p["matched"] == "bpfi" for p in d["diagnosis"]["peaks"])


def test_ball_defect_is_found(capsys):
    # rigid model, 1 s: the ball-defect line (2 x BSF, 135.45 Hz) and its cage sidebands.
    # Over 0.5 s the ball series scored 2-12 (threshold 2.6) as the load moved by 0.1 N:
    # the defect's impacts follow the integrator's tolerance-level differences, and a few
    # cage turns decide; over 1 s it scored 13-25.
    one_second = [*SIM[:-4], "--duration-s", "1", *SIM[-2:]]
    d = run_json(capsys, *one_second, "--defect", "ball:width_mm=1.2")
    assert d["likely_fault"] == "ball"
    measured = d["diagnosis"]["ball_defect_frequency_hz"]
    assert measured == pytest.approx(d["kinematic"]["ball_defect_hz"], abs=2.0)
    assert d["defects"][0]["ball"] == 0


def test_human_output_and_plots(tmp_path, capsys):
    sim_png, an_png, npz = tmp_path / "sim.png", tmp_path / "an.png", tmp_path / "s.npz"
    assert main([*SIM, *OUTER, "-o", str(npz), "--plot", str(sim_png)]) == 0
    out = capsys.readouterr().out
    assert "verdict: outer race" in out and "1x bpfo" in out
    assert sim_png.read_bytes()[:4] == b"\x89PNG"
    assert (
        main(["analyze", str(npz), *ANALYZE, "--band-hz", "3000,7000", "--plot", str(an_png)]) == 0
    )
    out = capsys.readouterr().out
    assert "verdict: outer race" in out and "3000 - 7000 Hz" in out
    assert an_png.read_bytes()[:4] == b"\x89PNG"


def test_analyze_band_options(tmp_path, capsys):
    npz = tmp_path / "s.npz"
    run_json(capsys, *SIM, *OUTER, "-o", str(npz))
    assert run_json(capsys, "analyze", str(npz), *ANALYZE, "--band-hz", "none")["band_hz"] is None
    assert run_json(capsys, "analyze", str(npz), *ANALYZE, "--band-hz", "2000,6000")["band_hz"] == [
        2000.0,
        6000.0,
    ]
    for bad in ("2000", "6000,2000", "fast"):
        assert "--band-hz" in run_error(capsys, "analyze", str(npz), *ANALYZE, "--band-hz", bad)
    err = run_error(capsys, "analyze", str(npz), *ANALYZE, "--band-hz", "2000,15000")
    assert "--band-hz" in err and "Nyquist" in err
    assert "--channel" in run_error(capsys, "analyze", str(npz), *ANALYZE, "--channel", "DE")


@pytest.mark.parametrize(
    "spec, why",
    [
        ("outer", "width_mm is required"),
        ("outer:width_mm=-1", "width_mm must be > 0"),
        ("core:width_mm=1", "unknown location 'core'"),
        ("outer:foo=1", "unknown key 'foo'"),
        ("outer:width_mm=1,width_mm=2", "given twice"),
        ("outer:width_mm=abc", "not a number"),
        ("ball:width_mm=1,ball=1.5", "not a whole number"),
        ("inner:width_mm=1,ball=0", "unknown key 'ball'"),
        ("outer:width_mm=9", "less than the ball diameter"),
        ("ball:width_mm=1,ball=9", "a ball index in [0, 8]"),
    ],
)
def test_bad_defect_specs(capsys, spec, why):
    err = run_error(capsys, *SIM, "--defect", spec)
    assert err.startswith("error: --defect = ") and repr(spec) in err
    assert "LOCATION outer, inner, ball" in err and why in err


def test_defect_spec_units_and_angles():
    d = parse_defect("outer:width_mm=1.2,depth_mm=0.25,angle_deg=270")
    assert d.width == pytest.approx(1.2e-3) and d.depth == pytest.approx(0.25e-3)
    assert d.angle == pytest.approx(-math.pi / 2)
    assert parse_defect("outer:width_mm=1").angle == pytest.approx(-math.pi / 2)  # bottom
    assert parse_defect("outer:width_mm=1,angle_deg=90").angle == pytest.approx(math.pi / 2)
    ball = parse_defect(" Ball : width_mm=1.2 , ball=3 ")
    assert ball.location == "ball" and ball.ball == 3 and ball.depth is None
    with pytest.raises(InputError):
        parse_defect("outer:width_mm=inf")


@pytest.mark.parametrize(
    "args, flag",
    [
        (["--duration-s", "0"], "--duration-s"),
        (["--duration-s", "0.001"], "--duration-s"),
        (["--sample-rate-hz", "-5"], "--sample-rate-hz"),
        (["--noise-ms2", "-1"], "--noise-ms2"),
        # slips of the keyboard: an overflow or an integrator that stalls, not named
        (["--noise-ms2", "1e300"], "--noise-ms2 = 1e+300 is not allowed"),
        (["--sample-rate-hz", "1e9"], "--sample-rate-hz = 1000000000 is not allowed"),
        (["--settle-s", "1e9"], "--settle-s = 1000000000 is not allowed"),
        (["--model", "slip", "--oil-fraction", "-1"], "--oil-fraction = -1 is not allowed"),
        (["--speed-rpm", "0"], "--speed-rpm"),
        (["--radial-load-n", "-3"], "--radial-load-n"),
        (["-o", "signal.txt"], "--output"),
        (["-o", "no/such/dir/signal.npz"], "--output"),
        (["--plot", "plot.txt"], "--plot"),
        (["--sample-rate-hz", "20000.5", "-o", "s.wav"], "--sample-rate-hz"),
    ],
)
def test_bad_simulate_options(tmp_path, monkeypatch, capsys, args, flag):
    monkeypatch.chdir(tmp_path)
    assert flag in run_error(capsys, *SIM, *OUTER, *args)
    assert not list(tmp_path.iterdir())


def test_slip_model_needs_ring_dimensions(capsys):
    err = run_error(capsys, *SIM, "--model", "slip")
    assert "--bore-mm" in err and "--outside-diameter-mm" in err


def test_analyze_missing_file(tmp_path, capsys):
    missing = tmp_path / "missing.npz"
    err = run_error(capsys, "analyze", str(missing), *ANALYZE)
    assert "SIGNAL_FILE" in err and str(missing) in err
    assert "--sample-rate-hz" in run_error(
        capsys, "analyze", str(missing), *ANALYZE, "--sample-rate-hz", "-1"
    )


# ------------------------------------------------------------------ form errors (issue 5)
ER16K_BPFI_HZ = 158.31


def _line(peaks, name, harmonic=1):
    found = [p for p in peaks if p.get("matched") == name and p.get("harmonic") == harmonic]
    return max(found, key=lambda p: p["amplitude"]) if found else None


def test_simulate_with_inner_waviness_shows_its_line_in_the_plain_spectrum(capsys):
    """Inner-race waviness of order Z = 9 under a radial load moves the ring at
    Z (f_i - f_c) = BPFI: a line of the plain displacement spectrum (spectrum_peaks),
    absent from the healthy bearing's."""
    wavy = run_json(capsys, *SIM, "--waviness", "inner:order=9,amplitude_um=1")
    healthy = run_json(capsys, *SIM)
    for d in (wavy, healthy):
        assert d["spectrum"]["channel"] == "disp_y" and d["spectrum"]["resolution_hz"] == 2.0
        assert d["spectrum"]["peaks"]
        assert {"frequency_hz", "amplitude", "matched", "harmonic"} <= d["spectrum"]["peaks"][
            0
        ].keys()
    line = _line(wavy["spectrum"]["peaks"], "bpfi")
    assert line is not None and line["frequency_hz"] == pytest.approx(ER16K_BPFI_HZ, abs=2.0)
    assert line["amplitude"] == max(p["amplitude"] for p in wavy["spectrum"]["peaks"])
    assert _line(healthy["spectrum"]["peaks"], "bpfi") is None
    assert wavy["imperfections"]["waviness"] == [
        {"race": "inner", "order": 9, "amplitude_um": 1.0, "phase_deg": 0.0}
    ]
    assert healthy["imperfections"] is None
    assert any("form errors" in w for w in wavy["warnings"])


def test_outer_waviness_q_z_plus_1_raises_the_bpfo_line(capsys):
    """Outer-race order q = kZ + 1 = 10 excites k Z f_c = BPFO, where the healthy
    bearing's ball-pass line already is (its varying compliance, named so): match_peaks
    labels it bpfo, and it grows."""
    wavy = run_json(capsys, *SIM, "--waviness", "outer:order=10,amplitude_um=1")
    healthy = run_json(capsys, *SIM)
    grown = _line(wavy["spectrum"]["peaks"], "bpfo")
    plain = _line(healthy["spectrum"]["peaks"], "varying_compliance")
    assert _line(healthy["spectrum"]["peaks"], "bpfo") is None
    assert grown["frequency_hz"] == pytest.approx(BPFO_HZ, abs=2.0)
    assert grown["amplitude"] > 1.5 * plain["amplitude"]


def test_simulate_ball_size_errors_are_seeded(capsys):
    one = run_json(capsys, *SIM, "--ball-size-error-um", "4", "--seed", "3")
    again = run_json(capsys, *SIM, "--ball-size-error-um", "4", "--seed", "3")
    errors = one["imperfections"]["ball_size_errors"]["ball_size_errors_um"]
    assert (
        len(errors) == 9
        and errors == again["imperfections"]["ball_size_errors"]["ball_size_errors_um"]
    )
    assert max(errors) - min(errors) <= 4.0 and max(abs(e) for e in errors) <= 2.0
    assert one["spectrum"]["peaks"] == again["spectrum"]["peaks"]
    # the errors turn with the cage: a line at the cage frequency (the healthy bearing
    # has none there)
    assert _line(one["spectrum"]["peaks"], "ftf") is not None
    assert _line(run_json(capsys, *SIM)["spectrum"]["peaks"], "ftf") is None


def test_simulate_plots_both_spectra(tmp_path, capsys):
    png = tmp_path / "spectra.png"
    assert main([*SIM, "--waviness", "outer:order=10,amplitude_um=1", "--plot", str(png)]) == 0
    out = capsys.readouterr().out
    assert "plain spectrum lines" in out and "form errors" in out
    assert png.read_bytes()[:4] == b"\x89PNG"


@pytest.mark.parametrize(
    "args, words",
    [
        (["--waviness", "ball:order=2,amplitude_um=0.1,ball=9"], ["a ball index in [0, 8]"]),
        (["--waviness", "outer:amplitude_um=1"], ["--waviness", "order is required"]),
        (
            ["--surface3d", "outer:amplitude_um=0.1,length_circ_mm=-1,length_axial_mm=1"],
            ["--surface3d", "length_circ_mm must be > 0"],
        ),
        (["--ball-size-error-um", "1,x"], ["--ball-size-error-um"]),
        (["--spectrum-channel", "cage_speed"], ["--spectrum-channel"]),
    ],
)
def test_bad_form_error_options(capsys, args, words):
    err = run_error(capsys, *SIM, *args)
    for word in words:
        assert word in err, err
