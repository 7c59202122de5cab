"""collidescope.open: a recording (docs/reference/recording.md) read with h5py and numpy alone.

Frames are named by their scene frame number, as in `check --pairs` (for a Session's recording,
0, 1, 2, ... in step order); `rec.frames` lists them. Only complete frames count: a recording
still being written, or killed, has every dataset up to its last flushed frame (the rule of
docs/reference/recording.md, "Frames complete"), and `refresh()` picks up frames written since.
"""
import os

import h5py
import numpy as np

SCHEMA = "collidescope-trace"
MAJOR = 1
METHOD_GROUPS = ("gpu", "aabb", "decision", "hybrid")
CSR_OFFSETS = ("collisions/offsets", "gpu/pass_offsets", "gpu/survivor_offsets", "gpu/depth/image_offsets",
               "regions/offsets", "intervals/offsets")
# Per-frame datasets of /intervals (schema 1.7): one row per frame, row r the interval into frame r.
INTERVAL_ROWS = ("intervals/counts", "intervals/ms", "intervals/tolerance")
INTERVAL_COUNTS = ("candidate_pairs", "start_contacts", "primitive_queries", "inclusion_boxes", "contacts",
                   "pass_throughs", "unresolved")
# One row of Recording.intervals() (record --between-frames, schema 1.7).
INTERVAL_DTYPE = np.dtype([("from_frame", np.int64), ("to_frame", np.int64), ("tolerance", np.float64)] +
                          [(name, np.uint64) for name in INTERVAL_COUNTS] +
                          [("broad_ms", np.float64), ("narrow_ms", np.float64), ("total_ms", np.float64)])
# One row of Recording.interval_contacts(frame).
CONTACT_DTYPE = np.dtype([("obj_a", np.uint32), ("tri_a", np.uint32), ("obj_b", np.uint32), ("tri_b", np.uint32),
                          ("toi", np.float64), ("pass_through", np.bool_), ("resolved", np.bool_)])

# One row of Recording.regions(frame) (/regions/table, /regions/measures and, from schema 1.6, /regions/penetration; the
# inside areas and the depth from 1.6, NaN where not defined and in older recordings).
REGION_DTYPE = np.dtype([("id", np.uint32), ("obj_a", np.uint32), ("obj_b", np.uint32), ("pairs", np.uint32),
                         ("triangles_a", np.uint32), ("triangles_b", np.uint32), ("loops", np.uint32),
                         ("curve_length", np.float64), ("coplanar_area", np.float64),
                         ("box_min", np.float64, (3,)), ("box_max", np.float64, (3,)),
                         ("inside_area_a", np.float64), ("inside_area_b", np.float64), ("depth", np.float64)])
# One row of Recording.region_tracks().
TRACK_DTYPE = np.dtype([("id", np.uint32), ("obj_a", np.uint32), ("obj_b", np.uint32), ("first_frame", np.int64),
                        ("last_frame", np.int64), ("frames", np.int64), ("max_curve_length", np.float64),
                        ("max_curve_length_frame", np.int64), ("max_pairs", np.int64), ("split_from", np.uint32),
                        ("merged_into", np.uint32), ("max_depth", np.float64), ("max_depth_frame", np.int64)])


class RecordingError(ValueError):
    """A file that is not a readable collidescope recording (one line naming it)."""


def attr_text(obj, name, default=None):
    """String attribute NAME of OBJ as str (schema 1.2 writes fixed-length strings, which h5py
    returns as bytes; 1.0 and 1.1 wrote variable-length ones, returned as str)."""
    value = obj.attrs.get(name, default)
    if isinstance(value, (bytes, np.bytes_)):
        return value.decode("utf-8")
    return value


def open(path):  # noqa: A001  (collidescope.open, like h5py.File or gzip.open)
    """Opens the recording at PATH read-only (SWMR, so one still being written or killed opens)."""
    return Recording(path)


