"""Checks the schema 1.1 details of a recording made with --method gpu (tests/recorder).

Usage: check_details.py RUN.h5 STATS.jsonl   (the same run's `check --stats`)
Exits non-zero, naming the mismatch, when the file's /frames/gpu, /gpu/passes and
/frames/aabb do not hold what the engine reported.
"""
import json
import sys

import h5py

recording, stats_path = sys.argv[1], sys.argv[2]
stats = [json.loads(line) for line in open(stats_path)]
with h5py.File(recording, "r") as f:
    gpu = f["frames/gpu"]
    assert len(gpu["present"]) == len(stats), "one row per frame"
    assert all(gpu["present"][:] == 1), "every frame ran the GPU cull"
    assert all(f["frames/aabb/present"][:] == 0), "no frame ran the aabb method"
    offsets = f["gpu/pass_offsets"][:]
    passes = f["gpu/passes"][:]
    assert offsets[0] == 0 and offsets[-1] == len(passes), "pass offsets cover the passes"
    for row, frame in enumerate(stats):
        g = frame["gpu"]
        assert gpu["pcs_triangles_in"][row] == g["pcs_triangles"][0], f"row {row}: pcs in"
        assert gpu["pcs_triangles_out"][row] == g["pcs_triangles"][1], f"row {row}: pcs out"
        assert gpu["queries"][row] == g["queries"], f"row {row}: queries"
        assert gpu["triangles_per_query"][row] == g["triangles_per_query"], f"row {row}: P"
        assert offsets[row + 1] - offsets[row] == len(g["passes"]), f"row {row}: pass count"
        for k, p in enumerate(g["passes"]):
            stored = passes[int(offsets[row]) + k]
            assert stored[3] == p["tested"] and stored[4] == p["hidden"], f"row {row} pass {k}"
            assert stored[5] == p["queries"] and stored[6] == p["samples_passed"], f"row {row} pass {k}"
        chosen = "".join("xyz"[int(gpu[f"chosen_view_{i}"][row])] for i in range(3) if gpu[f"chosen_view_{i}"][row] >= 0)
        assert chosen == g["chosen_views"], f"row {row}: chosen views {chosen} vs {g['chosen_views']}"
    unit = gpu["query_ms"].attrs["unit"]
    assert (unit.decode() if isinstance(unit, bytes) else unit) == "ms", "fixed-length (1.2) or variable-length unit"
print("ok")
