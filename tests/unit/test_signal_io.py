"""Signal records and their files (bearinglab.signal.record, bearinglab.signal.io)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.io
import scipy.io.wavfile

from bearinglab.errors import InputError
from bearinglab.signal import SUFFIXES, Signal, read_signal, write_signal

FS = 12000.0


@pytest.fixture
def record():
    rng = np.random.default_rng(11)
    return Signal(
        {"DE": rng.standard_normal(600) * 0.3, "FE": rng.standard_normal(600)},
        FS,
        {"speed_rpm": 1797.0, "designation": "6205-2RS JEM SKF", "source": "test"},
    )


def _same_data(a: Signal, b: Signal, rtol=1e-12):
    assert a.sample_rate == pytest.approx(b.sample_rate, rel=1e-12)
    assert len(a.names) == len(b.names)
    for x, y in zip(a.channels.values(), b.channels.values(), strict=True):
        np.testing.assert_allclose(x, y, rtol=rtol, atol=0)


# ---------------------------------------------------------------- Signal


def test_signal_properties(record):
    assert record.names == ("DE", "FE")
    assert record.n_samples == 600
    assert record.duration == pytest.approx(0.05)
    assert record.time[-1] == pytest.approx(599 / FS)
    assert record.channel() is record.channels["DE"]
    assert record.select("FE").names == ("FE",)
    with pytest.raises(ValueError):
        record.channels["DE"][0] = 1.0  # read-only samples


def test_unknown_channel_lists_the_names(record):
    with pytest.raises(InputError, match="DE") as err:
        record.channel("BA")
    assert err.value.parameter == "channel"


@pytest.mark.parametrize(
    ("channels", "rate", "parameter"),
    [
        ({}, FS, "channels"),
        ({"a": np.ones(20), "b": np.ones(21)}, FS, "channels"),
        ({"a": np.r_[np.ones(20), np.inf]}, FS, "channels['a']"),
        ({"a": np.ones(15)}, FS, "channels['a']"),
        ({"a": np.ones((20, 2))}, FS, "channels['a']"),
        ({"a": np.ones(20)}, 0.0, "sample_rate"),
        ({"a": np.ones(20)}, -FS, "sample_rate"),
        ({"a": np.ones(20)}, "fast", "sample_rate"),
    ],
)
def test_signal_validation(channels, rate, parameter):
    with pytest.raises(InputError) as err:
        Signal(channels, rate)
    assert err.value.parameter == parameter


def test_metadata_must_be_json_able():
    with pytest.raises(InputError) as err:
        Signal({"a": np.ones(20)}, FS, {"when": object()})
    assert err.value.parameter == "metadata"
    assert Signal({"a": np.ones(20)}, FS, {"speed_rpm": np.float64(1797)}).metadata


# ---------------------------------------------------------------- round trips


def test_npz_round_trip_keeps_everything(tmp_path, record):
    back = read_signal(write_signal(tmp_path / "r.npz", record))
    _same_data(record, back)
    assert back.names == record.names
    assert back.metadata == record.metadata


def test_csv_round_trip_infers_the_rate(tmp_path, record):
    path = write_signal(tmp_path / "r.csv", record)
    assert path.read_text().splitlines()[0] == "time_s,DE,FE"
    back = read_signal(path)
    _same_data(record, back)
    assert back.names == record.names
    assert back.metadata == {"source": "r.csv"}


def test_wav_round_trip_in_float32(tmp_path, record):
    back = read_signal(write_signal(tmp_path / "r.wav", record))
    _same_data(record, back, rtol=1e-6)
    assert back.names == ("channel_0", "channel_1")
    mono = read_signal(write_signal(tmp_path / "m.wav", record.select("FE")))
    np.testing.assert_allclose(mono.channel(), record.channel("FE"), rtol=1e-6)


def test_mat_round_trip_in_the_cwru_layout(tmp_path, record):
    path = write_signal(tmp_path / "r.mat", record)
    variables = scipy.io.loadmat(path)
    assert variables["X000_DE_time"].shape == (600, 1)
    assert variables["X000RPM"].item() == 1797.0
    back = read_signal(path)
    _same_data(record, back)
    assert back.names == record.names
    assert back.metadata["speed_rpm"] == 1797.0
    assert back.metadata["designation"] == record.metadata["designation"]


def test_read_one_channel_and_override_the_rate(tmp_path, record):
    path = write_signal(tmp_path / "r.npz", record)
    back = read_signal(path, sample_rate=48000.0, channel="FE")
    assert back.names == ("FE",) and back.sample_rate == 48000.0
    with pytest.raises(InputError) as err:
        read_signal(path, channel="BA")
    assert err.value.parameter == "channel"


# ---------------------------------------------------------------- CWRU files


def _cwru(path, rpm=True):
    rng = np.random.default_rng(5)
    variables = {
        "X097_DE_time": rng.standard_normal((1200, 1)),
        "X097_FE_time": rng.standard_normal((1200, 1)),
    }
    if rpm:
        variables["X097RPM"] = np.array([[1797]], dtype=np.uint16)
    scipy.io.savemat(path, variables)
    return variables


def test_cwru_mat_needs_the_sample_rate(tmp_path):
    path = tmp_path / "97.mat"
    variables = _cwru(path)
    with pytest.raises(InputError) as err:
        read_signal(path)
    assert err.value.parameter == "sample_rate_hz"
    s = read_signal(path, sample_rate=12000)
    assert s.names == ("DE", "FE")
    assert s.sample_rate == 12000.0
    assert s.metadata["speed_rpm"] == 1797.0
    assert s.metadata["cwru_record"] == "X097"
    np.testing.assert_array_equal(s.channel("FE"), variables["X097_FE_time"][:, 0])


def test_cwru_mat_without_rpm_and_with_two_records(tmp_path):
    path = tmp_path / "98.mat"
    rng = np.random.default_rng(6)
    scipy.io.savemat(
        path,
        {
            "X099_DE_time": rng.standard_normal((64, 1)),
            "X098_DE_time": rng.standard_normal((64, 1)),
            "X098_BA_time": rng.standard_normal((64, 1)),
        },
    )
    s = read_signal(path, sample_rate=48000)
    assert s.metadata["cwru_record"] == "X098"  # the one named like the file
    assert s.names == ("DE", "BA") and "speed_rpm" not in s.metadata


def test_cwru_records_chosen_by_name_and_never_guessed(tmp_path):
    """A file holding several records none of which is named like it is refused until the
    record is named; the record can be named as X099, 099, 99; a record asked of a file
    without CWRU records, or of another format, is refused."""
    rng = np.random.default_rng(7)
    variables = {f"X{n}_DE_time": rng.standard_normal((64, 1)) for n in ("098", "099")}
    path = tmp_path / "500.mat"
    scipy.io.savemat(path, variables)
    with pytest.raises(InputError) as err:
        read_signal(path, sample_rate=48000)
    assert err.value.parameter == "record" and "X098" in err.value.allowed
    for name in ("X099", "099", 99, "x099_DE_time"):
        s = read_signal(path, sample_rate=48000, record=name)
        assert s.metadata["cwru_record"] == "X099"
        np.testing.assert_array_equal(s.channel("DE"), variables["X099_DE_time"][:, 0])
    with pytest.raises(InputError, match="X098"):
        read_signal(path, sample_rate=48000, record="X097")
    scipy.io.savemat(tmp_path / "s.mat", {"bearing": {"gs": np.arange(32.0), "sr": 1000.0}})
    with pytest.raises(InputError, match="no CWRU records"):
        read_signal(tmp_path / "s.mat", record="X099")
    write_signal(tmp_path / "r.npz", Signal({"a": np.zeros(32)}, 1000.0))
    with pytest.raises(InputError) as err:
        read_signal(tmp_path / "r.npz", record="X099")
    assert err.value.parameter == "record"


def test_foreign_mat_and_csv_files(tmp_path):
    scipy.io.savemat(tmp_path / "v.mat", {"vib": np.arange(32.0), "fs": 1000.0})
    s = read_signal(tmp_path / "v.mat", sample_rate=1000.0)
    assert s.names == ("vib",)
    (tmp_path / "v.csv").write_text("a,b\n" + "".join(f"{i},{-i}\n" for i in range(20)))
    with pytest.raises(InputError) as err:
        read_signal(tmp_path / "v.csv")
    assert err.value.parameter == "sample_rate"
    assert read_signal(tmp_path / "v.csv", sample_rate=10.0).names == ("a", "b")


def test_integer_pcm_wav_reads_as_fractions_of_full_scale(tmp_path):
    scipy.io.wavfile.write(tmp_path / "p.wav", 8000, np.full(64, 16384, dtype=np.int16))
    s = read_signal(tmp_path / "p.wav")
    assert s.sample_rate == 8000.0
    np.testing.assert_allclose(s.channel(), 0.5)


# ---------------------------------------------------------------- bad inputs


def test_unknown_suffix(tmp_path, record):
    for call in (
        lambda: write_signal(tmp_path / "r.txt", record),
        lambda: read_signal(tmp_path / "r.txt"),
    ):
        with pytest.raises(InputError) as err:
            call()
        assert err.value.parameter == "path"
        assert all(s in str(err.value) for s in SUFFIXES)
    assert list(tmp_path.iterdir()) == []


def test_missing_file_and_directory(tmp_path, record):
    with pytest.raises(InputError) as err:
        read_signal(tmp_path / "none.npz")
    assert err.value.parameter == "path"
    with pytest.raises(InputError) as err:
        write_signal(tmp_path / "no" / "r.npz", record)
    assert err.value.parameter == "path"


@pytest.mark.parametrize("suffix", SUFFIXES)
def test_corrupt_files_give_input_errors(tmp_path, suffix):
    path = tmp_path / f"bad{suffix}"
    path.write_bytes(b"\x00\x01 not a signal \xff" * 7)
    with pytest.raises(InputError) as err:
        read_signal(path, sample_rate=FS)
    assert err.value.parameter == "path"


@pytest.mark.parametrize("suffix", [".npz", ".mat", ".csv"])
def test_truncated_files_give_input_errors(tmp_path, record, suffix):
    whole = write_signal(tmp_path / f"r{suffix}", record).read_bytes()
    path = tmp_path / f"half{suffix}"
    path.write_bytes(whole[: len(whole) // 2])
    with pytest.raises(InputError) as err:
        read_signal(path)
    assert err.value.parameter == "path"


def test_irregular_csv_times(tmp_path):
    t = np.arange(32) / 100.0
    t[20:] += 0.05  # five samples lost
    rows = "".join(f"{ti},{i}\n" for i, ti in enumerate(t))
    (tmp_path / "gap.csv").write_text("time_s,a\n" + rows)
    with pytest.raises(InputError) as err:
        read_signal(tmp_path / "gap.csv")
    assert err.value.parameter == "time_s"


def test_what_a_format_cannot_hold(tmp_path, record):
    odd_rate = Signal(dict(record.channels), 12000.5)
    with pytest.raises(InputError) as err:
        write_signal(tmp_path / "r.wav", odd_rate)
    assert err.value.parameter == "sample_rate"
    spaced = Signal({"drive end": record.channel()}, FS)
    with pytest.raises(InputError) as err:
        write_signal(tmp_path / "r.mat", spaced)
    assert err.value.parameter == "channels"
    with pytest.raises(InputError) as err:
        write_signal(tmp_path / "r.npz", Signal({"sample_rate_hz": record.channel()}, FS))
    assert err.value.parameter == "channels"
    with pytest.raises(InputError) as err:
        write_signal(tmp_path / "r.npz", {"DE": record.channel()})
    assert err.value.parameter == "signal"
    assert list(tmp_path.iterdir()) == []


def test_failed_write_leaves_no_file(tmp_path, record, monkeypatch):
    target = tmp_path / "r.npz"
    write_signal(target, record)
    before = target.read_bytes()

    def broken_savez(file, **arrays):
        with open(file, "wb") as fh:
            fh.write(b"PK half an archive")
        raise OSError("disk full")

    monkeypatch.setattr(np, "savez", broken_savez)
    with pytest.raises(OSError, match="disk full"):
        write_signal(target, record)
    with pytest.raises(OSError, match="disk full"):
        write_signal(tmp_path / "new.npz", record)
    assert [p.name for p in tmp_path.iterdir()] == ["r.npz"]  # no temporary, no new.npz
    assert target.read_bytes() == before  # the old file is untouched
