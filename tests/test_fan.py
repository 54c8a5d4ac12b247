"""The fan: a stand fan's rotor, given a motor's torque, spins whole turns inside its guard in MuJoCo (the blades
clear the grille wires' collision band and front lens at every angle) while the head stays on its stops."""

from __future__ import annotations

import math

import pytest

import infmob_usd

pytestmark = pytest.mark.sim


def test_a_stand_fans_rotor_spins_whole_turns_inside_its_guard(tmp_path):
    import mujoco

    obj = infmob_usd.generate("fan", seed=0, texture_size=16, design="pedestal", oscillation="oscillating")
    folder = infmob_usd.save(obj, tmp_path / "fan", formats="urdf,mjcf")
    m = mujoco.MjModel.from_xml_path(str(next(folder.glob("*.xml"))))
    d = mujoco.MjData(m)
    rotor, head = (mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, n) for n in ("joint_rotor", "joint_head"))
    dof, q, body = m.jnt_dofadr[rotor], m.jnt_qposadr[rotor], m.jnt_bodyid[rotor]
    touched = set()
    for _ in range(int(1.0 / m.opt.timestep)):
        d.qfrc_applied[:] = 0.0
        d.qfrc_applied[dof] = 0.3  # N m: a 40-60 W stand fan motor's torque near its running speed
        mujoco.mj_step(m, d)
        for c in d.contact[: d.ncon]:
            b1, b2 = int(m.geom_bodyid[c.geom1]), int(m.geom_bodyid[c.geom2])
            if body in (b1, b2):
                touched.add(mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b2 if b1 == body else b1))
    turned = float(d.qpos[q])
    assert not touched, f"the spinning rotor touched {sorted(touched)}"
    assert turned > 4 * math.pi, f"the rotor turned {math.degrees(turned):.0f} degrees in 1 s: blocked by its guard?"
    assert abs(float(d.qpos[m.jnt_qposadr[head]])) < math.radians(2), "spinning the rotor moved the head"
