"""The transfer path from the bearing to the sensor: structural resonances in series.

Envelope analysis works on real machines because the impacts of a defect ring the
structure between the bearing and the transducer, and the envelope of that ringing
carries the defect rate (Randall R. B., Antoni J., "Rolling element bearing diagnostics -
A tutorial", MSSP 25 (2011) 485-520, sec. 2). The dynamic models give the pedestal's
acceleration; the path adds the resonances of the housing and mounting as base-excited
single-degree-of-freedom stages in series: each stage's acceleration follows the one
below with the transmissibility of base excitation (Rao S. S., *Mechanical Vibrations*,
sec. "Base excitation" of the harmonic-response chapter)

    T(s) = (2 zeta omega_n s + omega_n^2) / (s^2 + 2 zeta omega_n s + omega_n^2),

1 at low frequency (the shaft and load-zone content passes unchanged), about 1/(2 zeta)
at omega_n, falling above. Each stage is made digital by the bilinear transform with its
natural frequency pre-warped: the resonance sits exactly at omega_n; away from it the
frequency axis is compressed towards Nyquist as the bilinear map does, so keep the
resonances well below half the sample rate (at most 0.45 f_s is allowed).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError

#: Highest natural frequency allowed, as a fraction of the sample rate (below Nyquist
#: with room for the resonance's width).
MAX_FRACTION = 0.45


@dataclass(frozen=True)
class TransferPath:
    """Resonances between bearing and sensor: ``resonances`` = ((f_n [Hz], zeta [-]), ...).

    >>> p = TransferPath(((3000.0, 0.05),))
    >>> x = np.sin(2 * np.pi * 3000.0 * np.arange(20000) / 20000.0)
    >>> round(float(np.std(p.apply(x, 20000.0)[10000:]) / np.std(x)), 1)   # ~ 1/(2 zeta)
    10.0
    """

    resonances: tuple

    def __post_init__(self) -> None:
        checked = []
        for item in self.resonances:
            try:
                f, zeta = (float(v) for v in item)
            except (TypeError, ValueError):
                raise InputError(
                    "resonances", item, "pairs (frequency [Hz], damping ratio)"
                ) from None
            if not (math.isfinite(f) and f > 0):
                raise InputError("resonance frequency", f, "a frequency > 0 [Hz]")
            if not (math.isfinite(zeta) and 0 < zeta < 1):
                raise InputError("damping ratio", zeta, "a ratio in (0, 1)")
            checked.append((f, zeta))
        object.__setattr__(self, "resonances", tuple(checked))

    def check(self, sample_rate: float) -> None:
        """Refuse a resonance above MAX_FRACTION of ``sample_rate`` [Hz].

        Parameters
        ----------
        sample_rate : float
            Sample rate [Hz].

        Raises
        ------
        InputError
            If a resonance frequency exceeds MAX_FRACTION (0.45) of ``sample_rate``.
        """
        for f, _ in self.resonances:
            if f > MAX_FRACTION * sample_rate:
                raise InputError(
                    "resonance frequency",
                    f,
                    f"at most {MAX_FRACTION:g} x the "
                    f"sample rate ({MAX_FRACTION * sample_rate:g} Hz)",
                )

    def sos(self, sample_rate: float) -> np.ndarray:
        """Second-order sections of the digital path at ``sample_rate`` [Hz].

        Parameters
        ----------
        sample_rate : float
            Sample rate [Hz]; each resonance must be at most MAX_FRACTION (0.45) of it.

        Returns
        -------
        numpy.ndarray
            Shape (n, 6), as ``scipy.signal.sosfilt`` takes them; (0, 6) without resonances.
        """
        from scipy.signal import bilinear, tf2sos

        self.check(sample_rate)
        sections = []
        for f, zeta in self.resonances:
            # pre-warp: the bilinear transform maps this analog frequency to f exactly
            w = 2.0 * sample_rate * math.tan(math.pi * f / sample_rate)
            b, a = bilinear([2 * zeta * w, w * w], [1.0, 2 * zeta * w, w * w], sample_rate)
            sections.append(tf2sos(b, a))
        return np.vstack(sections) if sections else np.zeros((0, 6))

    def apply(self, x, sample_rate: float) -> np.ndarray:
        """The sensor's signal for the pedestal acceleration ``x`` [same unit], sampled at
        ``sample_rate`` [Hz]; the filter starts in the steady state of the first sample
        (no start-up transient).

        Parameters
        ----------
        x : array_like
            Pedestal acceleration samples, 1-D (any unit; the output has the same).
        sample_rate : float
            Sample rate [Hz]; each resonance must be at most MAX_FRACTION (0.45) of it.

        Returns
        -------
        numpy.ndarray
            The filtered samples (a copy of ``x`` when the path has no resonance).
        """
        from scipy.signal import sosfilt, sosfilt_zi

        x = np.asarray(x, float)
        if not self.resonances:
            return x.copy()
        sos = self.sos(sample_rate)
        y, _ = sosfilt(sos, x, zi=sosfilt_zi(sos) * x[0])
        return y

    def to_dict(self) -> dict:
        return {
            "resonances_hz": [f for f, _ in self.resonances],
            "damping_ratios": [z for _, z in self.resonances],
        }
