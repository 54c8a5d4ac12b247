import json
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from pxr import Sdf, Usd, UsdGeom, UsdPhysics, UsdShade

import infmob_usd
from infmob_usd.errors import OutputError

from zoo import zoo


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    obj = zoo()
    return obj, infmob_usd.save(obj, tmp_path_factory.mktemp("zoo"))


def test_folder_layout(written):
    obj, folder = written
    assert folder.name == "zoo_000000"
    for rel in ["zoo_000000.usda", "zoo_000000.urdf", "payload/contents.usda", "payload/geometry.usdc",
                "payload/materials.usda", "payload/physics.usda", "semantics.txt", "metadata.json", "annotations.json",
                "textures/body_basecolor.png", "textures/part_normal.png"]:
        assert (folder / rel).is_file(), rel
    assert not [p for p in folder.parent.iterdir() if p.name.startswith(".")]  # no temp folders left



def test_one_mtl_holds_every_material_and_each_visual_obj_finds_its_own(written):
    """meshes/ holds one MTL with a ``newmtl`` per material slot; every visual OBJ names that file and a
    material in it, and every map it lists is a file of the object."""
    obj, folder = written
    meshes = folder / "meshes"
    assert [m.name for m in meshes.glob("*.mtl")] == ["materials.mtl"]
    lines = (meshes / "materials.mtl").read_text().splitlines()
    assert [ln.split(" ", 1)[1] for ln in lines if ln.startswith("newmtl ")] == list(obj.materials)
    for ln in lines:
        if ln.startswith(("map_", "norm ")):
            assert (meshes / ln.split()[-1]).is_file(), ln
    visuals = [p for p in meshes.glob("*.obj") if "__collision_" not in p.name]
    assert visuals
    for p in visuals:
        head = [ln for ln in p.read_text().splitlines() if ln.startswith(("mtllib ", "usemtl "))]
        assert head[0] == "mtllib materials.mtl" and head[1].split(" ", 1)[1] in obj.materials, p.name

def test_interface_layer(written):
    obj, folder = written
    stage = Usd.Stage.Open(str(folder / "zoo_000000.usda"))
    root = stage.GetDefaultPrim()
    assert root.GetPath() == Sdf.Path("/zoo_000000")
    assert Usd.ModelAPI(root).GetKind() == "component"
    assert Usd.ModelAPI(root).GetAssetInfo()["name"] == "zoo_000000"
    assert UsdGeom.GetStageUpAxis(stage) == "Z" and UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert UsdPhysics.GetStageKilogramsPerUnit(stage) == 1.0
    assert root.GetAttribute("semantics:labels:class").Get() == ["zoo"]
    layer = Sdf.Layer.FindOrOpen(str(folder / "zoo_000000.usda"))
    payloads = layer.GetPrimAtPath("/zoo_000000").payloadList.GetAddedOrExplicitItems()
    assert [p.assetPath for p in payloads] == ["./payload/contents.usda"]
    contents = Sdf.Layer.FindOrOpen(str(folder / "payload/contents.usda"))
    assert list(contents.subLayerPaths) == ["./physics.usda", "./materials.usda", "./geometry.usdc"]
    assert open(folder / "payload/geometry.usdc", "rb").read(8) == b"PXR-USDC"


def test_layers_hold_only_their_own_kind_of_fact(written):
    _, folder = written
    geo = (folder / "payload/geometry.usdc")
    text = Sdf.Layer.FindOrOpen(str(geo)).ExportToString()
    assert "physics" not in text and "material:binding" not in text
    mats = (folder / "payload/materials.usda").read_text()
    assert "physics" not in mats and "points" not in mats
    phys = (folder / "payload/physics.usda").read_text()
    assert "UsdPreviewSurface" not in phys and "point3f[] points" not in phys


def test_bodies_meshes_and_materials(written):
    obj, folder = written
    stage = Usd.Stage.Open(str(folder / "zoo_000000.usda"))
    bodies = [p for p in stage.Traverse() if p.HasAPI(UsdPhysics.RigidBodyAPI)]
    assert len(bodies) == len(obj.links)
    for body in bodies:
        assert body.GetParent() == stage.GetDefaultPrim()  # flat siblings
        mass = UsdPhysics.MassAPI(body)
        assert mass.GetMassAttr().Get() > 0
        assert mass.GetPrincipalAxesAttr().HasAuthoredValue()
    for mesh in (UsdGeom.Mesh(p) for p in stage.Traverse() if p.IsA(UsdGeom.Mesh)):
        assert mesh.GetSubdivisionSchemeAttr().Get() == "none"
        prim = mesh.GetPrim()
        if "collisions" in str(prim.GetPath()):
            assert mesh.GetPurposeAttr().Get() == "guide"
            assert UsdPhysics.MeshCollisionAPI(prim).GetApproximationAttr().Get() == "convexHull"
        else:
            assert UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial()[0]
            st = UsdGeom.PrimvarsAPI(prim).GetPrimvar("st")
            assert st.GetInterpolation() == "faceVarying"
    tex = stage.GetPrimAtPath("/zoo_000000/Looks/body/basecolorTexture")
    assert tex.GetAttribute("inputs:sourceColorSpace").Get() == "sRGB"
    normal = stage.GetPrimAtPath("/zoo_000000/Looks/body/normalTexture")
    assert normal.GetAttribute("inputs:sourceColorSpace").Get() == "raw"
    assert tuple(normal.GetAttribute("inputs:bias").Get()) == (-1, -1, -1, 0)


