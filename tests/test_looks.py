"""Believable materials: grain along each part, one texel density, see-through glass, mirror
chrome, appliance palettes, and per-object wear of library looks written as shader inputs."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from pxr import Usd, UsdShade

import infmob_usd
from infmob_usd import geometry as g
from infmob_usd import shading
from infmob_usd.layers.common import visual_meshes
from infmob_usd.materials import APPLIANCE, FAMILIES, library_look, sample_look, split_spec, synthesize
from infmob_usd.materials.cache import _look_key
from infmob_usd.materials.families import sample_wear
from infmob_usd.materials.synth import TILE_METRES


def _u_extent(piece: g.Piece, facing: int) -> tuple[float, float]:
    """(U, V) extents in metres of the faces of ``piece`` facing world axis ``facing``."""
    uv = piece.corner_uvs()
    n = piece.face_normals()
    sel = np.abs(n[:, facing]) > 0.9
    span = np.ptp(uv[sel].reshape(-1, 2), axis=0) * shading.UV_TILE
    return float(span[0]), float(span[1])


def test_one_texel_density_for_uvs_and_textures():
    assert TILE_METRES == shading.UV_TILE


def test_grain_runs_along_a_leg_a_rail_and_a_top():
    leg = g.box([0.05, 0.05, 0.72], [0, 0, 0.36], "wood")
    for facing in (0, 1):  # the four sides: U runs up the leg
        u, v = _u_extent(leg, facing)
        assert u == pytest.approx(0.72) and v == pytest.approx(0.05)
    rail = g.box([0.04, 1.2, 0.1], [0, 0, 0], "wood")  # a rail along Y
    for facing in (0, 2):
        assert _u_extent(rail, facing)[0] == pytest.approx(1.2)
    top = g.box([0.9, 1.6, 0.03], [0, 0, 0], "wood")  # grain along the long side of a top
    assert _u_extent(top, 2) == (pytest.approx(1.6), pytest.approx(0.9))
    arm = g.cylinder([0, 0, 0], [0.3, 0, 0.3], 0.01, "chrome")  # a slanted tube: U along it
    frame = shading.grain_frame(arm.vertices)
    np.testing.assert_allclose(frame[:, 0], [2 ** -0.5, 0, 2 ** -0.5], atol=1e-9)


def test_a_box_long_in_x_keeps_the_world_projection():
    np.testing.assert_array_equal(shading.grain_frame(g.box([1.0, 0.5, 0.1], [0, 0, 0], "m").vertices), np.eye(3))


def _gradients(img: np.ndarray) -> tuple[float, float]:
    """Mean absolute difference between neighbours along U (columns) and along V (rows)."""
    x = img.astype(float).mean(-1) if img.ndim == 3 else img.astype(float)
    return float(np.abs(np.diff(x, axis=1)).mean()), float(np.abs(np.diff(x, axis=0)).mean())


@pytest.mark.parametrize("family,variant", [("wood", "oak"), ("wood", "maple"), ("brushed_metal", "stainless")])
def test_grain_and_brushing_run_along_u(family, variant):
    for k in range(3):
        along, across = _gradients(synthesize(library_look(family, variant, k), 256)["basecolor"])
        assert across > 1.5 * along, (along, across)


def test_chrome_is_a_mirror_without_rings():
    for k in range(4):
        look = library_look("chrome", "chrome", k)
        maps = synthesize(look, 256)
        assert maps["roughness"].max() < 0.1 * 255
        low = np.asarray(maps["basecolor"], float).reshape(16, 16, 16, 16, 3).mean((1, 3))  # 16 px blocks
        assert low.std(axis=(0, 1)).max() < 0.5  # no bands: under half a level between blocks


def test_wear_varies_per_object_but_not_the_library_look():
    look = library_look("wood", "oak", 3)
    a, b = (dataclasses.replace(look, wear=sample_wear(look, np.random.default_rng(s))) for s in (1, 2))
    assert a.wear != b.wear
    assert a == b == look and hash(a) == hash(look)  # the same library look, the same cached maps
    assert _look_key(a, 512) == _look_key(look, 512)
    assert a.to_dict()["wear"]["uv_offset"] == list(a.wear.uv_offset)
    assert type(a).from_dict(a.to_dict()).wear == a.wear


def test_wear_rotation_keeps_the_grain_along_the_part():
    rng = np.random.default_rng(0)
    for family in ("wood", "brushed_metal"):
        assert {sample_look(family, rng).wear.uv_rotation for _ in range(40)} == {0.0, 180.0}
    rots = {sample_look("plastic", rng).wear.uv_rotation for _ in range(40)}
    assert len(rots) == 40  # isotropic finishes turn any way
    for _ in range(40):
        look = sample_look("rubber", rng)  # the roughest family: a scaled map stays below 1
        assert look.wear.roughness_scale * (look.roughness + 2.5 * look.roughness_variation) <= 0.98 + 1e-9
        assert all(0.5 <= t <= 2.0 for t in look.wear.tint)


@pytest.fixture(scope="module")
def window(tmp_path_factory):
    obj = infmob_usd.generate("window", seed=1, texture_size=16)
    return obj, infmob_usd.save(obj, tmp_path_factory.mktemp("looks"))


def _mtl(folder, slot: str) -> dict[str, str]:
    """The ``newmtl slot`` block of the object's MTL."""
    lines = (folder / "meshes" / "materials.mtl").read_text().splitlines()
    block = lines[lines.index(f"newmtl {slot}") + 1:]
    block = block[:next((i for i, ln in enumerate(block) if ln.startswith("newmtl ")), len(block))]
    return {ln.split(" ", 1)[0]: ln.split(" ", 1)[1] for ln in block if " " in ln}


