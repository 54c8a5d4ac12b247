"""MJCF, GLB and --formats: what the files hold, that MuJoCo reads them, that the mujoco check bites."""

from __future__ import annotations

import json
import re
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import infmob_usd
from infmob_usd.errors import OutputError
from infmob_usd.layers import DEFAULT_FORMATS, FORMATS, parse_formats, write_textures
from infmob_usd.layers.mjcf import write_mjcf

from zoo import zoo

mujoco = pytest.importorskip("mujoco")

from infmob_usd.validate.mujoco_sim import check_mujoco, load_model, push_joints  # noqa: E402


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    obj = zoo(texture_size=16)
    return obj, infmob_usd.save(obj, tmp_path_factory.mktemp("zoo"), formats="usd,urdf,mjcf,glb")


def _xml(folder: Path) -> ET.Element:
    return ET.parse(folder / f"{folder.name}.xml").getroot()


def test_mjcf_mirrors_the_model(written):
    obj, folder = written
    root = _xml(folder)
    bodies = {b.get("name"): b for b in root.iter("body")}
    assert set(bodies) == {link.name for link in obj.links}
    world = root.find("worldbody")
    assert [b.get("name") for b in world.findall("body")] == [obj.links[0].name]  # one welded base
    assert world.find("body/joint") is None and world.find("body/freejoint") is None
    for j in obj.joints:  # nesting follows the joint tree; bodies sit at their link frames
        child = bodies[j.child]
        assert child in list(bodies[j.parent])
        assert np.allclose([float(x) for x in child.get("pos").split()],
                           obj.link(j.child).origin - obj.link(j.parent).origin, atol=1e-8)
        joint = child.find("joint")
        if not j.movable:
            assert joint is None
            continue
        assert joint.get("name") == j.name
        assert joint.get("type") == ("slide" if j.type == "prismatic" else "hinge")
        assert float(joint.get("damping")) == pytest.approx(j.damping)
        assert float(joint.get("frictionloss")) == pytest.approx(j.friction)
        assert float(joint.get("armature")) == pytest.approx(j.armature) and j.armature > 0
        assert [float(x) for x in joint.get("actuatorfrcrange").split()] == pytest.approx([-j.effort, j.effort])
        if j.type == "continuous":
            assert joint.get("limited") == "false"
        else:
            assert [float(x) for x in joint.get("range").split()] == pytest.approx([j.lower, j.upper])
    # a compound chain's real parent and child are excluded from contact (dummies between them)
    excluded = {(e.get("body1"), e.get("body2")) for e in root.iter("exclude")}
    chains = {j.group for j in obj.joints if j.kind not in ("fixed", "revolute", "continuous", "prismatic")}
    assert excluded == {("base", g) for g in chains}


def test_mujoco_reads_materials_textures_meshes_and_inertia(written):
    obj, folder = written
    model = load_model(folder / f"{folder.name}.xml")
    assert model.nmat == len(obj.materials) and model.ntex == sum(len(m) for m in obj.textures.values())
    rgb = int(mujoco.mjtTextureRole.mjTEXROLE_RGB)
    assert all(model.mat_texid[i][rgb] >= 0 for i in range(model.nmat))
    urdf = ET.parse(folder / f"{folder.name}.urdf").getroot()
    n_collision = len(urdf.findall("link/collision"))
    collide = [g for g in range(model.ngeom) if model.geom_contype[g] or model.geom_conaffinity[g]]
    assert len(collide) == n_collision
    assert all(model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH for g in collide)
    masses = {mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b): model.body_mass[b] for b in range(model.nbody)}
    for link in obj.links:
        assert masses[link.name] == pytest.approx(link.mass, rel=1e-6)


def test_free_base_option(written, tmp_path):
    obj, _ = written
    obj._mesh_files = None
    write_textures(obj, tmp_path)
    path = write_mjcf(obj, tmp_path, free_base=True)
    obj._mesh_files = None
    model = mujoco.MjModel.from_xml_path(str(path))
    assert model.jnt_type[0] == mujoco.mjtJoint.mjJNT_FREE
    data = mujoco.MjData(model)
    for _ in range(200):
        mujoco.mj_step(model, data)
    assert data.qpos[2] < -0.05  # nothing holds it: it falls


def test_urdf_carries_the_mujoco_compiler_hint(written):
    _, folder = written
    compiler = ET.parse(folder / f"{folder.name}.urdf").getroot().find("mujoco/compiler")
    assert compiler.get("strippath") == "false" and compiler.get("discardvisual") == "false"
    model = load_model(folder / f"{folder.name}.urdf")  # finds meshes/ and keeps the visuals
    assert model.nmesh > 0


