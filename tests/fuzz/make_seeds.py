#!/usr/bin/python3
"""Writes the fuzz targets' seed inputs (docs/how-to/fuzzing.md): small valid files of every form each
reader accepts. The committed corpus (tests/fuzz/corpus/) grew from these seeds and was
minimised with `scripts/fuzz.sh merge`; this script says where it started.

    tests/fuzz/make_seeds.py OUT_DIR COLLIDESCOPE_BINARY

writes OUT_DIR/{ply,obj,scene,recording,cache}/; the recording seeds are recordings made by the given
`collidescope` binary from small meshes (the committed recording corpus is gzipped, see
scripts/fuzz.sh)."""

import os
import struct
import subprocess
import sys
import tempfile

TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def ply_ascii():
    return ("ply\r\nformat ascii 1.0\ncomment hand written\nobj_info test\n"
            "element vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
            "element face 2\nproperty list uchar int vertex_indices\nproperty int flags\n"
            "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
            "0 0 0 255\n1 0 0 0\n0 1 0 7\n0 0 1 9\n3 0 2 1 5\n4 0 1 3 2 6\n0 1\n")


def ply_binary(endian, coord, index_count, index_type):
    fmt = {"<": "binary_little_endian", ">": "binary_big_endian"}[endian]
    coord_code = {"float": "f", "double": "d"}[coord]
    count_code = {"uchar": "B", "ushort": "H", "uint": "I"}[index_count]
    index_code = {"int": "i", "uint": "I", "short": "h"}[index_type]
    header = (f"ply\nformat {fmt} 1.0\nelement vertex 4\nproperty {coord} x\nproperty {coord} y\n"
              f"property {coord} z\nproperty float nx\nelement face 4\n"
              f"property list {index_count} {index_type} vertex_indices\nend_header\n")
    body = b"".join(struct.pack(endian + coord_code * 3 + "f", *v, 0.5) for v in TETRA_V)
    body += b"".join(struct.pack(endian + count_code + index_code * 3, 3, *f) for f in TETRA_F)
    return header.encode() + body


def obj_text(shift=0.0, faces=TETRA_F, extra=""):
    lines = ["# tetrahedron", "o tet", "g group"]
    lines += [f"v {x + shift} {y} {z}" for x, y, z in TETRA_V]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    return "\n".join(lines) + "\n" + extra


def obj_forms():
    return ("v 0 0 0\nv 1 0 0 1.0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
            "s off\nusemtl m\nf 1/1 3/3 2/2\nf 1//1 2//1 4//1\nf 1/1/1 4/2/1 3/3/1\n"
            "f -3 -2 -1\nf 1 2 3 4\n")


def scenes():
    return {
        "printf": '{"name": "cloth", "frames": 3, "objects": [{"name": "cloth", "pattern": "cloth.%04d.ply"}], "self": true}',
        "hashes": '{"objects": [{"pattern": "body.####.obj"}, {"pattern": "floor.ply"}]}',
        "mixed": '{"frames": 2, "objects": [{"pattern": "cloth.%04d.ply"}, {"pattern": "body.####.obj", "name": "b"},'
                 ' {"pattern": "sub/cap.%d.obj"}], "self": false}',
        "static": '{"name": "s", "objects": [{"pattern": "floor.ply"}, {"pattern": "sub/../floor.ply"}]}',
        "cache": '{"objects": [{"mesh": "floor.ply", "cache": "tet.pc2"}, {"pattern": "cloth.%04d.ply"}]}',
    }


def pc2(frames):
    """A PC2 point cache (little-endian; version 1, start frame 0, sample rate 1)."""
    data = b"POINTCACHE2\0" + struct.pack("<iiffi", 1, len(frames[0]), 0.0, 1.0, len(frames))
    return data + b"".join(struct.pack("<3f", *p) for frame in frames for p in frame)


def mdd(frames, times):
    """An MDD point cache (big-endian: counts, times, positions)."""
    data = struct.pack(">ii", len(frames), len(frames[0])) + struct.pack(">%df" % len(times), *times)
    return data + b"".join(struct.pack(">3f", *p) for frame in frames for p in frame)


def tetra_frames(count):
    return [[(x + 0.25 * f, y, z - 0.5 * f) for x, y, z in TETRA_V] for f in range(count)]


def record(binary, out, inputs, *options):
    subprocess.run([binary, "record", *inputs, "-o", out, "--threads", "1", "-q", *options], check=True)


def recordings(binary, directory):
    """Recordings of two tetrahedra meeting over three frames (the second gains a triangle at
    frame 2: two topologies): the GPU cull with depth images, the hybrid method with
    self-collision, the AABB method and the decision system (its /frames/decision rows)."""
    with tempfile.TemporaryDirectory() as work:
        for f in range(3):
            write(f"{work}/a.{f:04d}.obj", obj_text(0.3 * f))
            # The second object gains a triangle at frame 2: two topologies.
            faces = TETRA_F + ([(1, 2, 0)] if f == 2 else [])
            write(f"{work}/b.{f:04d}.obj", obj_text(0.8 - 0.3 * f, faces))
        inputs = [f"{work}/a.####.obj", f"{work}/b.####.obj"]
        gpu = ["--gpu-resolution", "8", "--depth", "every:1"]
        record(binary, f"{directory}/gpu.h5", inputs, "--method", "gpu", *gpu)
        record(binary, f"{directory}/hybrid.h5", inputs, "--method", "hybrid", "--self", *gpu)
        record(binary, f"{directory}/adaptive.h5", inputs, "--method", "adaptive", "--gpu-resolution", "8")
        record(binary, f"{directory}/aabb.h5", inputs, "--method", "aabb")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    out, binary = sys.argv[1], sys.argv[2]
    write(f"{out}/ply/ascii.ply", ply_ascii())
    write(f"{out}/ply/le_float.ply", ply_binary("<", "float", "uchar", "int"))
    write(f"{out}/ply/le_double.ply", ply_binary("<", "double", "ushort", "uint"))
    write(f"{out}/ply/be_float.ply", ply_binary(">", "float", "uint", "short"))
    write(f"{out}/ply/be_double.ply", ply_binary(">", "double", "uchar", "uint"))
    write(f"{out}/obj/plain.obj", obj_text())
    write(f"{out}/obj/forms.obj", obj_forms())
    for name, text in scenes().items():
        write(f"{out}/scene/{name}.json", text)
    write(f"{out}/cache/tetra.pc2", pc2(tetra_frames(3)))
    write(f"{out}/cache/tetra.mdd", mdd(tetra_frames(2), [0.0, 1.0 / 24]))
    os.makedirs(f"{out}/recording", exist_ok=True)
    recordings(binary, f"{out}/recording")


if __name__ == "__main__":
    main()
