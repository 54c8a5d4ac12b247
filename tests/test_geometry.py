import math
import re
from pathlib import Path

import numpy as np
import pytest
import trimesh

from infmob_usd import geometry as g
from infmob_usd import hulls, measures, profiles, shading
from infmob_usd.errors import GeometryError
from infmob_usd.rotation import axis_angle


def _closed(piece):
    return trimesh.Trimesh(piece.vertices, piece.faces, process=False)


def test_box_bounds_volume_and_convex():
    b = g.box([0.2, 0.4, 0.6], [1, 2, 3], "m")
    assert np.allclose(b.bounds, [[0.9, 1.8, 2.7], [1.1, 2.2, 3.3]])
    assert b.volume() == pytest.approx(0.048)
    assert len(b.convex) == 1


def test_bevelled_box_is_smaller_and_convex():
    b = g.box([1, 1, 1], [0, 0, 0], "m", bevel=0.05)
    assert 0.98 < b.volume() < 1.0
    assert _closed(b).is_watertight


def test_panel_with_holes_keeps_the_hollow_for_collisions():
    p = g.panel([0, 0, 0], [0.02, 1, 1], "m", "x", holes=[(0.1, 0.1, 0.4, 0.9), (0.6, 0.1, 0.9, 0.9)])
    assert _closed(p).is_watertight
    expected = 0.02 * (1 - 2 * 0.3 * 0.8)
    assert p.volume() == pytest.approx(expected, rel=1e-6)
    hull_volume = sum(g.convex_hull(c).volume for c in p.convex)
    assert hull_volume == pytest.approx(expected, rel=1e-6)  # exact decomposition, nothing filled
    centre_of_hole = np.array([0.01, 0.25, 0.5])
    for c in p.convex:
        assert not g.convex_hull(c).contains([centre_of_hole])[0]


_GRID = [(0.1 + 0.2 * i, 0.1 + 0.2 * j, 0.2 + 0.2 * i, 0.15 + 0.2 * j) for i in range(4) for j in range(4)]


@pytest.mark.parametrize("axis", "xyz")
@pytest.mark.parametrize("holes", [
    [(0.1, 0.1, 0.9, 0.9)],  # one window
    _GRID,  # a button grid
    [(0.1, 0.1, 0.4, 0.9), (0.6, 0.3, 0.9, 0.5), (0.6, 0.6, 0.7, 0.7)],  # holes of unrelated heights
    [(0.0, 0.1, 0.4, 0.9), (0.6, 0.1, 1.0, 1.0)],  # notches at the edges and a corner
    [(0.1, 0.1, 0.5, 0.5), (0.5, 0.5, 0.9, 0.9)],  # touching at a corner only (the boolean's case)
], ids=["window", "grid", "mixed", "notches", "corner"])
def test_panel_is_a_closed_outward_solid_with_exact_holes(axis, holes):
    n = "xyz".index(axis)
    hi = np.ones(3)
    hi[n] = 0.02
    p = g.panel([0, 0, 0], hi, "m", axis, holes=holes)
    mesh = _closed(p)
    assert mesh.is_watertight and mesh.is_winding_consistent
    open_area = sum((h[2] - h[0]) * (h[3] - h[1]) for h in holes)
    # (the corner case goes through the float32 boolean: 1e-6)
    assert mesh.volume == pytest.approx(0.02 * (1 - open_area), rel=1e-6)  # positive: faces outward
    flat = np.abs(mesh.face_normals[:, n]) > 0.5  # front and back: the plate less its holes, once each
    assert mesh.area_faces[flat].sum() == pytest.approx(2 * (1 - open_area), rel=1e-6)
    assert sum(g.convex_hull(c).volume for c in p.convex) == pytest.approx(mesh.volume, rel=1e-6)
    a, b = [k for k in range(3) if k != n]
    for h in holes:  # nothing of the surface lies inside a hole
        inside = ((p.vertices[:, a] > h[0] + 1e-6) & (p.vertices[:, a] < h[2] - 1e-6)
                  & (p.vertices[:, b] > h[1] + 1e-6) & (p.vertices[:, b] < h[3] - 1e-6))
        assert not inside.any()