def test_mjcf_and_glb_are_deterministic(tmp_path):
    a = infmob_usd.save(infmob_usd.generate("oven", seed=3, texture_size=16), tmp_path / "a", formats="mjcf,glb")
    b = infmob_usd.save(infmob_usd.generate("oven", seed=3, texture_size=16), tmp_path / "b", formats="mjcf,glb")
    for ext in ("xml", "glb"):
        assert (a / f"{a.name}.{ext}").read_bytes() == (b / f"{b.name}.{ext}").read_bytes()


def test_the_mujoco_check_passes_on_every_joint_kind(written):
    """All but one known failure: the zoo's flip_revolute second hinge carries a part 3 cm off its
    pivot with friction as its only hold (the same joint fails SAPIEN's rest check, see
    test_physics_checks.KNOWN_FAILURES); MuJoCo's soft friction lets it sag too."""
    (result,) = check_mujoco(written[1])
    assert result.name == "mujoco"
    assert re.fullmatch(r"rest: joint_fr_part_1 moved [\d.]+ deg \[[\d.]+ s\]", result.detail), result.detail


def test_an_effort_far_above_the_weight_drives_through_the_stop(written, tmp_path):
    """Ten times the old role table (20 N) on a light part: even the MJCF's stiff stop gives way (200 N
    no longer does); the check says so."""
    obj, folder = written
    bad = tmp_path / folder.name
    import shutil

    shutil.copytree(folder, bad)
    xml = bad / f"{folder.name}.xml"
    text = xml.read_text()
    text = re.sub(r'(<joint name="joint_pris_part"[^>]*actuatorfrcrange=")[^"]*"', r'\g<1>-2000 2000"', text)
    xml.write_text(text)
    (result,) = check_mujoco(bad)
    assert not result.ok
    assert re.search(r"push joint_pris_part -> upper with 2e\+03: [\d.]+ % of its range past its limit", result.detail)


def test_a_link_pushed_into_another_fails_contacts(written, tmp_path):
    obj, folder = written
    import shutil

    bad = tmp_path / folder.name
    shutil.copytree(folder, bad)
    xml = bad / f"{folder.name}.xml"
    root = ET.parse(xml).getroot()
    body = next(b for b in root.iter("body") if b.get("name") == "cont_part")
    other = obj.link("pris_part").origin - obj.link("base").origin
    body.set("pos", " ".join(repr(float(x)) for x in other + [0.02, 0, 0]))  # into its neighbour
    ET.ElementTree(root).write(xml)
    (result,) = check_mujoco(bad)
    assert not result.ok and "contact at rest" in result.detail, result.detail


def test_a_folder_without_mjcf_is_skipped_not_failed(tmp_path):
    folder = infmob_usd.save(zoo(texture_size=16), tmp_path, formats="urdf")
    (result,) = check_mujoco(folder)
    assert result.ok and result.detail.startswith("skipped: no MJCF")


def test_push_joints_reports_every_joint_and_side(written):
    obj, folder = written
    pushes = push_joints(load_model(folder / f"{folder.name}.xml"), duration=0.2)
    sides = {(p.joint, p.side) for p in pushes}
    for j in obj.movable_joints:
        assert (j.name, "upper") in sides
        assert ((j.name, "lower") in sides) == (j.type != "continuous")


# ----------------------------------------------------------------------------- GLB


def test_glb_is_a_valid_container_with_pbr_materials(written):
    obj, folder = written
    data = (folder / f"{folder.name}.glb").read_bytes()
    magic, version, length = struct.unpack("<4sII", data[:12])
    assert (magic, version, length) == (b"glTF", 2, len(data))
    n_json, kind = struct.unpack("<I4s", data[12:20])
    assert kind == b"JSON" and n_json % 4 == 0
    doc = json.loads(data[20:20 + n_json])
    n_bin, kind = struct.unpack("<I4s", data[20 + n_json:28 + n_json])
    assert kind == b"BIN\0" and doc["buffers"][0]["byteLength"] <= n_bin
    for v in doc["bufferViews"]:
        assert v["byteOffset"] % 4 == 0 and v["byteOffset"] + v["byteLength"] <= n_bin
    assert [n["name"] for n in doc["nodes"][1:]] == [link.name for link in obj.links]
    assert len(doc["materials"]) == len(obj.materials)
    for m in doc["materials"]:
        pbr = m["pbrMetallicRoughness"]
        assert "baseColorTexture" in pbr and "metallicRoughnessTexture" in pbr and "normalTexture" in m
    joints = {n["extras"]["joint"]["name"] for n in doc["nodes"][1:] if "joint" in n["extras"]}
    assert joints == {j.name for j in obj.joints}
    import trimesh

    scene = trimesh.load(folder / f"{folder.name}.glb")
    assert len(scene.geometry) == sum(1 for n in doc["nodes"] if "mesh" in n)
    # Z up in our files, Y up in glTF: the scene's height is the object's height
    height = obj.bounds()[1, 2] - obj.bounds()[0, 2]
    assert scene.bounds[1, 1] - scene.bounds[0, 1] == pytest.approx(height, rel=1e-3)


