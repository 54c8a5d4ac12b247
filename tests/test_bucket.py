"""The bucket: a mop bucket's wringer lever, pressed in MuJoCo, drives its press plate forward (a coupled joint)
and springs back up when let go."""

from __future__ import annotations

import math

import pytest

import infmob_usd

pytestmark = pytest.mark.sim

HAND = 20.0  # N m: a hand's 50 N on the grip of a 0.4 m lever


@pytest.fixture(scope="module")
def mop_bucket(tmp_path_factory):
    obj = infmob_usd.generate("bucket", seed=9, texture_size=16, design="mop_bucket", has_casters=False)
    return infmob_usd.save(obj, tmp_path_factory.mktemp("bucket") / "mop", formats="usd,urdf,mjcf")


def test_the_lever_drives_the_press_plate_and_springs_back(mop_bucket):
    import mujoco

    m = mujoco.MjModel.from_xml_path(str(next(mop_bucket.glob("*.xml"))))
    d = mujoco.MjData(m)
    lever, press = (mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, n) for n in ("joint_lever", "joint_press"))
    ql, qp = m.jnt_qposadr[lever], m.jnt_qposadr[press]
    for _ in range(int(1.0 / m.opt.timestep)):  # a hand pushes the grip down with ~50 N, 0.4 m out
        d.qfrc_applied[:] = 0
        d.qfrc_applied[m.jnt_dofadr[lever]] = HAND
        mujoco.mj_step(m, d)
    pressed, plate = float(d.qpos[ql]), float(d.qpos[qp])
    assert pressed > math.radians(20)
    ratio = m.jnt_range[press][1] / m.jnt_range[lever][1]
    assert plate == pytest.approx(ratio * pressed, rel=0.1, abs=0.003)
    d.qfrc_applied[:] = 0
    for _ in range(int(2.0 / m.opt.timestep)):  # let go
        mujoco.mj_step(m, d)
    assert float(d.qpos[ql]) < math.radians(5) and float(d.qpos[qp]) < 0.01
