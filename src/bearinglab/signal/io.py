"""Reading and writing vibration records (.npz, .csv, .wav, .mat).

The format follows the file name's suffix:

- ``.npz`` (NumPy archive): one array per channel, ``sample_rate_hz`` and ``metadata_json``
  (the metadata as a JSON string); everything round-trips.
- ``.csv``: a header row of channel names; a time column (``time_s``, ``time``, ``t``,
  ``time [s]``, ``time_ms``..., in any position) gives the sample rate (n - 1 intervals
  over the time span), otherwise it must be passed. Metadata are not stored. A file whose
  first row is all numbers has no header: its columns are ``column_1``, ``column_2``...,
  the first that rises at every row is the time in s, and both are said in
  ``metadata["reading_notes"]`` (which the diagnosis repeats as warnings).
- ``.wav`` (``scipy.io.wavfile``): written as 32-bit float, unscaled (WAV has no field for
  a scale factor); channels read back as ``channel_0``, ``channel_1``...; integer PCM
  files read as fractions of full scale in [-1, 1). The sample rate must be a whole
  number of Hz.
- ``.mat`` (``scipy.io.loadmat``/``savemat``, MATLAB 5): the layout of the Case Western
  Reserve University bearing data centre files (https://engineering.case.edu/
  bearingdatacenter): column vectors ``X097_DE_time``, ``X097_FE_time``,
  ``X097_BA_time`` (drive end, fan end, base accelerometers) and a 1x1 ``X097RPM``,
  read as channels ``DE``, ``FE``, ``BA`` and ``metadata["speed_rpm"]``. CWRU files
  do not store their sample rate (12 kHz or 48 kHz, given on the data centre's pages),
  so it must be passed unless the file has a ``sample_rate_hz`` variable, which
  :func:`write_signal` adds (with ``metadata_json``). Other .mat files: every numeric
  vector variable is a channel, and every numeric vector field of a MATLAB struct a
  channel named by its field path: the MFPT files' struct ``bearing`` gives channel
  ``bearing.gs`` (``gs`` selects it too), its scalar ``sr`` the sample rate and ``rate``
  (the shaft rate, Hz) ``metadata["speed_rpm"]``; fields that are not numeric vectors
  are listed in ``metadata["non_numeric_fields"]`` and refused as channels by name.
  MATLAB v7.3 files are HDF5: read with h5py when it is installed (an InputError
  says how to install it otherwise).

Writes are atomic (:func:`bearinglab.files.write_atomically`); a file that cannot be read
gives an :class:`~bearinglab.errors.InputError` naming it.
"""

from __future__ import annotations

import csv
import io
import json
import math
import re
import struct
import zipfile
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..files import write_atomically
from .record import Signal, json_default

#: File name suffixes understood, by format.
SUFFIXES = (".npz", ".csv", ".wav", ".mat")
#: Variable names in .npz and .mat files that are not channels.
RESERVED = ("sample_rate_hz", "metadata_json")
_CWRU_CHANNEL = re.compile(r"^X(\d+)_(\w+)_time$")
_CWRU_RPM = re.compile(r"^X(\d+)RPM$")
_MAT_NAME = re.compile(r"^\w+$", re.ASCII)
#: CSV headers of a time column: time_s, time, t, time [s], time (ms), Time_ms...
_TIME = re.compile(r"^\s*(t|time)(\s*[\[(]\s*(s|ms)\s*[\])]|_(s|ms))?\s*$", re.IGNORECASE)
_MAT_NAME_MAX = 63  # MATLAB's namelengthmax


def _corrupt() -> tuple:
    """What corrupt or foreign files make NumPy, zipfile, csv and scipy.io raise (a
    truncated WAV only warns, unless warnings are errors). A function, so that scipy.io is
    imported only when a file fails (it costs ~0.2 s at start-up)."""
    import scipy.io
    import scipy.io.wavfile

    return (
        OSError,
        ValueError,
        TypeError,
        KeyError,
        IndexError,
        EOFError,
        StopIteration,
        NotImplementedError,
        zipfile.BadZipFile,
        struct.error,
        csv.Error,
        scipy.io.matlab.MatReadError,
        scipy.io.wavfile.WavFileWarning,
    )


