"""Whether a channel can be a vibration record at all: the checks that catch inputs that lie.

Layer 1 (NumPy). A spectrum of any array can be computed; these checks stop the ones whose
answer would mean nothing, in the user's terms, before any analysis:

- **constant** (a dead, disconnected or unpowered sensor, a channel of zeros): refused, its
  spectrum is zero and every test reads "no fault" from nothing;
- **monotonic** (every sample above, or every one below, the one before: a time or
  sample-index column read as a channel): refused - no vibration rises for thousands of
  samples in a row;
- **overflowing** (magnitudes beyond OVERFLOW: the squared envelope's power, x^4 times the
  record length, leaves float64's range, ~1.8e308): refused;
- **clipped** (many samples at exactly the record's largest or smallest value: the sensor or
  its amplifier saturated, which flattens impacts and adds lines of its own to the
  envelope; Randall R. B., Vibration-based Condition Monitoring, Wiley 2011, sec. 3.1 on
  transducer range and dynamic range): a warning;
- **coarse** (fewer than COARSE_LEVELS distinct values: a signal below the resolution of its
  converter): a warning.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

#: Largest magnitude a sample may have [unit of the samples]: beyond it the fourth power of
#: the samples times the samples of a long record leaves float64's range (1e60^4 x 1e8).
OVERFLOW = 1e60
#: Samples at one extreme that make a channel clipped: more than this fraction of the record
#: and at least CLIPPED_SAMPLES (a clean record reaches each extreme once or twice).
CLIPPED_FRACTION = 1e-3
CLIPPED_SAMPLES = 10
#: Distinct values below which a channel is called coarse.
COARSE_LEVELS = 16


def check_channel(x: np.ndarray, name: str = "signal", parameter: str | None = None) -> list[str]:
    """Refuse a channel that cannot be a vibration record; return warnings for one that is
    suspect (see the module docstring).

    Parameters
    ----------
    x : numpy.ndarray
        The samples (1-D, finite), any unit.
    name : str
        The channel's name, as the user knows it (for the messages).
    parameter : str, optional
        The parameter an error names (default ``name``); its value then names the channel.

    Returns
    -------
    list of str
        Warnings, in the user's terms (empty for a sound channel).

    Raises
    ------
    InputError
        A constant, monotonic or overflowing channel, naming it.

    Examples
    --------
    >>> check_channel(np.sin(np.arange(1000.0)))
    []
    >>> check_channel(np.zeros(1000), "DE")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: DE = 'every sample 0' is not allowed: expected a varying ...
    """
    low, high = float(np.min(x)), float(np.max(x))
    parameter, prefix = (name, "") if parameter is None else (parameter, f"channel {name}: ")
    if low == high:
        raise InputError(
            parameter,
            f"{prefix}every sample {low:g}",
            "a varying record (a constant channel is a dead or disconnected sensor)",
        )
    if max(-low, high) > OVERFLOW:
        raise InputError(
            parameter,
            f"{prefix}samples up to {max(-low, high):.3g}",
            f"magnitudes below {OVERFLOW:g} (no sensor reads these: a corrupt file or a "
            "wrong data type; the envelope's power would overflow)",
        )
    step = np.diff(x)
    if np.all(step > 0) or np.all(step < 0):
        way = "rises" if step[0] > 0 else "falls"
        raise InputError(
            parameter,
            f"{prefix}a channel that {way} at every sample",
            "a vibration record (this is a time or sample-index column)",
        )
    warnings = []
    at_extremes = max(int(np.count_nonzero(x == high)), int(np.count_nonzero(x == low)))
    if at_extremes >= max(CLIPPED_SAMPLES, CLIPPED_FRACTION * x.size):
        warnings.append(
            f"{name}: {at_extremes} samples ({100 * at_extremes / x.size:.2g} %) sit at the "
            f"record's extreme ({low:.6g} or {high:.6g}): the channel looks clipped (the "
            "sensor's or the amplifier's range exceeded), which flattens impacts and adds "
            "lines of its own to the envelope"
        )
    elif (levels := np.unique(x[:: max(1, x.size // 4096)]).size) < COARSE_LEVELS:
        # (a coarse channel shows its few levels in any few thousand of its samples)
        warnings.append(
            f"{name}: only {levels} distinct values: the signal is below the "
            "resolution of its converter (or the channel is nearly dead)"
        )
    return warnings
