"""Sound pressure of a running ball bearing at a field point (layer 3).

Seed 003 part 4 (Zhang, Yang & An 2018, noise model, seed file lines 765-835): the noise
is the sound radiated by the inner ring (a transversely vibrating cylinder, eq. 19) and by
each ball (a pulsating sphere, eqs. 20-23); the pressures of the balls are summed (eq. 24)
and added to that of the ring (eq. 26), and the level is SPL = 20 lg(p_e / 2e-5 Pa) with
p_e the effective pressure (eq. 27). Seed 002 (Sun & An 2021, abstract) uses the same
sources and adds the directivity of the radiation round the bearing and pressure spectra
whose peaks sit at the ball-pass frequencies.

The sources of eqs. 19 and 23 are harmonic, so the velocities are taken to the frequency
domain: each velocity record is Fourier transformed (the record is taken as one period of
a periodic signal), every line is multiplied by the source's transfer function at its
frequency (:mod:`.sources`), and the pressures are summed in the time domain. The balls
move round the pitch circle, so their distance r_j(t) to the point changes: the pressure
of ball j is p_j(t) = s_j(t - r_j(t)/c_0) / r_j(t) with s_j the inverse transform of
G(k) U_j (the source strength times the velocity spectrum), evaluated at each sample's own
retarded time. This is the quasi-stationary moving source (ball speeds are ~1e-3 of the
speed of sound, so Doppler terms of that order are left out). That computation is in
:mod:`.field`; this module checks the inputs and builds the :class:`SoundPressure`.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .field import pressures_at, velocity_spectra
from .model import Air, FieldPoint, as_field_point, default_field_point
from .result import Directivity, SoundPressure
from .sources import CYLINDER_FORMS, REFERENCE_PRESSURE

#: How a ball's velocity radiates: eq. 23 (the seed) or a translating rigid sphere.
BALL_SOURCES = ("pulsating", "oscillating")
#: Relative uniformity asked of the time steps.
STEP_TOLERANCE = 1e-6


# ---------------------------------------------------------------- helpers


def velocity_from_positions(time, positions) -> np.ndarray:
    """Time derivative of positions sampled at ``time`` (second-order central differences,
    ``numpy.gradient``), e.g. the inner-ring centre (n, 2) or the ball centres (n, Z, 2) of
    an orbit, to give the velocities :func:`sound_pressure` takes (seed 003 figs. 9E-F, 11).

    Parameters
    ----------
    time : array_like (n,)
        Sample times [s], increasing.
    positions : array_like (n, ...)
        Positions [m].

    Returns
    -------
    numpy.ndarray
        Velocities, same shape [m/s].
    """
    t = _time(time)
    x = np.asarray(positions, dtype=float)
    if x.ndim < 1 or x.shape[0] != t.size or not np.all(np.isfinite(x)):
        raise InputError(
            "positions",
            f"array of shape {x.shape}",
            f"finite positions with {t.size} rows (one per sample)",
        )
    return np.gradient(x, t, axis=0, edge_order=2)


def _time(time) -> np.ndarray:
    try:
        t = np.asarray(time, dtype=float)
    except (TypeError, ValueError):
        raise InputError("time", type(time).__name__, "a 1-D array of times [s]") from None
    if t.ndim != 1 or t.size < 16 or not np.all(np.isfinite(t)):
        raise InputError(
            "time", f"array of shape {t.shape}", "a 1-D array of at least 16 finite times [s]"
        )
    step = np.diff(t)
    mean = (t[-1] - t[0]) / (t.size - 1)
    if mean <= 0 or np.max(np.abs(step - mean)) > STEP_TOLERANCE * mean:
        raise InputError(
            "time", "unevenly spaced or decreasing times", "uniformly spaced increasing times"
        )
    return t


def _array(name, value, shapes: str, n: int, ndims: tuple[int, ...]) -> np.ndarray:
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(name, type(value).__name__, shapes) from None
    if a.ndim not in ndims or a.shape[0] != n or not np.all(np.isfinite(a)):
        raise InputError(name, f"array of shape {a.shape}", f"finite values of shape {shapes}")
    return a


# ---------------------------------------------------------------- the analysis


def sound_pressure(
    time,
    inner_ring_velocity=None,
    ball_velocity=None,
    ball_angle=None,
    bearing=None,
    *,
    point: FieldPoint | tuple | None = None,
    medium: Air | None = None,
    ring_radius: float | None = None,
    ball_radius: float | None = None,
    pitch_radius: float | None = None,
    ring_model: str = "exact",
    ball_source: str = "pulsating",
    detrend: bool = False,
) -> SoundPressure:
    """Sound pressure of the inner ring and the balls at a field point (seed 003 eqs.
    19-27; seed 002 for the directivity).

    Parameters
    ----------
    time : array_like (n,)
        Uniformly spaced sample times, n >= 16 [s]. The record is taken as one period of
        a periodic signal: pass whole periods (e.g. a cage revolution) or set ``detrend``.
    inner_ring_velocity : array_like (n, 2), optional
        Velocity (v_x, v_y) of the inner-ring centre [m/s]; the ring surface then moves
        with normal velocity v . n, a transversely vibrating cylinder (eq. 19).
    ball_velocity : array_like (n, Z) or (n, Z, 2), optional
        (n, Z): surface (pulsation) velocity of each ball, outward positive [m/s], a
        pulsating sphere (eq. 23). (n, Z, 2): velocity (v_x, v_y) of each ball centre
        [m/s]; with ``ball_source="pulsating"`` each component drives eq. 23 as the seed
        does (its figs. 11 and 13 A/B), with ``"oscillating"`` the ball is a translating
        rigid sphere (a dipole).
    ball_angle : array_like (n, Z) or (Z,)
        Angular position psi of each ball centre on the pitch circle, from +x towards +y
        [rad]; needed with ``ball_velocity``.
    bearing : BallBearing, optional
        Gives the default radii: the inner ring is a cylinder of radius d_i / 2 (the
        inner groove bottom, ``inner_raceway_diameter``), the balls have radius D_w / 2 on
        a circle of radius d_m / 2.
    point : FieldPoint or (distance, angle), optional
        The field point [m, rad]; default with a ``bearing``
        :func:`.model.default_field_point` (10 mm outside its outside diameter, straight
        up), without one ``FieldPoint()``: 10 mm from the centre (seed 003's point A),
        straight up.
    medium : Air, optional
        rho_0 [kg/m^3] and c_0 [m/s]; default ``Air()`` (20 deg C).
    ring_radius, ball_radius, pitch_radius : float, optional
        Override the bearing's radii [m].
    ring_model : {"exact", "seed"}
        The exact cylinder solution or eq. 19's small-argument form.
    ball_source : {"pulsating", "oscillating"}
        Eq. 23 or the translating sphere (needs (n, Z, 2) velocities).
    detrend : bool
        Take off a ramp that closes the jump between the end and the start of each
        velocity record before the transform (for records that are not whole periods; a
        ramp's own pressure is a constant, not sound).

    Returns
    -------
    SoundPressure

    Examples
    --------
    A ball pulsating at 1 kHz with 1 mm/s, 10 mm from the point (eq. 23: p_e = 2.15 mPa):

    >>> t = np.arange(4800) / 48000.0
    >>> u = 1e-3 * np.sin(2 * np.pi * 1000.0 * t)[:, None]
    >>> r = sound_pressure(t, ball_velocity=u, ball_angle=[0.0], ball_radius=2e-3,
    ...                    pitch_radius=0.02, point=FieldPoint(0.03, 0.0))
    >>> round(r.spl("balls"), 2)
    40.62
    """
    t = _time(time)
    n = t.size
    fs = float((n - 1) / (t[-1] - t[0]))
    if point is None:
        point = FieldPoint() if bearing is None else default_field_point(bearing)[0]
    medium = Air() if medium is None else medium
    point = as_field_point(point)
    if not isinstance(medium, Air):
        raise InputError("medium", medium, "an Air(density, sound_speed)")
    if ring_model not in CYLINDER_FORMS:
        raise InputError("ring_model", ring_model, f"one of {CYLINDER_FORMS}")
    if ball_source not in BALL_SOURCES:
        raise InputError("ball_source", ball_source, f"one of {BALL_SOURCES}")
    if inner_ring_velocity is None and ball_velocity is None:
        raise InputError(
            "inner_ring_velocity", None, "an inner-ring velocity, ball velocities or both"
        )

    def radius(name, given, from_bearing):
        if given is None:
            if bearing is None:
                raise InputError(name, None, "a radius [m] (or a bearing to take it from)")
            given = from_bearing()
        try:
            v = float(given)
        except (TypeError, ValueError):
            v = math.nan
        if not math.isfinite(v) or v <= 0:
            raise InputError(name, given, "a finite radius > 0 [m]")
        return v

    options = {
        "ring_model": ring_model,
        "ball_source": ball_source,
        "detrend": bool(detrend),
        "ring_radius": None,
        "ball_radius": None,
        "pitch_radius": None,
    }
    inputs = {"n": n, "sample_rate": fs}
    if inner_ring_velocity is not None:
        v = _array("inner_ring_velocity", inner_ring_velocity, "(n, 2)", n, (2,))
        if v.shape[1] != 2:
            raise InputError(
                "inner_ring_velocity", f"array of shape {v.shape}", "finite values of shape (n, 2)"
            )
        options["ring_radius"] = radius(
            "ring_radius", ring_radius, lambda: 0.5 * bearing.inner_raceway_diameter
        )
        inputs["ring_velocity"] = v
        inputs["ring_spectrum"] = velocity_spectra(v, n, detrend)
    if ball_velocity is not None:
        u = _array("ball_velocity", ball_velocity, "(n, Z) or (n, Z, 2)", n, (2, 3))
        if u.ndim == 3 and u.shape[2] != 2:
            raise InputError(
                "ball_velocity",
                f"array of shape {u.shape}",
                "finite values of shape (n, Z) or (n, Z, 2)",
            )
        if ball_source == "oscillating" and u.ndim != 3:
            raise InputError(
                "ball_velocity",
                f"array of shape {u.shape}",
                "ball-centre velocities of shape (n, Z, 2) for an oscillating sphere",
            )
        if ball_angle is None:
            raise InputError("ball_angle", None, "ball angles (n, Z) or (Z,) [rad]")
        psi = np.asarray(ball_angle, dtype=float)
        if psi.ndim == 1:
            psi = np.broadcast_to(psi, (n, psi.size))
        if psi.shape != u.shape[:2] or not np.all(np.isfinite(psi)):
            raise InputError(
                "ball_angle",
                f"array of shape {psi.shape}",
                f"finite angles of shape {u.shape[:2]} or ({u.shape[1]},) [rad]",
            )
        options["ball_radius"] = radius(
            "ball_radius", ball_radius, lambda: 0.5 * bearing.ball_diameter
        )
        options["pitch_radius"] = radius(
            "pitch_radius", pitch_radius, lambda: 0.5 * bearing.pitch_diameter
        )
        inputs.update(
            ball_velocity=u, ball_angle=psi, ball_spectrum=velocity_spectra(u, n, detrend)
        )
    parts = pressures_at(inputs, point, medium, options)
    return SoundPressure(t, parts, point, medium, options, inputs)


__all__ = [
    "BALL_SOURCES",
    "REFERENCE_PRESSURE",
    "Air",
    "Directivity",
    "FieldPoint",
    "SoundPressure",
    "sound_pressure",
    "velocity_from_positions",
]  # re-exported
