"""Session.step hands (V, 3) float64 C-contiguous arrays to the engine with no copy, neither in
the module (nothing is allocated from Python's or numpy's allocators for them) nor in the
engine (stats counts.positions_copied_bytes == 0); float32 and strided arrays are converted once
(V * 24 bytes) and give identical pairs; a NaN still raises ValueError naming the element."""
import tracemalloc

import numpy as np
import pytest

import collidescope


def step_allocations(session, positions):
    """Bytes allocated through Python's and numpy's allocators (numpy reports its array
    buffers to tracemalloc) at the peak of one step, and its pairs."""
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        base, _ = tracemalloc.get_traced_memory()
        pairs = session.step(positions)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    return peak - base, pairs


def test_tracemalloc_sees_a_numpy_copy():
    """The measure below can see a copy: numpy's buffers are traced."""
    array = np.zeros((20000, 3))
    tracemalloc.start()
    try:
        base, _ = tracemalloc.get_traced_memory()
        copy = np.ascontiguousarray(array, dtype=np.float32)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak - base >= copy.nbytes


def test_float64_c_contiguous_is_not_copied():
    scene = collidescope.scene("C")  # 20,402 vertices: 490 KB of positions per frame
    session = collidescope.Session(scene.triangles(), method="aabb", threads=1)
    positions = [np.ascontiguousarray(p, dtype=np.float64) for p in scene.positions(5)]
    assert all(p.flags.c_contiguous and p.dtype == np.float64 for p in positions)
    session.step(positions)  # the first step builds the trees
    allocated, pairs = step_allocations(session, positions)
    nbytes = sum(p.nbytes for p in positions)
    assert session.stats["counts"]["positions_copied_bytes"] == 0
    # The pairs array and a few small Python objects are all the step allocates.
    assert allocated < min(pairs.nbytes + 16384, nbytes / 4), "the step allocated %d bytes" % allocated


def converted_layouts(positions):
    """The same coordinates (float32 values) as arrays the engine cannot read in place."""
    single = positions.astype(np.float32)
    padded = np.zeros((len(positions), 4))
    padded[:, :3] = single
    return {
        "float32": single,
        "fortran": np.asfortranarray(single.astype(np.float64)),
        "padded rows": padded[:, :3],
        "reversed rows": np.ascontiguousarray(single[::-1].astype(np.float64))[::-1],
    }


@pytest.mark.parametrize("layout", ["float32", "fortran", "padded rows", "reversed rows"])
def test_converted_layouts_count_their_bytes_and_give_the_same_pairs(layout):
    scene = collidescope.scene("C:small")
    in_place = collidescope.Session(scene.triangles(), method="aabb")
    converted = collidescope.Session(scene.triangles(), method="aabb")
    total = 0
    for frame in range(len(scene)):
        doubles = [np.ascontiguousarray(p, dtype=np.float64) for p in scene.positions(frame)]
        assert all(np.array_equal(p.astype(np.float32), p) for p in doubles)  # float32 values
        others = [converted_layouts(p)[layout] for p in doubles]
        expected = in_place.step(doubles)
        pairs = converted.step(others)
        assert np.array_equal(pairs, expected), "frame %d" % frame
        assert in_place.stats["counts"]["positions_copied_bytes"] == 0
        assert converted.stats["counts"]["positions_copied_bytes"] == 24 * sum(len(p) for p in doubles)
        total += len(pairs)
    assert total > 0


def test_the_other_byte_order_is_read_right():
    """'>f8' arrays are converted to native order (numpy, one copy), not read as garbage."""
    scene = collidescope.scene("C:small")
    native = collidescope.Session(scene.triangles(), method="aabb")
    swapped = collidescope.Session(scene.triangles(), method="aabb")
    total = 0
    for frame in range(len(scene)):
        positions = scene.positions(frame)
        expected = native.step(positions)
        assert np.array_equal(swapped.step([p.astype(">f8") for p in positions]), expected)
        total += len(expected)
    assert total > 0


def test_a_nan_in_a_view_still_raises():
    scene = collidescope.scene("C:small")
    session = collidescope.Session(scene.triangles(), method="aabb", names=["floor", "lid"])
    positions = [np.ascontiguousarray(p, dtype=np.float64) for p in scene.positions(2)]
    positions[1][4, 2] = np.nan
    with pytest.raises(ValueError, match=r"^object 1 \('lid'\): vertex 4 has a non-finite z coordinate \(nan\)$"):
        session.step(positions)
    positions[1][4, 2] = scene.positions(2)[1][4, 2]
    assert np.array_equal(session.step(positions), collidescope.Session(scene.triangles(), method="aabb").step(positions))
