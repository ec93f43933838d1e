"""The pressure along a roller's line contact from the elastic half-space, edge stress
included (layer 1).

The slice model of ISO/TS 16281 (:mod:`.line`) treats the slices as independent springs:
an aligned unprofiled roller then loads its slices evenly, and the stress peak at its ends
is out of its reach. Here the contact of one roller with one raceway is solved on the
elastic half-space with the influence coefficients of uniformly loaded rectangles
(Love A. E. H., "The stress produced in a semi-infinite solid by pressure on part of the
boundary", Phil. Trans. R. Soc. A 228 (1929) 377-420; Johnson K. L., *Contact Mechanics*,
1985, sec. 3.3, eq. 3.25; the numerical method of Kalker and of Hartnett M. J., "The
analysis of contact stresses in rolling element bearings", J. Lubr. Technol. 101 (1979)
105-109): the surface is cut into rectangles, cosine-spaced along the roller so that its
ends are resolved; the combined normal displacement of both bodies at the centre of cell
i is w_i = sum_k p_k (2 / (pi E')) F_ik, F_ik = integral of 1/r over cell k,

    F = sum over the corners (+-) of [X asinh(Y/X) + Y asinh(X/Y)],

and contact holds where w_i = delta - h_i (p_i > 0), separation where w_i > delta - h_i
(p_i = 0), with the gap of one contact h(x, y) = y^2 / (2R) + P(x) + theta x (the roller's
profile drop P and the tilt theta between roller and raceway) and sum p_i A_i = Q. An
active-set iteration solves it (each step a dense linear solve).

The end cells' pressure of an unprofiled roller grows as the cells shrink (the stress at a
sharp edge is singular); the value reported is that of the mesh, a measure of the edge
stress, not a converged number (docs/capabilities/roller_bearings.md). Checked: the middle
of a long unprofiled roller reaches Hertz's 2-D p_0 (tests/unit/test_roller_pressure.py).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import ConvergenceError, InputError, positive_number


def _f(x, y):
    """X asinh(Y/X) + Y asinh(X/Y), 0 where a coordinate is 0 (the integral of 1/r over the
    rectangle [0, X] x [0, Y], by signs)."""
    ax, ay = np.abs(x), np.abs(y)
    with np.errstate(divide="ignore", invalid="ignore"):
        a = np.where(ax > 0, ax * np.arcsinh(ay / np.where(ax > 0, ax, 1.0)), 0.0)
        b = np.where(ay > 0, ay * np.arcsinh(ax / np.where(ay > 0, ay, 1.0)), 0.0)
    return np.sign(x) * np.sign(y) * (a + b)


def rectangle_influence(xc, yc, x0, x1, y0, y1):
    """Integral of 1/r over the rectangles [x0, x1] x [y0, y1] seen from points (xc, yc)
    [m] (broadcast): the surface displacement per unit pressure times pi E'/2.

    Parameters
    ----------
    xc, yc : array
        Field points [m].
    x0, x1, y0, y1 : array
        Rectangle edges [m].

    Examples
    --------
    >>> round(float(rectangle_influence(0.0, 0.0, -1.0, 1.0, -1.0, 1.0)), 4)  # 8 asinh(1)
    7.051
    """
    return _f(x1 - xc, y1 - yc) - _f(x0 - xc, y1 - yc) - _f(x1 - xc, y0 - yc) + _f(x0 - xc, y0 - yc)


@dataclass(frozen=True)
class LinePressure:
    """The pressure field of one roller-raceway contact (SI).

    Attributes: ``x`` (n_x,) cell centres along the roller [m], ``y`` (n_y,) across [m],
    ``pressure`` (n_x, n_y) [Pa], ``approach`` delta [m], ``load`` Q [N],
    ``hertz_pressure`` p_0 of the 2-D Hertz contact of the mean load per length [Pa].
    """

    x: np.ndarray
    y: np.ndarray
    pressure: np.ndarray
    approach: float
    load: float
    hertz_pressure: float

    @property
    def along(self) -> np.ndarray:
        """Largest pressure across the contact at each position along the roller (n_x,)
        [Pa]."""
        return self.pressure.max(axis=1)

    @property
    def max_pressure(self) -> float:
        """Largest pressure of the contact [Pa]."""
        return float(self.pressure.max())

    @property
    def middle_pressure(self) -> float:
        """Largest pressure across the contact at the roller's middle [Pa]."""
        return float(self.along[np.argmin(np.abs(self.x))])

    @property
    def edge_ratio(self) -> float:
        """Largest pressure at either end cell over the middle pressure [-]: above 1 an edge
        stress, below 1 a profile that keeps the ends free."""
        return float(max(self.along[0], self.along[-1]) / max(self.middle_pressure, 1e-300))


