"""SAPIEN and ManiSkill checks themselves (real simulators, CPU, no renderer): the zoo and broken objects."""

from __future__ import annotations

import importlib.util
import json
import shutil
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

pytest.importorskip("sapien")

import infmob_usd  # noqa: E402
from infmob_usd.validate import sim  # noqa: E402

from zoo import zoo  # noqa: E402

pytestmark = pytest.mark.sim

# Every category's generated objects go through the SAPIEN and ManiSkill checks in
# tests/test_physics_checks.py (seeds 0-2, with the known failures recorded there); this file tests the checks
# themselves on the zoo and on objects broken on purpose.
SAPIEN_NAMES = ["sapien_load", *(n for n in sim.SAPIEN_CHECKS if n != "rest")]


@pytest.fixture(scope="module")
def chair(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("sim_objects")
    return Path(infmob_usd.save(infmob_usd.generate("bar_chair", 0, texture_size=16), out))


@pytest.fixture(scope="module")
def good(tmp_path_factory) -> Path:
    """The zoo: one joint of every kind (compound ones through dummy links)."""
    return Path(infmob_usd.save(zoo(texture_size=16), tmp_path_factory.mktemp("sim_zoo")))


def _by_name(results):
    return {r.name: r for r in results}


def _assert_all_pass(results, names):
    res = _by_name(results)
    assert list(res) == names
    failed = {n: r.detail for n, r in res.items() if not r.ok}
    assert not failed, failed


def test_every_joint_kind_passes(good):
    _assert_all_pass(sim.check_sapien(good, checks=SAPIEN_NAMES[1:]), SAPIEN_NAMES)
    meta = json.loads((good / "metadata.json").read_text())
    assert {j["type"] for j in meta["joints"]} == {"fixed", "revolute", "continuous", "prismatic"}


def test_load_sapien_gives_a_fixed_physics_only_articulation(good):
    scene, art = sim.load_sapien(next(good.glob("*.urdf")))
    meta = json.loads((good / "metadata.json").read_text())
    assert len(art.links) == len(meta["links"])
    assert art.links[0].joint.type == "fixed"
    for _ in range(10):
        scene.step()
    assert abs(float(art.qpos.sum())) < 0.1


# ----------------------------------------------------------------------------- broken assets


def _copy(src: Path, tmp_path: Path) -> Path:
    dst = tmp_path / src.name
    shutil.copytree(src, dst)
    return dst


def _edit_urdf(folder: Path, edit) -> None:
    path = next(folder.glob("*.urdf"))
    tree = ET.parse(path)
    edit(tree.getroot())
    tree.write(path, xml_declaration=True, encoding="utf-8")


def _joint(root, name):
    return next(j for j in root.iter("joint") if j.get("name") == name)


def test_inverted_limits_fail_load_and_reach(good, tmp_path):
    bad = _copy(good, tmp_path)

    def invert(root):
        lim = _joint(root, "joint_pris_part").find("limit")
        lim.set("lower", "0.15")
        lim.set("upper", "0.05")

    _edit_urdf(bad, invert)
    res = _by_name(sim.check_sapien(bad))
    assert not res["sapien_load"].ok
    assert "joint_pris_part: limits lower 0.15 >= upper 0.05" in res["sapien_load"].detail
    assert not res["reach"].ok
    assert "joint_pris_part" in res["reach"].detail


def test_zero_axis_fails_load(good, tmp_path):
    bad = _copy(good, tmp_path)
    _edit_urdf(bad, lambda root: _joint(root, "joint_rev_part").find("axis").set("xyz", "0 0 0"))
    res = _by_name(sim.check_sapien(bad, checks=[]))
    assert not res["sapien_load"].ok
    detail = res["sapien_load"].detail
    assert "joint_rev_part: URDF axis [0.0, 0.0, 0.0] has no direction" in detail
    assert "joint joint_rev_part: axis" in detail  # SAPIEN's silent 1 0 0 != metadata 0 0 1


def test_zero_mass_fails_load(good, tmp_path):
    bad = _copy(good, tmp_path)

    def zero(root):
        link = next(x for x in root.iter("link") if x.get("name") == "pris_part")
        link.find("inertial/mass").set("value", "0")

    _edit_urdf(bad, zero)
    res = _by_name(sim.check_sapien(bad, checks=[]))
    assert not res["sapien_load"].ok
    assert "link pris_part: mass" in res["sapien_load"].detail


def test_missing_collision_mesh_fails_sapien_and_maniskill(chair, tmp_path):
    bad = _copy(chair, tmp_path)
    victim = sorted((bad / "meshes").glob("*collision*.obj"))[-1]
    victim.unlink()
    res = _by_name(sim.check_sapien(bad, checks=[]))
    detail = res["sapien_load"].detail
    assert not res["sapien_load"].ok
    assert f"File not found: meshes/{victim.name}" in detail
    assert "collision shapes, URDF has" in detail
    if importlib.util.find_spec("mani_skill") is not None:
        ms = _by_name(sim.check_maniskill(bad))["maniskill_load"]
        assert not ms.ok and victim.name in ms.detail


def test_a_joint_blocked_by_the_ground_fails_reach(good, tmp_path):
    bad = _copy(good, tmp_path)

    def downward(root):
        joint = _joint(root, "joint_pris_part")  # part bottom 0.27 m above the floor
        joint.find("axis").set("xyz", "0 0 -1")
        joint.find("limit").set("upper", "0.5")

    _edit_urdf(bad, downward)
    res = _by_name(sim.check_sapien(bad, checks=["reach"]))
    drive = res["reach"]
    assert not drive.ok
    assert "joint_pris_part -> upper 0.5: stopped at 0.27" in drive.detail, drive.detail


def test_missing_sapien_raises_with_install_hint(monkeypatch, good):
    monkeypatch.setattr(sim, "_SAPIEN", None)
    monkeypatch.setitem(sys.modules, "sapien", None)
    with pytest.raises(sim.SimUnavailableError, match=r"pip install -e \.\[sim\]"):
        sim.check_sapien(good)
    assert issubclass(sim.SimUnavailableError, RuntimeError)


def test_a_scene_is_judged_with_sapiens_defaults_whatever_ran_before(good):
    """ManiSkill sets PhysX's process-wide defaults for its scenes (a 0.02 m contact offset, its own solver
    iterations and friction); a check run after it in the same process used them (phone seed 236's slider stalled
    on a false contact only after the ManiSkill tests had run)."""
    import sapien.physx as physx

    physx.set_shape_config(contact_offset=0.02, rest_offset=0.001)
    physx.set_body_config(solver_position_iterations=15, solver_velocity_iterations=1, sleep_threshold=0.005)
    physx.set_default_material(1.0, 1.0, 0.0)
    scene, art = sim.load_sapien(next(good.glob("*.urdf")))
    shapes = [s for link in art.get_links() for s in link.get_collision_shapes()]
    assert shapes and all(s.get_contact_offset() == pytest.approx(0.01) for s in shapes)
    assert all(s.get_rest_offset() == 0.0 for s in shapes)
    assert physx.get_default_material().static_friction == pytest.approx(0.3)
