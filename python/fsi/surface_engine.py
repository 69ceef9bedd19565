"""The geometry engine of the post-processing: fsi-surface-query (apps/fsi-surface-query), which
answers with the solver's own code (geometry/: the STL reader, the triangle BVH of the rigid
surfaces' exact distances, the spatial hash of the self-contacts) over a pipe. One server per
Python process, started on first use (engine()) and ended at exit.

The executable is looked up in $FSI_BIN_DIR (set by ./fsi and by the tests), else in the
repository's build/bin. All lengths in m."""

import atexit
import os
import subprocess
import tempfile

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
NAME = "fsi-surface-query"


class EngineError(Exception):
    """A request the engine refused (its message), or an engine that is missing or ended."""


def executable():
    folder = os.environ.get("FSI_BIN_DIR") or os.path.join(ROOT, "build", "bin")
    path = os.path.join(folder, NAME)
    if not os.access(path, os.X_OK):
        raise EngineError("%s not found in %s (the geometry engine of the metrics: build it with ./fsi build, or set "
                          "FSI_BIN_DIR to the folder of the executables)" % (NAME, folder))
    return path


class SurfaceEngine:
    """A running fsi-surface-query and the triangle sets made in it."""

    def __init__(self, path=None):
        self.path = path or executable()
        self.errors = tempfile.TemporaryFile()
        self.process = subprocess.Popen([self.path], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        stderr=self.errors)

    def close(self):
        if self.process.poll() is None:
            try:
                self.process.stdin.write(b"quit\n")
                self.process.stdin.close()
            except OSError:
                pass
            self.process.wait()
        self.errors.close()

    # -- the pipe

    def _ask(self, line, *payload):
        try:
            self.process.stdin.write(line.encode() + b"\n")
            for values in payload:
                self.process.stdin.write(np.ascontiguousarray(values, dtype=np.float64).tobytes())
            self.process.stdin.flush()
        except OSError:
            self._ended()
        reply = self._line()
        if reply.startswith("error "):
            raise EngineError(reply[len("error "):])
        if reply != "ok" and not reply.startswith("ok "):
            raise EngineError("%s: unexpected reply %r to %r" % (NAME, reply, line))
        return reply.split()[1:]

    def _line(self):
        line = self.process.stdout.readline()
        if not line.endswith(b"\n"):
            self._ended()
        return line[:-1].decode()

    def _values(self, count, dtype):
        size = count * np.dtype(dtype).itemsize
        data = self.process.stdout.read(size)
        if len(data) != size:
            self._ended()
        return np.frombuffer(data, dtype=dtype).copy()

    def _ended(self):
        code = self.process.wait()
        self.errors.seek(0)
        raise EngineError("%s ended (exit code %s): %s" % (self.path, code,
                                                            self.errors.read().decode(errors="replace").strip()))

    # -- the requests

    def regions(self, path):
        """{region name: triangles [n, 3, 3]} of an STL file, regions in order of first
        appearance (geometry::read_stl_regions)."""
        count = int(self._ask("regions %s" % os.path.abspath(path))[0])
        regions = {}
        for _ in range(count):
            name = self._line()
            n = int(self._line())
            regions[name] = self._values(9 * n, np.float64).reshape(n, 3, 3)
        return regions

    def add_set(self, triangles):
        """A triangle set [n, 3, 3] made in the engine: (its id, the triangles kept, those of
        non-zero area)."""
        tri = np.asarray(triangles, float).reshape(-1, 3, 3)
        made = self._ask("set %d" % len(tri), tri)
        return int(made[0]), int(made[1])

    def nearest(self, set_id, points, caps=None):
        """(distances [m], triangles [m]) of points [m, 3] to a set: exact; with caps (one per
        point), inf and -1 where no triangle lies within the cap (inclusive)."""
        p = np.asarray(points, float).reshape(-1, 3)
        if caps is None:
            self._ask("nearest %d %d 0" % (set_id, len(p)), p)
        else:
            self._ask("nearest %d %d 1" % (set_id, len(p)), p, np.broadcast_to(np.asarray(caps, float), (len(p),)))
        return self._values(len(p), np.float64), self._values(len(p), np.int64)

    def pairs(self, positions, distance_m, grid_columns=0):
        """[P, 3] (frame, i, j), i < j: the point pairs of each frame of positions [F, N, 3]
        closer than distance_m (geometry::SpatialHashGrid), by frame, then i, then j. With
        grid_columns > 0 (point i at row i // grid_columns, column i % grid_columns), without
        the grid neighbours (rows and columns both at most 1 apart)."""
        x = np.asarray(positions, float)
        count = int(self._ask("pairs %d %d %r %d" % (x.shape[0], x.shape[1], float(distance_m), grid_columns), x)[0])
        return self._values(3 * count, np.int64).reshape(count, 3)


_ENGINE = None


def engine():
    """This process's engine, started on first use."""
    global _ENGINE
    if _ENGINE is None or _ENGINE.process.poll() is not None:
        _ENGINE = SurfaceEngine()
        atexit.register(_ENGINE.close)
    return _ENGINE
