"""collidescope from Python: collision detection in your own loop, and recordings to read.

    import collidescope
    with collidescope.Session(triangles, method="aabb", record="run.h5") as s:
        for positions in frames:                 # one (V_i, 3) float array per object
            pairs = s.step(positions)            # (N, 4) int64: objA triA objB triB, sorted
            print(s.stats["ms"]["total"], len(pairs))
    rec = collidescope.open("run.h5")            # len(rec), rec.pairs(f), rec.positions(f, k), rec.stats

`Session`, `scene` and `scene_files` are the compiled core (`collidescope._core`, pybind11 on
libcollidescope); `open` is pure Python on h5py and numpy, so the recording scripts need nothing
built. docs/reference/embedding.md is the reference.
"""
from .recording import Recording, RecordingError, open  # noqa: F401  (open shadows the builtin here only)

__all__ = ["Session", "UnavailableError", "scene", "scene_files", "open", "Recording", "RecordingError"]

_CORE_NAMES = ("Session", "UnavailableError", "Scene", "scene", "scene_files")


def __getattr__(name):
    # The compiled core is imported on first use: reading recordings needs only h5py and numpy.
    if name in _CORE_NAMES:
        from . import _core
        return getattr(_core, name)
    raise AttributeError("module 'collidescope' has no attribute %r" % name)
