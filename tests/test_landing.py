"""A sprung part released from its far stop lands on its rest stop within the stop budget (infmob_usd/effort.py,
``landing`` and ``_sprung``), measured in MuJoCo on the MJCF: a keyboard key (5 g, 1.5 mm of travel) held on its
stop by a spring twice its weight used to land 9 % of its travel past it, a camera's shutter button 6 %."""

from __future__ import annotations

import pytest

import infmob_usd
from infmob_usd import effort

mujoco = pytest.importorskip("mujoco")
pytestmark = pytest.mark.sim


def _model(tmp_path, category: str, seed: int):
    obj = infmob_usd.generate(category, seed=seed, texture_size=16)
    folder = infmob_usd.save(obj, tmp_path / category, formats="mjcf")
    return obj, mujoco.MjModel.from_xml_path(str(folder / f"{folder.name}.xml"))


def _released(model, name: str, seconds: float = 0.5, push: bool = False) -> tuple[float, float]:
    """Joint ``name`` started at its upper limit and let go (everything else at rest; ``push``: pushed towards its
    rest stop with its effort, as the push test does): the furthest it goes past its lower limit (share of its
    range) and the speed it crosses that limit with (range per second)."""
    data = mujoco.MjData(model)
    k = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
    adr, dof = model.jnt_qposadr[k], model.jnt_dofadr[k]
    lower, upper = model.jnt_range[k]
    span = upper - lower
    data.qpos[adr] = upper
    if push:
        data.qfrc_applied[dof] = model.jnt_actfrcrange[k][0]
    past, speed = -1.0, None
    for _ in range(int(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
        past = max(past, (lower - data.qpos[adr]) / span)
        if speed is None and data.qpos[adr] < lower:
            speed = -data.qvel[dof] / span
    return past, speed or 0.0


@pytest.mark.parametrize("push", [False, True], ids=["released", "pushed"])
@pytest.mark.parametrize("category,seed,joint", [("keyboard", 1, "joint_key_0"), ("keyboard", 0, "joint_key_0"),
                                                 ("camera", 68, "joint_shutter"), ("laptop", 0, "joint_key_0"),
                                                 ("laptop", 0, "joint_trackpad")])
def test_a_released_sprung_part_lands_within_the_stop_budget(tmp_path, category, seed, joint, push):
    """In MuJoCo (the MJCF's armature, damping and spring), within the push test's 5 % of its travel, let go or
    pushed home with its effort."""
    _, model = _model(tmp_path, category, seed)
    past, _ = _released(model, joint, push=push)
    assert past <= 0.05, f"{category} {seed} {joint} lands {past:.1%} of its travel past its rest stop"


def test_the_landing_estimate_follows_mujoco(tmp_path):
    """:func:`effort.landing`'s speed is MuJoCo's (within 10 %), and its share of the range bounds what MuJoCo
    measures: the rule is sized on what the simulator does."""
    obj, model = _model(tmp_path, "keyboard", 1)
    j = next(j for j in obj.joints if j.name == "joint_key_0")
    free = effort.free_inertias(obj)[j.name]
    d = effort.drive(obj, j, free, j.armature, effort.SPRING_DAMPING_RATE_MAX)
    assert d.armature == pytest.approx(j.armature, rel=1e-5) and d.damping == pytest.approx(j.damping, rel=1e-5)
    estimate = effort.landing(j, d, effort.gravity_at_rest(obj, j))
    past, speed = _released(model, j.name)
    assert estimate / effort.LAND_TIME == pytest.approx(speed, rel=0.1)
    assert past <= estimate + 0.005
    assert estimate <= effort.STOP_SHARE
