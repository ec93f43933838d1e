"""ISO 15242 vibration velocity bands of a bearing at an operating point (layer 3).

The one computation the ``noise`` command and the report share (issue 12).

What ISO 15242 measures (part 1, fundamentals, and part 2, radial ball bearings with
cylindrical bore and outside surface): the root-mean-square radial vibration velocity of
the outer ring, in um/s, while the inner ring turns on a stiff spindle and the outer ring
carries a light load through a compliant fixture, in three bands whose edges are, at the
default 1800 min^-1 (ISO 15242-2:2015 sec. 4.1), 50-300, 300-1800 and 1800-10000 Hz; at
another speed the edges move in proportion to it (the speed scaling of
:func:`bearinglab.signal.iso15242_bands`; sources in :mod:`bearinglab.signal.bands` and
docs/capabilities/noise.md). With the spindle stiff the outer ring moves as the inner
ring's motion relative to it, so the quantity here is the velocity of the inner ring
relative to the outer ring along the load (y), which both models give:

* the quasi-static orbit (:func:`bearinglab.quasistatic.orbit.inner_ring_orbit`, seed 003
  part 4) when it is sampled above twice the top band edge over at least
  :data:`bearinglab.signal.bands.MIN_PERIODS` periods of the lowest edge;
* otherwise seed 003's rigid dynamic model (:func:`bearinglab.dynamics.simulate`, no
  defects, the same form errors; its ``disp_y`` channel is that relative displacement) at
  :data:`BANDS_RATE_FACTOR` x the top edge; its shaft and pedestal resonances shape the
  medium and high bands.

The velocity is taken by central differences in time and detrended like the noise model's
records (a ramp brings the extrapolated next sample onto the first), because converting a
displacement in the frequency domain turns the record's end jump into a broadband spike.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..operating import speed_error
from ..signal.bands import MIN_PERIODS, VelocityBands, iso15242_bands, velocity_bands
from ..units import rad_s_to_rpm
from .radiation import velocity_from_positions

#: Sample rate of a band record over the top band edge (the usual analyser ratio: 25.6 kHz
#: for the 10 kHz edge at 1800 rpm).
BANDS_RATE_FACTOR = 2.56
#: Where the record may come from: the orbit when it resolves the bands, else the rigid
#: model (auto); the orbit (a second, finer one if needed); the rigid model.
BAND_SOURCES = ("auto", "orbit", "rigid")
#: Band names in order.
BAND_NAMES = ("low", "medium", "high")


@dataclass(frozen=True, eq=False)
class BearingVelocityBands:
    """ISO 15242 RMS velocity in the low, medium and high bands and where it came from.

    Attributes: ``bands`` (:class:`bearinglab.signal.VelocityBands`: ``low``, ``medium``,
    ``high`` [um/s] and the edges [Hz]); ``speed_rpm``, the speed the edges are scaled to
    [rpm]; ``source`` ("orbit" or "rigid model"); ``note``, how and why; ``sample_rate``
    [Hz] and ``duration`` [s] of the record.
    """

    bands: VelocityBands
    speed_rpm: float
    source: str
    note: str
    sample_rate: float
    duration: float

    def __getitem__(self, name: str) -> float:
        """RMS velocity of band ``name`` [um/s]."""
        if name not in BAND_NAMES:
            raise InputError("band", name, f"one of {BAND_NAMES}")
        return float(getattr(self.bands, name))

    def to_dict(self) -> dict:
        """``velocity_bands_um_s`` (low, medium, high), ``velocity_bands_hz`` (edges), the
        source, note, sample rate and duration (JSON-ready)."""
        return {
            "velocity_bands_um_s": {k: self[k] for k in BAND_NAMES},
            "velocity_bands_hz": {k: list(self.bands.bands[k]) for k in BAND_NAMES},
            "velocity_bands_source": self.source,
            "velocity_bands_note": self.note,
            "velocity_bands_sample_rate_hz": self.sample_rate,
            "velocity_bands_duration_s": self.duration,
        }

    def to_pandas(self):
        """One row per band: ``band``, ``low_hz``, ``high_hz``, ``velocity_um_s``."""
        import pandas as pd

        return pd.DataFrame(
            [
                {
                    "band": k,
                    "low_hz": self.bands.bands[k][0],
                    "high_hz": self.bands.bands[k][1],
                    "velocity_um_s": self[k],
                }
                for k in BAND_NAMES
            ]
        )

    def plot(self, ax=None):
        """Bar chart of the three bands [um/s] on ``ax`` (a matplotlib Axes; a new figure
        by default); returns (fig, ax), never shows.

        Parameters
        ----------
        ax : matplotlib Axes or None
            Where to draw; None: a new figure.
        """
        from ..plotting import figure_axes

        fig, ax = figure_axes(ax, figsize=(6.5, 3.2))
        edges = self.bands.bands
        ax.bar(
            [f"{k}\n{edges[k][0]:.4g}-{edges[k][1]:.4g} Hz" for k in BAND_NAMES],
            [self[k] for k in BAND_NAMES],
            color=["C0", "C1", "C2"],
        )
        ax.set_ylabel("RMS velocity [µm/s]")
        ax.set_title(f"ISO 15242 bands at {self.speed_rpm:.6g} rpm ({self.source})", fontsize=10)
        ax.grid(axis="y", alpha=0.3)
        return fig, ax


def _detrended_velocity(time, position) -> np.ndarray:
    """Velocity of a record by central differences, with the ramp taken off that brings
    the linearly extrapolated next sample onto the first (as the noise model does), so
    that the record's periodic extension has no jump [m/s]."""
    v = velocity_from_positions(time, position)
    n = v.size
    jump = 2.0 * v[-1] - v[-2] - v[0]
    return v - jump * np.arange(n) / n


