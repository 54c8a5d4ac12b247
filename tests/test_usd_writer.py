"""The Sdf-level USD writer: vectorised surface attributes, determinism, texture-map presence."""

from __future__ import annotations

import numpy as np
import pytest
from pxr import Sdf, Usd, UsdShade

import infmob_usd
from infmob_usd.layers.usd import _bounds, _visual_meshes, write_usd
from infmob_usd.shading import corner_attributes, grain_frame


@pytest.fixture(scope="module")
def objects():
    return [infmob_usd.generate(c, seed=s, texture_size=16)
            for c, s in (("microwave", 1), ("bottle", 0), ("storage_rack", 0), ("kitchen_cabinet", 2))]


def test_corner_attributes_match_the_pieces_bit_for_bit(objects):
    for obj in objects:
        pieces = [p for link in obj.links for p in link.pieces]
        verts, faces, frames, off = [], [], [], 0
        for p in pieces:
            verts.append(p.vertices)
            faces.append(p.faces + off)
            frames.append(np.broadcast_to(grain_frame(p.vertices), (len(p.faces), 3, 3)))
            off += len(p.vertices)
        normals, uvs = corner_attributes(np.vstack(verts), np.vstack(faces), np.concatenate(frames))
        want_n = np.concatenate([p.corner_normals().reshape(-1, 3) for p in pieces])
        want_uv = np.concatenate([p.corner_uvs().reshape(-1, 2) for p in pieces])
        assert np.array_equal(normals, want_n), obj.name
        assert np.array_equal(uvs, want_uv), obj.name


def test_bounds_match_the_object(objects):
    for obj in objects:
        lo, hi = _bounds(obj, _visual_meshes(obj))
        assert np.array_equal(np.array([lo, hi]), obj.bounds())


def test_same_object_gives_identical_files(objects, tmp_path):
    obj = objects[0]
    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir()
    b.mkdir()
    write_usd(obj, a)
    write_usd(obj, b)
    files = sorted(p.relative_to(a) for p in a.rglob("*") if p.is_file())
    assert len(files) == 5
    for f in files:
        assert (a / f).read_bytes() == (b / f).read_bytes(), f


def test_texture_readers_only_for_maps_written(objects, tmp_path):
    obj = objects[0]
    slots = list(obj.materials)
    saved = obj.textures
    try:
        obj.textures = {s: {"basecolor": b"", "normal": b""} for s in slots}
        obj.textures[slots[0]] = {m: b"" for m in ("basecolor", "roughness", "metallic", "normal")}
        path = write_usd(obj, tmp_path)
    finally:
        obj.textures = saved
    stage = Usd.Stage.Open(str(path))
    root = stage.GetDefaultPrim().GetPath()
    full = UsdShade.Shader.Get(stage, root.AppendPath(f"Looks/{slots[0]}/PreviewSurface"))
    for inp in ("diffuseColor", "roughness", "metallic", "normal"):
        assert full.GetInput(inp).HasConnectedSource(), inp
    for slot in slots[1:]:
        look = obj.materials[slot]
        surf = UsdShade.Shader.Get(stage, root.AppendPath(f"Looks/{slot}/PreviewSurface"))
        assert surf.GetInput("diffuseColor").HasConnectedSource()
        assert surf.GetInput("normal").HasConnectedSource()
        rough = min(1.0, look.roughness * look.wear.roughness_scale)  # this object's wear of the look
        for inp, value in (("roughness", rough), ("metallic", look.metallic)):
            i = surf.GetInput(inp)
            assert not i.HasConnectedSource()
            assert i.GetTypeName() == Sdf.ValueTypeNames.Float
            assert i.Get() == pytest.approx(value, rel=1e-6)
        for tex in ("roughness", "metallic"):
            assert not stage.GetPrimAtPath(root.AppendPath(f"Looks/{slot}/{tex}Texture"))
        assert stage.GetPrimAtPath(root.AppendPath(f"Looks/{slot}/basecolorTexture"))


