"""bearinglab: mechanics, vibration, noise and diagnostics of rolling bearings.

The layers (docs/architecture.md): physics functions (``contact.hertz``, ``geometry``
functions, ``kinematics.frequency_orders``), model objects (``Material``,
``BallBearing``, ``Designation``), analyses (``ball_contacts``,
``defect_frequencies``) and interfaces (``bearinglab`` command line).

The names below are imported on first use, so ``import bearinglab`` (and the command
line's start-up) stays light.
"""

from importlib import import_module

__version__ = "0.1.0"

#: public name -> module that defines it
_EXPORTS = {
    "BearinglabError": "errors", "CatalogError": "errors", "ConvergenceError": "errors",
    "DesignationError": "errors", "InputError": "errors",
    "BallBearing": "geometry", "Source": "geometry",
    "BEARING_STEEL": "materials", "SILICON_NITRIDE": "materials", "Material": "materials",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str):
    if name not in _EXPORTS:
        raise AttributeError(f"module 'bearinglab' has no attribute {name!r}")
    value = getattr(import_module(f".{_EXPORTS[name]}", __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_EXPORTS))
