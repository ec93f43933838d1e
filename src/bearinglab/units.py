"""Units at the edges: SI inside, engineering units on the command line and in JSON.

One table (:data:`UNITS`) says what each unit suffix means: the suffix that ends a JSON
key or a command-line flag (``speed_rpm``, ``--radial-load-n``), the symbol printed in
table headers (``rpm``, ``N``, ``µm``) and the SI value of one unit. The command line
converts option values with it, the error messages and table headers print its symbols,
and ``docs/json.md`` (checked by ``tests/unit/test_json_contract.py``) lists it as the
JSON contract: every key of every ``--json`` either ends in one of these suffixes or is
one of the dimensionless keys of :data:`DIMENSIONLESS`.

>>> rpm_to_rad_s(30.0) == math.pi
True
>>> UNITS["n_per_um"].to_si(100.0)
100000000.0
>>> label("stiffness", "n_per_um")
'stiffness [N/µm]'
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: Angular speed of one revolution per minute [rad/s].
RPM = math.pi / 30.0


def rpm_to_rad_s(speed_rpm: float) -> float:
    """A speed in rpm as an angular speed [rad/s].

    Parameters
    ----------
    speed_rpm : float
        Speed [rpm].

    Returns
    -------
    float
        The same speed [rad/s].
    """
    return speed_rpm * RPM


def rad_s_to_rpm(speed: float) -> float:
    """An angular speed [rad/s] in rpm.

    Parameters
    ----------
    speed : float
        Angular speed [rad/s].

    Returns
    -------
    float
        The same speed [rpm].
    """
    return speed / RPM


def rad_s_to_hz(speed: float) -> float:
    """An angular speed [rad/s] as a frequency of revolution [Hz]."""
    return speed / (2.0 * math.pi)


@dataclass(frozen=True)
class Unit:
    """One engineering unit: key suffix, printed symbol, SI value of one unit, meaning."""

    suffix: str
    symbol: str
    factor: float
    quantity: str

    def to_si(self, value: float) -> float:
        """``value`` in this unit, in SI."""
        return value * self.factor

    def from_si(self, value: float) -> float:
        """An SI ``value`` in this unit."""
        return value / self.factor


def _units(*rows: tuple[str, str, float, str]) -> dict[str, Unit]:
    return {row[0]: Unit(*row) for row in rows}


#: suffix -> Unit. Suffixes are matched longest first, so ``n_per_um`` is not ``um``.
UNITS: dict[str, Unit] = _units(
    ("m", "m", 1.0, "length"),
    ("mm", "mm", 1e-3, "length"),
    ("um", "µm", 1e-6, "length"),
    ("nm", "nm", 1e-9, "length"),
    ("mm2", "mm²", 1e-6, "area"),
    ("mm4", "mm⁴", 1e-12, "second moment of area"),
    ("mrad", "mrad", 1e-3, "angle"),
    ("deg", "deg", math.pi / 180.0, "angle"),
    ("rad", "rad", 1.0, "angle"),
    ("n", "N", 1.0, "force"),
    ("kn", "kN", 1e3, "force"),
    ("n_m", "N·m", 1.0, "moment, torque"),
    ("n_mm", "N·mm", 1e-3, "moment, torque"),
    ("n_per_um", "N/µm", 1e6, "stiffness"),
    ("n_per_m", "N/m", 1.0, "stiffness"),
    ("n_m_per_rad", "N·m/rad", 1.0, "tilt stiffness"),
    ("n_per_m1_5", "N/m^1.5", 1.0, "Hertz load-deflection constant"),
    ("n_per_um1_5", "N/µm^1.5", 1e9, "Hertz load-deflection constant"),
    ("n_s_per_m", "N·s/m", 1.0, "damping"),
    ("pa", "Pa", 1.0, "pressure, stress"),
    ("upa", "µPa", 1e-6, "sound pressure"),
    ("mpa", "MPa", 1e6, "pressure, stress"),
    ("gpa", "GPa", 1e9, "pressure, stress, modulus"),
    ("kg", "kg", 1.0, "mass"),
    ("g", "g", 1e-3, "mass"),
    ("kg_m3", "kg/m³", 1.0, "density"),
    ("kg_m", "kg·m", 1.0, "unbalance"),
    ("g_mm", "g·mm", 1e-6, "unbalance"),
    ("s", "s", 1.0, "time"),
    ("ms", "ms", 1e-3, "time"),
    ("hours", "h", 3600.0, "time (life)"),
    ("million_rev", "10⁶ rev", 1e6, "life in revolutions"),
    ("hz", "Hz", 1.0, "frequency"),
    ("per_s", "1/s", 1.0, "rate (items per second)"),
    ("per_hour", "1/h", 1.0 / 3600.0, "rate (events per hour)"),
    ("khz", "kHz", 1e3, "frequency"),
    ("rpm", "rpm", RPM, "speed (to rad/s)"),
    ("rad_s", "rad/s", 1.0, "angular speed"),
    ("m_s", "m/s", 1.0, "velocity"),
    ("um_s", "µm/s", 1e-6, "velocity"),
    ("mm_s", "mm/s", 1e-3, "velocity"),
    ("m_s2", "m/s²", 1.0, "acceleration"),
    ("w", "W", 1.0, "power"),
    ("mm2_s", "mm²/s", 1e-6, "kinematic viscosity"),
    ("c", "°C", 1.0, "temperature (not converted: degrees Celsius)"),
    ("db", "dB", 1.0, "level (sound pressure re 20 µPa)"),
    ("pct", "%", 0.01, "percentage"),
    ("percent", "%", 0.01, "percentage"),
    ("si", "SI", 1.0, "a matrix in SI units, its rows' units under <key>_units"),
)

#: The units a ``--json`` key may end in (docs/json.md, "One unit per quantity"): suffix ->
#: what it is used for. The others of :data:`UNITS` (``m``, ``n_m``, ``n_per_m``, ``pa``,
#: ``kn``, ...) are for command-line options and SI matrices only; a JSON key in one of them
#: must be in :data:`JSON_EXCEPTIONS`.
JSON_SUFFIXES: dict[str, str] = {
    "hz": "frequencies",
    "rpm": "speeds of rotation",
    "n": "loads and forces",
    "mm": "dimensions",
    "um": "clearances, displacements, film thickness, form errors",
    "mm2": "cross-section areas",
    "mm4": "second moments of area",
    "deg": "angles",
    "mrad": "small tilts and misalignments",
    "n_per_um": "stiffness",
    "n_per_um1_5": "Hertz load-deflection constants (Q [N] = K delta[µm]^1.5)",
    "n_s_per_m": "damping",
    "n_mm": "moments and torques",
    "gpa": "contact pressures, stresses and moduli",
    "upa": "sound pressures (levels in dB re 20 µPa)",
    "db": "sound pressure levels re 20 µPa",
    "s": "times",
    "hours": "lives in hours",
    "million_rev": "lives in revolutions",
    "per_s": "rates",
    "per_hour": "rates of events per hour of monitoring (false alarms)",
    "g": "masses of balls and rings",
    "kg": "masses of the machine in a simulation (rotor, housing) and of a ring",
    "kg_m3": "densities",
    "g_mm": "unbalance (ISO 21940)",
    "m_s": "sliding and sound speeds",
    "mm_s": "vibration velocity of a machine (ISO 20816)",
    "um_s": "vibration velocity of a bearing (ISO 15242 bands)",
    "m_s2": "accelerations",
    "mm2_s": "kinematic viscosity",
    "c": "temperatures",
    "w": "power",
    "percent": "percentages",
    "si": "matrices in mixed SI units, with their rows' units beside them",
}
#: JSON keys allowed a unit outside :data:`JSON_SUFFIXES`: key -> the reason.
JSON_EXCEPTIONS: dict[str, str] = {}

#: JSON keys that carry no unit: names, labels, counts, ratios, flags, and containers whose
#: members carry their own. key -> what it holds.
DIMENSIONLESS: dict[str, str] = {
    # what was asked and where values came from
    "designation": "the designation as typed (or null with explicit geometry)",
    "name": "the bearing's catalogue name or label",
    "system": "gost or iso: how the designation was read",
    "bearing": "the bearing's name",
    "bearing_type": "radial_ball, angular_contact_ball, ... (designation glossary)",
    "geometry_source": "catalog, estimated or user: where the geometry came from",
    "source": "where a value comes from (document, table)",
    "sources": "map: value -> where it came from",
    "geometry_sources": "map: geometry value -> {kind, reference}",
    "kind": "catalog, estimated, user or default",
    "reference": "document a value comes from",
    "notes": "remarks on a reading",
    "method": "the method chosen (e.g. exact, hamrock_brewe; iso281)",
    "model": "the model chosen (rigid, slip; constant, skf)",
    "warnings": "list of warnings in the user's terms",
    "reason": "why a verdict was reached",
    "output": "the file written",
    "file": "the file read",
    "seed": "seed of the random inputs",
    # designation parts
    "decoded": "the designation read part by part",
    "alternatives": "other readings of the same text",
    "text": "the text of a part as written",
    "parts": "list of designation parts with their meaning",
    "meaning": "what a designation part means",
    "description": "one-line description (of a reading, of a rule)",
    "prefixes": "designation prefixes",
    "suffixes": "designation suffixes",
    "series": "ISO family, e.g. 62",
    "dimension_series": "ISO dimension series, e.g. 02",
    "diameter_series": "ISO diameter series digit",
    "width_series": "ISO width series digit",
    "diameter_series_name": "its name",
    "width_series_name": "its name",
    "bore_code": "bore code digits",
    "precision_class": "tolerance class",
    "category": "GOST category (A, B, C)",
    "closures": "shields and seals",
    "design_variant": "GOST design-variant digits",
    "design_variant_meaning": "their meaning",
    "gost_equivalent": "the GOST designation of the same bearing",
    "iso_equivalent": "the ISO designation of the same bearing",
    # geometry numbers without units
    "ball_count": "number of balls Z",
    "inner_groove_factor": "groove curvature factor f_i = r_i / D_w",
    "outer_groove_factor": "groove curvature factor f_o = r_o / D_w",
    "ring_material": "material of the rings",
    "ball_material": "material of the balls",
    "frequency_factors": "the defect-frequency orders",
    "rolling_element": "ball or roller: what rolls between the rings",
    "roller_count": "number of rollers Z (per row)",
    "design": "the roller bearing's design: NU, N, NJ, NUP, NN, or the tapered series",
    "arrangement": "single, back_to_back, face_to_face or tandem (roller rows)",
    "roller_profile": "the roller's profile: flat, logarithmic, crowned or user",
    # kinematics
    "kinematic": "kinematic frequencies (their keys carry units or are orders)",
    "ftf_order": "cage frequency per shaft revolution",
    "bpfo_order": "ball-pass frequency of the outer race per shaft revolution",
    "bpfi_order": "ball-pass frequency of the inner race per shaft revolution",
    "bsf_order": "ball spin frequency per shaft revolution",
    "ball_defect_order": "ball-defect rate (2 BSF) per shaft revolution",
    "roller_defect_order": "roller-defect rate (2 x roller spin) per shaft revolution",
    "outer_rotating": "true when the outer ring turns",
    "cage_speed_ratio": "cage speed over its pure-rolling value",
    "spin_speed_ratio": "ball spin speed over its pure-rolling value",
    # contact and load distribution
    "inner": "the inner-race contact (or the inner race's values)",
    "outer": "the outer-race contact (or the outer race's values)",
    "ellipticity": "contact ellipse ratio a/b",
    "balls": "per-ball results",
    "ball": "ball index, or the ball fault family",
    "rollers": "per-roller results",
    "roller": "roller index",
    "row": "row index of a rolling element (0 first)",
    "loaded_rollers": "number of rollers in contact",
    "slices": "number of slices along each roller (ISO/TS 16281)",
    "end_load_ratio": "load of a roller's end slices over its mean slice load",
    "edge_pressure_ratio": "pressure at the end of a roller's contact over the mid-length's",
    "life_exponent": "exponent p of L = (C / P)^p: 3 balls, 10/3 rollers",
    "edge_stress": "true when ISO/TS 16281's edge-stress factors weight the slice loads",
    "contact_points": "number of ball-race contacts (2, 3 or 4)",
    "truncated": "true when the contact ellipse runs over the shoulder",
    "outer_raceway_control": "true when the ball is under outer-raceway control",
    "race_control": "outer, inner or hybrid raceway control",
    "stiffness_matrix_order": "the order of the degrees of freedom of the matrix",
    "stiffness_matrix_units": "the SI unit of each row of the stiffness matrix",
    "orbit": "the inner-ring centre orbit (its keys carry units)",
    "orbit_kind": "time (form errors, over a cage revolution) or ball_set (over a ball spacing)",
    "cases": "list of cases (or their count)",
    "rows": "list of table rows, or a bearing's number of rows of rolling elements",
    "solved": "number of cases solved",
    "status": "ok or the error text; a defect's width: sized, too small to size or not sized",
    # rings
    "modes": "list of ring modes",
    "m": "mode number (waves round the ring)",
    "split": "true when the mode splits in two (2m a multiple of Z)",
    "epsilon": "roots of seed 000 eq. (3.5)",
    "p": "frequency parameter of seed 000",
    "ball_mass_ratio": "kappa = Z m_b / m_ring",
    "contact_stiffness_ratio": "K1 / K2 of seed 000",
    "approx_ball_position": "nodes or antinodes",
    "refined_ball_position": "nodes or antinodes",
    # signals and diagnosis
    "channel": "the channel analysed",
    "spectrum_channel": "the channel of the plain spectrum",
    "peaks": "labelled spectrum lines",
    "spectrum_peaks": "labelled lines of the plain spectrum",
    "amplitude": "line amplitude: of a plain spectrum in the channel's unit (a pressure "
    "spectrum's in Pa), of a squared-envelope spectrum in the square of the channel's unit",
    "matched": "the frequency family a line was matched to (or null)",
    "harmonic": "harmonic number of the matched family",
    "deviation": "relative deviation of a line from its kinematic frequency",
    "sideband_of": "the family a sideband belongs to",
    "sideband_harmonic": "harmonic the sideband sits beside",
    "sideband_order": "signed order of the sideband",
    "modulation": "the modulating family of a sideband",
    "likely_fault": "the fault family found (null: no fault detected)",
    "faults": "every fault family found",
    "scores": "map: fault family -> score",
    "primary_fault": "the most significant fault family (or null)",
    "families": "map: fault family -> its series test",
    "tolerances": "map: fault family -> tolerance window (fractions below, above)",
    "false_alarm_probability": "largest chance of a fault called on a record without one",
    "test_level": "level of each test: the false-alarm probability over the tests "
    "(diagnosis: families x methods; trend: indicators x channels)",
    "threshold_significance": "-log10 of the test level",
    "significance": "-log10 of a p-value",
    "z": "line level over the local noise floor of the envelope spectrum",
    "p_value": "chance that noise alone shows what was found",
    "support_significance": "significance of a family's series without its strongest line",
    "harmonic_significance": "significance of a family's harmonics (with their sidebands up "
    "to the gate order) alone",
    "slip": "f'/f_kin - 1: relative deviation of the best fundamental from the kinematic frequency",
    "tolerance_below": "largest relative deviation searched below the kinematic frequency",
    "tolerance_above": "largest relative deviation searched above the kinematic frequency",
    "below": "largest relative deviation below the kinematic frequency (a fraction)",
    "above": "largest relative deviation above the kinematic frequency (a fraction)",
    "lines": "the lines of a family's series that the test counted",
    "n": "harmonic number of a line of a family's series",
    "k": "sideband order of a line (0: the harmonic itself)",
    "methods": "the diagnosis methods run (raw, cpw, drs-sk, ies)",
    "method_shown": "the method whose spectrum is shown",
    "cage_modulation_of": "faults whose FTF lines were counted as cage modulation",
    "band_kurtosis": "spectral kurtosis of the demodulation band",
    "harmonics": "highest harmonic order tested",
    "speed": "the speed given, found in the signal and used",
    "harmonics_found": "shaft harmonics found",
    "sub_multiple": "k when the shaft series is also one at 1/k of the speed (or null)",
    "confirmed": "true when the signal's shaft series confirms the speed (null: not checked)",
    "defects": "the simulated defects",
    "location": "outer, inner or ball",
    "stats": "integrator statistics (their keys carry units or are counts)",
    "steps": "accepted steps",
    "channels": "the channels of a record",
    "diagnosis": "the envelope diagnosis",
    "spectrum": "the plain spectrum and its labelled lines",
    "parameters": "a model's parameters (their keys carry units)",
    "rejected_steps": "rejected steps",
    "settle_turns": "cage revolutions of settling",
    "halves": "the slip model's speed ratios over each half of the record",
    "difference": "largest difference of the halves' ratios",
    "tolerance": "largest difference allowed",
    "agree": "true when the halves agree",
    "slip_parameters": "the slip model's parameters (SlipParameters)",
    "traction": "the traction model",
    "flow_index": "the lubricant's power-law flow index",
    "oil_fraction": "oil volume fraction of the oil-air mixture",
    "ball_drag_coefficient": "drag coefficient of a ball (seed 004 eq. 14)",
    "cage_drag_coefficient": "drag coefficient of the cage (seed 004 eq. 15)",
    "cage_friction": "ball-cage pocket friction coefficient",
    "spin_drag": "true when the balls' spin drag is included",
    "cage_mass_ratio": "cage mass over the balls' mass",
    "impact_forces": "true when ball-cage impacts are modelled",
    # imperfections and noise
    "imperfections": "form errors",
    "waviness": "waviness orders",
    "race": "inner, outer or ball",
    "order": "waviness order (waves round the ring)",
    "surfaces": "random 3-D surfaces",
    "ball_size_errors": "ball diameter errors",
    "points": "number of time points",
    "ring_model": "the sound model of the inner ring",
    "ball_model": "the sound model of a ball",
    "ball_source": "what drives a ball's sound",
    "velocity_bands_source": "where the bands come from",
    "velocity_bands_note": "how the bands were computed",
    "field_point_source": "given, or the rule that placed the default field point",
    # friction and life
    "friction_coefficient": "mu of seed 003's table",
    "friction_type": "the table's row",
    "equivalent_load_source": "how the equivalent load was found",
    "pitch_diameter_source": "where d_m came from",
    "seals": "the seal type",
    "a1": "reliability factor",
    "a_iso": "life modification factor",
    "kappa": "viscosity ratio nu / nu_1",
    "e_limit": "ISO 281 e (null where it does not apply: a cylindrical roller bearing)",
    "x_factor": "ISO 281 X",
    "y_factor": "ISO 281 Y",
    "f0": "ISO 76 f_0",
    "fc": "ISO 281 f_c",
    "gamma": "ISO 281 geometry term",
    "contamination_factor": "ISO 281 e_C",
    "contamination_source": "where e_C came from",
    "rating_kind": "basic, modified or reference",
    "static_safety_factor": "s0 = C0 / P0",
    "rating_factor_bm": "ISO 281 b_m (rating factor of the material)",
    "dynamic_rating_source": "given, or how C was computed",
    "static_rating_source": "given, or how C0 was computed",
    "fatigue_load_limit_source": "how Cu was computed (from C0)",
    "rotating_ring": "inner or outer: the ring that turns",
    "viscosity_source": "given, or the lubricant and temperature it was read at",
    "lubricant": "the lubricant's name",
    "lubricant_kind": "mineral, synthetic or transmission-fluid (SKF mu_EHL)",
    "lubrication": "grease, oil-air, oil-jet or low-oil-bath (SKF K_rs)",
    "lubrication_source": "given, or why this lubrication method",
    "k_rs": "SKF replenishment constant K_rs",
    "k_z": "SKF bearing-type constant K_Z",
    "inlet_shear_factor": "SKF phi_ish",
    "replenishment_factor": "SKF phi_rs",
    "sliding_weighting_factor": "SKF phi_bl",
    "sliding_friction_coefficient": "SKF mu_sl",
    "rolling_variable_skf": "SKF G_rr, in SKF's units (M_rr [N·mm] = G_rr (nu n)^0.6)",
    "sliding_variable_skf": "SKF G_sl, in SKF's units (M_sl [N·mm] = G_sl mu_sl)",
    "geometry_constants": "SKF geometry constants of the series (SKF's units)",
    "r1": "SKF R1",
    "r2": "SKF R2",
    "r3": "SKF R3",
    "s1": "SKF S1",
    "s2": "SKF S2",
    "s3": "SKF S3",
    "verified": "true when checked against a stored primary source",
    # validation and report
    "quantity": "what a published case checks",
    "unit": "the unit of published and computed",
    "published": "the published value (in unit)",
    "computed": "our value (in unit)",
    "verdict": "pass, fail or known failure (validate); no fault detected, a fault family "
    "or compound: a + b (analyze)",
    "passed": "true when the case passes (or count)",
    "known_failure": "the documented reason of a known failure",
    "tolerance_reason": "why the tolerance is what it is",
    "error": "error text (or null)",
    "summary": "counts of the verdicts",
    "total": "number of cases",
    "failed": "count",
    "errors": "count",
    "known_failures": "count",
    "unexpected_passes": "count",
    "ok": "true when every case passed or failed as documented",
    "sections": "the report's sections",
    "failed_sections": "sections whose analysis failed",
    "left_out_sections": "sections that do not apply to the bearing, each with why",
    # studies and data sets
    "analysis": "the analysis a study runs",
    "inputs": "input columns (with their units)",
    "outputs": "output columns (with their units)",
    "scheduler": "the dask scheduler used",
    "workers": "dask workers",
    "dashboard": "the dask dashboard address (or null)",
    "partitions": "Parquet partitions",
    "partitions_computed": "partitions computed this run",
    "partitions_reused": "partitions found done",
    "cases_computed": "cases computed this run",
    "failed_cases": "cases that failed (their error text is in the table)",
    "records": "records (a count, or per-record rows)",
    "records_computed": "records computed this run",
    "records_failed": "records that failed",
    "records_written": "records written",
    "open_with": "how to open the data set",
    # the diagnosis benchmark
    "folder": "the folder of recordings (labelled, for benchmark)",
    "columns": "the methods' columns",
    "confusion": "map: label -> verdict -> count",
    "recall": "map: label -> recall",
    "expected": "the fault family the label names (null: healthy)",
    "fault": "the label's fault (labels.csv)",
    "right": "true when the verdict is right",
    "wrong": "map: column -> records given a fault that is not the label's",
    "missed": "map: column -> faulty records called healthy",
    "outcome": "right, wrong (a fault not the label's), missed (no fault on a faulty "
    "record) or error",
    "smith_randall_2015": "Smith & Randall's diagnosability category of the record",
    # the width of a race defect (diagnosis.sizing)
    "defect_size": "the width of the verdict's first race fault (null without one)",
    "defect_sizes": "the width of every race fault found",
    "passages": "passages of the defect averaged",
    "sizing": "the widths read against the labels' (benchmark)",
    "labelled": "records whose label gives a defect width",
    "sized": "records sized (of those labelled)",
    "sized_without_label": "records sized whose label gives no width",
    "threshold": "the significance a family must reach (-log10 of the false-alarm "
    "probability, corrected)",
    "raw": "the verdict of the envelope of the raw signal",
    "cpw": "the verdict after cepstral pre-whitening",
    "drs-sk": "the verdict after discrete/random separation and a kurtogram band",
    "ies": "the verdict of the improved envelope spectrum (spectral coherence)",
    "all": "the verdict of the three methods together",
    # the trend of a series of recordings
    "layout": "how a trend's folder is laid out: pronostia or records",
    "channel_unit": "the channels' unit (g or m/s2), or null when not given",
    "start_time": "the first record's time as the files give it (time of day, or a UTC "
    "date and time), or null",
    "indicators": "map: channel -> its health indicators",
    "rms": "r.m.s. of a record about its mean, in the channel's unit",
    "peak": "largest excursion of a record from its mean, in the channel's unit",
    "crest_factor": "peak / rms",
    "kurtosis": "fourth moment over the squared variance (3 for Gaussian noise)",
    "spectral_kurtosis": "largest spectral kurtosis of the fast kurtogram",
    "zone": "ISO 20816 zone of the velocity: A, B, C or D",
    "above_limit": "the tests (indicator:channel) whose limit a record is above",
    "baseline": "the baseline: running-in records left out, its first and last times",
    "baseline_records": "records in the baseline",
    "running_in_records": "running-in records left out of the baseline",
    "rule": "the alarm rule and its false-alarm probabilities",
    "statistic": "what each test compares with its limit",
    "tail_model": "the model of the baseline's upper tail",
    "persistence": "records in the persistence window whose median is a test's level",
    "limit_excess": "how far a test's level may rise above the baseline median, in robust "
    "scales of the baseline (1.4826 median absolute deviations)",
    "measured_false_alarm": "the rule's false alarms measured on held-out healthy stretches "
    "of the series (or, named as such, of the learning runs)",
    "per_record": "measured false alarms per record monitored",
    "per_hour": "measured false alarms per hour of monitoring",
    "firings": "times the rule fired (a test's level rose above its limit) where counted",
    "measured_on": "where a measured rate was measured, in words",
    "calibration": "the excursion rates of healthy operation that set the limits",
    "excursion_threshold": "deviation above which healthy excursions are counted [robust scales]",
    "excursions": "healthy excursions above the threshold that were counted",
    "mean_excess": "mean excess of the excursions' maxima over the threshold [robust scales]",
    "documentation": "where the method is documented in the installed package",
    "short_crossings": "runs of records above a limit, before the alarm, that did not carry "
    "the level over it",
    "remaining_life": "the remaining useful life at the latest record, with its 80 % "
    "interval (or null)",
    "learned_from": "the runs to failure an estimate was learned from, in words",
    "basis": "survival (lives learned, given survival so far) or degradation (the trend "
    "seen since the alarm)",
    "tests": "the tests (indicator x channel), or how many",
    "false_alarm_per_record": "largest chance that the rule raises a false alarm at a "
    "given record: the rate per hour times the records' spacing over 3600 s (its model: "
    "independent records, exponential tail)",
    "false_alarm_per_run": "bound on the chance of a false alarm over the records monitored",
    "monitored_records": "records after the baseline, tested against it",
    "indicator": "a health indicator: rms, peak, crest_factor, kurtosis, spectral_kurtosis",
    "baseline_median": "median of the baseline, in the indicator's unit",
    "limit": "a test's limit, in the indicator's unit",
    "value": "the indicator's value, in its unit",
    "first_alarm_record": "record completing a test's first run above its limit (or null)",
    "alarm": "the alarm (null: none): its record, time and the test that raised it",
    "record": "a record's index in time order",
    "block_records": "consecutive records joined end to end for one diagnosis",
    "blocks": "diagnosis blocks",
    "after_alarm": "map: verdict -> diagnosis blocks after the alarm",
    "severity": "the ISO 20816 zones: machine group, boundaries, when each zone was reached",
    "machine": "the machine group of the ISO 20816 zones",
}

#: Maps: keys whose members are named by data, not by the contract (``scores`` is keyed by
#: fault family, ``sources`` by the value described), with the number of data-named levels
#: below the key (``confusion``: column -> label -> verdict -> count is 3). The names at those
#: levels are not checked; the keys inside the members, below them, keep the contract.
MAPS: dict[str, int] = {
    "sources": 1,
    "geometry_sources": 1,
    "scores": 1,
    "families": 1,
    "tolerances": 1,
    "confusion": 3,
    "recall": 2,
    "significance": 1,
    "indicators": 1,
    "after_alarm": 1,
}


def unit_of(key: str) -> Unit | None:
    """The unit a JSON key or flag ends in (longest suffix first), or None.

    >>> unit_of("stiffness_n_per_um").symbol
    'N/µm'
    >>> unit_of("ball_count") is None
    True
    """
    name = key.lstrip("-").replace("-", "_").lower()
    for suffix in sorted(UNITS, key=len, reverse=True):
        if name.endswith("_" + suffix):
            return UNITS[suffix]
    return None


def label(text: str, suffix: str) -> str:
    """A table header: ``text [symbol]`` of the unit with that suffix."""
    return f"{text} [{UNITS[suffix].symbol}]"


_CONTRACT_PROSE = """# The JSON contract

