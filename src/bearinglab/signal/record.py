"""A measured vibration record: equal-length channels sampled at one rate.

Layer 2 model object (see docs/architecture.md): :class:`Signal` validates its inputs on
construction and is what :func:`bearinglab.signal.read_signal` returns and
:func:`bearinglab.signal.write_signal` takes. Samples are in whatever unit the sensor gave
(m/s^2, g, V); the sample rate is in Hz; time in s.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError

#: Fewest samples a record may have: below this no spectrum or filter is meaningful.
MIN_SAMPLES = 16


def json_default(value):
    """``json.dumps`` fallback turning NumPy scalars and arrays into Python values.

    >>> json.dumps({"speed_rpm": np.float64(1797.0)}, default=json_default)
    '{"speed_rpm": 1797.0}'
    """
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"{type(value).__name__} is not JSON serialisable")


@dataclass(frozen=True, eq=False)
class Signal:
    """Channels of samples taken at one sample rate.

    Parameters
    ----------
    channels : dict[str, array_like]
        Channel name -> 1-D samples (any unit, e.g. m/s^2 or g); all the same length,
        at least 16 samples, all finite. Stored as read-only float64 copies, in the
        order given.
    sample_rate : float
        Samples per second [Hz], > 0.
    metadata : dict, optional
        Free JSON-able information, e.g. ``speed_rpm``, ``designation``, ``source``.

    Examples
    --------
    >>> s = Signal({"DE": np.zeros(1200), "FE": np.ones(1200)}, 12000.0, {"speed_rpm": 1797})
    >>> s.names, s.duration, s.channel().shape
    (('DE', 'FE'), 0.1, (1200,))
    """

    channels: dict[str, np.ndarray]
    sample_rate: float
    metadata: dict = field(default_factory=dict)

    def __post_init__(self) -> None:
        if not isinstance(self.channels, dict) or not self.channels:
            raise InputError(
                "channels", self.channels, "a non-empty dict of channel name -> 1-D samples"
            )
        checked = {}
        length = None
        for name, samples in self.channels.items():
            if not isinstance(name, str) or not name:
                raise InputError("channels", name, "non-empty strings as channel names")
            try:
                x = np.array(samples, dtype=float)
            except (TypeError, ValueError):
                raise InputError(
                    f"channels[{name!r}]", type(samples).__name__, "a 1-D array of numbers"
                ) from None
            if x.ndim != 1:
                raise InputError(
                    f"channels[{name!r}]", f"array of shape {x.shape}", "a 1-D array of samples"
                )
            if x.size < MIN_SAMPLES:
                raise InputError(
                    f"channels[{name!r}]", f"{x.size} samples", f"at least {MIN_SAMPLES} samples"
                )
            if not np.all(np.isfinite(x)):
                bad = int(np.flatnonzero(~np.isfinite(x))[0])
                raise InputError(
                    f"channels[{name!r}]",
                    f"non-finite sample at index {bad}",
                    "finite samples (no NaN or inf)",
                )
            if length is not None and x.size != length:
                raise InputError(
                    "channels",
                    {k: v.size for k, v in checked.items()} | {name: x.size},
                    "channels of equal length",
                )
            length = x.size
            x.flags.writeable = False  # frozen record: its samples cannot change either
            checked[name] = x
        try:
            rate = float(self.sample_rate)
        except (TypeError, ValueError):
            raise InputError("sample_rate", self.sample_rate, "a number > 0 Hz") from None
        if not math.isfinite(rate) or rate <= 0:
            raise InputError("sample_rate", self.sample_rate, "a finite number > 0 Hz")
        metadata = {} if self.metadata is None else self.metadata
        if not isinstance(metadata, dict):
            raise InputError("metadata", metadata, "a dict")
        try:
            json.dumps(metadata, default=json_default)
        except (TypeError, ValueError) as exc:
            raise InputError("metadata", metadata, "a JSON-able dict", hint=str(exc)) from None
        object.__setattr__(self, "channels", checked)
        object.__setattr__(self, "sample_rate", rate)
        object.__setattr__(self, "metadata", dict(metadata))

    @property
    def names(self) -> tuple[str, ...]:
        """Channel names, in order."""
        return tuple(self.channels)

    @property
    def n_samples(self) -> int:
        """Samples per channel."""
        return next(iter(self.channels.values())).size

    @property
    def duration(self) -> float:
        """Record length n / f_s [s]."""
        return self.n_samples / self.sample_rate

    @property
    def time(self) -> np.ndarray:
        """Time of each sample, starting at 0 [s]."""
        return np.arange(self.n_samples) / self.sample_rate

    def channel(self, name: str | None = None) -> np.ndarray:
        """Samples of channel ``name`` (default: the first channel).

        Parameters
        ----------
        name : str or None
            The channel's name; None: the first channel.

        Returns
        -------
        numpy.ndarray
            Its samples.

        Raises
        ------
        InputError
            If there is no channel of that name; the message lists the names there are.
        """
        if name is None:
            return next(iter(self.channels.values()))
        if name not in self.channels:
            raise InputError("channel", name, f"one of {list(self.channels)}")
        return self.channels[name]

    def select(self, names: str | list[str] | tuple[str, ...]) -> Signal:
        """A new record with only the channels ``names`` (in that order).

        Parameters
        ----------
        names : str or sequence of str
            The channel(s) to keep, in the order wanted; each must be a channel of this record
            (at least one).

        Returns
        -------
        Signal
            With those channels, the same sample rate and metadata.
        """
        wanted = [names] if isinstance(names, str) else list(names)
        if not wanted or any(not isinstance(n, str) or n not in self.channels for n in wanted):
            raise InputError("channel", names, f"one or more of {list(self.channels)}")
        return Signal({n: self.channel(n) for n in wanted}, self.sample_rate, self.metadata)