def test_text_layers_are_what_sdf_writes(objects, tmp_path):
    """contents.usda, materials.usda and physics.usda are written as text, not through Sdf: Sdf reads each back with
    the specs meant (bindings, colliders, joints) and saves it byte for byte as written (its own form:
    property order, float32 digits, indents)."""
    for i, obj in enumerate(objects):
        folder = tmp_path / str(i)
        folder.mkdir()
        write_usd(obj, folder)
        for name in ("contents.usda", "materials.usda", "physics.usda"):
            path = folder / "payload" / name
            layer = Sdf.Layer.FindOrOpen(str(path))
            assert layer.ExportToString() == path.read_text(), (obj.name, name)
        stage = Usd.Stage.Open(str(folder / f"{obj.name}.usda"))
        for link in obj.links:
            body = stage.GetPrimAtPath(f"/{obj.name}/{link.name}")
            assert body.GetAttribute("physics:mass").Get() == pytest.approx(link.mass, rel=1e-6)
            hulls, visuals = body.GetChild("collisions"), body.GetChild("visuals")
            assert bool(hulls) == bool(link.pieces) == bool(visuals)
            for hull in hulls.GetChildren() if hulls else ():
                assert hull.GetRelationship("material:binding:physics").GetTargets()
            for vis in visuals.GetChildren() if visuals else ():
                assert UsdShade.MaterialBindingAPI(vis).GetDirectBinding().GetMaterial()
        for j in obj.joints:
            joint = stage.GetPrimAtPath(f"/{obj.name}/Joints/{j.name}")
            assert joint.GetRelationship("physics:body1").GetTargets() == [Sdf.Path(f"/{obj.name}/{j.child}")]


def _colocated(v: np.ndarray) -> int:
    return len(v) - len(np.unique(np.asarray(v, np.float32) + np.float32(0), axis=0))


def test_no_visual_mesh_has_two_points_at_one_place_and_no_face_is_lost(objects):
    """Pieces of one material that touch are written as separate meshes (omniverse-asset-validator's WeldChecker
    finds nothing to merge, and no edge is shared by four faces); every face, normal and UV is still written."""
    from infmob_usd.layers.common import visual_meshes

    split = 0
    for obj in objects:
        for lname, meshes in _visual_meshes(obj).items():
            source = {m[0]: m for m in visual_meshes(obj)[lname]}
            names = [m[0] for m in meshes]
            assert len(names) == len(set(names)), (obj.name, lname)
            for name, _slot, _role, v, _lo, _hi, f, n, uv in meshes:
                assert _colocated(v) == 0, (obj.name, lname, name)
                assert len(n) == len(uv) == 3 * len(f) and f.max() < len(v)
            for vname, _slot, _role, v, f, _n, _uv in source.values():
                parts = [m for m in meshes if m[0] == vname or m[0].startswith(vname + "_w")]
                split += len(parts) > 1
                assert sum(len(m[6]) for m in parts) == len(f), (obj.name, vname)
                got = np.concatenate([m[3][m[6]].reshape(-1, 9) for m in parts])
                want = v.astype(np.float32)[f].reshape(-1, 9)
                assert np.array_equal(np.unique(got, axis=0), np.unique(want, axis=0)), (obj.name, vname)
    assert split, "no object here has touching pieces: the test would prove nothing"


def test_a_piece_touching_itself_is_cut_where_it_touches():
    """A strip whose two ends meet at one place (a wire loop) is one connected piece with two points at one
    place: it is cut into parts, each without such points, rather than welded into a non-manifold vertex."""
    from infmob_usd.layers.usd import _weld_free

    # a closed square ring of 4 quads whose last vertex pair repeats the first pair's places (a seam)
    ring = [(0, 0), (1, 0), (1, 1), (0, 1), (0, 0)]
    v = np.array([(x, y, z) for x, y in ring for z in (0.0, 0.1)])
    f = np.array([[2 * i, 2 * i + 2, 2 * i + 3] for i in range(4)] + [[2 * i, 2 * i + 3, 2 * i + 1] for i in range(4)])
    n = np.zeros((3 * len(f), 3))
    uv = np.zeros((3 * len(f), 2))
    out = _weld_free("loop", {"loop"}, v, f, n, uv)
    assert len(out) >= 2 and out[0][0] == "loop" and out[1][0] == "loop_w1"
    assert sum(len(m[2]) for m in out) == len(f)
    assert all(_colocated(m[1]) == 0 for m in out)
