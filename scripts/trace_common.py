"""Shared helpers of the trace scripts: open a collidescope recording with h5py alone.

The layout is docs/recording.md. Every per-frame dataset has one row per recorded frame; a
recording that was killed may have one dataset a row longer than another, so the scripts use
the complete frames only (the smallest length, as the tool's reader does).
"""
import sys

import h5py
import numpy as np

SCHEMA = "collidescope-trace"
MAJOR = 1


def attr_text(obj, name, default=None):
    """String attribute NAME of OBJ as str. Schema 1.2 writes fixed-length strings, which h5py
    returns as bytes; 1.0 and 1.1 wrote variable-length ones (str)."""
    value = obj.attrs.get(name, default)
    if isinstance(value, (bytes, np.bytes_)):
        return value.decode("utf-8")
    return value


def open_recording(path):
    """Opens PATH read-only (SWMR, so a recording being written or killed opens too)."""
    try:
        f = h5py.File(path, "r", swmr=True)
    except OSError:
        try:
            f = h5py.File(path, "r")
        except OSError as error:
            sys.exit("%s: cannot open as HDF5: %s" % (path, error))
    if attr_text(f, "schema") != SCHEMA:
        sys.exit("%s: not a collidescope recording" % path)
    major = int(f.attrs["schema_version_major"])
    if major > MAJOR:
        sys.exit("%s: schema version %d is newer than these scripts read (%d)" % (path, major, MAJOR))
    return f


def frames_complete(f):
    """Frames whose every per-frame dataset row is present."""
    lengths = [len(f["frames/index"]), len(f["frames/method"]), len(f["collisions/offsets"]) - 1]
    for group in ("frames/ms", "frames/counts"):
        lengths += [len(d) for d in f[group].values()]
    for obj in f["objects"].values():
        lengths.append(len(obj["vertex_offsets"]) - 1)
    return min(lengths)


def methods(f, n):
    """Method name of each of the first N frames."""
    names = {code: name for name, code in h5py.check_enum_dtype(f["frames/method"].dtype).items()}
    return [names[int(code)] for code in f["frames/method"][:n]]


def depth_image_count(f, row):
    """Depth images of frame row ROW (0 in files before schema 1.2)."""
    if "gpu/depth/image_offsets" not in f:
        return 0
    a, b = f["gpu/depth/image_offsets"][row:row + 2]
    return int(b - a)


def depth_image(f, row, index):
    """Image INDEX of frame row ROW as a dict: level, view, width, height, near, far and depth
    (a height x width float array of window depths in [0, 1], row 0 at the bottom; 1 where
    nothing was drawn). Pixels are stored as uint16: depth = q / 65535."""
    d = f["gpu/depth"]
    i = int(d["image_offsets"][row]) + index
    level, view, width, height = (int(v) for v in d["info"][i])
    near, far = (float(v) for v in d["range"][i])
    p0, p1 = (int(v) for v in d["pixel_offsets"][i:i + 2])
    if p1 - p0 != width * height:
        sys.exit("depth image %d: %d pixels for %dx%d" % (i, p1 - p0, width, height))
    depth = d["pixels"][p0:p1].astype(np.float64).reshape(height, width) / 65535.0
    return {"level": level, "view": view, "width": width, "height": height, "near": near, "far": far, "depth": depth}