# ----------------------------------------------------------------------------- formats


def test_formats_table_and_parsing():
    assert DEFAULT_FORMATS == ("usd", "urdf", "mjcf") and set(FORMATS) == {"usd", "urdf", "mjcf", "glb", "isaac"}
    assert parse_formats("glb, URDF") == ("urdf", "glb")
    assert parse_formats(None) == DEFAULT_FORMATS
    for bad in ("usd,obj", "", [" "]):
        with pytest.raises(OutputError, match="format"):
            parse_formats(bad)


def test_save_writes_only_the_formats_asked_for(tmp_path):
    folder = infmob_usd.save(zoo(texture_size=16), tmp_path, formats=["glb"])
    names = sorted(p.name for p in folder.iterdir())
    # metadata, semantics and the interaction annotations come with every format
    assert names == ["annotations.json", "metadata.json", "semantics.txt", "textures", "zoo_000000.glb"]
    meta = json.loads((folder / "metadata.json").read_text())
    assert meta["files"] == {"glb": "./zoo_000000.glb", "semantics": "./semantics.txt",
                             "annotations": "./annotations.json"}
    default = infmob_usd.save(zoo(texture_size=16), tmp_path / "d")
    assert {p.suffix for p in default.iterdir()} >= {".usda", ".urdf", ".xml"}
    assert not (default / "zoo_000000.glb").exists()


def test_cli_formats(tmp_path):
    run = [sys.executable, "-m", "infmob_usd", "generate", "tap", "--texture-size", "16", "--workers", "1"]
    bad = subprocess.run(run + ["--formats", "usd,fbx", "--out", str(tmp_path / "x")], capture_output=True, text=True)
    assert bad.returncode == 2 and "unknown format(s) 'fbx'" in bad.stderr and not (tmp_path / "x").exists()
    ok = subprocess.run(run + ["--formats", "urdf,mjcf", "--out", str(tmp_path / "y")], capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    folder = tmp_path / "y" / "tap" / "tap_000000"
    assert (folder / "tap_000000.xml").is_file() and not (folder / "tap_000000.usda").exists()
    row = json.loads((tmp_path / "y" / "manifest.jsonl").read_text().splitlines()[0])
    assert row["formats"] == ["urdf", "mjcf"]


def test_quaternions_agree_with_scipy():
    from scipy.spatial.transform import Rotation

    from infmob_usd.layers.mjcf import _quat

    flips = ([1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1])
    mats = list(Rotation.random(500, random_state=3).as_matrix()) + [np.diag(d) for d in flips]
    for m in mats:
        x, y, z, w = Rotation.from_matrix(m).as_quat()
        q = np.array([w, x, y, z])
        assert np.allclose(_quat(m), q if q[0] >= 0 else -q, atol=1e-12) or abs(q[0]) < 1e-12


def test_sprung_parts_stay_up_in_mujocos_urdf_reader(tmp_path):
    """A URDF has no spring: a toaster's carriage lever and its buttons must not sink onto their pressed stops
    when MuJoCo reads the URDF (the lever fell its whole 20 mm before the URDF's holding friction and no-slip
    pass), yet the lever still goes down under its effort."""
    from infmob_usd.validate.mujoco_sim import REST_MAX_PRISMATIC, REST_MAX_REVOLUTE, rest_motion

    obj = infmob_usd.generate("toaster", seed=0, texture_size=16)
    folder = infmob_usd.save(obj, tmp_path, formats="urdf")
    sprung = {j.name: j for j in obj.joints if j.stiffness > 0}
    assert any(j.hold_friction > j.friction for j in sprung.values())
    model = load_model(folder / f"{folder.name}.urdf")
    motion, _ = rest_motion(model)
    for name, j in sprung.items():
        assert motion[name] <= (REST_MAX_PRISMATIC if j.type == "prismatic" else REST_MAX_REVOLUTE), name
    lever = next(p for p in push_joints(model) if "lever" in p.joint and p.side == "upper")
    assert lever.travel > 0.9, lever
