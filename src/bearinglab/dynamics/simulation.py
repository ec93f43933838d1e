"""Running a dynamic model: time integration in chunks, resampling, the result object.

Layer 3. :func:`simulate` takes a bearing, an operating condition and defects, runs the
rigid-ring model (seed 003, :mod:`.rigid`) or the slip model (seed 004, :mod:`.slip`)
with a compiled integrator (:mod:`._integrate`, ``_rosenbrock.rosenbrock_chunk``),
drops the settling time and returns a :class:`Simulation` whose signal is sampled at the
user's rate. The same inputs give the same signal (the integrators are deterministic and
the optional measurement noise is drawn from ``seed``).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ..errors import ConvergenceError, InputError, positive_number
from ..kinematics import DefectFrequencies, defect_frequencies
from ..operating import speed_error
from ..signal import Signal
from . import _integrate, _kernels, _rosenbrock, _slip_kernels, rigid, slip
from .defects import Defect, pack_defects

MODELS = ("rigid", "slip")
MAX_STEPS_PER_CHUNK = 2_000_000
CHUNKS = 40
#: Largest rigid-model step, in sample intervals (its dense output is of order 4).
RIGID_STEPS_PER_SAMPLE = 2.0


@dataclass(frozen=True)
class Simulation:
    """A simulated vibration record and what produced it.

    Attributes: ``model`` ("rigid" or "slip"), ``bearing``, ``condition``, ``defects``,
    ``signal`` (:class:`bearinglab.signal.Signal`: ``acc_x``, ``acc_y`` [m/s^2] of the
    outer ring/pedestal, ``disp_x``, ``disp_y`` [m] of the inner ring relative to the
    outer; the slip model adds ``cage_speed`` [rad/s]), ``kinematic``
    (:class:`~bearinglab.kinematics.DefectFrequencies`), ``ball_orbital_speed`` and
    ``ball_spin_speed`` (Z, n) [rad/s] and ``slip_inner``, ``slip_outer`` (Z, n) [m/s]
    (slip model, eq. 13), ``parameters`` and ``stats`` (steps, rejected steps, settle
    time).

    Slip model only (None for the rigid one): ``ball_spin_phase`` (Z, n) [rad], the
    balls' continuous spin phases phi_j, and ``cage_angle`` (n,) [rad], from which
    ``spin_speed_ratio`` and ``cage_speed_ratio`` are measured; ``halves``, the two
    ratios over each half of the record (:func:`.slip.halves_check`); ``warnings``,
    plain-language notes on the record (not settled, halves disagree).
    """

    model: str
    bearing: object
    condition: object
    defects: tuple
    signal: Signal
    kinematic: DefectFrequencies
    parameters: object
    stats: dict
    ball_orbital_speed: np.ndarray | None = None
    ball_spin_speed: np.ndarray | None = None
    slip_inner: np.ndarray | None = None
    slip_outer: np.ndarray | None = None
    extra: dict = field(default_factory=dict)
    # --- slip model: angles, halves check, warnings (issue 14) ---
    ball_spin_phase: np.ndarray | None = None
    cage_angle: np.ndarray | None = None
    halves: dict | None = None
    warnings: tuple = ()
    imperfections: object = None

    def to_dict(self) -> dict:
        """JSON-ready summary in engineering units (no samples: :meth:`to_pandas` has them)."""
        c, sig = self.condition, self.signal
        return {
            "model": self.model,
            "bearing": getattr(self.bearing, "name", "") or None,
            "speed_rpm": c.speed_rpm,
            "radial_load_n": c.radial_load,
            "axial_load_n": c.axial_load,
            "sample_rate_hz": sig.sample_rate,
            "duration_s": sig.duration,
            "start_time_s": sig.metadata.get("start_time_s"),
            "channels": list(sig.names),
            "defects": [d.to_dict() for d in self.defects],
            "imperfections": (None if self.imperfections is None else self.imperfections.to_dict()),
            "kinematic": self.kinematic.to_dict(),
            "cage_speed_ratio": self.cage_speed_ratio,
            "spin_speed_ratio": self.spin_speed_ratio,
            "halves": self.halves,
            "parameters": self.parameters.to_dict(),
            "stats": dict(self.stats),
            "warnings": list(self.warnings),
        }

    def to_pandas(self):
        """The record as a table: ``time_s`` and one column per channel (SI units:
        ``acc_*`` [m/s^2], ``disp_*`` [m], ``cage_speed`` [rad/s])."""
        import pandas as pd

        sig = self.signal
        start = sig.metadata.get("start_time_s") or 0.0
        table = {"time_s": start + np.arange(sig.n_samples) / sig.sample_rate}
        table.update({name: sig.channel(name) for name in sig.names})
        return pd.DataFrame(table)

    def plot(self, axes=None, channels=("acc_y", "disp_y")):
        """The record's ``channels`` against time, one above the other, on ``axes`` (one
        matplotlib Axes per channel; a new figure by default); (fig, axes).

        Parameters
        ----------
        axes : sequence of matplotlib Axes or None
            One Axes per channel, top to bottom; None: a new figure.
        channels : sequence of str
            Channels to plot: ``acc_x``, ``acc_y`` [m/s^2], ``disp_x``, ``disp_y`` (drawn in
            [um]) and, for the slip model, ``cage_speed`` [rad/s].

        Returns
        -------
        (Figure, axes)
            The figure (not shown) and its Axes.
        """
        from ..plotting import _pyplot

        if axes is None:
            fig, axes = _pyplot().subplots(
                len(channels), 1, figsize=(10, 2.6 * len(channels)), sharex=True, squeeze=False
            )
            axes = axes[:, 0]
        else:
            fig = axes[0].figure
        table = self.to_pandas()
        units = {"acc": "m/s^2", "dis": "um", "cag": "rad/s"}
        for ax, name in zip(axes, channels, strict=True):
            values = table[name] * (1e6 if name.startswith("disp") else 1.0)
            ax.plot(table["time_s"], values, lw=0.6)
            ax.set_ylabel(f"{name} [{units[name[:3]]}]")
        axes[-1].set_xlabel("time [s]")
        axes[0].set_title(
            f"{getattr(self.bearing, 'name', '') or 'bearing'}: {self.model} "
            f"model, {self.condition.speed_rpm:g} rpm, "
            f"{self.condition.radial_load:g} N"
        )
        fig.tight_layout()
        return fig, axes

    def _angle_ratio(self, angle, order) -> float:
        span = (self.signal.n_samples - 1) / self.signal.sample_rate
        return advance_ratio(angle, span, self.kinematic, order)

    @property
    def cage_speed_ratio(self) -> float | None:
        """Mean cage speed over its pure-rolling value, from the advance of the cage
        angle over the record (slip model; None for rigid)."""
        if self.cage_angle is None:
            return None
        return self._angle_ratio(self.cage_angle, "ftf")

    @property
    def spin_speed_ratio(self) -> float | None:
        """Mean ball spin speed over its pure-rolling value, from the advance of the
        balls' unwrapped spin phases over the record, not from the sampled speeds (whose
        mean is biased when the spin varies round the orbit faster than the sampling
        resolves; see :func:`.slip.phase_ratios`). Slip model; None for rigid."""
        if self.ball_spin_phase is None:
            return None
        return self._angle_ratio(self.ball_spin_phase, "bsf")


def advance_ratio(angle, span: float, kin, order: str) -> float:
    """Advance of a continuous angle (or the mean of several) over ``span`` [s], as a
    ratio to the pure-rolling speed of ``order`` (:attr:`DefectFrequencies.orders`) [-]."""
    pure = kin.orders[order] * kin.shaft_speed
    return float(np.mean(angle[..., -1] - angle[..., 0]) / span / pure)


def simulate(
    bearing,
    condition,
    defects=(),
    *,
    model: str = "rigid",
    duration: float = 1.0,
    sample_rate: float = 50e3,
    parameters=None,
    lubricant=None,
    settle: float | None = None,
    rtol: float | None = None,
    noise: float = 0.0,
    seed: int | None = None,
    imperfections=None,
    progress: Callable[[float], None] | None = None,
) -> Simulation:
    """Simulate the vibration of ``bearing`` under ``condition`` with ``defects``.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        Geometry and materials.
    condition : OperatingCondition
        Radial load (direction included) and shaft speed [rad/s] (inner ring turning).
    defects : sequence of Defect
        Localised defects; empty for a healthy bearing.
    model : {"rigid", "slip"}
        Seed 003's rigid-ring model or seed 004's slip model.
    duration : float
        Length of the recorded signal [s], after ``settle``.
    sample_rate : float
        Output sampling rate [Hz].
    parameters : RigidParameters or SlipParameters, optional
        Model values; defaults documented on the classes.
    lubricant : Lubricant, optional
        Slip model only; default the seed-004 grease.
    settle : float, optional
        Time simulated and discarded before recording [s]; default 0.05 s (rigid) or
        two cage revolutions (slip).
    rtol : float, optional
        Relative tolerance of the integrator; default 1e-6 (rigid), 1e-3 (slip).
    noise : float
        RMS of white measurement noise added to the accelerations [m/s^2].
    seed : int, optional
        Seed of the noise generator.
    imperfections : Imperfections, optional
        Raceway and ball waviness, ball-size errors and random raceway surfaces
        (:class:`bearinglab.imperfections.Imperfections`), through the same surface table
        as the defects (:func:`.defects.pack_defects`).
    progress : callable, optional
        Called with the fraction done (0..1) between integration chunks.
    """
    if model not in MODELS:
        raise InputError("model", model, f"one of {MODELS}")
    duration = positive_number("duration", duration, "a duration > 0 [s]")
    sample_rate = positive_number("sample_rate", sample_rate, "a rate > 0 [Hz]")
    if duration * sample_rate < 64:
        raise InputError("duration", duration, f"at least {64 / sample_rate:g} s (64 samples)")
    if duration * sample_rate > 5e7:
        raise InputError("duration", duration, "at most 5e7 samples in one record")
    noise = positive_number("noise", noise, "an RMS >= 0 [m/s^2]", zero=True)
    if condition.shaft_speed <= 0:
        raise speed_error(condition.shaft_speed, "a speed > 0 rpm")
    defects = tuple(defects)
    if getattr(bearing, "rolling_element", "ball") == "roller":
        if model != "rigid":
            raise InputError(
                "model", model, "rigid for a roller bearing", "the slip model is for ball bearings"
            )
        if imperfections is not None:
            raise InputError(
                "imperfections",
                imperfections,
                "None for a roller bearing",
                "waviness, ball-size errors and random surfaces are modelled for ball "
                "bearings only",
            )
        if not bearing.contact_modelled or bearing.is_tapered or bearing.rows != 1:
            raise InputError(
                "bearing",
                bearing.name or bearing.bearing_type,
                "a single-row cylindrical or needle roller bearing for the rigid model",
                "the planar model has no axial load or second row",
            )
    table = pack_defects(defects, bearing, imperfections)
    kin = defect_frequencies(bearing, condition.shaft_speed)
    if model == "rigid":
        params = parameters or rigid.RigidParameters()
        if not isinstance(params, rigid.RigidParameters):
            raise InputError("parameters", type(params).__name__, "RigidParameters")
        p = rigid.pack(bearing, condition, params, table)
        y0 = rigid.static_state(p)
        atol = rigid.ATOL
        settle = 0.05 if settle is None else settle
        rtol = 1e-6 if rtol is None else rtol
    else:
        params = parameters or slip.SlipParameters()
        if not isinstance(params, slip.SlipParameters):
            raise InputError("parameters", type(params).__name__, "SlipParameters")
        widths = [d.width for d in defects if d.location == "ball"]
        p = slip.pack(bearing, condition, params, table, lubricant, max(widths, default=0.0))
        y0 = slip.initial_state(p)
        atol = slip.atol(bearing.ball_count)
        rtol = 1e-3 if rtol is None else rtol
    if settle is not None:  # slip default: detected below (slip.settle)
        settle = positive_number("settle", settle, "a time >= 0 [s]", zero=True)
    rtol = positive_number("rtol", rtol, "a tolerance in (0, 0.1]")
    if rtol > 0.1:
        raise InputError("rtol", rtol, "a tolerance in (0, 0.1]")

    start, notes, settled = (0.0, 1e-6), [], None
    if model == "slip" and settle is None:
        # settled when the cage and spin ratios stop changing from turn to turn
        t_s, y0, h_s, settled = slip.settle(p, table, y0, rtol, atol, 1.0 / sample_rate)
        start, settle = (t_s, h_s), t_s
        if not settled["settled"]:
            notes.append(
                f"not settled after {settled['turns']} cage revolutions "
                f"({settle:.3g} s): the speed ratios still change by "
                f"{settled['change']:.2g} per two revolutions (rule: "
                f"{slip.SETTLE_TOLERANCE:g}); give a longer settle"
            )
    n = round(duration * sample_rate)
    t_out = settle + np.arange(n) / sample_rate
    # the rigid model's dense output is 4th order, so its step may span two samples (30 %
    # fewer step attempts at equal accuracy, benchmarks/README.md); the slip model
    # interpolates by cubic Hermite and keeps one
    h_max = (RIGID_STEPS_PER_SAMPLE if model == "rigid" else 1.0) / sample_rate
    states, stats = _integrate_chunks(
        model, p, table, y0, t_out, rtol, atol, h_max, progress, start
    )
    stats["settle_s"] = settle
    if settled is not None:  # the settling run's steps count too
        stats["settle_turns"] = settled["turns"]
        stats["steps"] += settled["steps"]
        stats["rejected_steps"] += settled["rejected_steps"]
    sim = _result(
        model,
        bearing,
        condition,
        defects,
        params,
        kin,
        p,
        table,
        t_out,
        states,
        stats,
        noise,
        seed,
        sample_rate,
        notes,
        perfect=not defects and imperfections is None,
    )
    return dataclasses.replace(sim, imperfections=imperfections)


def needs_compiling(model: str = "rigid") -> bool:
    """True when the integrator of ``model`` is not yet in numba's on-disk cache: the first
    simulation in this install will compile it (several seconds; later ones load it).

    Parameters
    ----------
    model : {"rigid", "slip"}
        The dynamic model whose integrator is asked about (any other value is taken as
        "slip").
    """
    kernel = _integrate.dopri_chunk_rigid if model == "rigid" else _rosenbrock.rosenbrock_chunk
    return not _integrate.cached_on_disk(kernel)


def _integrate_chunks(model, p, table, y0, t_out, rtol, atol, h_max, progress, start=(0.0, 1e-6)):
    """Run the integrator chunk by chunk (progress between chunks) from the time and
    step ``start``; raise if it fails."""
    (t, h), y = start, y0.copy()
    pieces = []
    steps = rejected = 0
    bounds = np.linspace(0, t_out.size, min(CHUNKS, t_out.size) + 1).astype(int)
    for k in range(bounds.size - 1):
        chunk = t_out[bounds[k] : bounds[k + 1]]
        if model == "rigid":
            out, t, y, h, s, r, status = _integrate.dopri_chunk_rigid(
                p, table, t, y, h, chunk, rtol, atol, h_max, MAX_STEPS_PER_CHUNK
            )
        else:
            out, t, y, h, s, r, status = _rosenbrock.rosenbrock_chunk(
                p, table, t, y, h, chunk, rtol, atol, h_max, MAX_STEPS_PER_CHUNK
            )
        steps += s
        rejected += r
        if status != _integrate.OK:
            raise ConvergenceError(
                f"{model} model: integration stopped at t = {t:.6g} s: "
                f"{_integrate.STATUS_TEXT[status]} (steps {steps}, rejected {rejected}); "
                "try a smaller load step, a looser rtol or check the inputs"
            )
        pieces.append(out)
        if progress is not None:
            progress(bounds[k + 1] / t_out.size)
    states = np.concatenate(pieces)
    if not np.all(np.isfinite(states)):
        raise ConvergenceError(f"{model} model: the state became non-finite")
    return states, {"steps": int(steps), "rejected_steps": int(rejected)}


def _result(
    model,
    bearing,
    condition,
    defects,
    params,
    kin,
    p,
    table,
    t_out,
    states,
    stats,
    noise,
    seed,
    sample_rate,
    notes=(),
    perfect=False,
):
    accelerations = (
        _kernels.rigid_accelerations if model == "rigid" else _slip_kernels.slip_accelerations
    )
    acc = accelerations(p, table, t_out, states)
    disp = states[:, 0:2] - states[:, 2:4]  # both models start with (x_i, y_i, x_o, y_o)
    if noise > 0:
        acc = acc + np.random.default_rng(seed).normal(0.0, noise, acc.shape)
    channels = {"acc_x": acc[:, 0], "acc_y": acc[:, 1], "disp_x": disp[:, 0], "disp_y": disp[:, 1]}
    extra = {}
    if model == "slip":
        z = bearing.ball_count
        balls = states[:, _slip_kernels.NG :].reshape(t_out.size, z, _slip_kernels.NB)
        channels["cage_speed"] = states[:, 9]
        w_m = balls[:, :, 3].T
        w_r = balls[:, :, 5].T
        r_b, r_in, r_out = p[_slip_kernels.R_B], p[_slip_kernels.R_IN], p[_slip_kernels.R_OUT]
        extra = {
            "ball_orbital_speed": w_m,
            "ball_spin_speed": w_r,
            "slip_inner": (p[_slip_kernels.OMEGA_I] - w_m) * r_in - w_r * r_b,
            "slip_outer": w_r * r_b - w_m * r_out,
        }
        # the continuous spin phases and cage angle carry the speed ratios and the check
        # that the record's two halves agree
        extra["ball_spin_phase"] = balls[:, :, 4].T
        extra["cage_angle"] = states[:, 8]
        halves = slip.halves_check(t_out, extra["cage_angle"], extra["ball_spin_phase"], p)
        extra["halves"] = halves
        notes = list(notes)
        if not halves["agree"]:
            (c1, c2), (s1, s2) = halves["cage_speed_ratio"], halves["spin_speed_ratio"]
            notes.append(
                f"the two halves of the record disagree: spin ratio {s1:.4f} / "
                f"{s2:.4f}, cage speed ratio {c1:.4f} / {c2:.4f} (allowed "
                f"difference {halves['tolerance']:g}); the record is not "
                "stationary: settle longer or record longer"
            )
        extra["warnings"] = tuple(notes)
    metadata = {
        "source": f"bearinglab {model} model",
        "model": model,
        "speed_rpm": condition.shaft_speed * 30.0 / math.pi,
        "radial_load_n": condition.radial_load,
        "bearing": bearing.name or "",
        "defects": [d.to_dict() for d in defects],
        "start_time_s": float(t_out[0]),
    }
    if perfect:
        # a bearing without a defect or a form error under a radial load still vibrates at
        # the rate the balls pass the load zone, Z x the cage's: its stiffness varies as
        # they do (varying compliance; Sunnersjo C. S., JSV 58 (1978) 363-373). Its lines
        # are the model's, not a fault's: the diagnosis masks them as a machine line (form
        # errors put lines of their own there: outer-race waviness of order kZ +- 1 at
        # k x BPFO)
        cage = extra.get("cage_angle")  # the slip model's cage slips; the rigid one's not
        ratio = 1.0 if cage is None else advance_ratio(cage, t_out[-1] - t_out[0], kin, "ftf")
        metadata["varying_compliance_hz"] = float(kin.hz("bpfo") * ratio)
    signal = Signal(channels, sample_rate, metadata)
    return Simulation(
        model, bearing, condition, tuple(defects), signal, kin, params, stats, **extra
    )


__all__ = ["MODELS", "Defect", "Simulation", "needs_compiling", "simulate"]