def test_principal_axes_reproduce_the_inertia_tensor(written):
    obj, folder = written
    stage = Usd.Stage.Open(str(folder / "zoo_000000.usda"))
    link = max(obj.links, key=lambda link: link.mass)
    mass = UsdPhysics.MassAPI(stage.GetPrimAtPath(f"/zoo_000000/{link.name}"))
    d = np.array(mass.GetDiagonalInertiaAttr().Get())
    q = mass.GetPrincipalAxesAttr().Get()
    from pxr import Gf

    r = np.array(Gf.Matrix3d(Gf.Rotation(Gf.Quatd(q))).GetTranspose())  # column-vector convention
    # float32 moments and quaternion: ~1e-7 relative, so compare against the tensor's own scale
    assert np.allclose(r @ np.diag(d) @ r.T, link.inertia, rtol=1e-4, atol=1e-6 * np.abs(link.inertia).max())


def test_joints_in_usd(written):
    obj, folder = written
    stage = Usd.Stage.Open(str(folder / "zoo_000000.usda"))
    joints = {p.GetName(): p for p in stage.Traverse() if p.IsA(UsdPhysics.Joint)}
    assert len(joints) == len(obj.joints) + 1  # + the fixed joint to the world
    root_joint = UsdPhysics.Joint(joints["root_joint"])
    assert not root_joint.GetBody0Rel().GetTargets() and len(root_joint.GetBody1Rel().GetTargets()) == 1
    rev = joints["joint_rev_part"]
    assert rev.GetAttribute("physics:upperLimit").Get() == pytest.approx(90.0)  # degrees
    assert rev.GetAttribute("physics:axis").Get() == "X"
    assert rev.GetAttribute("drive:angular:physics:stiffness").Get() == 0
    assert rev.GetAttribute("drive:angular:physics:damping").Get() > 0
    cont = joints["joint_cont_part"]
    assert not cont.GetAttribute("physics:lowerLimit").HasAuthoredValue()
    pris = joints["joint_pris_part"]
    assert pris.GetAttribute("physics:upperLimit").Get() == pytest.approx(0.2)  # metres


def test_urdf(written):
    obj, folder = written
    root = ET.parse(folder / "zoo_000000.urdf").getroot()
    links = {el.get("name"): el for el in root.findall("link")}
    assert set(links) == {link.name for link in obj.links}
    for el in links.values():
        inertia = el.find("inertial/inertia")
        t = np.array([[float(inertia.get(f"i{a}{b}" if f"i{a}{b}" in inertia.attrib else f"i{b}{a}"))
                       for b in "xyz"] for a in "xyz"])
        assert np.all(np.linalg.eigvalsh(t) > 0)
        for mesh in el.iter("mesh"):
            assert not mesh.get("filename").startswith("/")
            assert (folder / mesh.get("filename")).is_file()
    joints = {el.get("name"): el for el in root.findall("joint")}
    rev = joints["joint_rev_part"]
    assert float(rev.find("limit").get("upper")) == pytest.approx(math.pi / 2)  # radians
    assert rev.find("dynamics").get("damping")
    assert joints["joint_cont_part"].get("type") == "continuous"
    assert joints["joint_cont_part"].find("limit").get("lower") is None


def test_semantics_and_metadata(written):
    obj, folder = written
    rows = [line.split() for line in (folder / "semantics.txt").read_text().splitlines()]
    assert ["rev_part", "hinge", "part"] in rows and ["pris_part", "slider", "part"] in rows
    assert ["lf_part", "free", "part"] in rows and ["base", "static", "body"] in rows
    assert not any("dummy" in r[0] for r in rows)
    meta = json.loads((folder / "metadata.json").read_text())
    assert meta["category"] == "zoo" and meta["seed"] == 0
    assert meta["counts"]["declared_movable_joints"] == 8
    assert meta["joint_kinds"]["limited_floating"] == 1


def test_save_replaces_an_existing_object_atomically(tmp_path):
    obj = zoo()
    first = infmob_usd.save(obj, tmp_path)
    (first / "stale.txt").write_text("old")
    second = infmob_usd.save(obj, tmp_path)
    assert first == second and not (second / "stale.txt").exists()
    assert [p.name for p in tmp_path.iterdir()] == ["zoo_000000"]


def test_a_failed_write_leaves_nothing(tmp_path):
    obj = zoo()
    obj.textures["body"]["basecolor"] = "not an image"
    with pytest.raises((TypeError, ValueError, AttributeError)):
        infmob_usd.save(obj, tmp_path)
    assert list(tmp_path.iterdir()) == []