def _suffix(path: Path) -> str:
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise InputError("path", str(path), f"a file name ending in one of {list(SUFFIXES)}")
    return suffix


def read_signal(path, sample_rate=None, channel=None, record=None) -> Signal:
    """Read a vibration record; the format follows the suffix (see the module docstring).

    Parameters
    ----------
    path : str or Path
        A ``.npz``, ``.csv``, ``.wav`` or ``.mat`` file.
    sample_rate : float, optional
        Sample rate [Hz]. When given it is used in place of what the file says (the time
        column of a CSV, the WAV header, ``sample_rate_hz``); required for CWRU .mat files.
    channel : str or sequence of str, optional
        Keep only these channels (in this order); default all.
    record : str or int, optional
        The CWRU record of a .mat file holding several (``X099``, ``099`` or 99); default
        the one named like the file, or the only one.

    Returns
    -------
    Signal
        ``metadata["source"]`` is the file name unless the file says otherwise; CWRU
        files add ``speed_rpm`` (when the file has an RPM variable) and ``cwru_record``.

    Raises
    ------
    InputError
        Unknown suffix, missing or unreadable file, no sample rate, unknown channel.
    """
    path = Path(path)
    suffix = _suffix(path)
    if sample_rate is not None:
        if isinstance(sample_rate, bool):
            raise InputError("sample_rate", sample_rate, "a finite number > 0 Hz")
        try:
            sample_rate = float(sample_rate)
        except (TypeError, ValueError):
            raise InputError("sample_rate", sample_rate, "a number > 0 Hz") from None
        if not math.isfinite(sample_rate) or sample_rate <= 0:
            raise InputError("sample_rate", sample_rate, "a finite number > 0 Hz")
    if not path.is_file():
        raise InputError("path", str(path), "an existing file")
    if record is not None and suffix != ".mat":
        raise InputError("record", record, "None: records are chosen in CWRU .mat files only")
    try:
        reader = _READERS[suffix]
        channels, file_rate, metadata = (
            reader(path, sample_rate, record) if suffix == ".mat" else reader(path, sample_rate)
        )
    except InputError:
        raise
    except _corrupt() as exc:
        raise InputError(
            "path", str(path), f"a readable {suffix} file", hint=f"{type(exc).__name__}: {exc}"
        ) from None
    fs = sample_rate if sample_rate is not None else file_rate
    if sample_rate is not None and file_rate is not None and sample_rate != file_rate:
        metadata["stored_sample_rate_hz"] = float(file_rate)  # overridden: say so later
    if fs is None:
        raise InputError(
            "sample_rate_hz",
            None,
            "a sample_rate argument in Hz (the file does not store it; CWRU "
            "records are 12000 or 48000 Hz)",
        )
    metadata.setdefault("source", path.name)
    if channel is not None:
        wanted = [channel] if isinstance(channel, str) else list(channel)
        resolved = [_channel_name(str(c), channels, metadata) for c in wanted]
        channels = {c: channels[c] for c in resolved}
        channel = resolved
    signal = Signal(channels, fs, metadata)
    return signal if channel is None else signal.select(channel)


def _channel_name(name: str, channels: dict, metadata: dict) -> str:
    """A channel or struct field path, or a unique last part of one (``gs`` for
    ``bearing.gs``); a field that is not a numeric vector is refused by name."""
    if name in channels:
        return name
    other = metadata.get("non_numeric_fields", {})
    if name in other:
        raise InputError(
            "channel", name, "a numeric vector field", hint=f"{name} holds {other[name]}"
        )
    ends = [c for c in channels if c.rsplit(".", 1)[-1] == name]
    if len(ends) == 1:
        return ends[0]
    raise InputError("channel", name, f"one of {list(channels)}")