Every command takes `--json` and then prints one JSON object on stdout and nothing else
(warnings go into its `warnings` list; progress bars go to stderr and only on a terminal).
This page is the contract those objects keep; `tests/unit/test_json_contract.py` runs every
command and checks its output against it, and checks that this page lists every unit and
every dimensionless key that `bearinglab/units.py` knows. The page is generated from that
module: `python -m bearinglab.units > docs/json.md`.

## Rules

- **Every key carries its unit** as a suffix from the table below (`speed_rpm`,
  `radial_load_n`, `stiffness_n_per_um`), or is one of the dimensionless keys listed
  further down (names, counts, ratios, flags, labels). Suffixes are matched longest first:
  `_n_per_um` is a stiffness, `_n_m` a moment in newton metres and `_nm` nanometres.
- **One unit per quantity across commands.** Frequencies are in Hz (`_hz`), speeds in rpm,
  loads in N, lengths in mm (dimensions) or µm (clearances, displacements, film, form
  errors), stiffness in N/µm (Hertz constants in N/µm^1.5), moments and torques in N·mm,
  pressures and stresses in GPa, sound pressures in µPa and their levels in dB re 20 µPa,
  times in s. The units table says which suffixes a JSON key may end in (column "JSON");
  the others (`_m`, `_n_m`, `_n_per_m`, `_pa`, `_kn`, ...) are for command-line options
  only, and a JSON key in one of them is listed under "Exceptions" with its reason.