def line_contact_pressure(
    load: float,
    length: float,
    reduced_radius: float,
    effective_modulus: float,
    drop=None,
    tilt: float = 0.0,
    *,
    axial_cells: int = 40,
    transverse_cells: int = 15,
) -> LinePressure:
    """Pressure along a roller's contact with a raceway on the elastic half-space.

    Parameters
    ----------
    load : float
        Contact load Q > 0 [N].
    length : float
        Contact length L_we [m].
    reduced_radius : float
        R of the contact in the rolling direction [m].
    effective_modulus : float
        E' [Pa].
    drop : callable or None
        P(x): the roller's profile drop at positions x from its middle [m] (None: flat).
    tilt : float
        Tilt of the roller against the raceway in the plane of its axis [rad] (the gap
        grows by tilt x).
    axial_cells, transverse_cells : int
        Cells along (cosine-spaced) and across the contact [-].

    Returns
    -------
    LinePressure

    Raises
    ------
    ConvergenceError
        When the active set does not settle.
    """
    q = positive_number("load", load, "a load > 0 [N]")
    length = positive_number("length", length, "a length > 0 [m]")
    radius = positive_number("reduced_radius", reduced_radius, "a radius > 0 [m]")
    e = positive_number("effective_modulus", effective_modulus, "a modulus > 0 [Pa]")
    for name, value in (("axial_cells", axial_cells), ("transverse_cells", transverse_cells)):
        if isinstance(value, bool) or not isinstance(value, int) or not 4 <= value <= 200:
            raise InputError(name, value, "an integer in [4, 200]")
    if not (isinstance(tilt, (int, float)) and math.isfinite(tilt) and abs(tilt) < 0.05):
        raise InputError("tilt", tilt, "a tilt within +-0.05 rad")
    w = q / length
    b_hertz = math.sqrt(8.0 * w * radius / (math.pi * e))
    p_hertz = 2.0 * w / (math.pi * b_hertz)
    extent = 1.5 * b_hertz
    for _ in range(6):
        out = _solve(q, length, radius, e, drop, tilt, axial_cells, transverse_cells, extent)
        if out is None:
            raise ConvergenceError(
                "line_contact_pressure: the contact area did not settle in 200 steps"
            )
        edge_rows = out.pressure[:, [0, -1]]
        if not np.any(edge_rows > 0):
            return LinePressure(out.x, out.y, out.pressure, out.approach, q, p_hertz)
        extent *= 1.6  # the contact reached the grid's side: widen it
    raise ConvergenceError(
        "line_contact_pressure: the contact width kept growing past 16 Hertz half-widths"
    )


def _solve(q, length, radius, e, drop, tilt, axial_cells, transverse_cells, extent):
    """One active-set solve on a grid of half-width ``extent`` across (None if it does not
    settle)."""
    edges_x = -0.5 * length * np.cos(np.linspace(0.0, math.pi, axial_cells + 1))
    edges_y = np.linspace(-extent, extent, transverse_cells + 1)
    xc = 0.5 * (edges_x[:-1] + edges_x[1:])
    yc = 0.5 * (edges_y[:-1] + edges_y[1:])
    gx, gy = np.meshgrid(xc, yc, indexing="ij")
    x0 = np.repeat(edges_x[:-1], transverse_cells)
    x1 = np.repeat(edges_x[1:], transverse_cells)
    y0 = np.tile(edges_y[:-1], axial_cells)
    y1 = np.tile(edges_y[1:], axial_cells)
    area = (x1 - x0) * (y1 - y0)
    px, py = gx.ravel(), gy.ravel()
    a = rectangle_influence(px[:, None], py[:, None], x0[None, :], x1[None, :], y0, y1)
    a *= 2.0 / (math.pi * e)
    profile = np.zeros_like(px) if drop is None else np.asarray(drop(px), float)
    h = py**2 / (2.0 * radius) + profile + tilt * px
    scale = extent**2 / radius
    active = h < float(np.min(h)) + 0.3 * scale
    n = px.size
    for _ in range(200):
        idx = np.flatnonzero(active)
        m = idx.size
        system = np.zeros((m + 1, m + 1))
        system[:m, :m] = a[np.ix_(idx, idx)]
        system[:m, m] = -1.0
        system[m, :m] = area[idx]
        sol = np.linalg.solve(system, np.append(-h[idx], q))
        p = np.zeros(n)
        p[idx], delta = sol[:m], sol[m]
        if np.any(p[idx] < 0):
            active[idx[p[idx] < 0]] = False
            continue
        gap = h - delta + a @ p
        entering = (~active) & (gap < -1e-12 * scale)
        if np.any(entering):
            active |= entering
            continue
        return LinePressure(xc, yc, p.reshape(axial_cells, transverse_cells), float(delta), q, 0.0)
    return None