def test_writers_apply_the_wear_as_shader_inputs(window):
    obj, folder = window
    stage = Usd.Stage.Open(str(next(folder.glob("*.usda"))))
    root = stage.GetDefaultPrim().GetPath()
    for slot, look in obj.materials.items():
        w = look.wear
        mat = root.AppendPath(f"Looks/{slot}")
        xf = UsdShade.Shader.Get(stage, mat.AppendPath("UVTransform"))
        assert xf.GetIdAttr().Get() == "UsdTransform2d"
        assert xf.GetInput("rotation").Get() == pytest.approx(w.uv_rotation, abs=1e-4)
        assert tuple(xf.GetInput("translation").Get()) == pytest.approx(w.uv_offset, abs=1e-6)
        base = UsdShade.Shader.Get(stage, mat.AppendPath("basecolorTexture"))
        assert tuple(base.GetInput("scale").Get())[:3] == pytest.approx(w.tint, abs=1e-6)
        src = base.GetInput("st").GetConnectedSources()[0][0].source.GetPath()
        assert src == mat.AppendPath("UVTransform")
        rough = UsdShade.Shader.Get(stage, mat.AppendPath("roughnessTexture"))
        assert tuple(rough.GetInput("scale").Get())[0] == pytest.approx(w.roughness_scale, abs=1e-6)
        mtl = _mtl(folder, slot)
        assert [float(x) for x in mtl["Kd"].split()] == pytest.approx(w.tint, abs=1e-4)
        assert mtl["map_Pr"].startswith(f"-mm 0 {w.roughness_scale:.4f} ")
    # the OBJ texture coordinates carry the rotation and offset (every URDF reader honours them)
    link = obj.links[0]
    vname, slot, _, _, _, _, uv = visual_meshes(obj)[link.name][0]
    m = obj.materials[slot].wear.uv_matrix()
    want = np.unique(np.round(uv @ m[:, :2].T + m[:, 2], 6), axis=0)
    text = (folder / "meshes" / f"{link.name}__{vname}.obj").read_text().splitlines()
    got = np.unique(np.array([[float(x) for x in ln.split()[1:3]] for ln in text if ln.startswith("vt ")]), axis=0)
    np.testing.assert_allclose(got, want, atol=2e-6)


