"""The folding chair folds with one DoF: lifting the seat's front in MuJoCo turns it up against the back and
swings the rear legs, hung under it and coupled to it, forward until their feet close on the front feet (the X
shuts and the chair is flat)."""

from __future__ import annotations

import json

import numpy as np
import pytest

import infmob_usd

pytestmark = pytest.mark.sim


def _feet_x(m, d, body: str) -> float:
    """The mean x of the lowest collision geoms of ``body`` (its two feet)."""
    import mujoco

    b = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, body)
    geoms = [g for g in range(m.ngeom) if m.geom_bodyid[g] == b and m.geom_contype[g]]
    low = sorted(geoms, key=lambda g: d.geom_xpos[g][2])[:2]
    return float(np.mean([d.geom_xpos[g][0] for g in low]))


def test_lifting_the_seat_shuts_the_legs_x(tmp_path):
    import mujoco

    obj = infmob_usd.generate("folding_chair", seed=2, texture_size=16, design="metal")
    folder = infmob_usd.save(obj, tmp_path / "chair", formats="urdf,mjcf")
    meta = json.loads((folder / "metadata.json").read_text())
    legs = next(j for j in meta["joints"] if j["name"] == "joint_legs")
    assert legs["mimic"]["joint"] == "joint_seat"
    m = mujoco.MjModel.from_xml_path(str(next(folder.glob("*.xml"))))
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    apart = _feet_x(m, d, "body") - _feet_x(m, d, "legs")
    assert apart > 0.2, f"the rear feet stand only {apart:.3f} m behind the front feet at rest"
    seat = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, "joint_seat")
    for _ in range(int(2.0 / m.opt.timestep)):
        d.qfrc_applied[:] = 0.0
        d.qfrc_applied[m.jnt_dofadr[seat]] = 30.0  # N m: a hand lifting the seat's front edge with ~80 N
        mujoco.mj_step(m, d)
    qs = float(d.qpos[m.jnt_qposadr[seat]])
    assert qs > 0.9 * m.jnt_range[seat][1], f"the seat did not fold up ({qs:.3f} rad)"
    shut = abs(_feet_x(m, d, "body") - _feet_x(m, d, "legs"))
    assert shut < 0.1, f"folded, the rear feet are {shut:.3f} m from the front feet: the X did not shut"
