#!/usr/bin/python3
"""Differential soak: adversarial OBJ frame sequences, every per-frame method against brute at
1 and 2 threads, and between frames against the per-frame brute pairs at both ends and across
thread counts.

Usage: soak.py SEED_FROM SEED_TO [--kinds N] [--only-kind K]
  the scene kind is seed % N (N = 10 by default; the logs say which N made them: kinds were
  added while the soak ran), or K for every seed with --only-kind."""
import itertools, os, subprocess, sys, shutil, random
import numpy as np

BIN = "/work/main/build/app/collidescope"
ROOT = "/tmp/w/soak/run"

def grid_soup(rng, n, offset, scale):
    # triangles whose corners lie on a coarse grid: shared planes, edges, vertices, T-junctions
    g = rng.integers(0, 5, size=(n, 3, 3)).astype(float)
    if rng.random() < 0.5:
        k = rng.integers(0, 3)
        g[:, :, k] = rng.integers(0, 2)   # many in one axis plane
    seg = rng.random(n) < 0.1
    g[seg, 2] = g[seg, 1]                  # segment triangles
    pts = rng.random(n) < 0.03
    g[pts, 1] = g[pts, 0]; g[pts, 2] = g[pts, 0]
    return g * scale / 4 + offset

def sheet(rng, cells, offset, scale, wave):
    xs = np.linspace(0, 1, cells + 1)
    V = []
    for i, x in enumerate(xs):
        for j, y in enumerate(xs):
            V.append([x, y, wave * np.sin(3 * x + 2 * y + rng.random())])
    V = np.array(V) * scale + offset
    T = []
    c = cells + 1
    for i in range(cells):
        for j in range(cells):
            a, b, d, e = i * c + j, i * c + j + 1, (i + 1) * c + j, (i + 1) * c + j + 1
            T += [[a, d, e], [a, e, b]]
    return V, np.array(T)

def soup(P):
    """An (n, 3, 3) array of triangle corners as a mesh: vertices, and triangles of their own."""
    V = P.reshape(-1, 3)
    return V, np.arange(len(V)).reshape(-1, 3)

def moving(tris, step, frames):
    """The frames of triangles translated by `step` a frame."""
    return [soup(tris + step * f) for f in range(frames)]

def write_obj(path, V, T):
    with open(path, "w") as f:
        for v in V:
            f.write("v %.17g %.17g %.17g\n" % tuple(v))
        for t in T:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))

