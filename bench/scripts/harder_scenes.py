#!/usr/bin/python3
"""Cloth-like scenes harder than the built-in cloth family, for measuring (issue 23).

Writes one folder per scene under OUT, each a binary PLY frame sequence and a scene.json
manifest with self-collision on, readable by `collidescope check` and by
build/bench/bench_embree_cgal_peers:

  rods      capped tubes (10 sides) in crossing layers, bending, twisting and sinking into
            each other: closed thin surfaces, where no BVH node holds a whole ring that
            projects one way, in one object (240,000 triangles at --size large)
  pile      icospheres pressed into each other in a jittered stack, squashing and drifting:
            an n-body pile exported as one mesh (147,200 triangles)
  wrinkled  a cloth over a ball on an irregular triangulation (jittered vertices, random
            diagonals), hanging in radial folds with a hem that curls back up: not a height
            field (178,802 triangles)

Usage: /usr/bin/python3 bench/scripts/harder_scenes.py OUT [--size small|large] [--frames N]
Deterministic: fixed seeds, the same files on every run.
"""
import argparse
import json
import os
import numpy as np


def write_ply(path, vertices, triangles):
    """One binary little-endian PLY: float32 positions, int32 triangle corners."""
    vertices = np.asarray(vertices, dtype="<f4")
    triangles = np.asarray(triangles, dtype="<i4")
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\n"
              "property float x\nproperty float y\nproperty float z\n"
              f"element face {len(triangles)}\nproperty list uchar int vertex_indices\nend_header\n")
    faces = np.zeros(len(triangles), dtype=[("n", "u1"), ("corners", "<i4", 3)])
    faces["n"] = 3
    faces["corners"] = triangles
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(vertices.tobytes())
        f.write(faces.tobytes())


def write_scene(out, name, frames):
    """frames: per frame, {object name: (vertices, triangles)}; a manifest with self on."""
    os.makedirs(out, exist_ok=True)
    names = list(frames[0])
    for f, objects in enumerate(frames):
        for object_name, (vertices, triangles) in objects.items():
            write_ply(os.path.join(out, f"{object_name}.{f:04d}.ply"), vertices, triangles)
    manifest = {"name": name, "frames": len(frames), "self": True,
                "objects": [{"name": n, "pattern": f"{n}.%04d.ply"} for n in names]}
    with open(os.path.join(out, "scene.json"), "w") as f:
        json.dump(manifest, f)
    print(f"{out}: {len(frames[0][names[0]][1])} triangles, {len(frames)} frames", flush=True)


def tube(around, along):
    """A tube's triangles, vertex (i around, j along) at j * around + i, closed by fans round
    two centre vertices after the rings (around * along and around * along + 1)."""
    def at(i, j):
        return j * around + (i % around)
    triangles = []
    for j in range(along - 1):
        for i in range(around):
            a, b, c, d = at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)
            triangles += [(a, b, d), (a, d, c)]
    first, last = around * along, around * along + 1
    for i in range(around):
        triangles.append((first, at(i + 1, 0), at(i, 0)))
        triangles.append((last, at(i, along - 1), at(i + 1, along - 1)))
    return np.array(triangles)