class Recording:
    """A collidescope recording: len(rec) complete frames, rec.frames, rec.objects,
    rec.pairs(frame), rec.positions(frame, obj), rec.triangles(frame, obj), rec.stats,
    rec.depth(frame), rec.attrs. A context manager; close() releases the file."""

    def __init__(self, path):
        self.path = str(path)
        self._file = _open_file(self.path)
        try:
            self._check_schema()
            self.objects = [attr_text(self._file["objects/%d" % k], "name", str(k))
                            for k in range(len(self._file["objects"]))]
            self.refresh()
        except (KeyError, OSError, ValueError) as error:
            self._file.close()
            if isinstance(error, RecordingError):
                raise
            raise RecordingError("%s: not a readable collidescope recording (%s)" % (self.path, error)) from None

    # -- the file as a whole ---------------------------------------------------------------

    def refresh(self):
        """Re-reads the frame count (SWMR: frames flushed since the file was opened)."""
        for name in self._counted_datasets():
            self._file[name].refresh()
        self._frames_complete = self._count_frames()
        self._frames = self._file["frames/index"][: self._frames_complete].astype(np.int64)
        self._rows = {int(frame): row for row, frame in enumerate(self._frames)}
        self._stats = None
        return self

    def __len__(self):
        return self._frames_complete

    @property
    def frames(self):
        """Scene frame number of every complete frame, ascending (an int64 array)."""
        return self._frames.copy()

    @property
    def times(self):
        """Seconds from the clip's start of every complete frame (/frames/time, schema 1.4; a
        float64 array), or None when the recording's inputs carried no time."""
        if "frames/time" not in self._file:
            return None
        return self._file["frames/time"][: len(self)].astype(np.float64)

    @property
    def fps(self):
        """The source animation's frames per second (attribute `fps`), or None when unknown."""
        value = self._file.attrs.get("fps")
        return float(value) if value is not None else None

    @property
    def clip(self):
        """The source animation clip's name (attribute `clip`), or None."""
        return attr_text(self._file, "clip")

    @property
    def up_axis(self):
        """The axis the inputs call up, "x", "y" or "z" (attribute `up_axis`), or None."""
        return attr_text(self._file, "up_axis")

    @property
    def attrs(self):
        """The root attributes (docs/reference/recording.md), strings as str."""
        return {name: attr_text(self._file, name) for name in self._file.attrs}

    @property
    def finished(self):
        """True when the writer closed the file cleanly (not killed, not still writing)."""
        return int(self._file.attrs.get("finished", 0)) == 1

    def unit(self, dataset):
        """The `unit` attribute of DATASET (a path such as "frames/ms/total" or "gpu/depth/range")."""
        return attr_text(self._file[dataset], "unit")

    def close(self):
        self._file.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __repr__(self):
        return "<collidescope.Recording %r: %d frames, %d objects>" % (self.path, len(self), len(self.objects))

    # -- per frame -------------------------------------------------------------------------

    def pairs(self, frame):
        """The colliding pairs of FRAME: an (N, 4) int64 array of objA triA objB triB rows,
        sorted (check --pairs without the frame column)."""
        row = self._row(frame)
        a, b = (int(v) for v in self._file["collisions/offsets"][row:row + 2])
        return self._file["collisions/pairs"][a:b].astype(np.int64).reshape(-1, 4)

    def positions(self, frame, obj):
        """Object OBJ's vertex positions at FRAME: a (V, 3) float32 array (as recorded)."""
        row = self._row(frame)
        group = self._object(obj)
        a, b = (int(v) for v in group["vertex_offsets"][row:row + 2])
        if a == b:
            raise ValueError("%s: the positions of frame %d were not recorded (dropped by --budget)" % (self.path, frame))
        return group["positions"][a:b]

    def triangles(self, frame, obj):
        """Object OBJ's triangles in force at FRAME: a (T, 3) int64 array of vertex indices."""
        frame_number = int(self._frames[self._row(frame)])
        group = self._object(obj)
        starts = group["topology_from_frame"][:]
        topology = max(i for i, start in enumerate(starts) if start <= frame_number)
        a, b = (int(v) for v in group["topology_offsets"][topology:topology + 2])
        return group["triangles"][a:b].astype(np.int64)

    def depth_count(self, frame):
        """How many depth images FRAME has (0 where none were recorded), without reading them."""
        row = self._row(frame)
        if "gpu/depth/image_offsets" not in self._file:
            return 0
        first, end = (int(v) for v in self._file["gpu/depth/image_offsets"][row:row + 2])
        return end - first

    def depth(self, frame):
        """The GPU cull's depth images recorded at FRAME (record --depth every:N), as a list of
        dicts: level (0 objects, 1 triangles), view (axis), width, height, near, far and depth
        (height x width window depths in [0, 1], row 0 at the bottom; 1 where nothing was
        drawn). Empty where none were recorded."""
        row = self._row(frame)
        if "gpu/depth/image_offsets" not in self._file:
            return []
        d = self._file["gpu/depth"]
        first, end = (int(v) for v in d["image_offsets"][row:row + 2])
        return [self._depth_image(d, i) for i in range(first, end)]

    # -- interpenetration regions (record --regions, schema 1.5) ----------------------------

    @property
    def has_regions(self):
        """True when the recording holds /regions (made with `record --regions`)."""
        return "regions/offsets" in self._file

    def regions(self, frame):
        """FRAME's interpenetration regions as a numpy record array (REGION_DTYPE): id (follows
        the region over frames), obj_a, obj_b (equal for self-contact), pairs, triangles_a,
        triangles_b, loops, curve_length, coplanar_area, box_min, box_max, inside_area_a (obj_a's
        surface inside obj_b), inside_area_b, depth (NaN where not defined). Raises ValueError
        when the recording has no regions (record it with --regions)."""
        first, end = self._region_rows(frame)
        r = self._file["regions"]
        out = np.zeros(end - first, dtype=REGION_DTYPE)
        table = r["table"][first:end]
        measures = r["measures"][first:end]
        for k, name in enumerate(("id", "obj_a", "obj_b", "pairs", "triangles_a", "triangles_b", "loops")):
            out[name] = table[:, k]
        out["curve_length"], out["coplanar_area"] = measures[:, 0], measures[:, 1]
        out["box_min"], out["box_max"] = measures[:, 2:5], measures[:, 5:8]
        if "penetration" in r:
            penetration = r["penetration"][first:end]
            out["inside_area_a"], out["inside_area_b"], out["depth"] = penetration[:, 0], penetration[:, 1], penetration[:, 2]
        else:  # schema 1.5
            out["inside_area_a"] = out["inside_area_b"] = out["depth"] = np.nan
        return out.view(np.recarray)

    def region_curves(self, frame):
        """FRAME's intersection curves: a list of (region id, closed, (N, 3) float64 points)."""
        first, end = self._region_rows(frame)
        r = self._file["regions"]
        ids = r["table"][first:end, 0]
        curve_offsets = r["curve_offsets"][first:end + 1]
        c0, c1 = int(curve_offsets[0]), int(curve_offsets[-1])
        closed = r["curve_closed"][c0:c1]
        point_offsets = r["point_offsets"][c0:c1 + 1]
        points = r["points"][int(point_offsets[0]):int(point_offsets[-1])]
        curves = []
        for k in range(end - first):
            for c in range(int(curve_offsets[k]), int(curve_offsets[k + 1])):
                p0, p1 = (int(v) - int(point_offsets[0]) for v in point_offsets[c - c0:c - c0 + 2])
                curves.append((int(ids[k]), bool(closed[c - c0]), points[p0:p1]))
        return curves

    def region_predecessors(self, frame):
        """For each of FRAME's regions (in regions(frame) order), the ids of the previous frame's
        regions it continues, strongest first (two or more: a merge)."""
        first, end = self._region_rows(frame)
        r = self._file["regions"]
        offsets = r["predecessor_offsets"][first:end + 1]
        predecessors = r["predecessors"][int(offsets[0]):int(offsets[-1])]
        base = int(offsets[0])
        return [predecessors[int(a) - base:int(b) - base].astype(np.int64) for a, b in zip(offsets[:-1], offsets[1:])]

    def region_tracks(self):
        """Every region over the run, one row per id (TRACK_DTYPE): objects, first and last
        frame, frames present, its longest curve and that frame, its most pairs, the region it
        split from and the region it merged into (0: none), its largest depth and that frame (NaN
        and 0 where never defined), as `check --regions` reports them."""
        if not self.has_regions:
            raise ValueError("%s: no regions recorded (record with --regions)" % self.path)
        tracks = {}
        for frame in self.frames:
            regions = self.regions(frame)
            predecessors = self.region_predecessors(frame)
            for region, before in zip(regions, predecessors):
                i = int(region.id)
                t = tracks.get(i)
                if t is None:
                    t = tracks[i] = {"id": i, "obj_a": int(region.obj_a), "obj_b": int(region.obj_b),
                                     "first_frame": int(frame), "frames": 0, "max_curve_length": -1.0,
                                     "max_pairs": 0, "split_from": int(before[0]) if len(before) else 0, "merged_into": 0,
                                     "max_depth": np.nan, "max_depth_frame": 0}
                t["last_frame"] = int(frame)
                t["frames"] += 1
                t["max_pairs"] = max(t["max_pairs"], int(region.pairs))
                if float(region.curve_length) > t["max_curve_length"]:
                    t["max_curve_length"], t["max_curve_length_frame"] = float(region.curve_length), int(frame)
                depth = float(region.depth)
                if not np.isnan(depth) and (np.isnan(t["max_depth"]) or depth > t["max_depth"]):
                    t["max_depth"], t["max_depth_frame"] = depth, int(frame)
            # A previous id that goes on nowhere merged into the first region continuing it.
            ids = {int(region.id) for region in regions}
            for region, before in zip(regions, predecessors):
                for p in (int(v) for v in before):
                    if p != int(region.id) and p not in ids and tracks[p]["merged_into"] == 0:
                        tracks[p]["merged_into"] = int(region.id)
        out = np.zeros(len(tracks), dtype=TRACK_DTYPE)
        for row, i in enumerate(sorted(tracks)):
            for name in TRACK_DTYPE.names:
                out[row][name] = tracks[i][name]
        return out.view(np.recarray)

    def _region_rows(self, frame):
        row = self._row(frame)
        if not self.has_regions:
            raise ValueError("%s: no regions recorded (record with --regions)" % self.path)
        a, b = (int(v) for v in self._file["regions/offsets"][row:row + 2])
        return a, b

    # -- between the frames (record --between-frames, schema 1.7) -----------------------------

    @property
    def has_intervals(self):
        """True when the recording holds /intervals (made with `record --between-frames`)."""
        return "intervals/offsets" in self._file

    def intervals(self):
        """Every interval between consecutive recorded frames as a numpy record array
        (INTERVAL_DTYPE): from_frame, to_frame, tolerance (the δ its times of contact are within),
        the counts of `check --between-frames --stats` (candidate_pairs, start_contacts,
        primitive_queries, inclusion_boxes, contacts, pass_throughs, unresolved) and broad_ms,
        narrow_ms, total_ms. Raises ValueError without /intervals."""
        self._need_intervals()
        n = max(0, len(self) - 1)
        i = self._file["intervals"]
        out = np.zeros(n, dtype=INTERVAL_DTYPE)
        out["from_frame"], out["to_frame"] = self._frames[:n], self._frames[1:n + 1]
        out["tolerance"] = i["tolerance"][1:n + 1]
        counts, ms = i["counts"][1:n + 1], i["ms"][1:n + 1]
        for k, name in enumerate(INTERVAL_COUNTS):
            out[name] = counts[:, k]
        out["broad_ms"], out["narrow_ms"], out["total_ms"] = ms[:, 0], ms[:, 1], ms[:, 2]
        return out.view(np.recarray)

    def interval_contacts(self, frame):
        """The pairs that touch between FRAME and the next recorded frame, as a numpy record
        array (CONTACT_DTYPE), sorted by pair: obj_a, tri_a, obj_b, tri_b, toi (a lower bound of
        the first time of contact, 0 at FRAME, 1 at the next), pass_through (apart at both
        frames), resolved (False: a query spent its budget; toi is still a lower bound). Raises
        IndexError when FRAME is not recorded or is the last one, ValueError without
        /intervals."""
        self._need_intervals()
        row = self._row(frame) + 1
        if row >= len(self):
            raise IndexError("%s: frame %d is the last recorded frame; no interval starts there" % (self.path, frame))
        i = self._file["intervals"]
        a, b = (int(v) for v in i["offsets"][row:row + 2])
        if not 0 <= a <= b <= min(len(i["pairs"]), len(i["toi"]), len(i["flags"])):
            raise RecordingError("%s: intervals/offsets rows %d-%d (%d, %d) are out of order or past the pairs "
                                 "(corrupt recording)" % (self.path, row, row + 1, a, b))
        out = np.zeros(b - a, dtype=CONTACT_DTYPE)
        pairs = i["pairs"][a:b]
        for k, name in enumerate(("obj_a", "tri_a", "obj_b", "tri_b")):
            out[name] = pairs[:, k]
        out["toi"] = i["toi"][a:b]
        if not np.all((out["toi"] >= 0) & (out["toi"] <= 1)):
            raise RecordingError("%s: intervals/toi rows %d-%d hold a time outside [0, 1] (corrupt recording)"
                                 % (self.path, a, b))
        flags = i["flags"][a:b]
        out["pass_through"] = (flags & 1) != 0
        out["resolved"] = (flags & 2) == 0
        return out.view(np.recarray)

    def _need_intervals(self):
        if not self.has_intervals:
            raise ValueError("%s: no intervals recorded (record with --between-frames)" % self.path)

    # -- per-frame stats -------------------------------------------------------------------

    @property
    def stats(self):
        """Per-frame stats as numpy arrays, one entry per complete frame: "frame" (scene frame
        numbers), "time" (seconds, or None without /frames/time), "method" (names), "mode" (1 or 2 where the decision system ran, 0 elsewhere),
        "ms" and "counts" (dicts: the names of `check --stats`), and "gpu", "aabb", "decision",
        "hybrid" (dicts of float64 arrays, NaN on frames whose method did not fill them) where
        the file has them."""
        if self._stats is None:
            self._stats = self._read_stats()
        return self._stats

    # -- internals -------------------------------------------------------------------------

    def _check_schema(self):
        if attr_text(self._file, "schema") != SCHEMA:
            raise RecordingError("%s: not a collidescope recording (no schema attribute %r)" % (self.path, SCHEMA))
        major = int(self._file.attrs["schema_version_major"])
        if major > MAJOR:
            raise RecordingError("%s: schema version %d is newer than this reader reads (%d)" % (self.path, major, MAJOR))

    def _counted_datasets(self):
        """Every dataset whose length bounds the complete frames (docs/reference/recording.md)."""
        f = self._file
        names = ["frames/index", "frames/method"] + (["frames/time"] if "frames/time" in f else [])
        for group in ("frames/ms", "frames/counts") + tuple("frames/" + g for g in METHOD_GROUPS):
            if group in f:
                names += [group + "/" + member for member in f[group]]
        names += [o for o in CSR_OFFSETS if o in f]
        names += [d for d in INTERVAL_ROWS if d in f]
        names += ["objects/%d/vertex_offsets" % k for k in range(len(self.objects))]
        return names

    def _count_frames(self):
        lengths = []
        for name in self._counted_datasets():
            length = len(self._file[name])
            is_offsets = name in CSR_OFFSETS or name.endswith("vertex_offsets")
            lengths.append(length - 1 if is_offsets else length)
        return max(0, min(lengths))

    def _row(self, frame):
        row = self._rows.get(int(frame))
        if row is None:
            recorded = "none" if not len(self) else "%d..%d" % (self._frames[0], self._frames[-1])
            raise IndexError("%s: frame %d is not recorded (frames %s)" % (self.path, frame, recorded))
        return row

    def _object(self, obj):
        if not 0 <= int(obj) < len(self.objects):
            raise IndexError("%s: no object %d (it has %d)" % (self.path, obj, len(self.objects)))
        return self._file["objects/%d" % int(obj)]

    def _depth_image(self, d, i):
        level, view, width, height = (int(v) for v in d["info"][i])
        near, far = (float(v) for v in d["range"][i])
        p0, p1 = (int(v) for v in d["pixel_offsets"][i:i + 2])
        if p1 - p0 != width * height:
            raise RecordingError("%s: depth image %d has %d pixels for %dx%d" % (self.path, i, p1 - p0, width, height))
        depth = d["pixels"][p0:p1].astype(np.float64).reshape(height, width) / 65535.0
        return {"level": level, "view": view, "width": width, "height": height, "near": near, "far": far,
                "depth": depth}

    def _read_stats(self):
        f, n = self._file, len(self)
        codes = h5py.check_enum_dtype(f["frames/method"].dtype)
        names = {code: name for name, code in codes.items()}
        stats = {
            "frame": self._frames.copy(),
            "time": self.times,
            "method": np.array([names[int(c)] for c in f["frames/method"][:n]], dtype=str),
            "ms": {stage: f["frames/ms/" + stage][:n] for stage in f["frames/ms"]},
            "counts": {count: f["frames/counts/" + count][:n] for count in f["frames/counts"]},
        }
        for group in METHOD_GROUPS:
            if "frames/" + group not in f:
                continue
            present = f["frames/%s/present" % group][:n].astype(bool)
            stats[group] = {name: np.where(present, f["frames/%s/%s" % (group, name)][:n], np.nan)
                            for name in f["frames/" + group] if name != "present"}
            stats[group]["present"] = present
        mode = np.zeros(n, dtype=np.int64)
        if "decision" in stats:
            decided = stats["decision"]["present"]
            mode[decided] = stats["decision"]["mode"][decided].astype(np.int64)
        stats["mode"] = mode
        return stats


