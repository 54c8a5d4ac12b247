"""A sprung part released from its far stop lands on its rest stop within the stop budget (infmob_usd/effort.py,
``landing``, ``landing_urdf`` and ``_sprung``), measured in MuJoCo on the MJCF: a keyboard key (5 g, 1.5 mm of
travel) held on its stop by a spring twice its weight used to land 9 % of its travel past it, a camera's shutter
button 6 %; and in PyBullet on the URDF (no armature, explicit damping, the spring from ``metadata.json``): the same
key 8.5 %, a laptop's trackpad 11.3 %."""

from __future__ import annotations

import pytest

import infmob_usd
from infmob_usd import effort

mujoco = pytest.importorskip("mujoco")
pytestmark = pytest.mark.sim


INDUCTION = {"design": "induction", "induction_controls": "keys", "mount": "built_in", "key_count": 4}
"""A built-in induction hob with four 2 mm touch keys pressing down through its glass."""


def _model(tmp_path, category: str, seed: int, **overrides):
    obj = infmob_usd.generate(category, seed=seed, texture_size=16, **overrides)
    folder = infmob_usd.save(obj, tmp_path / category, formats="mjcf")
    return obj, mujoco.MjModel.from_xml_path(str(folder / f"{folder.name}.xml"))


def _released_bullet(urdf, name: str, start: float = 0.0, seconds: float = 0.5) -> float:
    """Joint ``name`` of ``urdf`` started ``start`` of its range below its upper limit and let go in PyBullet (its
    default 1/240 s step, the URDF's damping, its return spring from ``metadata.json`` a joint torque, as
    ``push_bullet`` sets it): the furthest it goes past its lower limit (share of its range)."""
    pb = pytest.importorskip("pybullet")
    from infmob_usd.validate.push import _springs

    stiffness, zero = _springs(urdf)[name]
    cid = pb.connect(pb.DIRECT)
    try:
        pb.setGravity(0, 0, -9.81, physicsClientId=cid)
        pb.setTimeStep(1 / 240, physicsClientId=cid)
        body = pb.loadURDF(str(urdf), useFixedBase=True, flags=pb.URDF_USE_INERTIA_FROM_FILE, physicsClientId=cid)
        count = pb.getNumJoints(body, physicsClientId=cid)
        info = [pb.getJointInfo(body, i, physicsClientId=cid) for i in range(count)]
        moving = [i for i, f in enumerate(info) if f[2] in (pb.JOINT_REVOLUTE, pb.JOINT_PRISMATIC)]
        pb.setJointMotorControlArray(body, moving, pb.VELOCITY_CONTROL, forces=[0.0] * len(moving),
                                     physicsClientId=cid)
        k = next(i for i in moving if info[i][1].decode() == name)
        lower, upper = info[k][8], info[k][9]
        pb.resetJointState(body, k, upper - start * (upper - lower), 0.0, physicsClientId=cid)
        past = -1.0
        for _ in range(int(seconds * 240)):
            q = pb.getJointState(body, k, physicsClientId=cid)[0]
            pb.setJointMotorControl2(body, k, pb.TORQUE_CONTROL, force=stiffness * (zero - q), physicsClientId=cid)
            pb.stepSimulation(physicsClientId=cid)
            past = max(past, (lower - pb.getJointState(body, k, physicsClientId=cid)[0]) / (upper - lower))
        return past
    finally:
        pb.disconnect(physicsClientId=cid)


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


CASES = [("keyboard", 1, "joint_key_0", {}), ("keyboard", 0, "joint_key_0", {}), ("camera", 68, "joint_shutter", {}),
         ("laptop", 0, "joint_key_0", {}), ("laptop", 0, "joint_trackpad", {}),
         ("stovetop", 2, "joint_key_0", INDUCTION)]


@pytest.mark.parametrize("push", [False, True], ids=["released", "pushed"])
@pytest.mark.parametrize("category,seed,joint,overrides", CASES)
def test_a_released_sprung_part_lands_within_the_stop_budget(tmp_path, category, seed, joint, overrides, push):
    """In MuJoCo (the MJCF's armature, damping and spring), within the push test's 5 % of its travel, let go or
    pushed home with its effort."""
    _, model = _model(tmp_path, category, seed, **overrides)
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


@pytest.mark.parametrize("category,seed,joint,overrides", CASES)
def test_a_released_sprung_part_lands_within_the_stop_budget_in_a_urdf_reader(tmp_path, category, seed, joint,
                                                                              overrides):
    """In PyBullet on the URDF: no armature, the damping applied explicitly, the spring (sized on the inertia with
    the MJCF's armature) throwing the bare part; within the push test's 5 % of its travel from its far stop, and
    from starts just below it (Bullet holds a stop from the step after the part crosses it, so how far past it
    goes depends on where in a step it arrives)."""
    obj = infmob_usd.generate(category, seed=seed, texture_size=16, **overrides)
    folder = infmob_usd.save(obj, tmp_path / category, formats="urdf")
    urdf = folder / f"{folder.name}.urdf"
    past = max(_released_bullet(urdf, joint, start) for start in (0.0, 0.01, 0.02, 0.03))
    assert past <= 0.05, f"{category} {seed} {joint} lands {past:.1%} of its travel past its rest stop in PyBullet"


def test_the_urdf_landing_estimate_bounds_pybullet(tmp_path):
    """:func:`effort.landing_urdf` bounds what PyBullet measures from any start near the far stop (it takes the
    worst phase: a whole step's travel past the stop), and the rule keeps it within the budget."""
    obj = infmob_usd.generate("laptop", seed=0, texture_size=16)
    folder = infmob_usd.save(obj, tmp_path / "laptop", formats="urdf")
    j = next(j for j in obj.joints if j.name == "joint_trackpad")
    d = effort.drive(obj, j, effort.free_inertias(obj)[j.name], j.armature, effort.SPRING_DAMPING_RATE_MAX)
    estimate = effort.landing_urdf(j, d, effort.gravity_at_rest(obj, j))
    measured = [_released_bullet(folder / f"{folder.name}.urdf", j.name, s) for s in (0.0, 0.01, 0.02, 0.03, 0.04)]
    assert max(measured) <= estimate + 0.005
    assert estimate <= effort.STOP_SHARE


def test_pybullet_push_holds_a_key_up_with_its_spring(tmp_path):
    """``push_bullet`` sets the return springs of ``metadata.json`` (a URDF has none): a touch key pressing down
    through a hob's glass rests on its stop when pushed away from it with its small effort, rather than falling
    onto its pressed stop under its weight (which landed it 9.2 % of its travel past that stop)."""
    pytest.importorskip("pybullet")
    from infmob_usd.validate.push import failures, push_bullet

    obj = infmob_usd.generate("stovetop", seed=2, texture_size=16, **INDUCTION)
    folder = infmob_usd.save(obj, tmp_path / "stovetop", formats="urdf")
    keys = [p for p in push_bullet(folder / f"{folder.name}.urdf") if p.joint.startswith("joint_key_")]
    assert len(keys) == 8 and not failures(keys)
    # held on its rest stop: its effort (a hundredth of its weight) presses it nowhere, and it stays home
    assert all(p.travel < 0.05 if p.side == "upper" else p.travel > 0.95 for p in keys)