def test_shell_is_hollow_and_revolve_is_solid():
    s = g.shell([(0.15, 0.0), (0.08, 0.2)], 0.004, "m")
    assert _closed(s).is_watertight
    for c in s.convex:
        assert not g.convex_hull(c).contains([[0, 0, 0.1]])[0]
    r = g.revolve([(0, 0), (0.1, 0), (0.1, 0.2), (0, 0.2)], "m", sections=64)
    assert r.volume() == pytest.approx(np.pi * 0.01 * 0.2, rel=0.01)


def test_uvs_have_one_texel_density():
    small = g.box([0.1, 0.1, 0.1], [0, 0, 0], "m")
    big = g.box([1.0, 1.0, 1.0], [0, 0, 0], "m")
    span = lambda p: np.ptp(p.corner_uvs().reshape(-1, 2), axis=0)  # noqa: E731
    assert np.allclose(span(big) / span(small), 10)
    assert np.allclose(span(big), 1.0 / shading.UV_TILE)


def test_corner_normals_split_at_box_edges_and_smooth_on_cylinders():
    b = g.box([1, 1, 1], [0, 0, 0], "m")
    n = b.corner_normals()
    assert np.allclose(np.abs(n).max(axis=2), 1.0)  # flat faces: axis-aligned normals
    c = g.cylinder([0, 0, 0], [0, 0, 1], 0.5, "m", sections=32)
    side = np.abs(c.face_normals()[:, 2]) < 0.1
    cn = c.corner_normals()[side]
    assert np.allclose(np.linalg.norm(cn[..., :2], axis=-1), 1.0, atol=1e-6)
    assert not np.allclose(cn[:, 0], cn[:, 1])  # smooth: corners differ within a face


def test_corrupt_meshes_are_rejected_with_a_clear_error():
    v = np.zeros((3, 3))
    with pytest.raises(GeometryError, match="NaN"):
        g.Piece(np.array([[0, 0, 0], [1, 0, 0], [np.nan, 1, 0]]), [[0, 1, 2]], "m")
    with pytest.raises(GeometryError, match="missing vertex"):
        g.Piece(v, [[0, 1, 5]], "m")
    with pytest.raises(GeometryError, match="positive"):
        g.box([0, 1, 1], [0, 0, 0], "m")


def test_collision_hulls_stay_within_physx_vertex_limit():
    ball = g.sphere([0, 0, 0], 0.1, "m")
    rng = np.random.default_rng(0)
    pts = rng.normal(size=(3000, 3))
    ball = ball.replace(convex=[pts / np.linalg.norm(pts, axis=1, keepdims=True) * 0.1])  # ~3000 hull vertices
    (v, f), = ball.hulls()
    assert len(v) <= hulls.MAX_HULL_VERTICES
    assert trimesh.Trimesh(v, f).is_watertight
    assert np.ptp(v, axis=0).min() > 0.19  # still spans the sphere


def test_a_piece_is_an_immutable_value():
    import dataclasses

    b = g.box([0.1, 0.2, 0.3], [0, 0, 0], "m")
    with pytest.raises(dataclasses.FrozenInstanceError):
        b.sheet = 0.001
    for a in (b.vertices, b.faces, *b.convex):
        with pytest.raises(ValueError):
            a[0] = 0  # read-only arrays: an edit in place fails loudly
    src = np.r_[np.eye(3), [[0, 0, 0]]]
    p = g.Piece(src, [[0, 1, 2]], "m", [src])
    src[:] = 7  # the caller's arrays are copied, not frozen under them
    assert src.flags.writeable and p.vertices.sum() == 3 and p.convex[0].sum() == 3
    thin = b.replace(sheet=0.001)
    assert thin is not b and b.sheet == 0.0 and thin.sheet == 0.001
    assert thin.hulls_known[0] is not None  # the declared hull travels with an unchanged collision
    bare = b.replace(convex=[])
    assert bare.convex == () and bare.hulls() == [] and len(b.hulls()) == 1