def write_signal(path, signal: Signal) -> Path:
    """Write ``signal`` atomically; the format follows the suffix (see the module docstring).

    Parameters
    ----------
    path : str or Path
        Destination ``.npz``, ``.csv``, ``.wav`` or ``.mat`` file in an existing directory;
        replaced if it exists.
    signal : Signal
        The record.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    InputError
        Unknown suffix, missing directory, or a record the format cannot hold (e.g. a
        WAV sample rate that is not a whole number of Hz).
    """
    path = Path(path)
    suffix = _suffix(path)
    if not isinstance(signal, Signal):
        raise InputError("signal", type(signal).__name__, "a bearinglab.signal.Signal")
    if not path.parent.is_dir():
        raise InputError("path", str(path), "a file in an existing directory")
    writer = _WRITERS[suffix](signal)  # checks what the format can hold before writing
    return write_atomically(path, writer)


# ---------------------------------------------------------------- .npz


def _scalar(value, name: str) -> float:
    a = np.asarray(value)
    if a.size != 1 or a.dtype.kind not in "iuf":
        raise InputError(name, f"array of shape {a.shape}", "one number")
    return float(a.ravel()[0])


def _metadata(text, name: str = "metadata_json") -> dict:
    meta = json.loads(str(np.asarray(text).ravel()[0]))
    if not isinstance(meta, dict):
        raise InputError(name, meta, "a JSON object")
    return meta


def _read_npz(path: Path, sample_rate):
    with open(path, "rb") as fh:  # our handle: np.load leaks its own on a corrupt archive
        data = np.load(fh, allow_pickle=False)
        if not isinstance(data, np.lib.npyio.NpzFile):
            raise InputError("path", str(path), "an .npz archive (this is a single array)")
        with data:
            rate = (
                _scalar(data["sample_rate_hz"], "sample_rate_hz")
                if "sample_rate_hz" in data.files
                else None
            )
            meta = _metadata(data["metadata_json"]) if "metadata_json" in data.files else {}
            channels = {k: np.asarray(data[k]).squeeze() for k in data.files if k not in RESERVED}
    return channels, rate, meta


def _write_npz(signal: Signal):
    # np.savez's own parameters cannot be array names
    clash = set(signal.names) & {*RESERVED, "file", "allow_pickle"}
    if clash:
        raise InputError(
            "channels",
            sorted(clash),
            "channel names other than sample_rate_hz, metadata_json, file and allow_pickle in .npz",
        )
    arrays = dict(signal.channels)
    arrays["sample_rate_hz"] = np.array(signal.sample_rate)
    arrays["metadata_json"] = np.array(json.dumps(signal.metadata, default=json_default))
    return lambda tmp: np.savez(tmp, **arrays)


# ---------------------------------------------------------------- .csv


def _number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _read_csv(path: Path, sample_rate):
    with open(path, newline="", encoding="utf-8") as fh:
        first = fh.readline()
        header = [h.strip() for h in next(csv.reader([first]), [])]
        rows = fh.read()
    notes = []
    if header and all(_number(h) for h in header):
        # no header row: the first row is data; a column that rises at every sample is the
        # time (a headerless file read with its first row as names was analysed on it)
        rows, header = first + rows, [f"column_{i + 1}" for i in range(len(header))]
        notes.append(
            f"{path.name} has no header row (its first row is numbers): its columns are "
            f"read as {', '.join(header)}"
        )
    if not header or not rows.strip():  # (loadtxt only warns about no data)
        raise InputError("path", str(path), "a CSV file with a header row and data rows")
    data = np.loadtxt(io.StringIO(rows), delimiter=",", ndmin=2)
    if data.shape[1] != len(header):
        raise InputError(
            "path",
            str(path),
            f"{len(header)} columns as in the header",
            hint=f"the data have {data.shape[1]}",
        )
    rate = None
    column = next((i for i, h in enumerate(header) if _TIME.match(h)), None)
    if column is None and notes and data.shape[0] > 1:
        rising = [i for i in range(data.shape[1]) if np.all(np.diff(data[:, i]) > 0)]
        if rising:
            column = rising[0]
            notes.append(f"{header[column]} rises at every row: it is read as the time in s")
    if column is not None:
        time = data[:, column]
        data = np.delete(data, column, axis=1)
        scale = 1e-3 if "ms" in header[column].lower() and not notes else 1.0
        header = header[:column] + header[column + 1 :]
        if sample_rate is None:
            rate = _rate_from_time(time * scale)
    elif sample_rate is None:
        raise InputError(
            "sample_rate",
            None,
            "a sample rate in Hz (the CSV file has no time column: time_s, time, t or time [s])",
        )
    if not header:
        raise InputError("path", str(path), "a CSV file with at least one channel column")
    metadata = {"reading_notes": notes} if notes else {}
    return {name: data[:, i] for i, name in enumerate(header)}, rate, metadata