def make_scene(seed, d, kinds, only_kind):
    rng = np.random.default_rng(seed)
    kind = only_kind if only_kind is not None else seed % kinds
    frames = 4
    far = [0.0, 1e6, 2.0**30, 1e-3][rng.integers(0, 4)]
    offset = np.array([far, -far / 3, far / 7])
    objs = []
    if kind == 0:  # grid soups moving by grid steps
        for o in range(3):
            tris = grid_soup(rng, 40, offset, 1.0)
            step = rng.integers(-2, 3, size=3) / 8.0
            objs.append(moving(tris, step, frames))
    elif kind == 1:  # coplanar sheets sliding in their plane
        for o in range(2):
            V, T = sheet(rng, 8, offset, 1.0, 0.0)
            seq = []
            for f in range(frames):
                shift = np.array([f * 0.0625 * (o * 2 - 1), f * 0.03125 * o, 0.0])
                seq.append((V + shift, T))
            objs.append(seq)
    elif kind == 2:  # wavy sheet folding through itself and a rigid sheet, tiny and big triangles
        V, T = sheet(rng, 12, offset, 1.0, 0.3)
        seq = []
        for f in range(frames):
            W = V.copy()
            W[:, 2] += (W[:, 0] - offset[0] - 0.5) ** 2 * (f - 1.5) * 0.8
            seq.append((W, T))
        objs.append(seq)
        big = np.array([[-1e3, -1e3, 0.1], [1e3, -1e3, 0.1], [0, 1e3, 0.1]]) + offset
        objs.append([(big + [0, 0, 0.05 * f], np.array([[0, 1, 2]])) for f in range(frames)])
    elif kind == 4:  # near-degenerate: corners of one triangle on another's plane, rounded
        for o in range(2):
            seq = []
            base = rng.random((30, 3, 3)) + offset
            for f in range(frames):
                P = base.copy()
                if o == 1:
                    # each triangle gets a corner at an affine combination of the other object's
                    # triangle corners (rounded in double: on, just above or just below its plane)
                    Q = objs[0][f][0].reshape(-1, 3, 3)
                    for i in range(30):
                        a, b, c = Q[i]
                        s_, t_ = rng.random(2) * 0.5
                        P[i, 0] = a + s_ * (b - a) + t_ * (c - a)
                        if rng.random() < 0.3:
                            P[i, 1] = a + (b - a) * rng.random()
                seq.append(soup(P))
            objs.append(seq)
            # move object 0 a little per frame for the next object's frames
            if o == 0:
                objs[0] = [(V0 + np.array([0.01 * f, 0, 0]), T0) for f, (V0, T0) in enumerate(seq)]
    elif kind == 5:  # many small objects: two triangles each, on a grid, moving by exact steps
        for o in range(24):
            c = rng.integers(0, 4, size=3) / 4.0
            tri = (rng.integers(0, 3, size=(2, 3, 3)) / 4.0) + c + offset
            step = rng.integers(-1, 2, size=3) / 16.0
            objs.append(moving(tri, step, frames))
    elif kind == 6:  # a huge flat sheet at z = 0 and tiny triangles on it, a far object widening the scene
        V, T = sheet(rng, 4, offset + np.array([-5e3, -5e3, 0]), 1e4, 0.0)
        objs.append([(V, T) for f in range(frames)])
        small = []
        for i in range(40):
            c = rng.random(3) * 2 - 1
            c[2] = 0
            tri = c + (rng.random((3, 3)) - 0.5) * 1e-3
            if rng.random() < 0.5:
                tri[0, 2] = 0.0          # a corner exactly on the sheet's plane
            small.append(tri)
        small = np.array(small) + offset
        objs.append([(small.reshape(-1, 3) + np.array([0, 0, (f - 1) * 1e-4]), np.arange(120).reshape(-1, 3)) for f in range(frames)])
        far_tri = np.array([[3e5, 3e5, 3e5], [3e5 + 1, 3e5, 3e5], [3e5, 3e5 + 1, 3e5]]) + offset
        objs.append([(far_tri, np.array([[0, 1, 2]])) for f in range(frames)])
    elif kind in (7, 9):  # slivers: long thin triangles crossing near one point (9: in one plane)
        for o in range(2):
            seq = []
            tris = []
            for i in range(40):
                u = rng.normal(size=3)
                w = rng.normal(size=3) * 1e-6
                p = (rng.random(3) - 0.5) * 0.01
                if kind == 9:  # all in the plane z = 0: coplanar slivers crossing
                    u[2] = w[2] = p[2] = 0.0
                u /= np.linalg.norm(u)
                tris.append([p - u, p + u, p + w])
            tris = np.array(tris) + offset
            for f in range(frames):
                seq.append(((tris + np.array([0, 0, (f - 1.5) * 0.002 * (2 * o - 1)])).reshape(-1, 3), np.arange(120).reshape(-1, 3)))
            objs.append(seq)
    elif kind == 8:  # a crumpled sheet snapped to a grid of 1/16: exact self contacts
        V, T = sheet(rng, 10, np.zeros(3), 1.0, 0.0)
        seq = []
        for f in range(frames):
            W = V.copy()
            W[:, 2] = np.round(np.sin(7 * W[:, 0] + f) * np.cos(5 * W[:, 1]) * 0.08 * 16) / 16
            W[:, 0] = np.round((W[:, 0] + 0.2 * np.sin(12 * W[:, 0] + 3 * W[:, 1] * (f + 1))) * 16) / 16
            seq.append((W + offset, T))
        objs.append(seq)
    else:  # duplicated meshes: the same triangles twice, one copy nudged by an exact step
        V, T = sheet(rng, 6, offset, 1.0, 0.2)
        for o in range(3):
            seq = [(V + np.array([0, 0, (o - 1) * f / 16.0]), T) for f in range(frames)]
            objs.append(seq)
    names = []
    for o, seq in enumerate(objs):
        for f, (V, T) in enumerate(seq):
            write_obj(os.path.join(d, "o%d.%04d.obj" % (o, f)), V, T)
        names.append(os.path.join(d, "o%d.####.obj" % o))
    return names, kind, far

