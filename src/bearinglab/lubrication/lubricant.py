"""Lubricant properties: viscosity, its temperature and pressure dependence.

Layer 1 holds the pure functions (exponential viscosity-temperature law, the initial
pressure-viscosity slope of Roelands' equation); layer 2 holds :class:`Lubricant`, a
validated, frozen record that calls them. Temperatures are absolute, in kelvin
(40 degC = 313.15 K); see :data:`ZERO_CELSIUS`.

Sources:

- Reynolds' exponential viscosity-temperature law eta(T) = eta_0 exp(-beta (T - T_0)),
  as given e.g. by Hamrock B. J., Schmid S. R., Jacobson B. O., *Fundamentals of Fluid
  Film Lubrication*, 2nd ed., Marcel Dekker, 2004, ch. 4 (viscosity-temperature
  effects). It is a local fit: beta depends on the temperature range it was fitted over.
- Roelands C. J. A., *Correlational aspects of the viscosity-temperature-pressure
  relationship of lubricating oils*, PhD thesis, TU Delft, 1966:
  eta(p) = eta_0 exp{(ln eta_0 + 9.67) [(1 + p / p_0)^Z - 1]}, eta_0 in Pa s,
  p_0 = 1.96e8 Pa (9.67 = -ln(eta_inf), eta_inf = 6.31e-5 Pa s). Its slope at p = 0 is
  the pressure-viscosity coefficient of Barus' law,
  alpha = d(ln eta)/dp |_(p=0) = Z (ln eta_0 + 9.67) / p_0,
  the relation used (as Z = alpha / (5.1e-9 (ln eta_0 + 9.67))) throughout the EHL
  literature to pass between alpha and Z.

Built-in lubricants (:data:`LUBRICANTS`):

- ``seed004-grease`` — the grease of seed 004 (Hou et al., *J. Mech. Electr. Eng.*
  41 (2024) 271-279, section 2, lubricant paragraph): density 850 kg/m^3, dynamic
  viscosity 0.04 Pa s "at room temperature" (taken as 20 degC: the paper names no
  temperature), limiting shear coefficient 0.0434 (limiting shear stress / pressure),
  viscosity-temperature coefficient 0.027 (read as the exponential beta, 1/K: the value
  is typical of that coefficient and far from Roelands' S_0 ~ 1), pressure-viscosity
  index Z = 0.45 (Roelands' Z: the paper's "黏压指数 Z"). alpha follows from Z by
  Roelands' initial slope: alpha = 0.45 (ln 0.04 + 9.67) / 1.96e8 = 1.481e-8 1/Pa.
- ``iso-vg68`` — a typical ISO VG 68 mineral oil at 40 degC: kinematic viscosity
  68 mm^2/s (the mid-point of ISO 3448 grade VG 68, limits 61.2-74.8 mm^2/s), density
  860 kg/m^3 (a typical paraffinic mineral oil at 40 degC; an estimate, +-2 %), so
  eta_0 = 0.0585 Pa s; beta = ln(68 / 8.5) / 60 K = 0.0347 1/K, the secant of ln(nu)
  between 40 and 100 degC with the typical nu_100 = 8.5 mm^2/s of a VG 68 oil of viscosity
  index ~95 (density change neglected; the local slope at 40 degC by ASTM D341 is larger,
  ~0.05 1/K); alpha = 2.5e-8 1/Pa, from Stachowiak G. W., Batchelor A. W., *Engineering
  Tribology*, 2nd ed., 2001, Table 2.3: the mineral oils there closest to VG 68 at 40 degC
  (log-interpolated) are a heavy machine oil (122/26.3 mPa s at 30/60 degC, ~73 mPa s at
  40 degC; alpha 27.0/21.6 GPa^-1, linearly 25.2 GPa^-1 at 40 degC) and a medicinal white
  oil (107/23.3 mPa s, ~64 mPa s; alpha 29.6/22.8 GPa^-1, 27.3 GPa^-1 at 40 degC); we take
  the lower, 2.5e-8 1/Pa (a typical value, not a measurement of a particular oil).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, positive_number

#: 0 degC in kelvin [K].
ZERO_CELSIUS = 273.15
#: Roelands' reference pressure p_0 [Pa].
ROELANDS_PRESSURE = 1.96e8
#: -ln(eta_inf / (1 Pa s)) in Roelands' equation, eta_inf = 6.31e-5 Pa s [-].
ROELANDS_LOG_VISCOSITY = 9.67
#: Temperatures below this are refused: they are almost certainly degC given for K [K].
MIN_TEMPERATURE = 150.0


# ---------------------------------------------------------------- layer 1: functions


def _temperature(name: str, value):
    t = np.asarray(value, dtype=float)
    if np.any(~np.isfinite(t)) or np.any(t < MIN_TEMPERATURE):
        raise InputError(
            name,
            value,
            f"absolute temperatures >= {MIN_TEMPERATURE} K",
            "temperatures are in kelvin: 40 degC = 313.15 K",
        )
    return t


def reynolds_viscosity(
    reference_viscosity, temperature_coefficient, temperature, reference_temperature
):
    """Dynamic viscosity by Reynolds' exponential law [Pa s].

    eta(T) = eta_0 exp(-beta (T - T_0)) (Hamrock, Schmid & Jacobson 2004, ch. 4).

    Parameters
    ----------
    reference_viscosity : float or array
        eta_0 at the reference temperature [Pa s].
    temperature_coefficient : float or array
        beta [1/K], >= 0.
    temperature : float or array
        T [K].
    reference_temperature : float or array
        T_0 [K].

    Examples
    --------
    >>> round(float(reynolds_viscosity(0.04, 0.027, 313.15, 293.15)), 5)
    0.02331
    """
    t = _temperature("temperature", temperature)
    t0 = _temperature("reference_temperature", reference_temperature)
    eta0 = np.asarray(reference_viscosity, dtype=float)
    beta = np.asarray(temperature_coefficient, dtype=float)
    if np.any(~np.isfinite(eta0)) or np.any(eta0 <= 0):
        raise InputError("reference_viscosity", reference_viscosity, "a positive viscosity [Pa s]")
    if np.any(~np.isfinite(beta)) or np.any(beta < 0):
        raise InputError(
            "temperature_coefficient", temperature_coefficient, "a finite coefficient >= 0 [1/K]"
        )
    return (eta0 * np.exp(-beta * (t - t0)))[()]


def roelands_pressure_viscosity_coefficient(viscosity, roelands_index):
    """Pressure-viscosity coefficient alpha from Roelands' index Z [1/Pa].

    alpha = Z (ln eta_0 + 9.67) / p_0, p_0 = 1.96e8 Pa, eta_0 in Pa s: the slope of
    ln(eta) at p = 0 in Roelands' equation (Roelands 1966). Needs eta_0 > eta_inf =
    6.31e-5 Pa s (ln eta_0 + 9.67 > 0).

    Parameters
    ----------
    viscosity : float or array
        Dynamic viscosity eta_0 at atmospheric pressure [Pa s].
    roelands_index : float or array
        Roelands' pressure-viscosity index Z [-], > 0.

    Examples
    --------
    >>> round(float(roelands_pressure_viscosity_coefficient(0.04, 0.45)) * 1e8, 4)
    1.4811
    """
    eta = np.asarray(viscosity, dtype=float)
    z = np.asarray(roelands_index, dtype=float)
    if np.any(~np.isfinite(eta)) or np.any(
        np.log(np.maximum(eta, 1e-300)) + ROELANDS_LOG_VISCOSITY <= 0
    ):
        raise InputError(
            "viscosity",
            viscosity,
            f"a viscosity above eta_inf = {math.exp(-ROELANDS_LOG_VISCOSITY):.3g} "
            "Pa s (Roelands' equation)",
        )
    if np.any(~np.isfinite(z)) or np.any(z <= 0):
        raise InputError("roelands_index", roelands_index, "a positive index Z [-]")
    return (z * (np.log(eta) + ROELANDS_LOG_VISCOSITY) / ROELANDS_PRESSURE)[()]


def roelands_index(viscosity, pressure_viscosity_coefficient):
    """Roelands' index Z that gives the pressure-viscosity coefficient alpha [-].

    Inverse of :func:`roelands_pressure_viscosity_coefficient`:
    Z = alpha p_0 / (ln eta_0 + 9.67).

    Parameters
    ----------
    viscosity : float or array
        eta_0 [Pa s].
    pressure_viscosity_coefficient : float or array
        alpha [1/Pa].

    Examples
    --------
    >>> round(float(roelands_index(0.04, 1.4811254e-8)), 4)
    0.45
    """
    eta = np.asarray(viscosity, dtype=float)
    a = np.asarray(pressure_viscosity_coefficient, dtype=float)
    # Reuse the validation of the forward relation with Z = 1.
    per_z = roelands_pressure_viscosity_coefficient(eta, 1.0)
    if np.any(~np.isfinite(a)) or np.any(a <= 0):
        raise InputError(
            "pressure_viscosity_coefficient",
            pressure_viscosity_coefficient,
            "a positive coefficient [1/Pa]",
        )
    return (a / per_z)[()]


# ---------------------------------------------------------------- layer 2: the model


@dataclass(frozen=True)
class Lubricant:
    """A Newtonian lubricant (oil, or the base oil of a grease) for EHL calculations.

    Parameters
    ----------
    name : str
        What the lubricant is, for reports [-].
    dynamic_viscosity : float
        Dynamic viscosity eta_0 at atmospheric pressure and the reference temperature [Pa s].
    reference_temperature : float
        Temperature T_0 at which ``dynamic_viscosity`` holds [K] (absolute: 40 degC = 313.15 K).
    pressure_viscosity_coefficient : float
        alpha of Barus' law eta = eta_0 exp(alpha p) [1/Pa], > 0.
    density : float
        Density rho at the reference temperature [kg/m^3].
    temperature_coefficient : float or None
        Reynolds' viscosity-temperature coefficient beta [1/K], >= 0; None if unknown
        (then only the reference temperature can be used).
    limiting_shear_coefficient : float or None
        Limiting shear stress over pressure, tau_L / p [-], in (0, 1); for traction
        models, not used by the film thickness.
    roelands_index : float or None
        Roelands' pressure-viscosity index Z [-], if that is what was published
        (see :meth:`from_roelands`); informational.
    source : str
        Where the values come from [-].

    Examples
    --------
    >>> oil = Lubricant("test oil", 0.05, 313.15, 2e-8, 870.0, temperature_coefficient=0.03)
    >>> round(float(oil.viscosity(323.15)), 5)
    0.03704
    """

    name: str
    dynamic_viscosity: float
    reference_temperature: float
    pressure_viscosity_coefficient: float
    density: float
    temperature_coefficient: float | None = None
    limiting_shear_coefficient: float | None = None
    roelands_index: float | None = None
    source: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise InputError("name", self.name, "a non-empty string")
        positive_number("dynamic_viscosity", self.dynamic_viscosity, "a positive viscosity [Pa s]")
        positive_number(
            "reference_temperature", self.reference_temperature, "an absolute temperature [K]"
        )
        if self.reference_temperature < MIN_TEMPERATURE:
            raise InputError(
                "reference_temperature",
                self.reference_temperature,
                f"an absolute temperature >= {MIN_TEMPERATURE} K",
                "temperatures are in kelvin: 40 degC = 313.15 K",
            )
        positive_number(
            "pressure_viscosity_coefficient",
            self.pressure_viscosity_coefficient,
            "a positive coefficient alpha [1/Pa] (typically 1e-8 to 3e-8 for oils)",
        )
        if self.pressure_viscosity_coefficient > 1e-6:
            raise InputError(
                "pressure_viscosity_coefficient",
                self.pressure_viscosity_coefficient,
                "a coefficient in 1/Pa, at most 1e-6",
                "GPa^-1 values must be multiplied by 1e-9",
            )
        positive_number("density", self.density, "a positive density [kg/m^3]")
        beta = self.temperature_coefficient
        if beta is not None and (
            isinstance(beta, bool)
            or not isinstance(beta, (int, float, np.integer, np.floating))
            or not math.isfinite(beta)
            or not 0.0 <= beta < 1.0
        ):
            raise InputError("temperature_coefficient", beta, "None or a value in [0, 1) [1/K]")
        lim = self.limiting_shear_coefficient
        if lim is not None and (
            isinstance(lim, bool)
            or not isinstance(lim, (int, float, np.integer, np.floating))
            or not 0.0 < lim < 1.0
        ):
            raise InputError("limiting_shear_coefficient", lim, "None or a value in (0, 1) [-]")
        z = self.roelands_index
        if z is not None:
            positive_number("roelands_index", z, "None or a positive index Z [-]")

    @classmethod
    def from_roelands(
        cls,
        name: str,
        dynamic_viscosity: float,
        reference_temperature: float,
        roelands_index: float,
        density: float,
        **kwargs,
    ) -> Lubricant:
        """A lubricant whose pressure-viscosity behaviour is given as Roelands' Z.

        alpha = Z (ln eta_0 + 9.67) / 1.96e8 Pa (see
        :func:`roelands_pressure_viscosity_coefficient`).

        Parameters
        ----------
        name : str
            Label [-].
        dynamic_viscosity : float
            eta_0 [Pa s].
        reference_temperature : float
            T_0 [K].
        roelands_index : float
            Z [-].
        density : float
            rho [kg/m^3].
        **kwargs
            ``temperature_coefficient`` [1/K], ``limiting_shear_coefficient`` [-],
            ``source`` [-].
        """
        positive_number("roelands_index", roelands_index, "a positive index Z [-]")
        alpha = float(roelands_pressure_viscosity_coefficient(dynamic_viscosity, roelands_index))
        return cls(
            name,
            dynamic_viscosity,
            reference_temperature,
            alpha,
            density,
            roelands_index=roelands_index,
            **kwargs,
        )

    def viscosity(self, temperature=None):
        """Dynamic viscosity at ``temperature`` (default: the reference) [Pa s].

        Reynolds' law, :func:`reynolds_viscosity`; vectorised over ``temperature``.

        Parameters
        ----------
        temperature : float, array or None
            T [K]; None means the reference temperature.
        """
        if temperature is None:
            return self.dynamic_viscosity
        t = _temperature("temperature", temperature)
        if self.temperature_coefficient is None:
            if np.all(t == self.reference_temperature):
                return (self.dynamic_viscosity * np.ones_like(t))[()]
            raise InputError(
                "temperature",
                temperature,
                f"the reference temperature {self.reference_temperature} K",
                f"{self.name!r} has no temperature_coefficient",
            )
        return reynolds_viscosity(
            self.dynamic_viscosity, self.temperature_coefficient, t, self.reference_temperature
        )

    def kinematic_viscosity(self, temperature=None):
        """Kinematic viscosity eta / rho [m^2/s]; density held at its reference value.

        Parameters
        ----------
        temperature : float, array or None
            T [K]; None means the reference temperature.
        """
        return self.viscosity(temperature) / self.density

    def to_dict(self) -> dict:
        """JSON-ready summary in engineering units."""
        beta = self.temperature_coefficient
        return {
            "name": self.name,
            "dynamic_viscosity_pa_s": self.dynamic_viscosity,
            "reference_temperature_c": self.reference_temperature - ZERO_CELSIUS,
            "pressure_viscosity_coefficient_per_gpa": self.pressure_viscosity_coefficient * 1e9,
            "density_kg_m3": self.density,
            "temperature_coefficient_per_k": beta,
            "limiting_shear_coefficient": self.limiting_shear_coefficient,
            "roelands_index": self.roelands_index,
            "source": self.source,
        }


SEED004_GREASE = Lubricant.from_roelands(
    "grease of seed 004 (Hou et al. 2024)",
    dynamic_viscosity=0.04,
    reference_temperature=ZERO_CELSIUS + 20.0,
    roelands_index=0.45,
    density=850.0,
    temperature_coefficient=0.027,
    limiting_shear_coefficient=0.0434,
    source="seed 004, section 2 (lubricant parameters); 'room temperature' taken as 20 degC; "
    "alpha from Roelands' Z = 0.45",
)

ISO_VG68 = Lubricant(
    "ISO VG 68 mineral oil (typical)",
    dynamic_viscosity=68e-6 * 860.0,
    reference_temperature=ZERO_CELSIUS + 40.0,
    pressure_viscosity_coefficient=2.5e-8,
    density=860.0,
    temperature_coefficient=math.log(68.0 / 8.5) / 60.0,
    source="ISO 3448 VG 68 mid-point 68 mm^2/s at 40 degC; density 860 kg/m^3 (typical, "
    "estimate); beta from nu_100 = 8.5 mm^2/s (typical VI ~95); alpha from Stachowiak "
    "& Batchelor, Engineering Tribology, Table 2.3",
)

#: Built-in lubricants by key.
LUBRICANTS: dict[str, Lubricant] = {"seed004-grease": SEED004_GREASE, "iso-vg68": ISO_VG68}

#: Operating temperatures at which :func:`operating_viscosity` evaluates a lubricant [K]:
#: -60 ... 300 degC (Reynolds' law is a local fit; beyond this no oil is in service).
OPERATING_TEMPERATURE_RANGE = (ZERO_CELSIUS - 60.0, ZERO_CELSIUS + 300.0)


def check_operating_temperature(temperature) -> float:
    """``temperature`` [K] as a float if it is in :data:`OPERATING_TEMPERATURE_RANGE`;
    InputError (in K and degC) otherwise."""
    low, high = OPERATING_TEMPERATURE_RANGE
    if (
        isinstance(temperature, bool)
        or not isinstance(temperature, (int, float, np.integer, np.floating))
        or not math.isfinite(temperature)
        or not low <= temperature <= high
    ):
        raise InputError(
            "temperature",
            temperature,
            f"an operating temperature in [{low:g}, {high:g}] K "
            f"({low - ZERO_CELSIUS:g} to {high - ZERO_CELSIUS:g} degC)",
        )
    return float(temperature)


def operating_viscosity(lubricant, temperature=None) -> tuple[float, str]:
    """Kinematic viscosity of a lubricant at its operating temperature [m^2/s], and how it
    was found (one sentence).

    Reynolds' exponential law through :meth:`Lubricant.kinematic_viscosity` (Hamrock,
    Schmid & Jacobson 2004, ch. 4), the density held at its reference value. Used by the
    friction analysis and the report, so both read a lubricant the same way.

    Parameters
    ----------
    lubricant : Lubricant or str
        The lubricant, or the key of a built-in one (:data:`LUBRICANTS`) [-].
    temperature : float or None
        Operating temperature [K] in :data:`OPERATING_TEMPERATURE_RANGE`; None means the
        lubricant's reference temperature.

    Examples
    --------
    >>> nu, how = operating_viscosity("iso-vg68")
    >>> round(nu * 1e6, 6), how
    (68.0, 'ISO VG 68 mineral oil (typical) at its reference temperature 40 degC')
    >>> round(operating_viscosity("iso-vg68", ZERO_CELSIUS + 100.0)[0] * 1e6, 3)
    8.5
    """
    if isinstance(lubricant, str):
        if lubricant not in LUBRICANTS:
            raise InputError("lubricant", lubricant, "one of " + ", ".join(LUBRICANTS))
        lubricant = LUBRICANTS[lubricant]
    if not isinstance(lubricant, Lubricant):
        raise InputError("lubricant", lubricant, "a Lubricant or the name of a built-in one")
    t0 = lubricant.reference_temperature
    if temperature is None:
        return (
            float(lubricant.kinematic_viscosity(t0)),
            f"{lubricant.name} at its reference temperature {t0 - ZERO_CELSIUS:.4g} degC",
        )
    nu = float(lubricant.kinematic_viscosity(check_operating_temperature(temperature)))
    return nu, (
        f"{lubricant.name} at {temperature - ZERO_CELSIUS:.4g} degC (Reynolds' "
        f"exponential law from {t0 - ZERO_CELSIUS:.4g} degC)"
    )
