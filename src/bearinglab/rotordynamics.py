"""From a bearing and its operating point to a rotor-dynamics bearing element (ROSS).

ROSS (Timbo R. et al., *ROSS - Rotordynamic Open Source Software*, JOSS 5(48), 2120, 2020;
the ``ross-rotordynamics`` package, an optional dependency) models a bearing as springs
and dampers at a shaft node, with coefficients that may depend on the shaft speed. This
module solves the quasi-static load distribution at each speed asked for and hands ROSS
the x-y stiffness (kxx, kxy, kyx, kyy) and the axial kzz of the tangent stiffness matrix;
the tilt terms have no place in a ROSS bearing element and are left out.

Damping: ball bearings have little damping of their own. Unless a value is given, the
direct damping follows Kramer's rule for rolling bearings, c = beta k with
beta = 0.25e-5 ... 2.5e-5 s (Kramer E., *Dynamics of Rotors and Foundations*, Springer,
1993, ch. 8, rolling-element bearings); we take beta = 1e-5 s (``KRAMER_FACTOR``) and
cxx = beta kxx, cyy = beta kyy, no cross damping. It is a rule of thumb with a range of
ten: give ``damping`` [N s/m] when you have a measured value.

The speed goes to ROSS as its speed axis: ``speed=`` for ROSS >= 3 (where ``frequency``
is the whirl frequency), ``frequency=`` for ROSS 1.x-2.x (where it is the speed), read
from the installed ``BearingElement`` signature. Tested with ROSS 2.3.0 (Python 3.11).

>>> # element = ross_bearing("6205", n=0, radial_load=500.0, speed_rpm=[0, 3000, 6000])
"""

from __future__ import annotations

import inspect
import math
import warnings

import numpy as np

from .catalog import bearing_from_designation
from .errors import InputError
from .geometry import BallBearing
from .operating import OperatingCondition
from .quasistatic import solve_load_distribution

#: beta of Kramer's rule c = beta k for rolling bearings [s] (range 0.25e-5 to 2.5e-5 s).
KRAMER_FACTOR = 1.0e-5