def run(args):
    r = subprocess.run([BIN] + args, capture_output=True, text=True)
    return r

def pairs(path):
    # a list, in file order: a duplicated or misordered line is a difference too
    out = []
    with open(path) as f:
        for line in f:
            c = line.split("\t")
            out.append(tuple(int(x) for x in c[:5]))
    return out

def ccd_pairs(path):
    out = {}
    with open(path) as f:
        for line in f:
            c = line.rstrip("\n").split("\t")
            out[tuple(int(x) for x in c[:5])] = (float(c[5]), int(c[6]))
    return out

methods = ["aabb", "gpu", "gpu-naive", "aabb-thesis", "hybrid", "adaptive", "adaptive-thesis", "adaptive-cost"]
bad = 0
args = sys.argv[1:]
kinds, only_kind = 10, None
if "--kinds" in args:
    kinds = int(args[args.index("--kinds") + 1])
if "--only-kind" in args:
    only_kind = int(args[args.index("--only-kind") + 1])
for seed in range(int(args[0]), int(args[1])):
    d = os.path.join(ROOT, str(seed)); shutil.rmtree(d, ignore_errors=True); os.makedirs(d)
    names, kind, far = make_scene(seed, d, kinds, only_kind)
    for selfflag in (["--no-self"], ["--self"]):
        ref = os.path.join(d, "brute.tsv")
        r = run(["check"] + names + selfflag + ["--method", "brute", "-q", "--exit-zero", "--pairs", ref])
        if r.returncode != 0:
            print("seed", seed, "brute failed", r.stderr.strip()[-300:]); bad += 1; continue
        want = pairs(ref)
        for m, th in itertools.product(methods, (1, 2)):
            out = os.path.join(d, "m.tsv")
            r = run(["check"] + names + selfflag + ["--method", m, "--threads", str(th), "-q", "--exit-zero", "--pairs", out])
            if r.returncode != 0:
                print("seed", seed, m, th, "failed", r.stderr.strip()[-300:]); bad += 1; continue
            got = pairs(out)
            if got != want:
                bad += 1
                w, g = set(want), set(got)
                print("MISMATCH seed %d kind %d far %g %s %s threads %d: missing %d extra %d lines %d/%d e.g. %s %s" % (
                    seed, kind, far, selfflag[0], m, th, len(w - g), len(g - w), len(want), len(got),
                    sorted(w - g)[:3], sorted(g - w)[:3]))
        # between frames: ends included, same at 1, 2, 4 threads
        prev = None
        for th in (1, 2, 4):
            out = os.path.join(d, "ccd%d.tsv" % th)
            r = run(["check"] + names + selfflag + ["--between-frames", "--threads", str(th), "-q", "--exit-zero", "--pairs", out])
            if r.returncode != 0:
                print("seed", seed, "ccd", th, "failed", r.stderr.strip()[-300:]); bad += 1; break
            cur = ccd_pairs(out)
            if prev is not None and set(cur) != set(prev):
                bad += 1; print("CCD THREADS seed %d %s: %d vs %d" % (seed, selfflag[0], len(cur), len(prev)))
            prev = cur
        else:
            nf = 4
            for (f, a, ta, b, tb) in want:
                for k in (f - 1, f):
                    if 0 <= k < nf - 1:
                        v = prev.get((k, a, ta, b, tb))
                        if v is None:
                            bad += 1
                            print("CCD MISSES END PAIR seed %d kind %d far %g %s: interval %d pair %s (frame %d)" % (seed, kind, far, selfflag[0], k, (a, ta, b, tb), f))
                        elif k == f and v[0] != 0.0:
                            bad += 1
                            print("CCD TOI NOT 0 seed %d %s: interval %d pair %s toi %g" % (seed, selfflag[0], k, (a, ta, b, tb), v[0]))
                        elif v[1] != 0:
                            bad += 1
                            print("CCD PASS FLAG seed %d %s: interval %d pair %s" % (seed, selfflag[0], k, (a, ta, b, tb)))
    print("seed %d kind %d far %g done (%d brute pairs with self last)" % (seed, kind, far, len(want)), flush=True)
print("bad", bad)