def test_glass_is_see_through_in_usd_and_mtl(window):
    obj, folder = window
    look = obj.materials["glass"]
    assert look.opacity < 0.2
    stage = Usd.Stage.Open(str(next(folder.glob("*.usda"))))
    surf = UsdShade.Shader.Get(stage, stage.GetDefaultPrim().GetPath().AppendPath("Looks/glass/PreviewSurface"))
    assert surf.GetInput("opacity").Get() == pytest.approx(look.opacity, abs=1e-6)
    assert surf.GetInput("ior").Get() == pytest.approx(1.52)
    mtl = _mtl(folder, "glass")
    assert float(mtl["d"]) == pytest.approx(look.opacity, abs=1e-3)
    assert float(mtl["Tr"]) == pytest.approx(1 - look.opacity, abs=1e-3)
    frame = UsdShade.Shader.Get(stage, stage.GetDefaultPrim().GetPath().AppendPath("Looks/frame/PreviewSurface"))
    assert not frame.GetInput("ior")  # opaque looks say nothing about refraction


@pytest.mark.parametrize("category", ["microwave", "oven", "beverage_fridge", "dishwasher"])
def test_appliance_bodies_wear_real_appliance_finishes(category):
    allowed = {}
    for spec in APPLIANCE.values():
        family, variants = split_spec(spec)
        allowed[family] = set(variants) or {v for v, _ in FAMILIES[family].palette}
    for seed in range(3):
        obj = infmob_usd.generate(category, seed=seed, texture_size=16)
        body = obj.materials["body"]
        assert body.variant in allowed[body.family], (seed, body.family, body.variant)
        assert "pastel" not in body.variant


def test_tv_screen_is_glossy_and_bulbs_warm_white():
    tv = infmob_usd.generate("tv", seed=0, texture_size=16)
    assert tv.materials["display"].family == "screen" and tv.materials["display"].roughness < 0.1
    lamp = infmob_usd.generate("lamp", seed=0, texture_size=16, has_bulb=True)
    assert lamp.materials["bulb"].variant == "frosted"



@pytest.mark.parametrize("category", ["kitchen_cabinet", "lamp", "cocktail_table", "dining_table", "office_chair",
                                      "bar_chair", "plate_rack", "storage_rack", "door", "window"])
def test_furniture_wears_real_paint_and_plastic_colours(category):
    """Kitchens, tables, chairs, lamps, racks, doors and windows draw painted and moulded parts from the
    furniture palette (materials.palettes.FURNITURE): no pastel-pink carcass, no teal lamp fitting. A slot
    that names its own variants (a bar stool's coloured seat, a storage crate) keeps them."""
    from infmob_usd.materials.palettes import FURNITURE

    cat = infmob_usd.get_category(category)
    checked = 0
    for seed in range(8):
        obj = infmob_usd.generate(category, seed=seed, texture_size=16)
        specs = cat.resolve_materials(obj.params)
        for slot, look in obj.materials.items():
            family, variants = split_spec(specs[slot])
            assert variants or family not in FURNITURE, (slot, specs[slot])  # no bare painted / plastic
            if specs[slot] == FURNITURE.get(family):
                assert look.variant in variants, (slot, look.variant)
                checked += 1
    if category in ("kitchen_cabinet", "lamp", "cocktail_table"):  # their paints and fittings come from it
        assert checked


def test_brushed_steel_carries_its_anisotropy_along_the_part(tmp_path):
    import json
    import struct

    obj = infmob_usd.generate("pot", seed=1, texture_size=16, body_finish="brushed_metal")
    folder = infmob_usd.save(obj, tmp_path, formats="urdf,glb")
    brushed = [s for s, look in obj.materials.items() if look.family == "brushed_metal"]
    assert brushed
    raw = next(folder.glob("*.glb")).read_bytes()
    (length,) = struct.unpack_from("<I", raw, 12)
    doc = json.loads(raw[20:20 + length])
    assert "KHR_materials_anisotropy" in doc["extensionsUsed"]
    for mat in doc["materials"]:
        ext = mat.get("extensions", {}).get("KHR_materials_anisotropy")
        if mat["name"] in brushed:
            assert ext == {"anisotropyStrength": pytest.approx(0.6), "anisotropyRotation": 0.0}
        else:
            assert ext is None
    # no MTL "aniso": Assimp's MTL reader (SAPIEN, URDF importers) fails to load a mesh that has it
    assert not any(ln.startswith("aniso") for m in folder.glob("meshes/*.mtl") for ln in m.read_text().splitlines())
