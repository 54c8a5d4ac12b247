"""Every joint can be moved with its own effort: its friction, its return spring and the joints it drives do not
take the whole effort (infmob_usd/effort.py), checked on the model and in MuJoCo on the written MJCF."""

from __future__ import annotations

from dataclasses import replace

import pytest

import infmob_usd
from infmob_usd import effort

SAMPLE = ("scissors", "bucket", "tap", "lamp", "switch", "laptop", "kettle", "office_chair", "plate_rack",
          "monitor", "trash_can", "toaster")


@pytest.mark.parametrize("category", SAMPLE)
def test_friction_is_below_the_effort(category):
    """A role's friction (0.5 N m for a hinge) on a 20 g scissors blade whose effort is 0.02 N m: no push
    within the effort moves it. Friction is at most a share of the effort, or (a friction-held joint) the
    effort is raised by it."""
    for seed in (0, 1, 2):
        obj = infmob_usd.generate(category, seed=seed, texture_size=16)
        for j in obj.movable_joints:
            if j.stiffness > 0:
                continue  # a return spring sizes its joint's friction
            assert 0 < j.friction < j.effort or j.friction == 0 < j.effort, (seed, j.name, j.friction, j.effort)
            if j.role not in effort.HELD_ROLES:
                assert j.friction <= effort.FRICTION_SHARE * j.effort * 1.0001, (seed, j.name)


def test_a_holding_joint_still_holds_its_load():
    """A laptop lid's friction hinge holds the lid at any angle, whatever share of the effort that is."""
    obj = infmob_usd.generate("laptop", seed=0, texture_size=16)
    lid = next(j for j in obj.movable_joints if j.role == "holding")
    assert lid.friction >= effort.holding(obj, replace(lid, friction=0.0)) * 0.9999 > 0
    assert lid.effort > lid.friction


def _pushed(tmp_path, category, seed, joint):
    """How much of its range ``joint`` covers when pushed with its own effort for 1 s from rest (MuJoCo, MJCF)."""
    pytest.importorskip("mujoco")
    from infmob_usd.validate.mujoco_sim import load_model, push_joints

    obj = infmob_usd.generate(category, seed=seed, texture_size=16)
    folder = infmob_usd.save(obj, tmp_path / category, formats="mjcf")
    pushes = push_joints(load_model(folder / f"{folder.name}.xml"), rest=False)
    return {p.side: p.travel for p in pushes if p.joint == joint}


@pytest.mark.sim
@pytest.mark.parametrize("category,seed,joint", [("scissors", 0, "joint_blade"), ("scissors", 1, "joint_blade"),
                                                 ("door", 0, "joint_leaf")])
def test_a_joint_moves_under_its_own_effort(tmp_path, category, seed, joint):
    """A scissors blade (friction 0.5 N m, effort 0.019 N m before) crept 20 % of its range in a second of its own
    effort in MuJoCo; a door swings open and shut."""
    travel = _pushed(tmp_path, category, seed, joint)
    assert travel["upper"] > 0.95 and travel["lower"] > 0.95, travel


def test_a_sprung_lever_is_pressed_home_against_its_spring():
    """A mop bucket's wringer lever (bucket seed 5) had 0.85 N m of effort against 5.6 N m of spring at its far
    limit: a robot at that effort stalls. Every spring the simulators' step allows is beaten by a fifth."""
    obj = infmob_usd.generate("bucket", seed=5, texture_size=16)
    lever = next(j for j in obj.movable_joints if j.stiffness > 0)
    assert lever.role == "lever" and lever.effort >= effort.SPRING_MARGIN * effort.against_spring(obj, lever) * 0.999
    for category, seed in (("toaster", 0), ("dispenser", 0), ("refrigerator", 2)):
        obj = infmob_usd.generate(category, seed=seed, texture_size=16)
        levers = [j for j in obj.movable_joints if j.stiffness > 0 and j.role == "lever"]
        assert levers
        for j in levers:
            assert j.effort >= effort.SPRING_MARGIN * effort.against_spring(obj, j) * 0.999, (category, j.name)


@pytest.mark.sim
def test_a_sprung_lever_reaches_its_far_stop_in_mujoco(tmp_path):
    travel = _pushed(tmp_path, "bucket", 5, "joint_lever")
    assert travel["upper"] > 0.95, travel


def test_a_coupled_leader_drives_its_followers():
    """A pedal bin's pedal opens a lid turning 5 times as far (trash_can seed 7): its effort (0.0087 N m) was its
    own, not the 4.8 N m the lid's effort takes at the pedal. A wringer lever drives its press plate, a folding
    chair's seat its legs."""
    for category, seed in (("trash_can", 7), ("bucket", 5), ("folding_chair", 0)):
        obj = infmob_usd.generate(category, seed=seed, texture_size=16)
        by_name = {j.name: j for j in obj.joints}
        followers = [j for j in obj.movable_joints if j.mimic is not None]
        assert followers, category
        for j in followers:
            leader, ratio, _ = j.mimic
            assert by_name[leader].effort > abs(ratio) * j.effort, (category, leader, j.name)