def _rate_from_time(time: np.ndarray) -> float:
    """Sample rate (n - 1)/(t_last - t_first) [Hz] of uniformly spaced times [s]."""
    if time.size < 2 or np.any(np.diff(time) <= 0):
        raise InputError("time_s", "not increasing", "strictly increasing times in s")
    dt = (time[-1] - time[0]) / (time.size - 1)
    # rounding in the file shifts times by a fraction of dt; a lost sample shifts by dt
    gap = np.max(np.abs(time - (time[0] + dt * np.arange(time.size))))
    if gap > 0.5 * dt:
        raise InputError(
            "time_s",
            f"a deviation of {gap:g} s from uniform spacing",
            f"uniformly spaced times (every {dt:g} s)",
        )
    return 1.0 / dt


def _write_csv(signal: Signal):
    if "time_s" in signal.names:
        raise InputError("channels", "time_s", "channel names other than time_s in .csv")
    table = np.column_stack([signal.time, *signal.channels.values()])

    def write(tmp: str) -> None:
        with open(tmp, "w", newline="", encoding="utf-8") as fh:
            csv.writer(fh).writerow(["time_s", *signal.names])
            np.savetxt(fh, table, delimiter=",", fmt="%.17g")  # 17 digits: exact float64

    return write


# ---------------------------------------------------------------- .wav


def _read_wav(path: Path, sample_rate):
    import scipy.io.wavfile

    rate, data = scipy.io.wavfile.read(path)
    data = data.reshape(len(data), -1)
    if data.dtype.kind == "u":  # 8-bit PCM is unsigned, centred on 128
        data = (data.astype(float) - 128.0) / 128.0
    elif data.dtype.kind == "i":
        data = data.astype(float) / float(2 ** (8 * data.dtype.itemsize - 1))
    else:
        data = data.astype(float)
    return {f"channel_{i}": data[:, i] for i in range(data.shape[1])}, float(rate), {}


def _write_wav(signal: Signal):
    import scipy.io.wavfile

    fs = signal.sample_rate
    if fs != round(fs) or fs > 2**32 - 1:
        raise InputError("sample_rate", fs, "a whole number of Hz below 2**32 for .wav")
    data = np.column_stack(list(signal.channels.values()))
    if np.max(np.abs(data)) > np.finfo(np.float32).max:
        raise InputError(
            "channels",
            "samples beyond the float32 range",
            "samples within +-3.4e38 for .wav (32-bit float)",
        )
    data = data.astype(np.float32)
    if data.shape[1] == 1:
        data = data[:, 0]
    return lambda tmp: scipy.io.wavfile.write(tmp, int(fs), data)


# ---------------------------------------------------------------- .mat


#: Scalar variables or struct fields read as the sample rate [Hz] (MFPT: ``sr``).
RATE_NAMES = ("sr", "fs", "sample_rate", "samplerate", "sampling_rate")
#: Scalar fields read as the shaft rate [Hz] (MFPT's ``rate``) or speed [rpm].
SHAFT_HZ_NAMES = ("rate",)
RPM_NAMES = ("rpm", "speed_rpm")