def test_declared_hulls_skip_qhull_and_travel_with_transforms():
    c = g.cylinder([0, 0, 0], [0, 0, 0.2], 0.05, "m", 24)
    (v, f), = c.hulls()
    assert np.array_equal(f, c.hulls_known[0][1])  # the declared hull, not a Qhull one
    m = np.eye(4)
    m[:3, :3] = axis_angle([1, 0, 0], 0.3)
    m[:3, 3] = [1, 2, 3]
    moved = c.transformed(m)
    (mv, mf), = moved.hulls()
    assert np.array_equal(mf, f) and np.allclose(mv, v @ m[:3, :3].T + m[:3, 3])
    assert trimesh.Trimesh(mv, mf).is_watertight and trimesh.Trimesh(mv, mf).volume > 0


# -- tolerances: sections round an axis, profile points, collision bands ---------------------------


def test_sections_for_keeps_the_sagitta_within_the_chord_tolerance_with_the_fewest_multiple_of_4():
    for r in (0.002, 0.01, 0.035, 0.1, 0.3, 1.0):
        n = g.sections_for(r)
        assert n % 4 == 0 and 12 <= n <= 64
        if 12 < n < 64:
            assert r * (1 - math.cos(math.pi / n)) <= profiles.CHORD_TOL + 1e-12
            assert r * (1 - math.cos(math.pi / (n - 4))) > profiles.CHORD_TOL  # four fewer would not do
    assert [g.sections_for(r) for r in (0.002, 0.01, 0.035, 0.1, 1.0)] == [12, 12, 24, 36, 64]
    assert 360 / g.sections_for(0.0) < shading.CREASE_DEG  # never so few that the normals split: flat shading
    # the default of revolve and shell: a small knob gets few sections, a wide bowl many
    knob = g.revolve([(0, 0), (0.01, 0), (0.01, 0.01), (0, 0.01)], "m")
    bowl = g.shell([(0.15, 0.0), (0.16, 0.05)], 0.003, "m")
    assert len(knob.faces) == 2 * 12 * 3 - 2 * 12 and len(bowl.vertices) == 4 * g.sections_for(0.16)


def test_simplify_profile_keeps_the_curve_within_tolerance_and_turns_gently():
    t = np.linspace(-math.pi / 2, 0, 400)
    arc = np.c_[0.05 * np.cos(t), 0.05 * np.sin(t)]  # a 5 cm quarter circle, then straight on up
    line = np.c_[np.full(100, 0.05), np.linspace(0.0, 0.25, 100)]
    pts = np.vstack([arc, line[1:]])
    out = g.simplify_profile(pts)
    assert np.allclose(out[0], pts[0]) and np.allclose(out[-1], pts[-1]) and len(out) < 30
    # every original point within PROFILE_TOL of the thinned polyline
    seg_a, seg_b = out[:-1], out[1:]
    d = seg_b - seg_a
    w = np.clip(np.einsum("ijk,jk->ij", pts[:, None] - seg_a[None], d) / np.einsum("jk,jk->j", d, d), 0, 1)
    near = np.linalg.norm(pts[:, None] - (seg_a[None] + w[..., None] * d[None]), axis=2).min(1)
    assert near.max() <= profiles.PROFILE_TOL + 1e-12
    heading = np.degrees(np.arctan2(*np.diff(out, axis=0).T[::-1]))
    assert np.abs(np.diff(heading)).max() <= 20.0 + 1e-9  # smooth normals where the curve was smooth


