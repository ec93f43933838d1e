"""Outer-ring resonances of a loaded ball bearing: the analysis (seed 000).

Layer 3: :func:`ring_modes` gathers the inputs (from a BallBearing and its Hertz
constants, or overridden by the user as the paper's own measured values) and returns
:class:`RingModes`; the formulas are in :mod:`bearinglab.rings.frequencies`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError, positive_number
from .frequencies import (
    free_ring_frequency,
    linear_stiffness_ratio,
    loaded_ring_frequencies,
    radial_stiffness_under_axial_load,
    refined_ring_frequencies,
    rigid_body_frequency,
    split_mode,
)


@dataclass(frozen=True)
class RingMode:
    """Mode m of the loaded outer ring, frequencies in Hz: ``free`` f*_m, ``approximate``
    (eq. 1.9: one value, or (nodes, antinodes) when ``split``, 2m = l n), ``refined`` (every
    stationary value of eq. 3.3/3.6, ascending) with the aligned ``epsilon`` (None for the
    node solution 3.8) and ``positions`` ("any", "nodes", "antinodes"), and
    ``p`` = kappa (f*/f_1)^2 (for the antinode solutions the paper finds the positive-epsilon
    one a minimum of (3.6) if p > 4, a saddle if p < 4, f = f* if p = 4)."""

    mode: int
    free: float
    split: bool
    approximate: tuple[float, ...]
    refined: tuple[float, ...]
    epsilon: tuple[float | None, ...]
    positions: tuple[str, ...]
    p: float


@dataclass(frozen=True)
class RingModes:
    """Outer-ring natural frequencies of a loaded ball bearing (seed 000).

    ``modes`` (:class:`RingMode` each) and the inputs used: ``ball_count`` n,
    ``rigid_body_frequency`` f_1 [Hz], ``ball_mass_ratio`` kappa, ``contact_stiffness_ratio``
    K1/K2, ``ring_mass`` [kg], ``radial_stiffness`` K_x [N/m], ``axial_load`` [N],
    ``contact_angle`` [rad] (None where not used), ``bearing``, ``measured``
    ((m, (Hz, ...)) pairs, for comparison), ``sources`` (input -> user, bearing, derived
    or default), ``rigid_body_mode`` (mode 1 was asked for: the tables show it) and
    ``warnings`` (the axial load against the static rating, in the user's terms).
    """

    modes: tuple[RingMode, ...]
    ball_count: int
    rigid_body_frequency: float
    ball_mass_ratio: float
    contact_stiffness_ratio: float
    ring_mass: float | None = None
    radial_stiffness: float | None = None
    axial_load: float | None = None
    contact_angle: float | None = None
    bearing: object = field(default=None, repr=False)
    measured: tuple = ()
    sources: dict = field(default_factory=dict, compare=False)
    rigid_body_mode: bool = False
    warnings: tuple[str, ...] = ()

    def mode(self, m: int) -> RingMode:
        """The :class:`RingMode` of mode number ``m``.

        Parameters
        ----------
        m : int
            Mode number (the number of waves round the ring), one of the computed modes.

        Returns
        -------
        RingMode
            That mode.

        Raises
        ------
        InputError
            If mode ``m`` was not computed.
        """
        found = [r for r in self.modes if r.mode == m]
        if not found:
            raise InputError("m", m, f"one of the computed modes {[r.mode for r in self.modes]}")
        return found[0]

    def to_dict(self) -> dict:
        """JSON-ready dict in engineering units (Hz, kg, N, N/m, deg); mode 1, the ring as
        a rigid body on the ball springs (eq. 1.7), first when it was asked for."""
        measured, modes = dict(self.measured), []
        if self.rigid_body_mode:
            modes.append(
                {
                    "m": 1,
                    "free_hz": 0.0,
                    "split": False,
                    "approx_hz": [self.rigid_body_frequency],
                    "approx_ball_position": ["any"],
                    "refined_hz": [],
                    "epsilon": [],
                    "refined_ball_position": [],
                    "p": None,
                }
            )
        for r in self.modes:
            d = {
                "m": r.mode,
                "free_hz": r.free,
                "split": r.split,
                "approx_hz": list(r.approximate),
                "approx_ball_position": ["nodes", "antinodes"] if r.split else ["any"],
                "refined_hz": list(r.refined),
                "epsilon": list(r.epsilon),
                "refined_ball_position": list(r.positions),
                "p": r.p if math.isfinite(r.p) else None,
            }
            if r.mode in measured:
                d["measured_hz"] = list(measured[r.mode])
            modes.append(d)
        angle = self.contact_angle
        return {
            "bearing": getattr(self.bearing, "name", None) or None,
            "ball_count": self.ball_count,
            "axial_load_n": self.axial_load,
            "contact_angle_deg": None if angle is None else math.degrees(angle),
            "ring_mass_kg": self.ring_mass,
            "radial_stiffness_n_per_um": (
                None if self.radial_stiffness is None else self.radial_stiffness * 1e-6
            ),
            "rigid_body_frequency_hz": self.rigid_body_frequency,
            "ball_mass_ratio": self.ball_mass_ratio,
            "contact_stiffness_ratio": self.contact_stiffness_ratio,
            "sources": dict(self.sources),
            "modes": modes,
            "warnings": list(self.warnings),
        }

    def to_pandas(self):
        """One row per (m, model, solution): m, model (rigid body, free, approximate,
        refined, measured), ball_position, frequency_hz, epsilon."""
        import pandas as pd

        def row(m, model, f, pos="", eps=None):
            return {"m": m, "model": model, "ball_position": pos, "frequency_hz": f, "epsilon": eps}

        rows, measured = [row(1, "rigid body", self.rigid_body_frequency)], dict(self.measured)
        for r in self.modes:
            pos = ("nodes", "antinodes") if r.split else ("any",)
            rows += [row(r.mode, "free", r.free)]
            rows += [
                row(r.mode, "approximate", f, p) for f, p in zip(r.approximate, pos, strict=True)
            ]
            rows += [
                row(r.mode, "refined", f, p, e)
                for f, e, p in zip(r.refined, r.epsilon, r.positions, strict=False)
            ]
            rows += [row(r.mode, "measured", f) for f in measured.get(r.mode, ())]
        return pd.DataFrame(rows)

    def plot(self, ax=None):
        """Frequencies by mode number (free, approximate, refined, measured) on ``ax`` (a
        matplotlib Axes; a new figure by default); (fig, ax).

        Parameters
        ----------
        ax : matplotlib Axes or None
            Where to draw; None: a new figure.
        """
        from ..plotting import figure_axes

        fig, ax = figure_axes(ax, figsize=(8, 4.5))
        df = self.to_pandas()
        for i, (model, marker) in enumerate(
            (
                ("rigid body", "D"),
                ("free", "o"),
                ("approximate", "s"),
                ("refined", "^"),
                ("measured", "x"),
            )
        ):
            part = df[df["model"] == model]
            if len(part):
                ax.plot(
                    part["m"] + 0.08 * (i - 2),
                    part["frequency_hz"] / 1e3,
                    marker,
                    color=f"C{i}",
                    linestyle="none",
                    label=model,
                )
        ax.set_xticks([1] + [r.mode for r in self.modes])
        ax.set_xlabel("mode number m (1: ring as a rigid body)")
        ax.set_ylabel("natural frequency [kHz]")
        ax.set_title(
            f"{getattr(self.bearing, 'name', '') or 'outer ring'}: n = "
            f"{self.ball_count}, kappa = {self.ball_mass_ratio:.3g}"
        )
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        return fig, ax


def _scalar(name, value, unit, allow_zero=False):
    allowed = f"a finite value {'>=' if allow_zero else '>'} 0 {unit}"
    return positive_number(name, value, allowed, zero=allow_zero)


def _per_mode(values, ms, name) -> dict:
    if values is None:
        return {}
    if isinstance(values, Mapping):
        return dict(values)
    if isinstance(values, (list, tuple, np.ndarray)) and len(values) == len(ms):
        return dict(zip(ms, values, strict=False))
    raise InputError(name, values, f"a dict m -> value or one value per mode {ms}")


_rigid_body = rigid_body_frequency  # the keyword of ring_modes shadows the name


def ring_modes(
    bearing=None,
    *,
    axial_load=None,
    contact_angle=None,
    modes=range(2, 7),
    ring_mass=None,
    radial_stiffness=None,
    rigid_body_frequency=None,
    free_frequencies=None,
    ball_mass_ratio=None,
    contact_stiffness_ratio=None,
    ball_count=None,
    measured=None,
    radial_stiffness_from: str = "closed_form",
) -> RingModes:
    """Outer-ring natural frequencies of a ball bearing under axial load (seed 000).

    Every input of the paper can be given; the rest comes from ``bearing``: f*_m from its
    outer-ring section, the vibrating mass from ``outer_ring_mass`` (no sensors), K_x from
    K_n at ``contact_angle`` -- by default the nominal angle, or the free contact angle of
    the clearance when the nominal one is 0 (not the larger angle the axial load produces)
    -- kappa = n m_b / ring_mass and K1/K2 = (K_o/K_i)^(2/3). Without a bearing K1/K2 is 1
    (the paper's case). f_1 = sqrt(K_x / ring_mass) / (2 pi) unless given.

    Parameters
    ----------
    bearing : BallBearing or None
        The bearing [-].
    axial_load : float or None
        A > 0, for K_x from the bearing [N].
    contact_angle : float or None
        tau for K_x and the Hertz constants [rad].
    modes : iterable of int
        Mode numbers m >= 1 [-]; m = 1 is the ring as a rigid body on the ball springs
        (f_1, eq. 1.7), m >= 2 the flexural modes.
    ring_mass : float or None
        Vibrating mass of the ring and what is attached to it, m_h [kg].
    radial_stiffness : float or None
        K_x >= 0 [N/m].
    rigid_body_frequency : float or None
        f_1, instead of sqrt(K_x / ring_mass) / (2 pi) [Hz].
    free_frequencies : dict or sequence or None
        f*_m (dict m -> value, or aligned with ``modes``), e.g. measured [Hz].
    ball_mass_ratio : float or None
        kappa = n m_b / m_k >= 0 [-].
    contact_stiffness_ratio : float or None
        K1 / K2 (ball-outer over ball-inner) > 0 [-].
    ball_count : int or None
        n >= 3, instead of the bearing's [-].
    measured : dict or None
        Measured resonances to compare, m -> value or list of values [Hz].
    radial_stiffness_from : str
        Where K_x comes from when it is not given: ``"closed_form"`` (seed 000's
        K_x = 0.75 (n K_n)^(2/3) (A / sin tau)^(1/3) cos^2 tau) or ``"load_distribution"``
        (the tangent radial stiffness of :func:`bearinglab.quasistatic.solve_load_distribution`
        at the axial load, which counts the contact angle the load produces) [-].

    Examples
    --------
    >>> r = ring_modes(ball_count=8, rigid_body_frequency=2500.0, ball_mass_ratio=0.33,
    ...                free_frequencies={4: 10000.0}, modes=[4])
    >>> [round(f / 1e3, 2) for f in r.mode(4).approximate + r.mode(4).refined]
    [10.0, 11.11, 9.46, 10.0, 14.46]
    """
    ms = list(modes) if not isinstance(modes, (str, bytes)) else []
    if not ms or any(
        isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < 1 for m in ms
    ):
        raise InputError("modes", modes, "mode numbers m >= 1 (m = 1 is the rigid body)")
    if radial_stiffness_from not in ("closed_form", "load_distribution"):
        raise InputError(
            "radial_stiffness_from", radial_stiffness_from, "'closed_form' or 'load_distribution'"
        )
    rigid_mode = 1 in ms
    ms = sorted({int(m) for m in ms if m >= 2})
    src: dict[str, str] = {}
    warnings: tuple[str, ...] = ()
    n = ball_count if ball_count is not None else getattr(bearing, "ball_count", None)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 3:
        raise InputError("ball_count", n, "an integer >= 3 (or a bearing)")
    src["ball_count"] = "user" if ball_count is not None else "bearing"
    free = {
        m: _scalar("free_frequencies", f, "[Hz]")
        for m, f in _per_mode(free_frequencies, ms, "free_frequencies").items()
    }
    missing = [m for m in ms if m not in free]
    if missing and bearing is None:
        raise InputError(
            "free_frequencies",
            free_frequencies,
            f"a value for each of {ms}",
            "or a bearing to compute them from",
        )
    if missing:
        s, mat = bearing.outer_ring_section, bearing.ring_material
        free.update(
            {
                m: float(
                    free_ring_frequency(
                        m, mat.elastic_modulus, mat.density, s.second_moment, s.mean_radius, s.area
                    )
                )
                for m in missing
            }
        )
    src["free_frequencies"] = {0: "user", len(ms): "bearing"}.get(len(missing), "user+bearing")
    alpha = k_n = k_o = k_i = None
    if bearing is not None:
        from ..contact.ball_race import load_deflection_constants

        alpha = (
            _scalar("contact_angle", contact_angle, "[rad]", True)
            if contact_angle is not None
            else bearing.contact_angle or bearing.free_contact_angle
        )
        src["contact_angle"] = "user" if contact_angle is not None else "bearing"
        k_i, k_o, k_n = load_deflection_constants(bearing, alpha)
    if ring_mass is not None:
        ring_mass, src["ring_mass"] = _scalar("ring_mass", ring_mass, "[kg]"), "user"
    elif bearing is not None and None not in (
        bearing.bore,
        bearing.outside_diameter,
        bearing.width,
    ):
        ring_mass, src["ring_mass"] = bearing.outer_ring_mass, "bearing"
    if radial_stiffness is not None and rigid_body_frequency is not None:
        # f_1 would silently replace the K_x given (two answers to one question)
        raise InputError(
            "rigid_body_frequency",
            rigid_body_frequency,
            "no value when the radial stiffness K_x is given (give one of them)",
            "f_1 = sqrt(K_x / ring mass) / (2 pi)",
        )
    if radial_stiffness is not None:
        radial_stiffness = _scalar("radial_stiffness", radial_stiffness, "[N/m]", True)
        src["radial_stiffness"], axial_load = "user", None
    elif bearing is not None and axial_load is not None:
        axial_load = _scalar("axial_load", axial_load, "[N]")
        from ..plausibility import load_warnings

        # s0 < 1 a warning; past 8 C0 no elastic model applies: an error
        warnings = tuple(load_warnings(bearing, 0.0, axial_load))
        if radial_stiffness_from == "load_distribution":
            from ..operating import OperatingCondition
            from ..quasistatic import solve_load_distribution

            radial_stiffness = solve_load_distribution(
                bearing, OperatingCondition(axial_load=axial_load)
            ).radial_stiffness
            src["radial_stiffness"] = (
                f"load distribution: tangent radial stiffness at F_a = {axial_load:g} N"
            )
        else:
            radial_stiffness = float(radial_stiffness_under_axial_load(n, k_n, axial_load, alpha))
            src["radial_stiffness"] = "derived (K_n, axial load)"
    else:
        axial_load = None
    if rigid_body_frequency is not None:
        f1 = _scalar("rigid_body_frequency", rigid_body_frequency, "[Hz]", True)
        src["rigid_body_frequency"] = "user"
    elif radial_stiffness is not None and ring_mass is not None:
        f1 = float(_rigid_body(radial_stiffness, ring_mass))
        src["rigid_body_frequency"] = "derived (K_x, ring mass)"
    else:
        raise InputError(
            "rigid_body_frequency",
            None,
            "f_1, or K_x and the ring mass",
            "give radial_stiffness (or a bearing and axial_load) and ring_mass",
        )
    if ball_mass_ratio is not None:
        kappa = _scalar("ball_mass_ratio", ball_mass_ratio, "[-]", True)
        src["ball_mass_ratio"] = "user"
    elif bearing is not None and ring_mass is not None:
        kappa, src["ball_mass_ratio"] = n * bearing.ball_mass / ring_mass, "derived"
    else:
        raise InputError("ball_mass_ratio", None, "kappa = n m_b / m_k >= 0 (or a bearing)")
    if contact_stiffness_ratio is not None:
        ratio = _scalar("contact_stiffness_ratio", contact_stiffness_ratio, "[-]")
        src["contact_stiffness_ratio"] = "user"
    elif k_o is not None:
        ratio, src["contact_stiffness_ratio"] = float(linear_stiffness_ratio(k_o, k_i)), "derived"
    else:
        ratio, src["contact_stiffness_ratio"] = 1.0, "default (K1 = K2)"
    results = []
    for m in ms:
        fs, split = free[m], bool(split_mode(m, n))
        approx = tuple(float(f) for f in loaded_ring_frequencies(fs, f1, m, n)[1 - split :])
        freqs, eps = refined_ring_frequencies(fs, f1, m, kappa, ratio, 2.0 if split else 1.0)
        sols = [
            (float(f), float(e), "antinodes" if split else "any")
            for f, e in zip(freqs, eps, strict=False)
            if np.isfinite(e)
        ]
        sols = sorted(sols + ([(fs, None, "nodes")] if split else []), key=lambda t: t[0])
        p = kappa * (fs / f1) ** 2 if f1 > 0 else math.inf
        columns = (tuple(x) for x in zip(*sols, strict=True))
        results.append(RingMode(m, fs, split, approx, *columns, p))
    meas = tuple(
        (int(m), tuple(_scalar("measured", x, "[Hz]") for x in np.atleast_1d(v)))
        for m, v in _per_mode(measured, ms, "measured").items()
    )
    return RingModes(
        tuple(results),
        int(n),
        f1,
        kappa,
        ratio,
        ring_mass,
        radial_stiffness,
        axial_load,
        alpha,
        bearing,
        meas,
        src,
        rigid_mode,
        warnings,
    )
