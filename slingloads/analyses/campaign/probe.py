"""The first exchange with a Dask scheduler, bounded in time and memory before
``dask.distributed`` is given its address.

``distributed``'s TCP comm reads a message by allocating the size its 8-byte length prefix
announces, whatever it is: a server that is not a Dask scheduler (a wrong port, a hostile
host) can announce gigabytes and then stream them, and the reader fills them at the speed of
the network, past any time-out (the read goes on in the background after the caller has given
up). So the first exchange of a campaign with a scheduler is written here by hand, on a plain
socket, from the wire format of ``distributed.comm.tcp``:

* a message is an unsigned 64-bit length ``n`` (the machine's byte order, as ``distributed``
  writes it), then ``n`` bytes: the frame count, the frame lengths (64-bit each), then the
  frames; the first frame is the message in msgpack (``distributed.protocol.core.dumps``);
* on connecting, each side writes its handshake (a mapping: ``compression``, ``python``,
  ``pickle-protocol``) and reads the other's; then the client writes
  ``{"op": "identity", "reply": True}`` and a scheduler answers with a mapping whose ``type``
  is ``"Scheduler"``.

Bounds: every step (name resolution, connection, each write and read) within what is left of
``timeout`` seconds, the socket closed at once after; a message announced longer than
:data:`MAX_PROBE_MESSAGE` is refused before a byte of it is read, and what is read grows
with what arrives (never the announced size). Only ``tcp://`` (the default protocol) and
``tls://`` (the same framing inside TLS, with the client's Dask security settings) are spoken
here, and the only protocols a scheduler address may name
(:func:`slingloads.io.campaign.rows.address_rule` refuses ws, wss, ucx and inproc, whose
first exchange would go to ``distributed``'s own reader, bounded in time but not in memory).

Past this exchange the scheduler is trusted, as ``distributed`` trusts it (its messages may
hold pickled objects): a server that answers the identity request as a Dask scheduler is
one.
"""

from __future__ import annotations

import socket
import struct
import time

#: Longest message the first exchange accepts (a scheduler's identity lists its workers, about
#: 1 kB each: this allows tens of thousands). [bytes]
MAX_PROBE_MESSAGE = 32 * 2**20
#: Protocols whose first exchange is spoken here (module notes).
SPOKEN = ("tcp", "tls")
_CHUNK = 2**16


class NotAScheduler(Exception):
    """The server answered, but not as a Dask scheduler (the message says how)."""


def split_address(address, default_port=8786):
    """(protocol, host, port) of a scheduler address ``[protocol://]host[:port]``.

    Parameters
    ----------
    address : str
    default_port : int
        Dask's scheduler port, used when none is written. [-]

    Returns
    -------
    (str, str, int)
        Protocol, host and port. [-]
    """
    protocol, _, rest = address.rpartition("://")
    protocol = protocol or "tcp"
    if rest.startswith("["):  # [IPv6]:port
        host, _, tail = rest[1:].partition("]")
        port = tail[1:] if tail.startswith(":") else ""
    else:
        host, _, port = rest.rpartition(":") if ":" in rest else (rest, "", "")
    return protocol, host, int(port) if port else default_port


class _Deadline:
    """What is left of ``seconds`` from now, for each step."""

    def __init__(self, seconds):
        self.end = time.monotonic() + seconds

    def left(self):
        left = self.end - time.monotonic()
        if left <= 0:
            raise TimeoutError("no answer within the time-out")
        return left


def _send(sock, deadline, message):
    import msgpack

    frame = msgpack.dumps(message, use_bin_type=True)
    body = struct.pack("QQ", 1, len(frame)) + frame
    sock.settimeout(deadline.left())
    sock.sendall(struct.pack("Q", len(body)) + body)


def _receive(sock, deadline, n):
    """Exactly ``n`` bytes (``n`` already checked against the cap), as they arrive."""
    data = bytearray()
    while len(data) < n:
        sock.settimeout(deadline.left())
        chunk = sock.recv(min(_CHUNK, n - len(data)))
        if not chunk:
            raise NotAScheduler("the connection was closed in the middle of a message")
        data += chunk
    return bytes(data)


def _read(sock, deadline):
    """One message: its first frame decoded from msgpack (without unpickling anything)."""
    import msgpack

    (total,) = struct.unpack("Q", _receive(sock, deadline, 8))
    if total > MAX_PROBE_MESSAGE:
        raise NotAScheduler(f"it announced a message of {total:,} bytes (at most "
                            f"{MAX_PROBE_MESSAGE:,} are read from a server not yet known "
                            "to be a scheduler)")
    if total < 16:
        raise NotAScheduler(f"it announced a message of {total} bytes, too short for one")
    body = _receive(sock, deadline, total)
    (frames,) = struct.unpack_from("Q", body)
    if not 1 <= frames <= (total - 8) // 8:
        raise NotAScheduler(f"its message announces {frames:,} frames")
    lengths = struct.unpack_from(f"{frames}Q", body, 8)
    start = 8 * (1 + frames)
    if lengths[0] > total - start:
        raise NotAScheduler("its message's first frame is longer than the message")

    def refuse_objects(mapping):  # a scheduler's identity is plain data
        if "__Pickled__" in mapping or "__Serialized__" in mapping:
            return {"__object__": True}
        return mapping

    try:
        return msgpack.loads(body[start:start + lengths[0]], raw=False, strict_map_key=False,
                             use_list=False, object_hook=refuse_objects)
    except (ValueError, TypeError, msgpack.UnpackException) as err:
        raise NotAScheduler(f"its message is not msgpack ({type(err).__name__})") from None


def _tls_context():
    from distributed.security import Security

    return Security().get_connection_args("client").get("ssl_context")


def identity(address, timeout):
    """Connect to the scheduler at ``address`` (``tcp://`` or ``tls://``), exchange the
    handshake and ask who it is, within ``timeout`` seconds and
    :data:`MAX_PROBE_MESSAGE` bytes a message (module notes).

    Parameters
    ----------
    address : str
        ``[protocol://]host[:port]``, the protocol one of :data:`SPOKEN`.
    timeout : float
        Seconds for the whole exchange. [s]

    Returns
    -------
    object
        The decoded answer (a scheduler's is a mapping whose ``type`` is ``"Scheduler"``).

    Raises
    ------
    TimeoutError
        Nothing (or not all) within ``timeout``.
    OSError
        No connection.
    NotAScheduler
        An answer that is no Dask message, or too long for one.
    """
    import sys

    deadline = _Deadline(timeout)
    protocol, host, port = split_address(address)
    sock = socket.create_connection((host, port), timeout=deadline.left())
    try:
        if protocol == "tls":
            context = _tls_context()
            if context is None:
                raise OSError("no TLS settings for the client (distributed.comm.tls)")
            sock = context.wrap_socket(sock, server_hostname=host)
        _send(sock, deadline, {"compression": None, "python": tuple(sys.version_info)[:3],
                               "pickle-protocol": 5})
        handshake = _read(sock, deadline)
        if not isinstance(handshake, dict) or "pickle-protocol" not in handshake:
            raise NotAScheduler("its first message is not a Dask handshake")
        _send(sock, deadline, {"op": "identity", "reply": True})
        return _read(sock, deadline)
    finally:
        sock.close()
