"""Elastic and mass properties of bearing materials.

Sources: Harris T. A., Kotzalas M. N., *Essential Concepts of Bearing Technology*,
5th ed., CRC Press, 2007, table of material properties (AISI 52100: E = 208 GPa,
nu = 0.3, rho = 7830 kg/m^3; hot-pressed silicon nitride: E = 310 GPa, nu = 0.26,
rho = 3190 kg/m^3).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import InputError


@dataclass(frozen=True)
class Material:
    """An isotropic, linear-elastic material.

    Parameters
    ----------
    name : str
        What the material is, for reports.
    elastic_modulus : float
        Young's modulus E [Pa].
    poisson_ratio : float
        Poisson's ratio nu [-], 0 <= nu < 0.5.
    density : float
        Mass density rho [kg/m^3].

    Examples
    --------
    >>> BEARING_STEEL.elastic_modulus
    208000000000.0
    """

    name: str
    elastic_modulus: float
    poisson_ratio: float
    density: float

    def __post_init__(self) -> None:
        if not (np.isfinite(self.elastic_modulus) and self.elastic_modulus > 0):
            raise InputError("elastic_modulus", self.elastic_modulus, "a positive modulus [Pa]")
        if not (np.isfinite(self.poisson_ratio) and 0.0 <= self.poisson_ratio < 0.5):
            raise InputError("poisson_ratio", self.poisson_ratio, "a value in [0, 0.5)")
        if not (np.isfinite(self.density) and self.density > 0):
            raise InputError("density", self.density, "a positive density [kg/m^3]")

    @property
    def compliance(self) -> float:
        """Contact compliance (1 - nu^2) / E [1/Pa]."""
        return (1.0 - self.poisson_ratio**2) / self.elastic_modulus


def effective_modulus(first: Material, second: Material) -> float:
    """Effective elastic modulus E' of two bodies in contact [Pa].

    E' = 2 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b) (Hamrock B. J., Brewe D. E.,
    "Simplified solution for stresses and deformations", J. Lubr. Technol. 105, 1983,
    eq. for E'). Two steel bodies give about 228.6 GPa.

    >>> round(effective_modulus(BEARING_STEEL, BEARING_STEEL) / 1e9, 1)
    228.6
    """
    return 2.0 / (first.compliance + second.compliance)


BEARING_STEEL = Material("AISI 52100 bearing steel", 208e9, 0.30, 7830.0)
SILICON_NITRIDE = Material("silicon nitride (Si3N4)", 310e9, 0.26, 3190.0)

MATERIALS: dict[str, Material] = {"steel": BEARING_STEEL, "si3n4": SILICON_NITRIDE}
