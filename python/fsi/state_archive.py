#!/usr/bin/python3
"""state_archive.py: read and write the state archives of checkpoints (checkpoint/ArchiveFile.hpp
gives the format), to look into a checkpoint, or to make a damaged one for a test:

    state_archive.py FILE          list the entries of FILE (name, kind, shape, first values)

read(path) -> {name: value} (numpy arrays for arrays, float for numbers, int, str) and raises
ArchiveError naming the file for a file that is truncated, longer or corrupted; write(path,
entries) writes one (not atomically: for tests and tools, not for runs).
"""

import struct
import sys

import numpy

MAGIC = b"FSI-STATE-ARCHIVE\n"
VERSION = 1
BOM = 0x01020304
HEADER = struct.Struct("<IIQQ")
DOUBLES, INTEGER, TEXT = 1, 2, 3


class ArchiveError(Exception):
    pass


def fnv1a(data):
    h = 14695981039346656037
    for b in data:
        h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h


class Number(float):
    """A rank-0 array entry (put_double): a float that remembers it is one."""


def read(path):
    with open(path, "rb") as f:
        data = f.read()
    start = len(MAGIC) + HEADER.size
    if len(data) < start + 8 or not data.startswith(MAGIC):
        raise ArchiveError("%s: truncated or not a state archive" % path)
    version, bom, n_entries, body_length = HEADER.unpack_from(data, len(MAGIC))
    if version != VERSION or bom != BOM:
        raise ArchiveError("%s: format %d, byte-order mark %#x" % (path, version, bom))
    if len(data) != start + body_length + 8:
        raise ArchiveError("%s: %d bytes, the header says %d" % (path, len(data), start + body_length + 8))
    body = data[start:start + body_length]
    (checksum,) = struct.unpack_from("<Q", data, start + body_length)
    if fnv1a(body) != checksum:
        raise ArchiveError("%s: checksum mismatch" % path)
    entries, at = {}, 0
    for _ in range(n_entries):
        (n,) = struct.unpack_from("<I", body, at)
        name = body[at + 4:at + 4 + n].decode()
        kind = body[at + 4 + n]
        at += 5 + n
        if kind == DOUBLES:
            (rank,) = struct.unpack_from("<I", body, at)
            shape = struct.unpack_from("<%dQ" % rank, body, at + 4)
            at += 4 + 8 * rank
            count = int(numpy.prod(shape)) if rank else 1
            values = numpy.frombuffer(body, dtype="<f8", count=count, offset=at).copy()
            at += 8 * count
            entries[name] = values.reshape(shape) if rank else Number(values[0])
        elif kind == INTEGER:
            (entries[name],) = struct.unpack_from("<q", body, at)
            at += 8
        elif kind == TEXT:
            (n,) = struct.unpack_from("<Q", body, at)
            entries[name] = body[at + 8:at + 8 + n].decode()
            at += 8 + n
        else:
            raise ArchiveError("%s: entry %s of unknown kind %d" % (path, name, kind))
    return entries


def write(path, entries):
    body = b""
    for name in sorted(entries):
        value = entries[name]
        encoded = name.encode()
        body += struct.pack("<I", len(encoded)) + encoded
        if isinstance(value, str):
            body += struct.pack("<BQ", TEXT, len(value.encode())) + value.encode()
        elif isinstance(value, (int, numpy.integer)) and not isinstance(value, Number):
            body += struct.pack("<Bq", INTEGER, int(value))
        else:
            array = numpy.asarray(value, dtype="<f8")
            body += struct.pack("<BI", DOUBLES, array.ndim) + struct.pack("<%dQ" % array.ndim, *array.shape)
            body += array.tobytes()
    with open(path, "wb") as f:
        f.write(MAGIC + HEADER.pack(VERSION, BOM, len(entries), len(body)) + body + struct.pack("<Q", fnv1a(body)))


def main(argv):
    if len(argv) != 1:
        sys.exit(__doc__)
    for name, value in read(argv[0]).items():
        if isinstance(value, numpy.ndarray):
            print("%s: array %s, first %s" % (name, "x".join(map(str, value.shape)), value.ravel()[:3]))
        else:
            print("%s: %r" % (name, value))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
