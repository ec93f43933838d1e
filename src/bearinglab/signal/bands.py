"""Vibration velocity in the ISO 15242 frequency bands (layer 1).

ISO 15242 ("Rolling bearings - Measuring methods for vibration"; part 1 fundamentals,
part 2 radial ball bearings with cylindrical bore and outside surface) rates a bearing by
the root-mean-square radial velocity of its outer ring, in um/s, in three bands, with the
inner ring turning at the default 1800 min^-1 (30 s^-1; ISO 15242-2:2015 sec. 4.1, quoted
in ANSI/ABMA/ISO 15242-2-2016):

    low (L) 50-300 Hz, medium (M) 300-1800 Hz, high (H) 1800-10000 Hz.

Sources checked: the measured quantity is the RMS vibration velocity (GOST R 52545.4-2013,
the Russian adoption of ISO 15242-4, sec. 5.1.1; JB/T 5313-2001 sec. 4: radial outer-ring
velocity in um/s); the band edges move in proportion to the rotational frequency (the
same standard's Table 2 gives 25-150, 150-900 and 900-5000 Hz for 882-909 min^-1, half
the 1800 min^-1 edges); the 1800 min^-1 bands 50-300, 300-1800 and 1800-10000 Hz are
those used with ISO 15242 test rigs, e.g. Adamczak S. et al., Materials 13(23) 5440
(2020), on 6304 bearings. The full text of ISO 15242-2 was not available here, so the
speed scaling (``speed_rpm``) is the rule of the part-4 table applied to ball bearings.
The bands of a bearing at an operating point (:func:`bearinglab.noise.bearing_velocity_bands`,
used by the ``noise`` command and the report) always scale the edges to its speed.

The RMS in a band is integrated over the FFT lines f_lo <= f < f_hi of the whole record
(Parseval; rectangular window, so a tone on a line gives its exact RMS and the energy of
a tone between lines stays near it). Displacement and acceleration are turned into
velocity line by line (V = j omega X, V = A / (j omega)).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..errors import InputError
from .spectra import rate, samples

#: ISO 15242 bands at the default 1800 min^-1: name -> (low, high) [Hz].
ISO15242_BANDS = {"low": (50.0, 300.0), "medium": (300.0, 1800.0), "high": (1800.0, 10000.0)}
#: Rotational speed the default bands belong to [rpm].
ISO15242_SPEED_RPM = 1800.0
#: Quantities a record may hold.
QUANTITIES = ("displacement", "velocity", "acceleration")
#: Periods of the lowest band edge the record must hold (10: lines 1/10 of that edge apart).
MIN_PERIODS = 10


class VelocityBands(NamedTuple):
    """RMS vibration velocity in each band [um/s] and the bands used (name -> (low, high)
    [Hz])."""

    low: float
    medium: float
    high: float
    bands: dict

    def to_dict(self) -> dict:
        """``low_um_per_s`` ... and ``low_band_hz`` ... (JSON-ready)."""
        out = {f"{k}_um_per_s": float(getattr(self, k)) for k in ISO15242_BANDS}
        out.update({f"{k}_band_hz": list(v) for k, v in self.bands.items()})
        return out


def iso15242_bands(speed_rpm: float | None = None) -> dict:
    """ISO 15242 band edges [Hz] at ``speed_rpm`` (default 1800 min^-1: 50-300, 300-1800,
    1800-10000 Hz), scaled in proportion to the speed.

    Parameters
    ----------
    speed_rpm : float or None
        Shaft speed [rpm], finite and > 0; None: the standard's 1800 rpm.

    Returns
    -------
    dict
        Band name ("low", "medium", "high") -> (low, high) edges [Hz].

    Examples
    --------
    >>> iso15242_bands(900.0)["high"]
    (900.0, 5000.0)
    """
    if speed_rpm is None:
        return dict(ISO15242_BANDS)
    try:
        s = float(speed_rpm)
    except (TypeError, ValueError):
        s = math.nan
    if not math.isfinite(s) or s <= 0:
        raise InputError("speed_rpm", speed_rpm, "a speed > 0 [rpm]")
    scale = s / ISO15242_SPEED_RPM
    return {k: (lo * scale, hi * scale) for k, (lo, hi) in ISO15242_BANDS.items()}


def velocity_bands(
    signal, sample_rate, quantity: str = "acceleration", speed_rpm: float | None = None
) -> VelocityBands:
    """RMS vibration velocity in the ISO 15242 low, medium and high bands [um/s].

    Parameters
    ----------
    signal : array_like
        1-D record of the radial vibration in SI units: displacement [m], velocity [m/s]
        or acceleration [m/s^2], at least 16 samples.
    sample_rate : float
        Sample rate f_s [Hz]; it must exceed twice the top edge of the high band (20 kHz
        at 1800 min^-1).
    quantity : {"displacement", "velocity", "acceleration"}
        What ``signal`` holds. A displacement is differentiated in the frequency
        domain, which multiplies by f: the jump between the two ends of a record that is
        not a whole number of periods then inflates the high band. Detrend such a record
        or differentiate it in time and pass the velocity.
    speed_rpm : float, optional
        Inner-ring speed; the band edges scale with it from the 1800 min^-1 values
        (default: those values).

    Returns
    -------
    VelocityBands
        ``low``, ``medium``, ``high`` [um/s] and ``bands`` [Hz].

    Raises
    ------
    InputError
        If f_s cannot resolve the high band or the record is shorter than MIN_PERIODS
        periods of the low band's lower edge (0.2 s at 1800 min^-1).

    Examples
    --------
    A velocity tone of amplitude 1 mm/s at 1 kHz reads 1000 / sqrt(2) um/s in the medium
    band:

    >>> t = np.arange(25600) / 25600.0
    >>> r = velocity_bands(1e-3 * np.sin(2 * np.pi * 1000.0 * t), 25600.0, "velocity")
    >>> round(r.low, 6), round(r.medium, 3), round(r.high, 6)
    (0.0, 707.107, 0.0)
    """
    x = samples(signal, "signal")
    fs = rate(sample_rate)
    if quantity not in QUANTITIES:
        raise InputError("quantity", quantity, f"one of {QUANTITIES}")
    bands = iso15242_bands(speed_rpm)
    top = max(hi for _, hi in bands.values())
    if fs <= 2.0 * top:
        raise InputError(
            "sample_rate",
            sample_rate,
            f"a rate > {2.0 * top:g} Hz (twice the top of the high band, {top:g} Hz)",
        )
    bottom = min(lo for lo, _ in bands.values())
    n = x.size
    if n / fs < MIN_PERIODS / bottom:
        raise InputError(
            "signal",
            f"{n} samples ({n / fs:g} s)",
            f"a record of at least {MIN_PERIODS / bottom:g} s "
            f"({MIN_PERIODS} periods of the low band's {bottom:g} Hz edge)",
        )
    spectrum = np.fft.rfft(x - x.mean())
    f = np.fft.rfftfreq(n, 1.0 / fs)
    omega = 2.0 * np.pi * f
    live = f > 0
    if quantity == "displacement":
        spectrum = spectrum * 1j * omega
    elif quantity == "acceleration":
        spectrum = np.where(live, spectrum / np.where(live, 1j * omega, 1.0), 0.0)
    # one-sided mean square of each line: 2 |X_k|^2 / n^2 (|X_k|^2 / n^2 at 0 and Nyquist)
    power = 2.0 * np.abs(spectrum) ** 2 / n**2
    power[0] /= 2.0
    if n % 2 == 0:
        power[-1] /= 2.0
    rms = {
        k: math.sqrt(float(np.sum(power[(f >= lo) & (f < hi)]))) * 1e6
        for k, (lo, hi) in bands.items()
    }
    return VelocityBands(rms["low"], rms["medium"], rms["high"], bands)
