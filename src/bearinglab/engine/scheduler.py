"""Where work runs: a dask scheduler's address, checked before any work.

``"serial"`` is this process, ``"local"`` a :class:`distributed.LocalCluster` started here,
``"tcp://HOST:PORT"`` (or the environment variable ``DASK_SCHEDULER_ADDRESS``) a running
scheduler. A tcp address is probed with a plain socket and dask's own handshake, so that an
address where nothing listens, a server that never answers and one that answers in another
protocol are refused within ``CONNECT_TIMEOUT`` seconds, with one sentence saying which.
"""

from __future__ import annotations

import os
import time

from ..errors import InputError

ENV_ADDRESS = "DASK_SCHEDULER_ADDRESS"
#: Seconds to wait for a scheduler before saying it is unreachable.
CONNECT_TIMEOUT = 5.0


def _check_address(address: str) -> str:
    scheme, sep, rest = address.partition("://")
    host, colon, port = rest.rpartition(":")
    if (
        not sep
        or scheme not in ("tcp", "tls", "ucx", "inproc", "ws", "wss")
        or not colon
        or not host
        or not port.isdigit()
    ):
        raise InputError(
            "scheduler", address, "a dask scheduler address tcp://HOST:PORT, or 'local' or 'serial'"
        )
    return address


#: Largest first message a dask scheduler sends (its handshake: a few hundred bytes).
_HANDSHAKE_BYTES = 1 << 20


def _unreachable(address: str, why: str) -> InputError:
    return InputError("scheduler", address, "the address of a running dask scheduler", why)


def _why(exc: BaseException, timeout: float) -> str:
    """Why connecting failed, in a few words."""
    if isinstance(exc, TimeoutError) or "Timed out" in str(exc):
        return f"no answer within {timeout:g} s"
    if isinstance(exc, ConnectionRefusedError):
        return "connection refused: nothing listens there"
    text = " ".join(str(exc).split())[:120]
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def _receive(sock, n: int, deadline: float) -> bytes:
    """``n`` bytes from ``sock`` before ``deadline`` (time.monotonic()); fewer when the
    peer closes the connection; TimeoutError when the time runs out."""
    data = b""
    while len(data) < n:
        left = deadline - time.monotonic()
        if left <= 0:
            raise TimeoutError
        sock.settimeout(left)
        chunk = sock.recv(min(n - len(data), 65536))
        if not chunk:
            break
        data += chunk
    return data


def _handshake() -> bytes:
    """The first message dask's client sends (``Comm.handshake_info``), framed as on TCP."""
    import pickle
    import struct
    import sys

    from distributed.protocol.core import dumps
    from distributed.protocol.utils import pack_frames

    info = {
        "compression": None,
        "python": tuple(sys.version_info)[:3],
        "pickle-protocol": pickle.HIGHEST_PROTOCOL,
    }
    body = pack_frames(dumps(info))
    return struct.pack("<Q", len(body)) + body


def _probe_tcp(address: str, timeout: float) -> None:
    """Connect to a tcp:// address, send dask's handshake and read the scheduler's, all
    within ``timeout`` seconds. A port where nothing listens, a server that never answers
    and one that answers in another protocol (HTTP, ...) are refused here; dask's own
    client would wait for ever on the second, and read the third's first bytes as a
    message length (and ask for exbibytes of memory)."""
    import socket
    import struct

    host, _, port = address.partition("://")[2].rpartition(":")
    host = host.strip("[]")
    message = _handshake()  # imports distributed's protocol first: not on the clock
    deadline = time.monotonic() + timeout
    try:
        sock = socket.create_connection((host, int(port)), timeout=timeout)
    except socket.gaierror:
        raise _unreachable(address, f"unknown host {host!r}") from None
    except OSError as exc:
        raise _unreachable(address, _why(exc, timeout)) from None
    with sock:
        try:
            sock.sendall(message)
            head = _receive(sock, 8, deadline)
            (size,) = struct.unpack("<Q", head) if len(head) == 8 else (0,)
            body = _receive(sock, size, deadline) if 8 <= size <= _HANDSHAKE_BYTES else b""
        except TimeoutError:
            raise _unreachable(
                address,
                f"it accepted the connection but sent no dask handshake within {timeout:g} s",
            ) from None
        except OSError as exc:
            raise _unreachable(address, _why(exc, timeout)) from None
    if not head:
        raise _unreachable(address, "it closed the connection without a dask handshake")
    try:
        from distributed.protocol.core import loads
        from distributed.protocol.utils import unpack_frames

        if len(body) != size:
            raise ValueError(size)
        handshake = loads(unpack_frames(body, partial=True)[0], deserialize=False)
        if not isinstance(handshake, dict):
            raise ValueError(handshake)
    except Exception:  # noqa: BLE001 - anything that is not dask's handshake
        shown = "".join(c if c.isprintable() else "." for c in head.decode("latin-1"))
        raise _unreachable(
            address, f"it answers in another protocol (its first bytes: {shown!r})"
        ) from None


def check_scheduler(address: str, timeout: float | None = None) -> str:
    """``address`` if a dask scheduler answers there within ``timeout`` seconds, else an
    InputError saying what answered (a malformed address, nothing, something else);
    tcp:// addresses are probed with a plain socket first (:func:`_probe_tcp`).

    Parameters
    ----------
    address : str
        A dask scheduler address, ``tcp://HOST:PORT`` (also tls, ucx, inproc, ws, wss).
    timeout : float, optional
        Seconds to wait [s] (default :data:`CONNECT_TIMEOUT`).
    """
    address = _check_address(address)
    timeout = CONNECT_TIMEOUT if timeout is None else timeout
    if address.startswith("tcp://"):
        _probe_tcp(address, timeout)
    return address


def scheduler_of(scheduler: str | None) -> str:
    """The scheduler :func:`.runner.open_runner` uses: ``scheduler``, else
    $DASK_SCHEDULER_ADDRESS, else "local" (only a LocalCluster has a number of workers to
    choose).

    Parameters
    ----------
    scheduler : str, optional
        "serial", "local" or an address; None: the environment's, else "local".
    """
    if scheduler is None:
        return os.environ.get(ENV_ADDRESS) or "local"
    return scheduler
