"""Return springs and coupled joints (infmob_usd/springs.py), checked in MuJoCo (the MJCF) and SAPIEN
(the URDF, springs applied from metadata.json as the loader recipe says), and in the USD readers.

Each spring-returned joint, pressed to its upper limit and let go, is back within 5 % of its range of
rest within its role's return time, and never more than 5 % of its range outside its limits. A coupled
joint follows its leader: driven, the leader carries the follower at ``ratio`` times its coordinate.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import infmob_usd
from infmob_usd.springs import SPRINGS

from zoo import spring_zoo

pytestmark = pytest.mark.sim
TOL = 0.05


@pytest.fixture(scope="module")
def zoo_folder(tmp_path_factory):
    from infmob_usd.layers import write_object

    obj = spring_zoo()
    return write_object(obj, tmp_path_factory.mktemp("springs") / obj.name, "usd,urdf,mjcf"), obj


@pytest.fixture(scope="module")
def appliances(tmp_path_factory):
    out = tmp_path_factory.mktemp("appliances")
    made = {"microwave": dict(has_buttons=True), "oven": dict(has_buttons=True),
            "dishwasher": dict(has_control_panel=True, has_buttons=True)}
    return {c: infmob_usd.save(infmob_usd.generate(c, seed=0, texture_size=16, **kw), out / c, formats="urdf,mjcf")
            for c, kw in made.items()}


def _sprung(meta):
    return [j for j in meta["joints"] if "spring" in j]


def _release_mujoco(xml: Path, joint: str, duration: float):
    """The MJCF's ``joint`` (and what it leads) put at its upper limit, let go: its coordinates over ``duration``."""
    import mujoco

    from infmob_usd.validate.mujoco_sim import _follow

    m = mujoco.MjModel.from_xml_path(str(xml))
    d = mujoco.MjData(m)
    i = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, joint)
    d.qpos[m.jnt_qposadr[i]] = m.jnt_range[i][1]
    _follow(m, d, i)
    qs = []
    for _ in range(int(round(duration / m.opt.timestep))):
        mujoco.mj_step(m, d)
        qs.append(float(d.qpos[m.jnt_qposadr[i]]))
    return np.array(qs), m.opt.timestep


def _release_sapien(folder: Path, joint: str, duration: float):
    """The URDF in SAPIEN, springs set as drives from metadata.json (:func:`apply_springs`), ``joint`` at
    its upper limit (its followers where the coupling puts them), let go: its coordinates over ``duration``."""
    from infmob_usd.validate.sim import apply_springs, load_sapien

    meta = json.loads((folder / "metadata.json").read_text())
    scene, art = load_sapien(folder / f"{folder.name}.urdf", ground=False)
    joints = art.get_active_joints()
    names = [j.name for j in joints]
    apply_springs(art, meta)
    q = np.zeros(art.dof, dtype=np.float32)
    k = names.index(joint)
    q[k] = joints[k].get_limit()[0][1]
    for j in meta["joints"]:
        if j.get("mimic", {}).get("joint") == joint:
            q[names.index(j["name"])] = j["mimic"]["multiplier"] * q[k]
    art.set_qpos(q)
    qs = []
    for _ in range(int(round(duration * 240))):
        scene.step()
        qs.append(float(art.get_qpos()[k]))
    return np.array(qs), 1 / 240


def _check_return(qs, dt, lower, upper, time, what):
    span = upper - lower
    assert np.isfinite(qs).all(), what
    assert qs.min() >= lower - TOL * span and qs.max() <= upper + TOL * span, \
        f"{what}: left its limits [{lower:.4g}, {upper:.4g}]: {qs.min():.4g}..{qs.max():.4g}"
    back = int(math.ceil(time / dt))
    assert abs(qs[back - 1] - lower) <= TOL * span, \
        f"{what}: {abs(qs[back - 1] - lower) / span * 100:.1f} % of its range from rest after {time} s"
    assert np.abs(qs[back:] - lower).max() <= TOL * span, f"{what}: did not stay back"


def test_every_spring_role_has_a_spring(zoo_folder):
    folder, obj = zoo_folder
    roles = {j.role for j in obj.movable_joints if j.stiffness > 0}
    assert roles == set(SPRINGS)
    for j in obj.movable_joints:
        if j.stiffness > 0:
            assert j.spring_ref < j.lower  # preloaded: at rest it still presses the part on its stop


