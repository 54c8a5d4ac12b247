"""Monitor: a height-adjustable head stays where it is put (its carriage at any height, its tilt at any angle)."""

from __future__ import annotations

import math

import pytest

import infmob_usd

pytestmark = pytest.mark.sim


def _after(xml, q0: dict, seconds: float, friction: bool = True) -> dict:
    import mujoco

    m = mujoco.MjModel.from_xml_path(str(xml))
    d = mujoco.MjData(m)
    ids = {n: mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, n) for n in q0}
    for n, i in ids.items():
        d.qpos[m.jnt_qposadr[i]] = q0[n]
        if not friction:
            m.dof_frictionloss[m.jnt_dofadr[i]] = 0.0
    for _ in range(int(seconds / m.opt.timestep)):
        mujoco.mj_step(m, d)
    return {n: float(d.qpos[m.jnt_qposadr[i]]) for n, i in ids.items()}


def test_the_head_stays_at_the_height_and_tilt_it_is_put(tmp_path):
    """Raised half way and tilted 15 degrees, a 32-inch head stays there in MuJoCo; without the joints' friction
    the carriage sinks back (what holds it is the friction, sized by the core)."""
    obj = infmob_usd.generate("monitor", seed=0, texture_size=16, stand_style="adjustable_stand", has_pivot=False,
                              width=0.717, has_buttons=False)
    folder = infmob_usd.save(obj, tmp_path / "monitor", formats="mjcf")
    xml = next(folder.glob("*.xml"))
    lift = next(j for j in obj.joints if j.child == "carriage")
    tilt = next(j for j in obj.joints if j.child == "screen")
    q0 = {lift.name: lift.upper / 2, tilt.name: math.radians(15)}
    held = _after(xml, q0, 2.0)
    assert abs(held[lift.name] - q0[lift.name]) < 0.002
    assert abs(held[tilt.name] - q0[tilt.name]) < math.radians(1)
    assert _after(xml, q0, 2.0, friction=False)[lift.name] < q0[lift.name] - 0.02
