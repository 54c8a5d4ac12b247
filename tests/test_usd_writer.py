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