def import_ross():
    """The installed ROSS, imported quietly (its thermodynamics dependency warns about an
    optional library at import), or an ImportError saying how to get it."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            import ross
    except ImportError:
        raise ImportError(
            "the ROSS export needs ROSS: pip install ross-rotordynamics "
            "(on Python 3.11: 'ross-rotordynamics==2.3.0' 'plotly<6')"
        ) from None
    return ross


def speed_keyword(element_class) -> str:
    """The keyword of ROSS's ``BearingElement`` that takes the shaft-speed axis:
    ``speed`` (ROSS >= 3), ``frequency`` (1.x-2.x) or ``w`` (0.x) [-]."""
    names = inspect.signature(element_class.__init__).parameters
    for name in ("speed", "frequency", "w"):
        if name in names:
            return name
    raise ImportError(f"this ROSS BearingElement takes none of speed/frequency/w: {names}")


def ross_element(
    results,
    n: int,
    *,
    tag: str | None = None,
    damping: float | None = None,
    damping_factor: float = KRAMER_FACTOR,
):
    """A ``ross.BearingElement`` from load distributions solved at one or more speeds.

    Parameters
    ----------
    results : LoadDistribution or sequence of them
        Solutions at increasing shaft speeds (same bearing and node), ball or roller
        (:class:`~bearinglab.quasistatic.roller_result.RollerLoadDistribution`) [-].
    n : int
        Shaft node of the bearing in the ROSS rotor [-].
    tag : str, optional
        Element name; by default the bearing's name and the node, e.g. "6205 n3" (ROSS
        refuses a rotor whose elements share a tag) [-].
    damping : float, optional
        Direct damping cxx = cyy [N s/m]; by default Kramer's rule c = damping_factor k.
    damping_factor : float
        beta of Kramer's rule [s] (0.25e-5 to 2.5e-5 s).
    """
    ross = import_ross()
    results = [results] if not isinstance(results, (list, tuple)) else list(results)
    if not results:
        raise InputError("results", results, "at least one load distribution")
    if damping is not None and (not math.isfinite(damping) or damping < 0):
        raise InputError("damping", damping, "a finite damping >= 0 [N s/m]")
    if not (math.isfinite(damping_factor) and 0 <= damping_factor <= 1e-3):
        raise InputError(
            "damping_factor", damping_factor, "0 to 1e-3 s (Kramer: 0.25e-5 to 2.5e-5 s)"
        )
    speeds = np.array([r.condition.shaft_speed for r in results])
    if np.any(np.diff(speeds) <= 0):
        raise InputError(
            "speeds", (speeds * 30 / math.pi).tolist(), "distinct speeds in increasing order [rpm]"
        )
    k = np.array([r.stiffness_matrix for r in results])
    coefficients = {
        "kxx": k[:, 0, 0],
        "kyy": k[:, 1, 1],
        "kxy": k[:, 0, 1],
        "kyx": k[:, 1, 0],
        "kzz": k[:, 2, 2],
    }
    if damping is None:
        coefficients["cxx"] = damping_factor * k[:, 0, 0]
        coefficients["cyy"] = damping_factor * k[:, 1, 1]
    else:
        coefficients["cxx"] = coefficients["cyy"] = np.full(len(results), float(damping))
    single = len(results) == 1
    kwargs = {name: float(v[0]) if single else v.tolist() for name, v in coefficients.items()}
    kwargs[speed_keyword(ross.BearingElement)] = speeds.tolist()
    name = (
        results[0].bearing.name
        or f"{getattr(results[0].bearing, 'rolling_element', 'ball')} bearing"
    )
    return ross.BearingElement(n=n, tag=tag or f"{name} n{n}", **kwargs)


def bearing_element(
    bearing: BallBearing,
    n: int,
    *,
    speeds_rpm=(0.0,),
    radial_load: float = 0.0,
    axial_load: float = 0.0,
    tag: str | None = None,
    damping: float | None = None,
    damping_factor: float = KRAMER_FACTOR,
    **solve_options,
):
    """A ROSS bearing element of ``bearing`` with speed-dependent coefficients.

    Solves the load distribution at every speed (each from the previous solution) and
    passes the stiffness (and damping) at those speeds to ROSS, which interpolates.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing
        The bearing.
    n : int
        Shaft node [-].
    speeds_rpm : float or sequence of float
        Shaft speeds, increasing [rpm].
    radial_load, axial_load : float
        Loads on the inner ring [N].
    tag, damping, damping_factor :
        As for :func:`ross_element` [-, N s/m, s].
    **solve_options :
        Passed to :func:`bearinglab.quasistatic.solve_load_distribution` (``gyroscopic``,
        ``race_control``, ``lubricant``, ``ring_expansion``).
    """
    speeds = np.atleast_1d(np.asarray(speeds_rpm, dtype=float))
    if speeds.ndim != 1 or not np.all(np.isfinite(speeds)) or np.any(speeds < 0):
        raise InputError("speeds_rpm", speeds_rpm, "finite speeds >= 0 [rpm]")
    results, initial = [], None
    for rpm in speeds:
        condition = OperatingCondition(
            radial_load=radial_load, axial_load=axial_load, shaft_speed=rpm * math.pi / 30
        )
        r = solve_load_distribution(bearing, condition, initial=initial, **solve_options)
        initial = r.displacement
        results.append(r)
    return ross_element(results, n, tag=tag, damping=damping, damping_factor=damping_factor)


def ross_bearing(
    designation: str,
    n: int,
    *,
    radial_load: float = 0.0,
    axial_load: float = 0.0,
    speed_rpm=0.0,
    damping: float | None = None,
    tag: str | None = None,
    system: str | None = None,
    damping_factor: float = KRAMER_FACTOR,
    **overrides,
):
    """A ``ross.BearingElement`` for ``designation`` at its operating point(s).

    Builds the bearing from the catalogue (``overrides`` as for
    :func:`bearinglab.catalog.bearing_from_designation`, SI) and calls
    :func:`bearing_element`.

    Parameters
    ----------
    designation : str
        Bearing designation or catalogue name [-].
    n : int
        Shaft node of the bearing in the ROSS rotor [-].
    radial_load, axial_load : float
        Loads on the inner ring [N].
    speed_rpm : float or sequence of float
        Shaft speed(s) [rpm]; several give speed-dependent coefficients.
    damping : float, optional
        Direct damping [N s/m]; Kramer's rule by default (see the module docstring).
    tag : str, optional
        Element name; "<designation> n<node>" by default [-].
    system : str, optional
        "gost" or "iso" to force how the designation is read [-].
    damping_factor : float
        beta of Kramer's rule [s].
    """
    bearing, _ = bearing_from_designation(
        designation, system=system, overrides=overrides, rollers=True
    )
    return bearing_element(
        bearing,
        n,
        speeds_rpm=speed_rpm,
        radial_load=radial_load,
        axial_load=axial_load,
        tag=tag,
        damping=damping,
        damping_factor=damping_factor,
    )