def _open_file(path):
    try:
        f = h5py.File(path, "r", swmr=True)
    except OSError:
        f = None
    if f is None:
        try:
            f = h5py.File(path, "r")
        except OSError as error:
            raise RecordingError("%s: cannot open as HDF5 (%s)" % (path, error)) from None
    try:
        _check_virtual_sources(path, f)
    except RecordingError:
        f.close()
        raise
    return f


def _resolve_source(path, name):
    """Where HDF5 1.10 opens source file NAME of a virtual dataset in the file at PATH: an
    absolute name as is, then each directory of HDF5_VDS_PREFIX, then the file's own directory
    (HDF5 then tries NAME relative to the current directory, which could be another run's part:
    not followed here). None when not found."""
    name = name.replace("%%", "%")
    tail = name
    if os.path.isabs(name):
        if os.path.isfile(name):
            return name
        tail = os.path.basename(name)
    for prefix in os.environ.get("HDF5_VDS_PREFIX", "").split(":"):
        if prefix and os.path.isfile(os.path.join(prefix, tail)):
            return os.path.join(prefix, tail)
    beside = os.path.join(os.path.dirname(os.path.abspath(path)), tail)
    return beside if os.path.isfile(beside) else None


def _check_virtual_sources(path, f):
    """A virtual join (`join --virtual`, docs/how-to/mpi.md) reads its rows from part files; h5py reads
    a missing part's rows as zeros without an error. Raises RecordingError, one line naming the
    part and the dataset, unless every part is there with the rows its mapping reads."""
    virtual = []
    f.visititems(lambda name, obj: virtual.append(obj) if isinstance(obj, h5py.Dataset) and obj.is_virtual else None)
    for dataset in virtual:
        for mapping in dataset.virtual_sources():
            what = "%s: /%s maps rows of %s" % (path, dataset.name.lstrip("/"), mapping.file_name)
            found = _resolve_source(path, mapping.file_name)
            if found is None:
                raise RecordingError(what + ", which is missing (a virtual join reads its parts: keep them beside it)")
            try:
                with h5py.File(found, "r") as part:
                    rows = part[mapping.dset_name].shape[0] if mapping.dset_name in part else None
            except OSError:
                raise RecordingError(what + ", which is unreadable (%s)" % found) from None
            if rows is None:
                raise RecordingError(what + ", which has no dataset " + mapping.dset_name)
            needed = mapping.src_space.get_select_bounds()[1][0] + 1
            if rows < needed:
                raise RecordingError(what + ", which holds %d rows of %s, not the %d the mapping reads"
                                     % (rows, mapping.dset_name, needed))
