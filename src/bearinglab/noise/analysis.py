"""Noise of a running bearing, whole: the sound at a point, the lines of its spectrum and
the ISO 15242 velocity bands (layer 3; the ``noise`` command and the report call
:func:`noise_analysis`).

:func:`noise_analysis` runs :func:`.bearing_noise` (seed 003 part 4: the quasi-static orbit
of a bearing with form errors radiated by the inner ring and the balls), matches the lines
of the sound-pressure spectrum to the bearing's frequencies
(:func:`bearinglab.signal.lines.spectrum_lines`; seed 002: the pressure peaks at the
ball-pass frequencies) and computes the ISO 15242 bands
(:func:`.bands.bearing_velocity_bands`) from the same orbit when it resolves them, else
from the rigid dynamic model. docs/capabilities/noise.md, "The noise command".
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ..units import rad_s_to_rpm
from .bands import BAND_NAMES, BearingVelocityBands, bearing_velocity_bands
from .bearing import BearingNoise, bearing_noise
from .model import as_field_point, check_field_point, default_field_point
from .result import LEVELS

#: Lines of the pressure spectrum kept, and the highest harmonic matched.
PEAK_COUNT = 16
PEAK_HARMONICS = 10
#: Least prominence of a pressure line, in medians of the spectrum. The record is one
#: cage revolution by default, so every bin is a multiple of the cage frequency and the
#: quasi-static orbit's kinks (a ball entering or leaving the load zone) spread the
#: ball-pass harmonics evenly: they stand about 1.5 medians above the rest.
PEAK_PROMINENCE = 1.0
#: Frequencies marked on the spectrum plot.
PLOTTED_FREQUENCIES = ("shaft", "ftf", "bpfo", "bpfi")

#: (what, key of :meth:`NoiseAnalysis.to_dict`) of the levels, each with its definition.
LEVEL_ROWS = (
    ("L_eq, whole record (eq. 27)", "spl_leq_db"),
    ("SPL(t), time mean (seed 003's mean SPL)", "spl_time_mean_db"),
    ("SPL(t), maximum", "spl_time_max_db"),
    ("L_eq, inner ring alone", "spl_leq_inner_ring_db"),
    ("L_eq, balls alone", "spl_leq_balls_db"),
    ("effective pressure p_e (RMS)", "effective_pressure_upa"),
)


@dataclass(frozen=True, eq=False)
class NoiseAnalysis:
    """The noise of a bearing at an operating point.

    Attributes: ``noise`` (:class:`.BearingNoise`: the orbit, the sound at the point and the
    ball model), ``point_source`` (how the field point was chosen), ``spectrum``
    (:class:`bearinglab.signal.Spectrum` of the total pressure [Pa]) and ``peaks`` (its
    labelled lines up to ``max_frequency`` [Hz]), ``kinematic``
    (:class:`bearinglab.kinematics.DefectFrequencies`), ``bands``
    (:class:`.BearingVelocityBands`), ``warnings`` (sentences in the user's terms).

    Levels (each number one definition, :data:`.result.LEVELS`): ``spl_leq_db`` (eq. 27,
    the energy mean over the record), ``spl_time_mean_db`` and ``spl_time_max_db`` (the
    mean and maximum of the level curve SPL(t)), ``spl_leq_inner_ring_db`` and
    ``spl_leq_balls_db`` (L_eq of the inner ring or the balls alone).
    """

    noise: BearingNoise
    point_source: str
    spectrum: object
    peaks: list
    max_frequency: float
    kinematic: object
    bands: BearingVelocityBands
    warnings: tuple = field(default=())

    @property
    def sound(self):
        """The sound pressure at the point (:class:`.SoundPressure`)."""
        return self.noise.sound

    @property
    def orbit(self):
        """The quasi-static orbit (:class:`bearinglab.quasistatic.orbit.Orbit`)."""
        return self.noise.orbit

    def levels(self) -> dict:
        """The levels [dB] (None for a silent part): key -> value."""
        d = self.sound.to_dict()
        return {k: v for k, v in d.items() if k.startswith("spl_")}

    def to_dict(self) -> dict:
        """JSON-ready: the operating point, the field point and its source, the levels
        [dB], the pressure lines, the velocity bands and the record, in engineering units
        (the keys' suffixes give the units, docs/json.md)."""
        from ..signal.lines import lines_to_dict

        o = self.orbit
        summary = self.noise.to_dict()
        point = {k: summary.pop(k) for k in ("distance_mm", "angle_deg")}
        levels = {k: summary.pop(k) for k in list(summary) if k.startswith("spl_")}
        imperfections = summary.pop("imperfections", None)
        for key in ("speed_rpm", "radial_load_n"):
            summary.pop(key)
        return {
            "speed_rpm": rad_s_to_rpm(o.condition.shaft_speed),
            "radial_load_n": o.condition.radial_load,
            **point,
            "field_point_source": self.point_source,
            **levels,
            **self.bands.to_dict(),
            "peaks": lines_to_dict(self.peaks),
            "peaks_resolution_hz": self.spectrum.resolution,
            "peaks_max_frequency_hz": self.max_frequency,
            "kinematic": self.kinematic.to_dict(),
            **summary,
            "imperfections": imperfections,
            "warnings": list(self.warnings),
        }

    def to_pandas(self):
        """The levels and the bands as a table: ``quantity``, ``key``, ``value``, ``unit``
        (the time series are in ``sound.to_pandas()``)."""
        import pandas as pd

        from ..units import unit_of

        d = self.to_dict()
        rows = [(what, key, d.get(key)) for what, key in LEVEL_ROWS]
        rows += [
            (
                f"ISO 15242 {k} band {lo:.4g}-{hi:.4g} Hz",
                f"velocity_bands_um_s.{k}",
                d["velocity_bands_um_s"][k],
            )
            for k in BAND_NAMES
            for lo, hi in [d["velocity_bands_hz"][k]]
        ]
        return pd.DataFrame(
            [
                {
                    "quantity": what,
                    "key": key,
                    "value": value,
                    "unit": unit_of(key.split(".")[0]).symbol,
                }
                for what, key, value in rows
            ]
        )

    def plot(self, fig=None):
        """Pressure and SPL(t) against time (left), the pressure spectrum with the BPFO /
        BPFI harmonics and the labelled lines, and the directivity at the point's distance
        (right), on ``fig`` (a matplotlib Figure; a new one by default); returns
        (fig, axes), never shows.

        Parameters
        ----------
        fig : matplotlib Figure or None
            The figure to draw on (four Axes are added to it); None: a new figure.
        """
        from ..plotting import _pyplot, draw_spectrum

        if fig is None:
            fig = _pyplot().figure(figsize=(14, 8.5))
        pressure = fig.add_subplot(2, 2, 1)
        level = fig.add_subplot(2, 2, 3, sharex=pressure)
        self.sound.plot(axes=[pressure, level])
        spectrum = fig.add_subplot(2, 2, 2)
        draw_spectrum(
            spectrum,
            self.spectrum,
            self.peaks,
            self.kinematic,
            self.max_frequency,
            title=f"sound-pressure spectrum (resolution {self.spectrum.resolution:.3g} Hz)",
            ylabel="amplitude [Pa]",
            names=PLOTTED_FREQUENCIES,
            harmonics=PEAK_HARMONICS,
        )
        polar = fig.add_subplot(2, 2, 4, projection="polar")
        self.sound.directivity().plot(ax=polar)
        fig.tight_layout()
        return fig, [pressure, level, spectrum, polar]


def noise_analysis(
    bearing,
    condition,
    imperfections=None,
    *,
    point=None,
    angle: float | None = None,
    duration: float | None = None,
    points: int | None = None,
    bands_from: str = "auto",
    progress: Callable[[float, str], None] | None = None,
    **noise_options,
) -> NoiseAnalysis:
    """Noise of ``bearing`` under ``condition`` with ``imperfections``: SPL at a point
    (seed 003 part 4), the labelled lines of the pressure spectrum (seed 002) and the
    ISO 15242 velocity bands.

    Parameters
    ----------
    bearing : BallBearing
        Geometry and materials.
    condition : OperatingCondition
        Radial load > 0 [N] and shaft speed > 0 [rad/s].
    imperfections : bearinglab.imperfections.Imperfections, optional
        Waviness, ball-size errors, random surfaces; None: a perfect bearing.
    point : FieldPoint or (distance, angle), optional
        Field point [m, rad]; default :func:`.model.default_field_point` (10 mm outside
        the outside diameter, straight up). It must lie outside the balls' path.
    angle : float, optional
        Direction of the default point, from +x towards +y [rad] (with ``point`` None;
        default straight up).
    duration : float, optional
        Length of the orbit record [s]; default one cage revolution.
    points : int, optional
        Instants of the orbit; default 8192 per second (at least 256).
    bands_from : {"auto", "orbit", "rigid"}
        Source of the ISO 15242 bands (:func:`.bands.bearing_velocity_bands`).
    progress : callable, optional
        Called as ``progress(fraction, stage)`` between the stages.
    **noise_options
        Passed to :func:`.bearing_noise` (``medium``, ``ball_model``, ``ring_model``, orbit
        options).

    Returns
    -------
    NoiseAnalysis

    Raises
    ------
    InputError
        ``point`` inside the balls' path; a load or speed past the models' limits
        (:func:`bearinglab.plausibility.operating_warnings`); form errors whose contact
        pressure passes 8.4 GPa at an instant of the orbit (named ``waviness``,
        ``ball_size_error_um`` or ``surface3d``,
        :func:`bearinglab.plausibility.contact_warnings`); bad record options.
    """
    from ..dynamics import needs_compiling
    from ..errors import InputError
    from ..kinematics import defect_frequencies
    from ..plausibility import (
        contact_warnings,
        form_error_inputs,
        operating_warnings,
        sampling_warnings,
    )
    from ..signal.lines import spectrum_lines

    def stage(fraction: float, text: str) -> None:
        if progress is not None:
            progress(fraction, text)

    if not condition.radial_load > 0:
        raise InputError(
            "radial_load", condition.radial_load, "a radial load > 0 [N] (the orbit needs a load)"
        )
    if point is None:
        point, source = default_field_point(bearing, angle)
    else:
        if angle is not None:
            raise InputError(
                "angle", angle, "None when a point is given (its angle is the point's)"
            )
        point = as_field_point(point)
        source = "given"
    warnings = [*operating_warnings(bearing, condition), *check_field_point(bearing, point)]
    if imperfections is None or imperfections.is_empty:
        warnings.append(
            "no form errors given: the sound comes only from the varying "
            "compliance of a perfect bearing"
        )
    kin = defect_frequencies(bearing, condition.shaft_speed)
    stage(0.0, "orbit and sound pressure")
    noise = bearing_noise(
        bearing,
        condition,
        imperfections,
        duration=duration,
        points=points,
        point=point,
        **noise_options,
    )
    # the contact pressure of the form errors at the orbit's worst instant (ISO 76)
    warnings += contact_warnings(bearing, noise.orbit, cause=form_error_inputs(imperfections))
    stage(
        0.6,
        "velocity bands"
        + (
            " (compiling the rigid model, first run only)"
            if bands_from != "orbit" and needs_compiling("rigid")
            else ""
        ),
    )
    bands = bearing_velocity_bands(
        bearing,
        condition,
        imperfections,
        orbit=noise.orbit,
        source=bands_from,
        progress=lambda f: stage(0.6 + 0.3 * f, "velocity bands"),
    )
    stage(0.9, "pressure spectrum")
    sound = noise.sound
    # the record's sampling against the bearing's lines (too few points), and its length
    # against one cage revolution, the period of the steady orbit (not an envelope's
    # resolution: the default record is exactly one revolution)
    pressure = sound.pressure("total")
    warnings += sampling_warnings(kin, sound.sample_rate)
    revolution = 1.0 / kin.hz("ftf")
    if pressure.size / sound.sample_rate < 0.99 * revolution:
        warnings.append(
            f"the record ({pressure.size / sound.sample_rate:.3g} s) is shorter than one cage "
            f"revolution ({revolution:.3g} s): not every ball passes the load zone, and the "
            "levels are of part of the orbit"
        )
    top = PEAK_HARMONICS + 0.5
    max_frequency = min(0.5 * sound.sample_rate, top * max(kin.hz("bpfo"), kin.hz("bpfi")))
    spectrum, peaks = spectrum_lines(
        pressure,
        sound.sample_rate,
        kin,
        max_frequency,
        count=PEAK_COUNT,
        harmonics=PEAK_HARMONICS,
        prominence=PEAK_PROMINENCE,
        slip_tolerance=0.0,
    )
    stage(1.0, "done")
    return NoiseAnalysis(
        noise, source, spectrum, peaks, float(max_frequency), kin, bands, tuple(warnings)
    )


__all__ = ["LEVELS", "LEVEL_ROWS", "NoiseAnalysis", "noise_analysis"]