def test_shell_merges_collinear_collision_bands_and_stays_hollow():
    zs = np.linspace(0.0, 0.2, 9)
    straight = g.shell(np.c_[np.full(9, 0.05), zs], 0.003, "m", convex_sectors=12)
    assert len(straight.convex) == 12  # eight collinear bands collide as one
    bent = g.shell([(0.05, 0.0), (0.05, 0.1), (0.03, 0.2)], 0.003, "m", convex_sectors=12)
    assert len(bent.convex) == 24
    inside = np.vstack(straight.convex)
    assert np.hypot(inside[:, 0], inside[:, 1]).min() > 0.04  # no hull reaches the axis: a hollow wall



def test_batched_masses_and_the_qhull_runner_match_one_at_a_time_bit_for_bit():
    from scipy.spatial import ConvexHull

    from infmob_usd.api import generate

    def fresh(p):  # the same value with nothing measured yet
        return g.Piece(p.vertices, p.faces, p.material, p.convex, p.name, p.sheet, p.hulls(), wall=p.wall)

    pieces = [p for link in generate("beverage_fridge", seed=0, texture_size=16).links for p in link.pieces]
    pieces += [g.sphere([0.1, 0.2, 0.3], 0.05, "m"), g.tube([[0, 0, 0], [0, 0, 0.3], [0.2, 0, 0.4]], 0.01, "m"),
               g.revolve([(0, 0), (0.1, 0), (0.08, 0.2), (0, 0.25)], "m", center=[0.3, 0, 0])]
    shells = [k % 3 == 0 for k in range(len(pieces))]
    batch = [fresh(p) for p in pieces]
    measures._measure_closed(list(zip(batch, shells)))
    assert sum("_solids" in p.__dict__ for p in batch) > len(batch) // 2
    for p, b, w in zip(pieces, batch, shells):
        one = measures._solid_parts(fresh(p), w)
        got = measures._solid_parts(b, w)
        for x, y in zip(one[1:], got[1:]):
            for px, py in zip(x, y):
                for u, v in zip(px, py):
                    assert np.asarray(u).tobytes() == np.asarray(v).tobytes()
    rng = np.random.default_rng(0)
    for n in (5, 24, 300):
        pts = rng.normal(size=(n, 3))
        assert np.array_equal(hulls._simplices(pts), ConvexHull(pts).simplices)


def test_revolve_arrays_hands_out_its_own_faces():
    """The face topology is cached per (sections, axis points, closure): a caller that edits the faces
    it got must not change what the next caller gets."""
    prof = np.array([[0, 0], [0.05, 0], [0.05, 0.1], [0, 0.1]])
    v1, f1 = g.revolve_arrays(prof, 16)
    f1[:] = 0
    v2, f2 = g.revolve_arrays(prof * 2, 16)
    assert f2.flags.writeable and f2.max() == len(v2) - 1
    assert _closed(g.Piece(v2, f2, "m")).is_watertight
    inward = prof[::-1].copy()  # the same outline walked the other way: faces still outward
    v3, f3 = g.revolve_arrays(inward, 16)
    assert measures.mass_properties(v3, f3)[0] > 0


def test_the_authoring_api_names_what_categories_use():
    """``infmob_usd.geometry`` is the vocabulary categories build with: every ``g.<name>`` a category, a
    part library or a worked example uses is in its ``__all__``, and every name there exists."""
    root = Path(__file__).resolve().parents[1]
    used = set()
    for path in [*(root / "categories").rglob("*.py"), *(root / "docs" / "examples").glob("*.py")]:
        text = path.read_text()
        if "import geometry as g" in text:
            used |= set(re.findall(r"\bg\.([A-Za-z_]\w*)", text))
    assert used, "the scan found no category using the geometry API"
    unlisted = sorted(used - set(g.__all__))
    assert not unlisted, f"categories use names the geometry API does not list: {unlisted}"
    assert all(hasattr(g, name) for name in g.__all__), [n for n in g.__all__ if not hasattr(g, n)]