def test_unwritable_or_file_output_is_a_clear_error(tmp_path):
    f = tmp_path / "file"
    f.write_text("x")
    with pytest.raises(OutputError, match="is a file"):
        infmob_usd.save(zoo(), f)


def test_obj_numbers_are_printfs():
    """The OBJ writer formats all the numbers of an object's meshes at once (vectorised); the text is
    exactly what printf's %.6f / %.5f / %d write, ties, signed zeros, wide and tiny values included."""
    from infmob_usd.layers.urdf import _F9, _FT, _V, _VN, _VT, _format, _printf, _Text

    rng = np.random.default_rng(7)
    tricky = np.array([0.0078125, -0.0, -1e-9, 5e-7, -5e-7, 1.5e-6, 2.5e-6, 123.4567895, -99.9999995,
                       0.1234565, 1e4, -1e5, 0.5, -0.5, 9.9999995, 1e-300])
    floats = np.concatenate([tricky, rng.normal(size=3000) * 0.4,
                             rng.integers(-10**7, 10**7, 3000) / 2.0 ** rng.integers(0, 14, 3000),
                             rng.integers(-10**8, 10**8, 3000) / 1e6])
    ints = np.concatenate([[1, 9, 10, 99, 100, 999, 1000, 2**31 + 5], rng.integers(1, 70000, 3000)])
    cases = [(_V, floats[: len(floats) // 3 * 3].reshape(-1, 3)), (_VT, floats.reshape(-1, 2)),
             (_VN, floats[: len(floats) // 3 * 3].reshape(-1, 3)), (_F9, ints[: len(ints) // 9 * 9].reshape(-1, 9)),
             (_FT, ints[: len(ints) // 3 * 3].reshape(-1, 3))]
    text = _Text()
    for layout, a in cases:
        parts = text.file()
        text.lines(parts, layout, a[:7])  # several blocks of one layout: split back per file
        text.lines(parts, layout, a[7:])
    for (layout, a), got in zip(cases, text.render()):
        assert _format(a, layout) is not None  # the vectorised path, not the %-format fallback
        assert got.decode() == _printf(a, layout)


def test_obj_lists_made_together_are_each_files_own():
    """The visual OBJs of an object get their ``vt``/``vn`` lists from one sort for all files
    (:func:`~infmob_usd.layers.urdf._corner_lists`): each file's lists, indices and in-step choice
    are what it gets alone, with files of every size, empty ones, shared rows and a wide range."""
    from infmob_usd.layers.urdf import _corner_lists, _unique_inverse, _unique_rows

    rng = np.random.default_rng(3)
    meshes = []
    for k, m in enumerate([0, 1, 5, 40, 300, 2000]):
        nv = max(3 * m // 2, 1)
        f = rng.integers(0, nv, 3 * m)
        smooth = k % 2 == 0  # one uv and normal per vertex: listed in step
        n = rng.normal(size=(nv if smooth else 3 * m, 3))
        n /= np.linalg.norm(n, axis=1, keepdims=True)
        uv = (rng.normal(size=(nv, 2)) * 3)[f] if smooth else np.round(rng.normal(size=(3 * m, 2)), 2)
        meshes.append((uv, n[f] if smooth else np.round(n, 1), f.astype(np.int64), nv))
    wide = meshes[4][0].copy()
    wide[::2] *= 1e3  # too wide a range to pack with the file number: each file sorted alone
    for case in (meshes, meshes[:4] + [(wide, *meshes[4][1:])] + meshes[5:]):
        together = _corner_lists(case)
        assert any(t[4] for t in together) and not all(t[4] for t in together[1:])
        for (uv, n, f, nv), (vt, ti, vn, ni, smooth) in zip(case, together):
            alone = _corner_lists([(uv, n, f, nv)])[0]
            for a, b in zip(alone[:4], (vt, ti, vn, ni)):
                assert a.dtype == b.dtype and np.array_equal(a, b)
            for got, (rows, inv) in zip(((vt, ti), (vn, ni)), (_unique_rows(uv, 6), _unique_rows(n, 5))):
                assert np.array_equal(got[0], rows) and np.array_equal(got[1], inv)
            assert smooth == alone[4] == (len(_unique_inverse((f << 42) | (ti << 21) | ni)[0]) <= 1.25 * nv)


@pytest.mark.parametrize("make", [zoo, lambda: infmob_usd.generate("microwave", seed=3, texture_size=16)])
def test_metadata_bounds_from_the_kept_visual_meshes_are_the_objects(make):
    """While an object is written, metadata.json's bounds come from the visual meshes kept on it:
    exactly ``obj.bounds()``, float for float."""
    from infmob_usd.layers.common import visual_meshes
    from infmob_usd.layers.meta import _rest_bounds, metadata

    obj = make()
    plain = metadata(obj)
    obj._visual_meshes = visual_meshes(obj)
    try:
        assert np.array_equal(_rest_bounds(obj), obj.bounds())
        assert metadata(obj) == plain
    finally:
        obj._visual_meshes = None