def rods(out, count=150, around=10, along=80, frames=6, seed=1):
    """Capped tubes of radius r in layers that cross at right angles (give or take 0.3 rad),
    1.93 r apart: with the sine bends they pierce the next layer in places and graze it
    elsewhere; they twist and sink a little every frame."""
    rng = np.random.default_rng(seed)
    triangles = tube(around, along)
    r = 0.02
    per_layer = int(np.sqrt(count)) + 1
    all_triangles, positions = [], [[] for _ in range(frames)]
    for k in range(count):
        layer, slot = divmod(k, per_layer)
        angle = (layer % 2) * np.pi / 2 + rng.uniform(-0.3, 0.3)
        offset = (slot - per_layer / 2) * 2.05 * r + rng.uniform(-0.3, 0.3) * r
        height = layer * 1.93 * r
        phase = rng.uniform(0, 2 * np.pi)
        turn = np.array([[np.cos(angle), np.sin(angle), 0], [-np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
        s = np.linspace(-0.8, 0.8, along)
        around_angles = np.linspace(0, 2 * np.pi, around, endpoint=False)
        for f in range(frames):
            bend = 0.6 * r * np.sin(3 * s + phase + 0.4 * f)
            centre_z = height + 0.5 * r * np.sin(5 * s + phase * 2 + 0.3 * f) - 0.02 * r * f
            twisted = around_angles[:, None] + (0.5 * f * s)[None, :]
            x = np.broadcast_to(s[None, :], twisted.shape)
            y = offset + bend[None, :] + r * np.cos(twisted)
            z = centre_z[None, :] + r * np.sin(twisted)
            ring_points = np.stack([x.T, y.T, z.T], -1).reshape(-1, 3)  # ring after ring
            ends = [[s[0], offset + bend[0], centre_z[0]], [s[-1], offset + bend[-1], centre_z[-1]]]
            positions[f].append(np.vstack([ring_points, ends]) @ turn)
        all_triangles.append(triangles + k * (around * along + 2))
    triangles = np.vstack(all_triangles)
    write_scene(out, "rods", [{"rods": (np.vstack(p), triangles)} for p in positions])


def icosphere(level):
    """A unit icosphere: the icosahedron with each triangle split in four `level` times."""
    g = (1 + 5 ** 0.5) / 2
    corners = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g), (0, 1, -g),
               (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    vertices = [np.array(c, float) / np.linalg.norm(c) for c in corners]
    for _ in range(level):
        midpoints = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                m = vertices[a] + vertices[b]
                vertices.append(m / np.linalg.norm(m))
                midpoints[key] = len(vertices) - 1
            return midpoints[key]
        split = []
        for a, b, c in faces:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    return np.array(vertices), np.array(faces)


def pile(out, count=115, level=3, frames=6, seed=2):
    """Spheres of radius r on a jittered lattice 2 r apart, layers 1.6 r apart (pressed into
    each other), squashing and drifting, the upper ones sinking faster."""
    rng = np.random.default_rng(seed)
    sphere, faces = icosphere(level)
    r = 0.05
    side = int(np.ceil(count ** (1 / 3)))
    centres = []
    for k in range(count):
        i, j, layer = k % side, (k // side) % side, k // (side * side)
        lattice = np.array([i * 2.0 * r + (layer % 2) * r, j * 2.0 * r + (layer % 2) * r, layer * 1.6 * r])
        centres.append(lattice + rng.normal(0, 0.03 * r, 3))
    velocities = rng.normal(0, 0.02 * r, (count, 3))
    triangles = np.vstack([faces + k * len(sphere) for k in range(count)])
    frame_list = []
    for f in range(frames):
        placed = []
        for k in range(count):
            squash = 1 + 0.03 * np.sin(f + k)
            shape = sphere * r * np.array([1, 1, 1 / squash])
            sink = np.array([0, 0, 0.01 * r * f * (centres[k][2] / r)])
            placed.append(shape + centres[k] + velocities[k] * f - sink)
        frame_list.append({"pile": (np.vstack(placed), triangles)})
    write_scene(out, "pile", frame_list)


def irregular_grid(n, rng):
    """An n x n grid over the unit square, inner vertices jittered by 0.3 cell, each cell
    split along a random diagonal: (u, v, triangles)."""
    u, v = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n), indexing="xy")
    h = 1 / (n - 1)
    u = u + rng.uniform(-0.3, 0.3, u.shape) * h
    v = v + rng.uniform(-0.3, 0.3, v.shape) * h
    u[:, 0], u[:, -1], v[0, :], v[-1, :] = 0, 1, 0, 1
    flip = rng.random((n - 1, n - 1)) < 0.5
    triangles = []
    for j in range(n - 1):
        for i in range(n - 1):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i, (j + 1) * n + i + 1
            triangles += [(a, b, d), (a, d, c)] if flip[j, i] else [(a, b, c), (b, d, c)]
    return u.ravel(), v.ravel(), np.array(triangles)


def wrinkled(out, n=300, frames=6, seed=3):
    """A cloth over a ball of radius R: on the ball up to its equator, then hanging in 24
    radial folds whose depth grows, with a hem that curls outward and back up (an S: not a
    height field in any direction)."""
    rng = np.random.default_rng(seed)
    u, v, triangles = irregular_grid(n, rng)
    R = 0.5
    frame_list = []
    for f in range(frames):
        x, y = (u - 0.5) * 2.2, (v - 0.5) * 2.2
        rho, phi = np.hypot(x, y), np.arctan2(y, x)
        on_ball = rho < R * np.pi / 2
        ball_z = np.where(on_ball, R * np.cos(np.minimum(rho / R, np.pi / 2)) + 0.01, 0)
        ball_radius = np.where(on_ball, R * np.sin(np.minimum(rho / R, np.pi / 2)), R)
        hang = np.maximum(rho - R * np.pi / 2, 0)
        depth = 0.06 * (1 + 0.5 * f / frames) * np.minimum(hang / 0.2, 1)
        fold = depth * np.sin(24 * phi + 3 * hang)
        curl = 0.12 * np.sin(np.minimum(hang / 0.35, 1) * np.pi) * np.minimum(hang / 0.15, 1)
        radius = ball_radius + fold + curl + 0.002 * f
        z = ball_z - hang + 0.15 * np.maximum(hang - 0.3, 0) * np.sin(8 * hang)
        frame_list.append({"cloth": (np.stack([radius * np.cos(phi), radius * np.sin(phi), z], -1), triangles)})
    write_scene(out, "wrinkled", frame_list)


SIZES = {  # per scene: keyword arguments at each size
    "small": {"rods": dict(count=12, around=6, along=16), "pile": dict(count=8, level=1), "wrinkled": dict(n=24)},
    "large": {"rods": {}, "pile": {}, "wrinkled": {}},
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", help="folder to write the scenes into (created)")
    parser.add_argument("--size", choices=sorted(SIZES), default="large")
    parser.add_argument("--frames", type=int, default=6)
    args = parser.parse_args()
    if args.frames < 1:
        parser.error("--frames must be at least 1")
    for name, make in (("rods", rods), ("pile", pile), ("wrinkled", wrinkled)):
        make(os.path.join(args.out, name), frames=args.frames, **SIZES[args.size][name])


if __name__ == "__main__":
    main()
