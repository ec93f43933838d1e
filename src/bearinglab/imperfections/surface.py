"""3-D random raceway surfaces with an exponential autocorrelation (layers 1-2).

Seed 002 (Sun & An 2021), eq. 6: the waviness of a raceway is a random surface whose
autocorrelation is

    R(tau_r, tau_z) = dh^2 exp(-2.3 sqrt((tau_r/beta_r)^2 + (tau_z/beta_z)^2)),

tau_r, tau_z lags along the circumference (arc length) and the axis, beta_r, beta_z the
correlation lengths (2.3 = ln 10: R falls to a tenth of dh^2 at a lag of one correlation
length), dh the RMS height. The seed generates the surfaces "by the autocorrelation
function method" without giving the algorithm; the one used here is the usual spectral
(FFT) filter of white noise (Hu Y. Z., Tonder K., Int. J. Mach. Tools Manuf. 32 (1992)
83-90): the spectral density is the Fourier transform of R, and filtering white noise by
its square root gives a field with covariance R. Made exact on the sampling grid:

1. The grid spans the whole circumference (n_r points, periodic: a raceway is closed) and
   the axial band (n_z points) plus a margin of 4 beta_z (R < 1e-4 dh^2 beyond it) that is
   generated and thrown away, so the axial direction is not periodic.
2. The covariance sampled at the grid lags is periodised over that torus (a sum over the
   images of the lag; a periodised positive-definite function is positive definite), so
   its discrete Fourier transform S is the exact discrete spectral density, S >= 0.
3. S is scaled so that its mean is dh^2: every grid point then has variance exactly dh^2
   in expectation, and the covariance of any two grid points is exactly R at their lag
   (to within the images, exp(-2.3 C/beta_r) around the circumference C and < 1e-4
   axially).
4. h = IFFT(sqrt(S) FFT(w)), w standard normal white noise from ``numpy.random`` seeded by
   ``seed``; ``exact_rms=True`` additionally removes the sample mean and scales the one
   realisation to RMS exactly dh (which biases its sample autocorrelation slightly low).

Between grid points the height is interpolated bilinearly, periodic round the ring.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from .waviness import finite, generator, index

#: e-folding factor of seed 002 eq. 6 (R falls to 10 % at one correlation length).
DECAY = 2.3
#: Axial margin generated beyond the band and thrown away [correlation lengths].
AXIAL_MARGIN = 4.0


def exponential_autocorrelation(tau_r, tau_z, rms, length_circumferential, length_axial):
    """R(tau_r, tau_z) = dh^2 exp(-2.3 sqrt((tau_r/beta_r)^2 + (tau_z/beta_z)^2)) [m^2].

    Seed 002, eq. 6.

    Parameters
    ----------
    tau_r, tau_z : float or array
        Circumferential (arc length) and axial lags [m].
    rms : float
        dh, RMS height [m].
    length_circumferential, length_axial : float
        beta_r, beta_z, correlation lengths [m].

    Examples
    --------
    >>> round(float(exponential_autocorrelation(1e-3, 0.0, 1.0, 1e-3, 2e-3)), 4)
    0.1003
    """
    rho = np.hypot(
        np.asarray(tau_r, float) / length_circumferential, np.asarray(tau_z, float) / length_axial
    )
    return rms**2 * np.exp(-DECAY * rho)


def sample_autocorrelation(heights, lags_r, lags_z) -> np.ndarray:
    """Sample autocorrelation of a surface (n_r, n_z) at grid lags [m^2].

    C(a, b) = mean over i, j of h[i, j] h[i + a, j + b], circular in the first
    (circumferential, periodic) index, over the overlapping part in the second (axial).
    No mean is removed (the surfaces have zero mean by construction).

    Parameters
    ----------
    heights : array (n_r, n_z)
        Heights on the grid [m].
    lags_r, lags_z : sequences of int
        Lags in grid steps, >= 0 (lags_z < n_z) [-].
    """
    h = np.asarray(heights, float)
    n_r, n_z = h.shape
    spectrum = np.fft.fft(h, axis=0)
    out = np.empty((len(lags_r), len(lags_z)))
    for col, b in enumerate(lags_z):
        b = index("lags_z", b, f"an integer lag in [0, {n_z - 1}]")
        if b >= n_z:
            raise InputError("lags_z", b, f"an integer lag in [0, {n_z - 1}]")
        cross = np.fft.ifft(np.conj(spectrum[:, : n_z - b]) * spectrum[:, b:], axis=0).real
        mean = cross.sum(axis=1) / (n_r * (n_z - b))
        out[:, col] = mean[np.asarray(lags_r, int) % n_r]
    return out


@dataclass(frozen=True)
class RandomSurface:
    """A random raceway surface with seed 002's exponential autocorrelation (eq. 6).

    The height h(theta, z) is the radial deviation of the raceway, outward positive (the
    sign of seed 002 eq. 10: the approach grows by dh_i on the inner race and shrinks by
    dh_o on the outer), over the ring-frame angle theta and the axial coordinate z from
    the groove's mid-plane. See the module docstring for the generator.

    Parameters
    ----------
    race : {"inner", "outer"}
        Which raceway [-].
    amplitude : float
        dh, RMS height, >= 0 [m].
    length_circumferential : float
        beta_r, correlation length along the circumference (arc length), > 0 [m].
    length_axial : float
        beta_z, correlation length along the axis, > 0 [m].
    radius : float
        Raceway radius (groove bottom) whose circumference the surface covers, > 0 [m].
    width : float
        Axial extent of the surface, centred on the groove's mid-plane, > 0 [m]; heights
        beyond it are held at the edge values.
    seed : int
        Random seed, >= 0: the same seed gives the same surface [-].
    points_circumferential, points_axial : int
        Grid size n_r (whole circumference) and n_z (across ``width``); the spacings must
        be at most half the correlation lengths [-].
    exact_rms : bool
        Scale this realisation (mean removed) to RMS exactly dh.

    Examples
    --------
    >>> s = RandomSurface("outer", 0.1e-6, 0.5e-3, 0.5e-3, radius=11e-3, width=2e-3, seed=3)
    >>> s.heights.shape, bool(np.allclose(s.height(s.theta[:3], 0.0), s.heights[:3, 16]))
    ((512, 33), True)
    """

    race: str
    amplitude: float
    length_circumferential: float
    length_axial: float
    radius: float
    width: float
    seed: int
    points_circumferential: int = 512
    points_axial: int = 33
    exact_rms: bool = False
    heights: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self.race not in ("inner", "outer"):
            raise InputError("race", self.race, "'inner' or 'outer'")
        if finite("amplitude", self.amplitude, "an RMS height >= 0 [m]") < 0:
            raise InputError("amplitude", self.amplitude, "an RMS height >= 0 [m]")
        for name in ("length_circumferential", "length_axial", "radius", "width"):
            if finite(name, getattr(self, name), "a length > 0 [m]") <= 0:
                raise InputError(name, getattr(self, name), "a length > 0 [m]")
        index("seed", self.seed, "an integer >= 0")
        n_r = index("points_circumferential", self.points_circumferential, "an integer >= 8", 8)
        n_z = index("points_axial", self.points_axial, "an integer >= 2", 2)
        if self.circumferential_step > 0.5 * self.length_circumferential:
            need = math.ceil(4 * math.pi * self.radius / self.length_circumferential)
            raise InputError(
                "points_circumferential",
                n_r,
                f"at least {need}",
                "the grid step must be at most half the correlation length",
            )
        if self.axial_step > 0.5 * self.length_axial:
            need = math.ceil(2 * self.width / self.length_axial) + 1
            raise InputError(
                "points_axial",
                n_z,
                f"at least {need}",
                "the grid step must be at most half the correlation length",
            )
        if not isinstance(self.exact_rms, bool):
            raise InputError("exact_rms", self.exact_rms, "True or False")
        h = self._generate()
        h.flags.writeable = False
        object.__setattr__(self, "heights", h)

    # ------------------------------------------------------------------ grid
    @property
    def circumference(self) -> float:
        """2 pi R [m]."""
        return 2.0 * math.pi * self.radius

    @property
    def circumferential_step(self) -> float:
        """Arc length between grid points [m]."""
        return self.circumference / self.points_circumferential

    @property
    def axial_step(self) -> float:
        """Axial distance between grid points [m]."""
        return self.width / (self.points_axial - 1)

    @property
    def theta(self) -> np.ndarray:
        """Ring-frame angles of the grid rows [rad]."""
        return 2.0 * math.pi * np.arange(self.points_circumferential) / self.points_circumferential

    @property
    def z(self) -> np.ndarray:
        """Axial coordinates of the grid columns, from -width/2 to +width/2 [m]."""
        return np.linspace(-0.5 * self.width, 0.5 * self.width, self.points_axial)

    @property
    def rms(self) -> float:
        """RMS of this realisation's heights on the grid [m]."""
        return float(np.sqrt(np.mean(self.heights**2)))

    def spectral_density(self) -> np.ndarray:
        """Discrete spectral density S (n_r, n_gen) of the generating torus [m^2]: the 2-D
        DFT of the periodised covariance, scaled so that mean(S) = dh^2 (steps 2-3)."""
        n_r = self.points_circumferential
        n_g = self.generating_points
        dr, dz = self.circumferential_step, self.axial_step
        span_r, span_z = n_r * dr, n_g * dz
        images_r = math.ceil(16.0 * self.length_circumferential / span_r) + 1
        images_z = math.ceil(16.0 * self.length_axial / span_z) + 1
        lag_r = dr * np.arange(n_r)[:, None]
        lag_z = dz * np.arange(n_g)[None, :]
        cov = np.zeros((n_r, n_g))
        for m in range(-images_r, images_r + 1):
            for n in range(-images_z, images_z + 1):
                cov += exponential_autocorrelation(
                    lag_r + m * span_r,
                    lag_z + n * span_z,
                    1.0,
                    self.length_circumferential,
                    self.length_axial,
                )
        s = np.maximum(np.fft.fft2(cov).real, 0.0)
        return s * (self.amplitude**2 / np.mean(s))

    @property
    def generating_points(self) -> int:
        """Axial points of the generating torus: the band plus the discarded margin."""
        return self.points_axial + math.ceil(AXIAL_MARGIN * self.length_axial / self.axial_step)

    def _generate(self) -> np.ndarray:
        if self.amplitude == 0:
            return np.zeros((self.points_circumferential, self.points_axial))
        s = self.spectral_density()
        noise = generator(self.seed).standard_normal(s.shape)
        field_ = np.fft.ifft2(np.sqrt(s) * np.fft.fft2(noise)).real[:, : self.points_axial]
        if self.exact_rms:
            field_ = field_ - field_.mean()
            field_ *= self.amplitude / np.sqrt(np.mean(field_**2))
        return np.ascontiguousarray(field_)

    # ------------------------------------------------------------- evaluation
    def height(self, theta, z=0.0):
        """Radial deviation h(theta, z) [m], bilinear between grid points, periodic in theta.

        Parameters
        ----------
        theta : float or array
            Angle in the ring's own frame, from +x towards +y [rad].
        z : float or array
            Axial coordinate from the groove's mid-plane [m]; held at the edge beyond
            +-width/2. Broadcast with ``theta``.
        """
        theta, z = np.broadcast_arrays(np.asarray(theta, float), np.asarray(z, float))
        n_r, n_z = self.heights.shape
        u = np.mod(theta, 2.0 * math.pi) * (n_r / (2.0 * math.pi))
        i0 = np.floor(u)
        fr = u - i0
        i0 = i0.astype(np.intp) % n_r
        i1 = (i0 + 1) % n_r
        v = (np.clip(z, -0.5 * self.width, 0.5 * self.width) + 0.5 * self.width) / self.axial_step
        j0 = np.minimum(np.floor(v), n_z - 2).astype(np.intp)
        fz = v - j0
        h = self.heights
        return (
            (1 - fr) * ((1 - fz) * h[i0, j0] + fz * h[i0, j0 + 1])
            + fr * ((1 - fz) * h[i1, j0] + fz * h[i1, j0 + 1])
        )[()]

    def autocorrelation(self, tau_r, tau_z):
        """The target R(``tau_r``, ``tau_z``) of this surface (seed 002 eq. 6), at lags
        ``tau_r`` along the raceway and ``tau_z`` across it [m] [m^2].

        Parameters
        ----------
        tau_r : array_like
            Lag along the raceway (circumferential) [m].
        tau_z : array_like
            Lag across the raceway (axial) [m], broadcast against ``tau_r``.

        Returns
        -------
        numpy.ndarray
            R [m^2].
        """
        return exponential_autocorrelation(
            tau_r, tau_z, self.amplitude, self.length_circumferential, self.length_axial
        )

    def check(self, bearing) -> None:
        """Nothing to refuse: a surface fits any ``bearing`` (its radius is only its
        scale).

        Parameters
        ----------
        bearing : BallBearing
            Any bearing (not used).
        """

    def to_dict(self) -> dict:
        """JSON-ready description in engineering units."""
        return {
            "race": self.race,
            "rms_um": self.amplitude * 1e6,
            "length_circumferential_mm": self.length_circumferential * 1e3,
            "length_axial_mm": self.length_axial * 1e3,
            "radius_mm": self.radius * 1e3,
            "width_mm": self.width * 1e3,
            "seed": int(self.seed),
            "points_circumferential": int(self.points_circumferential),
            "points_axial": int(self.points_axial),
            "exact_rms": self.exact_rms,
            "sample_rms_um": self.rms * 1e6,
        }

    @classmethod
    def for_bearing(
        cls,
        bearing,
        race: str,
        amplitude: float,
        length_circumferential: float,
        length_axial: float,
        seed: int,
        *,
        width: float | None = None,
        **grid,
    ) -> RandomSurface:
        """A surface on ``bearing``'s raceway: radius d_i/2 or d_o/2, width D_w by default
        (the groove band the contacts can reach), grid fine enough for the correlation
        lengths (4 points per length, at least 256 round and 17 across) unless given.

        Parameters
        ----------
        bearing : BallBearing
            Geometry.
        race : {"inner", "outer"}
            Which raceway [-].
        amplitude, length_circumferential, length_axial : float
            dh, beta_r, beta_z [m].
        seed : int
            Random seed [-].
        width : float, optional
            Axial extent [m].
        **grid
            ``points_circumferential``, ``points_axial``, ``exact_rms``.
        """
        if race not in ("inner", "outer"):
            raise InputError("race", race, "'inner' or 'outer'")
        radius = 0.5 * (
            bearing.inner_raceway_diameter if race == "inner" else bearing.outer_raceway_diameter
        )
        width = (
            bearing.ball_diameter if width is None else finite("width", width, "a length > 0 [m]")
        )
        if width <= 0:
            raise InputError("width", width, "a length > 0 [m]")
        lr = finite("length_circumferential", length_circumferential, "a length > 0 [m]")
        lz = finite("length_axial", length_axial, "a length > 0 [m]")
        if lr <= 0 or lz <= 0:
            raise InputError(
                "length_circumferential" if lr <= 0 else "length_axial",
                lr if lr <= 0 else lz,
                "a length > 0 [m]",
            )
        n_r = max(256, 1 << math.ceil(math.log2(4 * 2 * math.pi * radius / lr)))
        n_z = max(17, math.ceil(4 * width / lz) + 1)
        grid.setdefault("points_circumferential", n_r)
        grid.setdefault("points_axial", n_z)
        return cls(race, amplitude, lr, lz, radius, width, seed, **grid)