def _walk_struct(name: str, value, channels: dict, scalars: dict, other: dict) -> None:
    """Flatten MATLAB structs (``scipy.io.loadmat`` structured arrays) into field paths
    ``a.b.c``: numeric vectors to ``channels``, numeric scalars to ``scalars``, anything
    else (text, cells, matrices) to ``other`` (path -> what it holds)."""
    a = np.asarray(value)
    if a.dtype.names:  # a struct (1x1 for MFPT's ``bearing``)
        if a.size != 1:
            other[name] = f"a {a.shape} struct array"
            return
        item = a.ravel()[0]
        for field in a.dtype.names:
            _walk_struct(f"{name}.{field}", item[field], channels, scalars, other)
        return
    if a.dtype == object and a.size == 1:  # loadmat wraps struct fields in 1x1 objects
        _walk_struct(name, a.ravel()[0], channels, scalars, other)
        return
    if a.dtype.kind in "iuf":
        squeezed = a.squeeze()
        if squeezed.ndim == 0 or squeezed.size == 1:
            scalars[name] = float(squeezed.ravel()[0]) if squeezed.size else math.nan
        elif squeezed.ndim == 1:
            channels[name] = squeezed.astype(float)
        else:
            other[name] = f"a {a.shape} matrix"
        return
    other[name] = "text" if a.dtype.kind in "US" else f"{a.dtype} data"


def _record_number(record) -> int | None:
    """The number of a CWRU record given as X099, 099, 99 or X099_DE_time (None: not one)."""
    match = re.fullmatch(r"\s*X?(\d+)(_\w+)?\s*", str(record), flags=re.IGNORECASE)
    return int(match[1]) if match else None


def _read_mat(path: Path, sample_rate, record=None):
    import scipy.io

    try:
        loaded = scipy.io.loadmat(path)
    except (NotImplementedError, ValueError):  # MATLAB v7.3 files are HDF5
        if not _is_hdf5(path):
            raise
        loaded = None
    if loaded is None:
        variables, nested, other = _read_mat73(path)
    else:
        variables = {k: v for k, v in loaded.items() if not k.startswith("__")}
        nested, other = {}, {}
    rate = (
        _scalar(variables["sample_rate_hz"], "sample_rate_hz")
        if "sample_rate_hz" in variables
        else None
    )
    meta = _metadata(variables["metadata_json"]) if "metadata_json" in variables else {}
    records: dict[str, dict[str, np.ndarray]] = {}
    for key, value in variables.items():
        match = _CWRU_CHANNEL.match(key)
        if match:
            records.setdefault(match[1], {})[match[2]] = np.asarray(value).squeeze()
    if records:
        # some CWRU files hold two records; the one named like the file is the file's own
        names = [f"X{r}" for r in records]
        if record is not None:
            wanted = _record_number(record)
            number = next((r for r in records if int(r) == wanted), None)
            if number is None:
                raise InputError("record", record, f"one of {names} (the records of {path.name})")
        else:
            stem = re.sub(r"\D", "", path.stem)
            number = next((r for r in records if stem and int(r) == int(stem)), None)
            if number is None and len(records) > 1:
                raise InputError(
                    "record",
                    None,
                    f"one of {names}: {path.name} holds several records, none named like the file",
                )
            number = number or next(iter(records))
        channels = records[number]
        meta["cwru_record"] = f"X{number}"
        rpm = next(
            (v for k, v in variables.items() if (m := _CWRU_RPM.match(k)) and m[1] == number), None
        )
        if rpm is not None:
            meta["speed_rpm"] = _scalar(rpm, f"X{number}RPM")
        return channels, rate, meta
    if record is not None:
        raise InputError("record", record, f"None: {path.name} holds no CWRU records")
    channels, scalars = dict(nested), {}
    for key, value in variables.items():
        if key in RESERVED or _CWRU_RPM.match(key):
            continue
        _walk_struct(key, value, channels, scalars, other)
    for name, value in scalars.items():
        leaf = name.rsplit(".", 1)[-1].lower()
        if leaf in RATE_NAMES and rate is None and math.isfinite(value) and value > 0:
            rate = value
        elif leaf in SHAFT_HZ_NAMES and "." in name and math.isfinite(value):
            meta.setdefault("speed_rpm", 60.0 * value)
        elif leaf in RPM_NAMES and math.isfinite(value):
            meta.setdefault("speed_rpm", value)
    if other:
        meta["non_numeric_fields"] = dict(other)
    if not channels:
        raise InputError(
            "path",
            str(path),
            "a .mat file with numeric vector variables or struct fields",
            hint=f"found {sorted(other) or 'none'}",
        )
    return channels, rate, meta


