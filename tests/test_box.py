"""The box: a chest's hasp, hanging over its staple, holds the lid shut in MuJoCo until it is swung up (the lid's
joint requires it open); a shoe box's lid lifts clear of its base."""

from __future__ import annotations

import json

import pytest

import infmob_usd
from infmob_usd.categories.parts import boxes as B

pytestmark = pytest.mark.sim


@pytest.fixture(scope="module")
def chest(tmp_path_factory):
    obj = infmob_usd.generate("box", seed=3, texture_size=16, design="chest", has_latch=True, has_handles=False)
    return infmob_usd.save(obj, tmp_path_factory.mktemp("box") / "chest", formats="usd,urdf,mjcf")


def _lid_after_push(folder, latch_open: bool) -> float:
    """The lid's angle after 1 s of a lifting torque twice its weight's (the hasp hanging, or swung up)."""
    import mujoco

    m = mujoco.MjModel.from_xml_path(str(next(folder.glob("*.xml"))))
    d = mujoco.MjData(m)
    lid, latch = (mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, n) for n in ("joint_lid", "joint_latch"))
    if latch_open:
        d.qpos[m.jnt_qposadr[latch]] = m.jnt_range[latch][1]
    mujoco.mj_forward(m, d)
    body = m.jnt_bodyid[lid]
    mass = sum(m.body_mass[b] for b in range(m.nbody) if b == body or m.body_parentid[b] == body)
    torque = 2 * mass * 9.81 * 0.5 * B.SIZES["chest"].depth[1] * B.SIZES["chest"].width[1]
    for _ in range(int(1.0 / m.opt.timestep)):
        d.qfrc_applied[:] = 0
        d.qfrc_applied[m.jnt_dofadr[lid]] = torque
        if latch_open:  # a hand holds the hasp up
            d.qpos[m.jnt_qposadr[latch]] = m.jnt_range[latch][1]
            d.qvel[m.jnt_dofadr[latch]] = 0
        mujoco.mj_step(m, d)
    return float(d.qpos[m.jnt_qposadr[lid]])


def test_the_lid_requires_the_hasp_open(chest):
    meta = json.loads((chest / "metadata.json").read_text())
    lid = next(j for j in meta["joints"] if j["name"] == "joint_lid")
    assert lid["requires_open"] == "latch"


def test_the_hasp_holds_the_lid_shut_in_mujoco(chest):
    import math

    assert _lid_after_push(chest, latch_open=False) < math.radians(5)
    assert _lid_after_push(chest, latch_open=True) > math.radians(30)


def test_a_shoe_box_lid_lifts_clear_of_its_skirt():
    """A two-piece shoe box's lid lifts off: its travel passes the skirt's overlap of the base (it is free)."""
    obj = infmob_usd.generate("box", seed=1, texture_size=16, design="shoe_box", shoe_closure="shoe_lid")
    lid = next(j for j in obj.joints if j.name == "joint_lid")
    rim = float(lid.origin[2])  # the lid sits on the base's rim: the base's height above the ground
    assert lid.type == "prismatic" and lid.role == "lift_off"
    assert lid.upper >= B.SHOE_LID["skirt"] * rim + 0.004
