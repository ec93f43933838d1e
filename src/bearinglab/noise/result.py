"""Result objects of the noise model: :class:`SoundPressure` and :class:`Directivity`
(layer 3 results; seed 003 eqs. 24-27 and figs. 12-14, seed 002 directivity).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import scipy.signal

from ..errors import InputError
from .field import pressures_at
from .model import Air, FieldPoint
from .sources import effective_pressure, sound_pressure_level

#: Floor of the envelope in the SPL(t) curve, so that its log stays finite [Pa].
ENVELOPE_FLOOR = 1e-12
#: The levels of :meth:`SoundPressure.to_dict` [dB re 20 uPa]: key -> its definition. The
#: parts (inner ring, balls and their x / y contributions) are L_eq: ``spl_leq_<part>_db``.
LEVELS = {
    "spl_leq_db": "L_eq: eq. 27 with p_e the RMS pressure over the whole record (the energy mean)",
    "spl_time_mean_db": "time mean of the level curve SPL(t) (Hilbert envelope), seed 003's "
    "'mean SPL'",
    "spl_time_max_db": "maximum of the level curve SPL(t)",
}


@dataclass(frozen=True)
class Directivity:
    """L_eq (eq. 27 over the record) round the bearing at one distance (seed 002: the
    radiation is directional). ``angle`` [rad]; ``levels`` part name -> L_eq at each angle
    [dB]."""

    angle: np.ndarray
    distance: float
    levels: dict

    def to_dict(self) -> dict:
        """JSON-ready: angles in degrees, levels in dB (None where a part is silent)."""
        return {
            "angle_deg": np.degrees(self.angle).tolist(),
            "distance_mm": self.distance * 1e3,
            **{
                f"spl_leq_{k}_db": [_finite_or_none(v) for v in lv] for k, lv in self.levels.items()
            },
        }

    def plot(self, ax=None):
        """Polar plot of the levels [dB] on ``ax`` (a polar matplotlib Axes; a new figure
        by default); returns (fig, ax).

        Parameters
        ----------
        ax : matplotlib Axes or None
            A polar Axes to draw on; None: a new figure.
        """
        from ..plotting import figure_axes

        fig, ax = figure_axes(ax, subplot_kw={"projection": "polar"}, figsize=(5.5, 5.5))
        closed = np.append(self.angle, self.angle[0])
        for name, lv in self.levels.items():
            ax.plot(closed, np.append(lv, lv[0]), label=name)
        ax.set_title(f"L_eq [dB] at {self.distance * 1e3:.4g} mm")
        ax.legend(fontsize=8, loc="lower right")
        return fig, ax


def _finite_or_none(value) -> float | None:
    v = float(value)
    return v if math.isfinite(v) else None


@dataclass(frozen=True, eq=False)
class SoundPressure:
    """Sound pressure at a field point and what produced it.

    Attributes: ``time`` [s]; ``parts`` part name -> pressure series [Pa]: ``inner_ring``,
    ``balls`` and ``total`` (eq. 26), and the contributions of the x and y velocity
    components (``inner_ring_x``, ``inner_ring_y``, ``balls_x``, ``balls_y``, the seed's
    figures 12-13 A/B) when they exist; ``point``, ``medium``, ``options`` (radii [m],
    models) and the input velocities (for :meth:`directivity`).

    Levels (one definition per number, :data:`LEVELS`):

    * :meth:`spl` -- eq. 27 with p_e the RMS over the whole record: the equivalent
      continuous level L_eq (the energy mean; IEC 61672-1's L_eq,T), ``spl_leq_db`` of
      :meth:`to_dict`, and ``spl_leq_<part>_db`` for the inner ring or the balls alone;
    * :meth:`spl_time` -- the level as it changes in time (the seed's figures 12-14 plot
      SPL against time over one cycle): by default from the instantaneous amplitude
      |p + j H[p]| / sqrt(2) (Hilbert envelope; for a pure tone it is the RMS level at
      every instant), or from a sliding RMS window;
    * ``spl_time_mean_db`` / ``spl_time_max_db`` of :meth:`to_dict` -- the time average
      (of the levels in dB, not of the energy) and the maximum of that curve: the seed's
      "mean SPL" (29.832 dB for its 608) is read as the mean of the SPL-time curve of its
      figure 14.
    """

    time: np.ndarray
    parts: dict
    point: FieldPoint
    medium: Air
    options: dict
    inputs: dict = field(repr=False)

    @property
    def sample_rate(self) -> float:
        """1 / time step [Hz]."""
        return float((self.time.size - 1) / (self.time[-1] - self.time[0]))

    def pressure(self, part: str = "total") -> np.ndarray:
        """Pressure series of ``part`` [Pa].

        Parameters
        ----------
        part : str
            One of :attr:`parts`: "inner_ring" or "balls" (those computed), "total" (the
            default) or an x / y contribution ("inner_ring_x", ...).

        Returns
        -------
        numpy.ndarray
            The pressure at each time [Pa].

        Raises
        ------
        InputError
            If ``part`` is not one of the parts computed.
        """
        if part not in self.parts:
            raise InputError("part", part, f"one of {list(self.parts)}")
        return self.parts[part]

    def effective_pressure(self, part: str = "total") -> float:
        """p_e = sqrt(1/T int p^2 dt) (seed 003, after eq. 27) of ``part`` ("inner_ring",
        "balls" or "total") [Pa].

        Parameters
        ----------
        part : str
            One of :attr:`parts`: "inner_ring" or "balls" (those computed), "total" (the
            default) or an x / y contribution ("inner_ring_x", ...).
        """
        return effective_pressure(self.pressure(part))

    def spl(self, part: str = "total") -> float:
        """SPL = 20 lg(p_e / p_ref) of ``part`` ("inner_ring", "balls" or "total") over the
        whole record (eq. 27) [dB]; -inf if silent.

        Parameters
        ----------
        part : str
            One of :attr:`parts`: "inner_ring" or "balls" (those computed), "total" (the
            default) or an x / y contribution ("inner_ring_x", ...).
        """
        return sound_pressure_level(self.effective_pressure(part))

    def spl_time(self, part: str = "total", window: float | None = None) -> np.ndarray:
        """SPL against time [dB].

        Parameters
        ----------
        part : str
            A key of ``parts``.
        window : float, optional
            Length of a centred sliding RMS window [s] (the record is periodic, so the
            window wraps round); None: the Hilbert envelope |p + j H[p]| / sqrt(2),
            floored at ENVELOPE_FLOOR.
        """
        p = self.pressure(part)
        n = p.size
        if window is None:
            level = np.abs(scipy.signal.hilbert(p)) / math.sqrt(2.0)
            return sound_pressure_level(np.maximum(level, ENVELOPE_FLOOR))
        try:
            w = round(float(window) * self.sample_rate)
        except (TypeError, ValueError):
            w = -1
        if not 1 <= w <= n:
            raise InputError(
                "window",
                window,
                f"a length in [{1 / self.sample_rate:g}, {n / self.sample_rate:g}] s",
            )
        h = w // 2
        ext = np.take(p**2, np.arange(-h, n - h + w - 1), mode="wrap")
        c = np.concatenate([[0.0], np.cumsum(ext)])
        mean_square = np.maximum((c[w : w + n] - c[:n]) / w, 0.0)
        return sound_pressure_level(np.sqrt(mean_square))

    def spectrum(self, part: str = "total", window="hann", segment_length=None):
        """Single-sided amplitude spectrum of the pressure of ``part`` ("inner_ring", "balls"
        or "total") [Pa] (:func:`bearinglab.signal.amplitude_spectrum`, with its
        ``window`` and ``segment_length``).

        Parameters
        ----------
        part : str
            One of :attr:`parts`: "inner_ring" or "balls" (those computed), "total" (the
            default) or an x / y contribution ("inner_ring_x", ...).
        window : str or tuple
            Any window ``scipy.signal.get_window`` accepts; default "hann".
        segment_length : int or None
            Samples per segment (Welch average); None: the whole record as one segment.

        Returns
        -------
        Spectrum
            ``frequency`` [Hz] and ``amplitude`` [Pa].
        """
        from ..signal import amplitude_spectrum

        return amplitude_spectrum(
            self.pressure(part), self.sample_rate, window=window, segment_length=segment_length
        )

    def directivity(self, angles=None, distance: float | None = None) -> Directivity:
        """SPL (eq. 27) of the inner ring, the balls and the total at points round the
        bearing at one distance (seed 002).

        Parameters
        ----------
        angles : array_like, optional
            Directions from +x towards +y [rad]; default 72 steps of 5 deg.
        distance : float, optional
            Distance from the bearing centre [m]; default the result's point distance.
        """
        angles = (
            np.linspace(0.0, 2 * math.pi, 72, endpoint=False)
            if angles is None
            else np.atleast_1d(np.asarray(angles, dtype=float))
        )
        if angles.ndim != 1 or angles.size == 0 or not np.all(np.isfinite(angles)):
            raise InputError("angles", angles, "a 1-D array of finite angles [rad]")
        d = self.point.distance if distance is None else distance
        levels: dict[str, list] = {}
        for a in angles:
            parts = pressures_at(self.inputs, FieldPoint(d, float(a)), self.medium, self.options)
            for name in ("inner_ring", "balls", "total"):
                if name in parts:
                    levels.setdefault(name, []).append(
                        sound_pressure_level(effective_pressure(parts[name]))
                    )
        return Directivity(
            angles, float(FieldPoint(d).distance), {k: np.array(v) for k, v in levels.items()}
        )

    def to_dict(self) -> dict:
        """JSON-ready summary: the levels of :data:`LEVELS` and the parts' L_eq in dB (None
        for a silent part), pressures in Pa."""
        total_t = self.spl_time("total")
        out = {
            "spl_leq_db": _finite_or_none(self.spl("total")),
            "spl_time_mean_db": _finite_or_none(np.mean(total_t)),
            "spl_time_max_db": _finite_or_none(np.max(total_t)),
        }
        for name in self.parts:
            if name != "total":
                out[f"spl_leq_{name}_db"] = _finite_or_none(self.spl(name))
        out.update(
            {
                "effective_pressure_upa": self.effective_pressure("total") * 1e6,
                "peak_pressure_upa": float(np.max(np.abs(self.parts["total"]))) * 1e6,
                "distance_mm": self.point.distance * 1e3,
                "angle_deg": math.degrees(self.point.angle),
                "sample_rate_hz": self.sample_rate,
                "duration_s": self.time.size / self.sample_rate,
                "density_kg_m3": self.medium.density,
                "sound_speed_m_s": self.medium.sound_speed,
                "ring_model": self.options["ring_model"],
                "ball_source": self.options["ball_source"],
            }
        )
        for key in ("ring_radius", "ball_radius", "pitch_radius"):
            if self.options.get(key) is not None:
                out[f"{key}_mm"] = self.options[key] * 1e3
        return out

    def to_pandas(self):
        """One row per sample: ``time_s`` and ``p_<part>_pa`` for every part."""
        import pandas as pd

        return pd.DataFrame(
            {"time_s": self.time, **{f"p_{k}_pa": v for k, v in self.parts.items()}}
        )

    def plot(self, axes=None):
        """Pressure against time (ring, balls, total) and SPL(t), labelled with its time
        mean and the L_eq of each part, on ``axes`` (two matplotlib Axes; a new figure
        by default); returns (fig, axes).

        Parameters
        ----------
        axes : pair of matplotlib Axes or None
            Where to draw: the pressure on the first, the SPL on the second; None: a new figure.
        """
        from ..plotting import figure_axes

        fig, axes = figure_axes(axes, 2, 1, figsize=(8, 6), sharex=True)
        t = self.time - self.time[0]
        for name in ("inner_ring", "balls", "total"):
            if name in self.parts:
                axes[0].plot(t, self.parts[name], lw=0.8, label=name)
                level = self.spl_time(name)
                axes[1].plot(
                    t,
                    level,
                    lw=0.8,
                    label=f"{name}: time mean {np.mean(level):.1f} "
                    f"dB, L_eq {self.spl(name):.1f} dB",
                )
        axes[0].set_ylabel("sound pressure [Pa]")
        axes[1].set_ylabel("SPL(t) [dB re 20 µPa]")
        axes[1].set_xlabel("time [s]")
        axes[0].set_title(
            f"point at {self.point.distance * 1e3:.4g} mm, "
            f"{math.degrees(self.point.angle):g} deg: L_eq {self.spl():.1f} dB"
        )
        for ax in axes:
            ax.legend(fontsize=8)
            ax.grid(alpha=0.3)
        fig.tight_layout()
        return fig, axes
