"""Files as they are published: MATLAB structs (MFPT), v7.3 (HDF5) .mat, CSV with a time
column anywhere, and the shared MFPT files themselves when present."""

from pathlib import Path

import numpy as np
import pytest
import scipy.io
from conftest import require

from bearinglab.errors import InputError
from bearinglab.signal import read_signal

REAL = Path(__file__).resolve().parents[3] / "shared" / "data" / "real"


def _mfpt_like(path, n=2000):
    gs = np.sin(np.arange(n) / 7.0)[:, None]
    scipy.io.savemat(
        path,
        {"bearing": {"gs": gs, "sr": np.array([[48828]]), "rate": np.array([[25]]), "load": "25"}},
    )
    return gs.ravel()


def test_matlab_struct_fields_are_channels(tmp_path):
    gs = _mfpt_like(tmp_path / "mfpt.mat")
    s = read_signal(tmp_path / "mfpt.mat")
    assert s.names == ("bearing.gs",)
    assert s.sample_rate == 48828.0  # from the struct's sr
    assert s.metadata["speed_rpm"] == 1500.0  # rate 25 Hz
    np.testing.assert_allclose(s.channel("bearing.gs"), gs)
    assert read_signal(tmp_path / "mfpt.mat", channel="gs").names == ("bearing.gs",)


def test_non_numeric_struct_field_is_refused_by_name(tmp_path):
    _mfpt_like(tmp_path / "mfpt.mat")
    with pytest.raises(InputError, match="bearing.load") as err:
        read_signal(tmp_path / "mfpt.mat", channel="bearing.load")
    assert err.value.parameter == "channel"
    with pytest.raises(InputError) as err:
        read_signal(tmp_path / "mfpt.mat", channel="bearing.xx")
    assert err.value.parameter == "channel"


def test_matlab_v73_hdf5(tmp_path):
    h5py = require("h5py")
    path = tmp_path / "v73.mat"
    x = np.cos(np.arange(1000) / 5.0)
    # as MATLAB writes it: a 512-byte header (user block) in front of the HDF5 file
    with h5py.File(path, "w", userblock_size=512) as f:
        g = f.create_group("bearing")
        g.create_dataset("gs", data=x[None, :])  # MATLAB stores transposed
        g.create_dataset("sr", data=np.array([[20000.0]]))
        text = g.create_dataset("load", data=np.array([[50], [48]], dtype=np.uint16))
        text.attrs["MATLAB_class"] = b"char"
    with open(path, "r+b") as fh:
        fh.write(
            b"MATLAB 7.3 MAT-file, Platform: GLNXA64, Created on: test HDF5 schema 1.00 .".ljust(
                116
            )
            + b"\x00" * 8
            + b"\x00\x02IM"
        )
    s = read_signal(path)
    assert s.names == ("bearing.gs",) and s.sample_rate == 20000.0
    np.testing.assert_allclose(s.channel(), x)
    with pytest.raises(InputError, match="bearing.load"):
        read_signal(path, channel="bearing.load")


@pytest.mark.parametrize(
    "header, scale", [("time", 1.0), ("t", 1.0), ("time [s]", 1.0), ("time_ms", 1e-3)]
)
def test_csv_time_column_anywhere(tmp_path, header, scale):
    t = np.arange(100) / 1000.0
    path = tmp_path / "r.csv"
    rows = "\n".join(
        f"{a},{tt / scale},{b}" for a, tt, b in zip(np.sin(t), t, np.cos(t), strict=True)
    )
    path.write_text(f"x,{header},y\n{rows}\n", encoding="utf-8")
    s = read_signal(path)
    assert s.names == ("x", "y") and s.sample_rate == pytest.approx(1000.0)


def test_csv_without_time_needs_a_rate(tmp_path):
    path = tmp_path / "r.csv"
    path.write_text("x,y\n" + "\n".join("1,2" for _ in range(20)) + "\n", encoding="utf-8")
    with pytest.raises(InputError, match="time column"):
        read_signal(path)
    assert read_signal(path, sample_rate=100.0).sample_rate == 100.0


@pytest.mark.skipif(not (REAL / "mfpt").is_dir(), reason="shared/data/real is absent")
def test_the_published_mfpt_file():
    s = read_signal(REAL / "mfpt" / "OuterRaceFault_vload_1.mat", channel="gs")
    assert s.sample_rate == 48828.0 and s.metadata["speed_rpm"] == 1500.0
    assert s.n_samples == 146484
