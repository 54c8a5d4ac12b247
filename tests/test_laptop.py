"""Laptop: the lid stays where it is put (a friction hinge), a convertible's lid folds past flat on a table
but never through it."""

from __future__ import annotations

import math

import numpy as np
import pytest

import infmob_usd

pytestmark = pytest.mark.sim

HOLD = math.radians(110)  # a working angle: the lid's weight pulls it back past upright


def _lid_after(xml, q0: float, seconds: float, friction: bool = True) -> float:
    import mujoco

    m = mujoco.MjModel.from_xml_path(str(xml))
    d = mujoco.MjData(m)
    i = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, "joint_lid")
    if not friction:
        m.dof_frictionloss[m.jnt_dofadr[i]] = 0.0
    d.qpos[m.jnt_qposadr[i]] = q0
    for _ in range(int(seconds / m.opt.timestep)):
        mujoco.mj_step(m, d)
    return float(d.qpos[m.jnt_qposadr[i]])


def test_the_lid_holds_at_a_working_angle(tmp_path):
    """The largest, heaviest lid (a 17-inch laptop's) put at 110 degrees stays there in MuJoCo; without the
    hinge's friction the same lid falls back to its stop (what the friction holds is real)."""
    obj = infmob_usd.generate("laptop", seed=0, texture_size=16, design="clamshell", has_numpad=True, size=1.0,
                              thickness=1.0, opens=math.pi)
    folder = infmob_usd.save(obj, tmp_path / "laptop", formats="mjcf")
    xml = next(folder.glob("*.xml"))
    assert abs(_lid_after(xml, HOLD, 2.0) - HOLD) < math.radians(2)
    assert _lid_after(xml, HOLD, 2.0, friction=False) > HOLD + math.radians(10)


def test_a_convertible_lid_opens_past_flat_and_stays_above_the_table():
    obj = infmob_usd.generate("laptop", seed=1, texture_size=16, design="convertible")
    lid = next(j for j in obj.joints if j.name == "joint_lid")
    assert math.pi < lid.upper < math.pi + math.radians(15)
    poses = obj.poses({lid.name: lid.upper})
    low = min(float((v @ poses[link.name][2, :3] + poses[link.name][2, 3]).min())
              for link in obj.links for p in link.pieces for v, _ in p.hulls())
    assert low > -1e-3
    assert np.isfinite(low)
