"""Vibration velocity in the ISO 15242 bands (bearinglab.signal.velocity_bands)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.signal import ISO15242_BANDS, iso15242_bands, velocity_bands

FS = 51200.0
N = 51200  # 1 s: 1 Hz lines
T = np.arange(N) / FS
W = 2 * np.pi


@pytest.mark.parametrize(
    "frequency, band", [(120.0, "low"), (1000.0, "medium"), (5000.0, "high"), (250.5, "low")]
)
@pytest.mark.parametrize("quantity", ["displacement", "velocity", "acceleration"])
def test_a_tone_reads_its_rms_velocity_in_its_band(frequency, band, quantity):
    v0 = 2e-4  # 0.2 mm/s velocity amplitude
    w = W * frequency
    x = {
        "displacement": v0 / w * np.sin(w * T),
        "velocity": v0 * np.cos(w * T),
        "acceleration": -v0 * w * np.sin(w * T),
    }[quantity]
    r = velocity_bands(x, FS, quantity)
    expected = v0 / math.sqrt(2) * 1e6
    # 250.5 Hz sits between lines: its leakage (rectangular window) spills ~0.2 % of its
    # energy over the 300 Hz edge, 50 lines away
    tolerance = 1e-9 if frequency % 1 == 0 else 1e-2
    assert getattr(r, band) == pytest.approx(expected, rel=tolerance)
    for other in set(ISO15242_BANDS) - {band}:
        assert getattr(r, other) < max(tolerance, 1e-9) * expected * 10


def test_out_of_band_content_is_ignored():
    """A 20 Hz tone (below the low band), a 15 kHz tone (above the high band) and an offset
    leave the bands empty; three in-band tones add up band by band."""
    outside = 3e-3 * np.sin(W * 20 * T) + 1e-3 * np.sin(W * 15000 * T) + 0.5
    r = velocity_bands(outside, FS, "velocity")
    assert max(r.low, r.medium, r.high) < 1e-6  # rounding only [um/s]
    inside = 1e-4 * (np.sin(W * 100 * T) + np.sin(W * 200 * T) + np.sin(W * 3000 * T))
    r = velocity_bands(inside + outside, FS, "velocity")
    assert r.low == pytest.approx(100.0, rel=1e-9)  # sqrt(2 x (100/sqrt 2)^2)
    assert r.medium < 1e-6
    assert r.high == pytest.approx(100 / math.sqrt(2), rel=1e-9)
    d = r.to_dict()
    assert d["low_band_hz"] == [50.0, 300.0] and d["high_um_per_s"] == pytest.approx(r.high)


def test_bands_scale_with_speed():
    assert iso15242_bands() == ISO15242_BANDS
    assert iso15242_bands(900.0) == {
        "low": (25.0, 150.0),
        "medium": (150.0, 900.0),
        "high": (900.0, 5000.0),
    }
    r = velocity_bands(1e-4 * np.sin(W * 200 * T), FS, "velocity", speed_rpm=900.0)
    assert r.medium == pytest.approx(100 / math.sqrt(2), rel=1e-9) and r.low < 1e-6


@pytest.mark.parametrize(
    "args, parameter",
    [
        ((np.zeros(N), 20000.0), "sample_rate"),  # cannot resolve 10 kHz
        ((np.zeros(5000), FS), "signal"),  # < 0.2 s
        ((np.zeros(N), FS, "jerk"), "quantity"),
        ((np.zeros(N), FS, "velocity", -5.0), "speed_rpm"),
        ((np.zeros(8), FS), "signal"),
    ],
)
def test_clear_errors(args, parameter):
    with pytest.raises(InputError) as err:
        velocity_bands(*args)
    assert err.value.parameter == parameter