@pytest.mark.parametrize("engine", ["mujoco", "sapien"])
def test_springs_bring_each_role_back(zoo_folder, engine):
    pytest.importorskip(engine)
    folder, obj = zoo_folder
    meta = json.loads((folder / "metadata.json").read_text())
    for j in _sprung(meta):
        if "mimic" in j:
            continue  # the lid returns with its pedal: test_coupled_lid_follows_and_returns_with_its_pedal
        time = SPRINGS[j["role"]].time
        qs, dt = (_release_mujoco(folder / f"{folder.name}.xml", j["name"], time + 0.5) if engine == "mujoco"
                  else _release_sapien(folder, j["name"], time + 0.5))
        _check_return(qs, dt, j["lower"], j["upper"], time, f"{engine} {j['name']} ({j['role']})")


@pytest.mark.parametrize("engine", ["mujoco", "sapien"])
def test_appliance_buttons_spring_back(appliances, engine):
    pytest.importorskip(engine)
    for category, folder in appliances.items():
        meta = json.loads((folder / "metadata.json").read_text())
        buttons = [j for j in meta["joints"] if j["role"] == "button"]
        assert buttons and all("spring" in j for j in buttons), category
        j = buttons[0]
        time = SPRINGS["button"].time
        qs, dt = (_release_mujoco(folder / f"{folder.name}.xml", j["name"], time + 0.3) if engine == "mujoco"
                  else _release_sapien(folder, j["name"], time + 0.3))
        _check_return(qs, dt, j["lower"], j["upper"], time, f"{engine} {category} {j['name']}")


def test_without_its_spring_a_pressed_button_stays_in(appliances):
    """The check above can fail: the MJCF with the spring taken out leaves the button pressed."""
    import re

    folder = appliances["microwave"]
    xml = (folder / f"{folder.name}.xml").read_text()
    (folder / "nospring.xml").write_text(re.sub(r' stiffness="[^"]*" springref="[^"]*"', "", xml))
    meta = json.loads((folder / "metadata.json").read_text())
    j = next(j for j in meta["joints"] if j["role"] == "button")
    qs, _ = _release_mujoco(folder / "nospring.xml", j["name"], 0.4)
    assert qs[-1] - j["lower"] > 0.5 * (j["upper"] - j["lower"])


@pytest.mark.parametrize("engine", ["mujoco", "sapien"])
def test_coupled_lid_follows_and_returns_with_its_pedal(zoo_folder, engine):
    pytest.importorskip(engine)
    folder, obj = zoo_folder
    lid = next(j for j in obj.joints if j.name == "joint_lid")
    assert lid.mimic == ("joint_pedal", 3.0, 0.0)
    pedal = next(j for j in obj.joints if j.name == "joint_pedal")
    assert lid.upper == pytest.approx(3.0 * pedal.upper)
    if engine == "mujoco":
        import mujoco

        m = mujoco.MjModel.from_xml_path(str(folder / f"{folder.name}.xml"))
        d = mujoco.MjData(m)
        ip, il = (mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, n) for n in ("joint_pedal", "joint_lid"))
        # drive the pedal with a stiff position servo to 0.8 of its range, then let it go
        target = 0.8 * pedal.upper
        for step in range(int(1.5 / m.opt.timestep)):
            if step * m.opt.timestep < 1.0:
                a = m.jnt_dofadr[ip]
                d.qfrc_applied[a] = 50.0 * (target - d.qpos[m.jnt_qposadr[ip]]) - 2.0 * d.qvel[a]
            else:
                d.qfrc_applied[:] = 0
            mujoco.mj_step(m, d)
            if abs(step * m.opt.timestep - 0.99) < m.opt.timestep / 2:
                qp, ql = d.qpos[m.jnt_qposadr[ip]], d.qpos[m.jnt_qposadr[il]]
        final = d.qpos[m.jnt_qposadr[il]]
    else:
        from infmob_usd.validate.sim import apply_springs, load_sapien

        meta = json.loads((folder / "metadata.json").read_text())
        scene, art = load_sapien(folder / f"{folder.name}.urdf", ground=False)
        apply_springs(art, meta)
        joints = art.get_active_joints()
        names = [j.name for j in joints]
        jp = joints[names.index("joint_pedal")]
        target = 0.8 * pedal.upper
        stiff, damp = jp.stiffness, jp.damping
        jp.set_drive_property(50.0, 5.0)
        jp.set_drive_target(target)
        for _ in range(240):
            scene.step()
        q = art.get_qpos()
        qp, ql = q[names.index("joint_pedal")], q[names.index("joint_lid")]
        jp.set_drive_property(stiff, damp)
        jp.set_drive_target(0.0)
        for _ in range(360):
            scene.step()
        final = art.get_qpos()[names.index("joint_lid")]
    assert qp > 0.5 * pedal.upper, f"{engine}: the pedal was not driven ({qp:.3f})"
    assert ql == pytest.approx(3.0 * qp, abs=0.03 * lid.upper), f"{engine}: lid {ql:.3f}, pedal {qp:.3f}"
    assert abs(final) <= TOL * lid.upper, f"{engine}: the lid did not come back with its pedal ({final:.3f})"