def _is_hdf5(path: Path) -> bool:
    """Whether the file holds the HDF5 signature at 0 or after a user block (MATLAB v7.3
    files start with a 512-byte MATLAB header)."""
    with open(path, "rb") as fh:
        head = fh.read(2048 + 8)
    return any(head[o : o + 8] == b"\x89HDF\r\n\x1a\n" for o in (0, 512, 1024, 2048))


def _read_mat73(path: Path):
    """Variables of a MATLAB v7.3 (HDF5) file: (top-level numeric arrays, vectors inside
    groups as ``group.field`` paths, other entries). MATLAB stores arrays transposed;
    text (``MATLAB_class`` char) and references are not channels."""
    try:
        import h5py
    except ImportError:
        raise InputError(
            "path",
            str(path),
            "a MATLAB file before v7.3, or h5py installed "
            "to read v7.3 (HDF5) files: pip install h5py",
        ) from None
    top, nested, other = {}, {}, {}
    with h5py.File(path, "r") as f:

        def visit(name, obj):
            if not isinstance(obj, h5py.Dataset) or name.startswith("#"):
                return
            key = name.replace("/", ".")
            kind = obj.attrs.get("MATLAB_class", b"")
            kind = kind.decode() if isinstance(kind, bytes) else str(kind)
            if kind in ("char", "cell", "struct") or obj.dtype.kind not in "iuf":
                other[key] = kind or str(obj.dtype)
                return
            data = np.asarray(obj[()]).T
            if "." in key:
                squeezed = data.squeeze()
                if squeezed.ndim == 1:
                    nested[key] = squeezed.astype(float)
                elif squeezed.size == 1:
                    top[key] = squeezed.reshape(1, 1)
                else:
                    other[key] = f"a {data.shape} matrix"
            else:
                top[key] = data

        f.visititems(visit)
    return top, nested, other


def _write_mat(signal: Signal):
    import scipy.io

    record = str(signal.metadata.get("cwru_record", "X000"))
    if not re.fullmatch(r"X\d+", record):
        record = "X000"
    variables = {}
    for name, x in signal.channels.items():
        key = f"{record}_{name}_time"
        if not _MAT_NAME.match(name) or len(key) > _MAT_NAME_MAX:
            raise InputError(
                "channels",
                name,
                "channel names of letters, digits and _ "
                f"(variable {key!r} at most {_MAT_NAME_MAX} characters) for .mat",
            )
        variables[key] = x[:, np.newaxis]  # CWRU stores column vectors
    variables["sample_rate_hz"] = np.array([[signal.sample_rate]])
    speed = signal.metadata.get("speed_rpm")
    if speed is not None:
        try:
            variables[f"{record}RPM"] = np.array([[float(speed)]])
        except (TypeError, ValueError):
            raise InputError(
                "metadata", {"speed_rpm": speed}, "speed_rpm a number in rpm for .mat"
            ) from None
    variables["metadata_json"] = json.dumps(signal.metadata, default=json_default)
    return lambda tmp: scipy.io.savemat(tmp, variables)


_READERS = {".npz": _read_npz, ".csv": _read_csv, ".wav": _read_wav, ".mat": _read_mat}
_WRITERS = {".npz": _write_npz, ".csv": _write_csv, ".wav": _write_wav, ".mat": _write_mat}
