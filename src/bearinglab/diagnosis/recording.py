"""analyze_file: the diagnosis of a recording on disk, the one call of ``bearinglab analyze``.

Reads the file (:func:`bearinglab.signal.read_signal`: .npz, .csv, .wav, .mat with CWRU
variables, MATLAB structs such as MFPT's ``bearing.gs``, v7.3), takes the speed from the
caller, from the file (CWRU ``XnnnRPM``, MFPT ``rate``) or from the signal ("auto"), and
runs :func:`~bearinglab.diagnosis.analyze_signal`.
"""

from __future__ import annotations

import math

from ..errors import InputError


def analyze_file(
    path,
    bearing,
    *,
    shaft_speed=None,
    speed_range=None,
    channel=None,
    sample_rate=None,
    record=None,
    **options,
):
    """Diagnose the recording ``path`` of ``bearing``.

    Parameters
    ----------
    path : str or Path
        The recording.
    bearing : BallBearing
        Its geometry.
    shaft_speed : float or "auto", optional
        Shaft speed [rad/s]; default the speed the file records; "auto": the speed the
        signal shows, in ``speed_range`` [rad/s] or +-5 % of the recorded speed.
    speed_range : (float, float), optional
        Speed search range [rad/s].
    channel : str, optional
        Channel or struct field path (``bearing.gs``, or just ``gs``).
    sample_rate : float, optional
        Sample rate [Hz] when the file does not store it, or to override it.
    record : str, optional
        The CWRU record of a .mat file holding several (``X099``); default the one named
        like the file.
    **options
        Passed to :func:`~bearinglab.diagnosis.analyze_signal` (methods, band, tolerances,
        false_alarm, supply_frequency, mesh_frequency, ...).

    Returns
    -------
    Diagnosis
        With ``speed["source"]`` "given", "file" or "signal".
    """
    from ..kinematics import defect_frequencies
    from ..signal import read_signal
    from .analysis import analyze_signal

    signal = read_signal(path, sample_rate=sample_rate, channel=channel, record=record)
    if channel is not None:
        channel = signal.names[0]  # as resolved: a struct field path from its last part
    recorded = signal.metadata.get("speed_rpm")
    recorded = (
        float(recorded) * math.pi / 30
        if isinstance(recorded, (int, float)) and not isinstance(recorded, bool) and recorded > 0
        else None
    )
    auto = isinstance(shaft_speed, str)
    nominal = shaft_speed if shaft_speed is not None and not auto else recorded
    if nominal is None and not (auto and speed_range is not None):
        raise InputError(
            "shaft_speed",
            shaft_speed,
            'a speed > 0 rad/s, or "auto" with a speed range (the file does not '
            "record the shaft speed)",
        )
    if nominal is not None:
        try:
            nominal = float(nominal)
        except (TypeError, ValueError):
            nominal = math.nan
        if not (math.isfinite(nominal) and nominal > 0):
            raise InputError("shaft_speed", shaft_speed, 'a speed > 0 rad/s or "auto"')
        frequencies = defect_frequencies(bearing, nominal)
    else:
        frequencies = bearing
    diagnosis = analyze_signal(
        signal,
        None,
        frequencies,
        channel=channel,
        shaft_speed="auto" if auto else None,
        speed_range=speed_range,
        **options,
    )
    if not auto and shaft_speed is None and diagnosis.speed["source"] == "given":
        diagnosis.speed["source"] = "file"
    return diagnosis
