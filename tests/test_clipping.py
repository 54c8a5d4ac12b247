"""The grasp search's batched cuts (infmob_usd/clipping.py, interaction._pinches, Neighbours.many, _path) give
the very floats of the one-at-a-time code they replace: trimesh's slicer, ``pinch``, ``Neighbours._one`` and
``obj.poses``."""

from __future__ import annotations

import numpy as np
import pytest
from trimesh.intersections import slice_faces_plane

from infmob_usd import api, clipping, interaction
from infmob_usd.interaction import _Part, _pinches, _soup, pinch

pytestmark = pytest.mark.skipif(not clipping.EXACT, reason="this BLAS rounds unlike the batch: the slicer is kept")


def _soups(rng, grid: bool):
    """Problems of random triangles and six planes each; ``grid``: on a 1 cm grid with axis normals, so
    vertices and whole triangles lie on the planes."""
    out = []
    for _ in range(6):
        v = rng.normal(size=(30, 3)) * 0.05
        c = rng.normal(size=3) * 0.02
        if grid:
            v, c = np.round(v, 2), np.round(c, 2)
        f = rng.integers(0, len(v), size=(int(rng.integers(1, 40)), 3))
        planes = []
        for _ in range(6):
            n = np.eye(3)[rng.integers(3)] * rng.choice([-1.0, 1.0]) if grid else rng.normal(size=3)
            off = float(rng.choice([0.0, 0.01, 0.02])) if grid else float(rng.uniform(0.0, 0.05))
            planes.append((n / np.linalg.norm(n), off))
        out.append((v, f, c, planes))
    return out


@pytest.mark.parametrize("grid", [False, True])
def test_clip_is_the_slicer_bit_for_bit(grid):
    rng = np.random.default_rng(5 + grid)
    for _ in range(40):
        problems = _soups(rng, grid)
        want = []
        for v, f, c, planes in problems:
            for n, off in planes:
                if len(f):
                    v, f = slice_faces_plane(v, f, n, c - n * off)[:2]
            want.append(sorted(map(bytes, v[f])) if len(f) else [])
        tri = np.concatenate([v[f] for v, f, _, _ in problems])
        pid = np.repeat(np.arange(len(problems)), [len(f) for _, f, _, _ in problems])
        normals = np.array([[n for n, _ in p[3]] for p in problems])
        origins = np.array([[p[2] - n * off for n, off in p[3]] for p in problems])
        got, of = clipping.clip(tri, pid, normals, origins)
        assert [sorted(map(bytes, got[of == i])) for i in range(len(problems))] == want


def test_gemv_rows_rounds_as_numpy_dot():
    rng = np.random.default_rng(2)
    x, n = rng.normal(size=(4000, 3)), rng.normal(size=3)
    assert (clipping.gemv_rows(x, n) == x @ n).all()
    assert (clipping.gemv_rows(x.reshape(-1, 2, 3), n) == x.reshape(-1, 2, 3) @ n).all()


@pytest.fixture(scope="module")
def cabinet():
    return api.generate("kitchen_cabinet", 1, texture_size=16)


def test_batched_pinches_are_pinch(cabinet):
    """Every candidate pinch of a real part, cut in one batch, gives pinch's width, depth and middle."""
    rng = np.random.default_rng(3)
    link = max((lk for lk in cabinet.links if lk.pieces), key=lambda lk: len(_soup(lk.pieces)[1]))
    v, f = _soup(link.pieces)[:2]
    part = _Part(v, f)
    problems = []
    for _ in range(150):
        c = v[rng.integers(len(v))] + rng.normal(size=3) * 0.005
        d = rng.normal(size=3)
        d /= np.linalg.norm(d)
        k = np.cross(d, rng.normal(size=3))
        problems.append((c, d, k / np.linalg.norm(k)))
    want = [pinch(v, f[part.near(c)], c, d, k) for c, d, k in problems]
    assert sum(w is not None for w in want) > 50  # most of them hold material: the floats are compared
    assert _pinches(part, problems) == want


def test_batched_neighbours_are_one_by_one(cabinet):
    """The hand boxes of every annotated grasp meet the same links cut in one batch as one by one."""
    checked = 0
    for t in cabinet.interaction:
        carrier = cabinet.link(t["link"])
        v, f, _, own = interaction._carried(cabinet, carrier)
        for press in (False, True):
            near = interaction.Neighbours(cabinet, carrier, own, (v, f), press)
            grasps = [interaction.Grasp.make(g["position"], g["approach"], g["closing"], g["width"], g["depth"])
                      for g in t["grasps"]]
            assert near.many(grasps) == [near._one(g, press) for g in grasps]
            checked += len(grasps)
    assert checked >= 10


def test_path_is_read_from_poses(cabinet):
    for t in cabinet.interaction:
        joint = next(j for j in cabinet.joints if j.name == t["joint"])
        p = np.append(np.asarray(t["grasps"][0]["position"]), 1.0)
        want = [(cabinet.poses({joint.name: t["rest"] + (t["open"] - t["rest"]) * i / 10})[t["link"]] @ p)[:3]
                .tolist() for i in range(11)]
        assert t["path"] == want


def test_the_one_at_a_time_fallback_annotates_the_same(cabinet, monkeypatch):
    """Where the BLAS rounds unlike the batch (clipping.EXACT false), the slicer path gives the same targets."""
    monkeypatch.setattr(interaction, "EXACT", False)
    assert interaction.annotate(cabinet) == cabinet.interaction