def test_coupling_in_the_files(zoo_folder):
    """URDF ``<mimic>``, MJCF ``<equality><joint>``, USD ``PhysxMimicJointAPI:rotX`` (which UsdPhysics'
    parser still reads as a revolute joint), and the spring as the USD drive."""
    import xml.etree.ElementTree as ET

    from pxr import Usd, UsdPhysics

    folder, obj = zoo_folder
    urdf = ET.parse(folder / f"{folder.name}.urdf").getroot()
    mimic = next(j for j in urdf.iter("joint") if j.get("name") == "joint_lid").find("mimic")
    assert mimic.get("joint") == "joint_pedal" and float(mimic.get("multiplier")) == 3.0
    mj = ET.parse(folder / f"{folder.name}.xml").getroot()
    eq = mj.find("equality").find("joint")
    assert (eq.get("joint1"), eq.get("joint2")) == ("joint_lid", "joint_pedal")
    assert [float(x) for x in eq.get("polycoef").split()][:2] == [0.0, 3.0]
    stage = Usd.Stage.Open(str(folder / f"{folder.name}.usda"))
    prim = next(p for p in stage.Traverse() if p.GetName() == "joint_lid")
    assert "PhysxMimicJointAPI:rotX" in prim.GetMetadata("apiSchemas").GetAddedOrExplicitItems()
    assert prim.GetRelationship("physxMimicJoint:rotX:referenceJoint").GetTargets()[0].name == "joint_pedal"
    assert prim.GetAttribute("physxMimicJoint:rotX:gearing").Get() == pytest.approx(-3.0)
    button = next(p for p in stage.Traverse() if p.GetName() == "joint_button")
    j = next(j for j in obj.joints if j.name == "joint_button")
    assert button.GetAttribute("drive:linear:physics:stiffness").Get() == pytest.approx(j.stiffness, rel=1e-6)
    assert button.GetAttribute("drive:linear:physics:targetPosition").Get() == pytest.approx(j.spring_ref, rel=1e-6)
    ret = UsdPhysics.LoadUsdPhysicsFromRange(stage, [prim.GetPath().GetParentPath().GetParentPath()])
    joints = {str(p).rsplit("/", 1)[-1] for kind, (paths, _descs) in ret.items() for p in paths
              if kind == UsdPhysics.ObjectType.RevoluteJoint}
    assert {"joint_lid", "joint_pedal"} <= joints


def test_bad_couplings_are_refused():
    from infmob_usd.errors import ModelError
    from infmob_usd.joints import Mimic

    from zoo import spring_blueprint

    with pytest.raises(ModelError, match="ratio"):
        Mimic("pedal", 0.0)
    bp = spring_blueprint()
    from infmob_usd.grammar import Layout

    lay = Layout(bp, {}, np.random.default_rng(0), None)
    with pytest.raises(ModelError, match="no joint moves part 'nothing'"):
        lay.couple("lid", "nothing")
    with pytest.raises(ModelError, match="offset must be 0"):
        lay.couple("lid", "pedal", 3.0, 0.1)
        infmob_usd.api.assemble(bp, 0, np.random.default_rng(0), 16)
