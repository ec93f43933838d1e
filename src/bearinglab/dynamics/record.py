"""A simulated record and what an engineer reads from it: the simulation, its envelope
diagnosis and the lines of its plain spectrum (what ``bearinglab simulate`` shows).

Layer 3: :func:`simulate_record` runs :func:`~bearinglab.dynamics.simulate` (seed 003's
rigid model or seed 004's slip model), diagnoses the pedestal acceleration ``acc_y`` by
:func:`bearinglab.diagnosis.analyze_signal` (Randall & Antoni 2011) and matches the lines
of a plain spectrum to the kinematic frequencies
(:func:`bearinglab.signal.lines.spectrum_lines`: the form-error lines of seed 003 part 4
stand out in ``disp_y``). The operating point and the record are checked first
(:mod:`bearinglab.plausibility`): a record whose sample rate cannot show the simulated
defects is refused, odd inputs are warned about.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from ..plausibility import (
    LOCATION_FAMILY,
    check_record_length,
    operating_warnings,
    sampling_warnings,
)
from .simulation import Simulation, simulate

#: Channels whose plain spectrum can be read (both models have them).
SPECTRUM_CHANNELS = ("disp_y", "disp_x", "acc_y", "acc_x")


@dataclass(frozen=True)
class SimulatedRecord:
    """A simulation (:class:`Simulation`), the envelope diagnosis of its ``acc_y``
    (:class:`bearinglab.diagnosis.Diagnosis`), the plain spectrum of ``spectrum_channel``
    with its labelled ``spectrum_lines``, and the ``warnings`` in the user's terms."""

    simulation: Simulation
    diagnosis: object
    spectrum_channel: str
    spectrum: object
    spectrum_lines: tuple
    warnings: tuple

    def to_dict(self) -> dict:
        """JSON-ready: the simulation's dict, the diagnosis (``diagnosis``, and its
        ``likely_fault`` and ``faults`` at the top), the plain spectrum's lines and the
        warnings."""
        from ..signal.lines import lines_to_dict

        diag = self.diagnosis
        out = self.simulation.to_dict()
        out.update(
            {
                "likely_fault": diag.likely_fault,
                "faults": list(diag.faults),
                "diagnosis": diag.to_dict(),
                "spectrum": {
                    "channel": self.spectrum_channel,
                    "resolution_hz": self.spectrum.resolution,
                    "peaks": lines_to_dict(self.spectrum_lines),
                },
                "warnings": list(self.warnings),
            }
        )
        return out

    def to_pandas(self):
        """The record: time and every channel (:meth:`Simulation.to_pandas`)."""
        return self.simulation.to_pandas()

    def plot(self, axes=None):
        """Envelope spectrum (top) and plain spectrum (bottom); returns (fig, axes)."""
        from ..plotting import _pyplot, draw_spectrum

        if axes is None:
            fig, axes = _pyplot().subplots(2, 1, figsize=(11, 8))
        else:
            fig = axes[0].figure
        diag, spec, channel = self.diagnosis, self.spectrum, self.spectrum_channel
        diag.plot(ax=axes[0])
        draw_spectrum(
            axes[1],
            spec,
            self.spectrum_lines,
            diag.frequencies,
            diag.max_frequency,
            title=f"plain spectrum of {channel} (resolution {spec.resolution:.3g} Hz)",
            ylabel=f"amplitude [{'m' if channel.startswith('disp') else 'm/s^2'}]",
        )
        fig.tight_layout()
        return fig, axes


def simulate_record(
    bearing,
    condition,
    defects=(),
    *,
    spectrum_channel: str = "disp_y",
    progress: Callable[[float], None] | None = None,
    **options,
) -> SimulatedRecord:
    """Simulate, diagnose and read the plain spectrum of one record.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing.
    condition : OperatingCondition
        Radial load and shaft speed (> 0) [N, rad/s]; the models are planar.
    defects : sequence of Defect
        Localised defects; empty for a healthy bearing.
    spectrum_channel : str
        One of :data:`SPECTRUM_CHANNELS` [-].
    progress : callable, optional
        Called with the fraction of the integration done.
    **options
        Keywords of :func:`~bearinglab.dynamics.simulate` (model, duration, sample_rate,
        settle, noise, seed, imperfections, parameters, lubricant, rtol).

    Raises
    ------
    InputError
        For a spectrum channel that is not one of :data:`SPECTRUM_CHANNELS`, a load or
        speed past the models' limits, or a sample rate whose Nyquist frequency is below
        the defect frequency of a simulated defect (of BPFO when there is none).
    """
    from ..diagnosis import analyze_signal
    from ..errors import InputError
    from ..kinematics import defect_frequencies
    from ..signal.lines import spectrum_lines

    if spectrum_channel not in SPECTRUM_CHANNELS:
        raise InputError(
            "spectrum_channel", spectrum_channel, f"one of {', '.join(SPECTRUM_CHANNELS)}"
        )
    defects = tuple(defects)
    # a record that cannot show the simulated defects (healthy: even BPFO) is refused
    families = [LOCATION_FAMILY[d.location] for d in defects] or ["outer_race"]
    warnings = operating_warnings(bearing, condition)
    if condition.shaft_speed > 0:
        kin = defect_frequencies(bearing, condition.shaft_speed)
        warnings += sampling_warnings(
            kin, options.get("sample_rate", 50e3), options.get("duration", 1.0), families
        )
        check_record_length(kin, options.get("duration", 1.0))
    sim = simulate(bearing, condition, defects, progress=progress, **options)
    # the simulated load: what the ball bridges at a race defect's edges (its width)
    load = condition.radial_load if condition.radial_load > 0 else None
    diag = analyze_signal(sim.signal, None, sim.kinematic, channel="acc_y", radial_load=load)
    spec, lines = spectrum_lines(
        sim.signal.channel(spectrum_channel),
        sim.signal.sample_rate,
        sim.kinematic,
        diag.max_frequency,
    )
    if "varying_compliance_hz" in sim.signal.metadata:
        # no defect: the lines at the ball-pass rate of the loaded outer ring are the
        # varying compliance (dynamics.simulate), named so
        lines = [
            {k: ("varying_compliance" if v == "bpfo" else v) for k, v in line.items()}
            for line in lines
        ]
    warnings += list(sim.warnings)
    if condition.axial_load:
        warnings.append(
            f"the axial load {condition.axial_load:g} N does not enter the "
            f"{sim.model} model (it is planar: radial load only)"
        )
    imperfections = options.get("imperfections")
    if imperfections is not None and not defects:
        warnings.append(
            "no defects were simulated: the lines at the defect frequencies come "
            "from the form errors (e.g. outer-race waviness of order kZ +- 1 "
            "gives k x BPFO), so a fault found is not a defect"
        )
    return SimulatedRecord(sim, diag, spectrum_channel, spec, tuple(lines), tuple(warnings))
