"""bearinglab: mechanics, vibration, noise and diagnostics of rolling bearings.

The layers (docs/architecture.md): physics functions (``contact.hertz``, ``geometry``
functions, ``kinematics.frequency_orders``), model objects (``Material``,
``BallBearing``, ``Designation``), analyses (``ball_contacts``,
``defect_frequencies``) and interfaces (``bearinglab`` command line).

The main entry points are here, imported on first use, so ``import bearinglab`` (and the
command line's start-up) stays light:

>>> import bearinglab as bl
>>> bearing, _ = bl.bearing_from_designation("6205-2RS")
>>> round(bl.defect_frequencies(bearing, speed_rpm=1797).hz("bpfo"), 2)
107.36
"""

from importlib import import_module

__version__ = "0.1.0"

#: public name -> module that defines it
_EXPORTS = {
    "BearinglabError": "errors",
    "CatalogError": "errors",
    "ConvergenceError": "errors",
    "DesignationError": "errors",
    "InputError": "errors",
    "BallBearing": "geometry",
    "RollerBearing": "roller_geometry",
    "RollerProfile": "roller_geometry",
    "Source": "geometry",
    "BEARING_STEEL": "materials",
    "SILICON_NITRIDE": "materials",
    "Material": "materials",
    "OperatingCondition": "operating",
    "rpm_to_rad_s": "units",
    "rad_s_to_rpm": "units",
    # the main analyses
    "bearing_from_designation": "catalog",
    "parse_designation": "designation",
    "defect_frequencies": "kinematics",
    "ball_contacts": "contact.ball_race",
    "solve_load_distribution": "quasistatic",
    "inner_ring_orbit": "quasistatic.orbit",
    "stiffness_map": "quasistatic.study",
    "ring_modes": "rings",
    "Defect": "dynamics",
    "simulate": "dynamics",
    "simulate_record": "dynamics.record",
    "analyze_signal": "diagnosis",
    "analyze_file": "diagnosis",
    "run_benchmark": "diagnosis",
    "size_defect": "diagnosis",
    "read_signal": "signal",
    "Waviness": "imperfections",
    "BallSizeErrors": "imperfections",
    "Imperfections": "imperfections",
    "bearing_noise": "noise",
    "noise_analysis": "noise",
    "bearing_friction": "friction",
    "load_ratings": "life",
    "rating_life": "life",
    "run_validation": "validation.run",
    "build_report": "report",
    "trend_records": "trend",
}
#: names that differ in their module
_ALIASES = {"parse_designation": "parse"}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str):
    if name not in _EXPORTS:
        raise AttributeError(f"module 'bearinglab' has no attribute {name!r}")
    value = getattr(import_module(f".{_EXPORTS[name]}", __name__), _ALIASES.get(name, name))
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_EXPORTS))
