"""The folding chair folds with one DoF: lifting the seat's front in MuJoCo carries the front legs up with it, and
they turn at the seat's rate (the coupling keeps them upright) until the seat stands against the back."""

from __future__ import annotations

import json

import pytest

import infmob_usd

pytestmark = pytest.mark.sim


def test_lifting_the_seat_folds_the_front_legs_with_it(tmp_path):
    import mujoco

    obj = infmob_usd.generate("folding_chair", seed=2, texture_size=16, design="metal")
    folder = infmob_usd.save(obj, tmp_path / "chair", formats="urdf,mjcf")
    meta = json.loads((folder / "metadata.json").read_text())
    legs = next(j for j in meta["joints"] if j["name"] == "joint_legs")
    assert legs["mimic"] == {"joint": "joint_seat", "multiplier": 1.0, "offset": 0.0}
    m = mujoco.MjModel.from_xml_path(str(next(folder.glob("*.xml"))))
    d = mujoco.MjData(m)
    seat, leg = (mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, n) for n in ("joint_seat", "joint_legs"))
    for _ in range(int(2.0 / m.opt.timestep)):
        d.qfrc_applied[:] = 0.0
        d.qfrc_applied[m.jnt_dofadr[seat]] = 30.0  # N m: a hand lifting the seat's front edge with ~80 N
        mujoco.mj_step(m, d)
    qs, ql = float(d.qpos[m.jnt_qposadr[seat]]), float(d.qpos[m.jnt_qposadr[leg]])
    assert qs > 0.8 * m.jnt_range[seat][1], f"the seat did not fold up ({qs:.3f} rad)"
    assert ql == pytest.approx(qs, abs=0.05), f"the legs turned {ql:.3f} rad while the seat turned {qs:.3f}"