def bearing_velocity_bands(
    bearing,
    condition,
    imperfections=None,
    *,
    orbit=None,
    source: str = "auto",
    progress: Callable[[float], None] | None = None,
) -> BearingVelocityBands:
    """ISO 15242 RMS radial vibration velocity of ``bearing`` under ``condition`` in the
    low, medium and high bands, the edges scaled to the shaft speed (see the module).

    Parameters
    ----------
    bearing : BallBearing
        Geometry and materials.
    condition : OperatingCondition
        Radial load > 0 [N] and shaft speed > 0 [rad/s].
    imperfections : bearinglab.imperfections.Imperfections, optional
        Waviness, ball-size errors, random surfaces (None: a perfect bearing).
    orbit : bearinglab.quasistatic.orbit.Orbit, optional
        An orbit of the same bearing and condition already computed (the noise model's):
        used when it resolves the bands.
    source : {"auto", "orbit", "rigid"}
        auto: ``orbit`` if it resolves the bands, else the rigid model; orbit: that orbit
        or a second, finer one; rigid: the rigid dynamic model.
    progress : callable, optional
        Called with the fraction done (0-1) of the model run.

    Returns
    -------
    BearingVelocityBands
    """
    from ..dynamics import simulate
    from ..quasistatic.orbit import inner_ring_orbit

    if source not in BAND_SOURCES:
        raise InputError("bands_from", source, f"one of {BAND_SOURCES}")
    speed_rpm = rad_s_to_rpm(condition.shaft_speed)
    if not speed_rpm > 0:
        raise speed_error(condition.shaft_speed, "a speed > 0 rpm")
    edges = iso15242_bands(speed_rpm)
    top = max(hi for _, hi in edges.values())
    need_rate = 2.0 * top
    need_length = MIN_PERIODS / min(lo for lo, _ in edges.values())
    rate_out = BANDS_RATE_FACTOR * top
    length_out = need_length
    fits = False
    if orbit is not None:
        t = orbit.time
        rate = (t.size - 1) / (t[-1] - t[0])
        length = t.size / rate
        fits = rate > need_rate and length >= need_length * (1 - 1e-9)
        length_out = max(need_length, length)
    if source == "rigid" or (source == "auto" and not fits):
        sim = simulate(
            bearing,
            condition,
            (),
            imperfections=imperfections,
            duration=length_out,
            sample_rate=rate_out,
            progress=progress,
        )
        y = sim.signal.channels["disp_y"]
        time = np.arange(y.size) / rate_out
        origin = "rigid model"
        note = (
            "the rigid dynamic model (seed 003's 4-DOF model, no defects, the same form "
            "errors; its resonances shape the medium and high bands)"
        )
        if source == "auto":
            note += (
                f": the orbit ({rate:.6g} Hz over {length:.4g} s) cannot resolve the "
                f"bands (it needs > {need_rate:.6g} Hz over >= {need_length:.4g} s)"
                if orbit is not None
                else ": no orbit given"
            )
    elif fits:
        time, y = orbit.time, orbit.y
        rate_out, length_out = rate, length
        origin, note = "orbit", "the orbit of the noise calculation (quasi-static)"
    else:
        count = math.ceil(rate_out * length_out)
        second = inner_ring_orbit(
            bearing, condition, imperfections=imperfections, duration=length_out, points=count
        )
        time, y = second.time, second.y
        origin = "orbit"
        note = (
            f"a quasi-static orbit at {rate_out:.6g} Hz over {length_out:.4g} s (the "
            "noise orbit's sampling cannot resolve the bands)"
            if orbit is not None
            else f"a quasi-static orbit at {rate_out:.6g} Hz over {length_out:.4g} s"
        )
    vb = velocity_bands(_detrended_velocity(time, y), rate_out, "velocity", speed_rpm=speed_rpm)
    return BearingVelocityBands(vb, speed_rpm, origin, note, float(rate_out), float(length_out))