- **Members of a unit-suffixed container** carry that unit: `velocity_bands_um_s.low`.
  Members of a map (`geometry_sources`, `scores`, `sources`, `families`, `confusion`, ...)
  are named by data (a fault family, a channel, a label), but the keys inside a member keep
  the contract: `families.outer_race.tolerance_below`.
- A matrix in mixed SI units ends in `_si` and has a sibling `<key>_units` that gives the
  unit of each row (e.g. `stiffness_matrix_si`, `stiffness_matrix_units`).
- Numbers are finite: a command never prints NaN or infinity (it fails with one line instead);
  a value that does not apply is `null`.
- **Fault families** are spelled `outer_race`, `inner_race`, `ball` and `cage` everywhere
  (keys of `scores` and `families`, the members of `faults`, `primary_fault`); `likely_fault`
  is one of them, `"compound: a + b"` for several, or `null` for "no fault detected".
"""


def contract_markdown() -> str:
    """docs/json.md: the rules, the unit table and the dimensionless keys."""
    lines = [
        _CONTRACT_PROSE.rstrip(),
        "",
        "## Units",
        "",
        "| suffix | symbol | SI value of one unit | quantity | JSON |",
        "|---|---|---|---|---|",
    ]
    for u in sorted(UNITS.values(), key=lambda u: (u.quantity, u.suffix)):
        use = JSON_SUFFIXES.get(u.suffix, "no (options only)")
        lines.append(f"| `_{u.suffix}` | {u.symbol} | {u.factor:g} | {u.quantity} | {use} |")
    if JSON_EXCEPTIONS:
        lines += ["", "## Exceptions", "", "| key | why its unit is not the rule's |", "|---|---|"]
        lines += [f"| `{k}` | {JSON_EXCEPTIONS[k]} |" for k in sorted(JSON_EXCEPTIONS)]
    lines += ["", "## Dimensionless keys", "", "| key | what it holds |", "|---|---|"]
    lines += [f"| `{k}` | {DIMENSIONLESS[k]} |" for k in sorted(DIMENSIONLESS)]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    print(contract_markdown(), end="")
