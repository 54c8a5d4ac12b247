"""The core's physics passes on small synthetic blueprints: ``limit_to_clearance`` (swept hulls
against every other link, then the combined states) and ``rest_on_stops`` (passive joints neutral
under gravity or pressed onto their rest stop)."""

import math

import numpy as np
import pytest

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.api import assemble
from infmob_usd.blueprint import Blueprint
from infmob_usd.physical import BALANCED, CLEARANCE, gravity_torque

from collide import overlap


def _make(bp):
    return assemble(bp, 0, np.random.default_rng(0), 16)


def _joint(obj, child):
    return next(j for j in obj.joints if j.child == child)


def _meet(obj, a, b, q):
    poses = obj.poses(q)
    return overlap(obj.link(a), poses[a], obj.link(b), poses[b])


def _door_beside_wall(wall_y=-0.12):
    """A 0.4 m leaf hinged at y = -0.1 on a low body's front, swinging about -Z toward -Y, and a
    wall (fixed to the body) in the plane y = ``wall_y`` in front of it."""
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("body", "body", [g.box_between([-0.3, -0.1, 0.0], [0.3, 0.3, 0.6], "m")])
    bp.add("wall", "body", [g.box_between([-0.3, wall_y - 0.02, 0.0], [0.6, wall_y, 0.6], "m")])
    bp.join(J.fixed("body", "wall"))
    bp.add("door", "door", [g.box_between([0.302, -0.098, 0.05], [0.322, 0.3, 0.55], "m")])
    bp.join(J.revolute("body", "door", (0.322, -0.1, 0.05), (0, 0, -1), 0.0, 0.9 * math.pi))
    return bp


def test_a_door_beside_a_wall_stops_before_the_wall():
    obj = _make(_door_beside_wall())
    door = _joint(obj, "door")
    # past 90 degrees the leaf's front face (on the hinge line) turns toward the wall face 2 cm
    # beside that line; the wall ends at x = 0.6, 0.278 m out: contact at 90 deg + asin(0.021 / 0.278)
    assert door.upper == pytest.approx(0.5 * math.pi + math.asin(0.021 / 0.278), abs=0.01)
    assert _meet(obj, "door", "wall", {door.name: door.upper}) == 0.0
    assert _meet(obj, "door", "wall", {door.name: door.upper + 0.05}) > 1e-7  # the limit is tight
    assert door.lower == 0.0


def test_a_door_with_room_keeps_its_declared_limit_and_the_object_is_not_modified():
    bp = _door_beside_wall(wall_y=-0.6)
    obj = _make(bp)
    assert _joint(obj, "door").upper == pytest.approx(0.9 * math.pi)


def test_the_pass_returns_a_new_object_and_leaves_the_old_one():
    from infmob_usd import physical

    bp = _door_beside_wall()
    original = physical.limit_to_clearance
    try:
        physical.limit_to_clearance = lambda o: o
        before = _make(bp)
    finally:
        physical.limit_to_clearance = original
    after = physical.limit_to_clearance(before)
    assert after is not before
    assert _joint(before, "door").upper == pytest.approx(0.9 * math.pi)  # untouched
    assert _joint(after, "door").upper < 0.6 * math.pi


def test_a_door_beside_a_drawer_stops_where_the_open_drawer_is_and_the_drawer_keeps_its_travel():
    # alone, the door swings past the closed drawer's front and the drawer slides out freely;
    # with both at 100 % (as validators sample) the leaf would sweep into the drawer's box
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("body", "body", [g.box_between([-0.3, -0.5, 0.0], [0.3, 0.5, 0.5], "m")])
    bp.add("drawer", "drawer", [g.box_between([-0.25, -0.48, 0.05], [0.32, -0.02, 0.45], "m")])
    bp.join(J.prismatic("body", "drawer", (0.32, -0.25, 0.05), (1, 0, 0), 0.0, 0.4))
    bp.add("door", "door", [g.box_between([0.302, 0.002, 0.05], [0.322, 0.48, 0.45], "m")])
    bp.join(J.revolute("body", "door", (0.322, 0.002, 0.05), (0, 0, -1), 0.0, 0.6 * math.pi))
    obj = _make(bp)
    door, drawer = _joint(obj, "door"), _joint(obj, "drawer")
    assert drawer.upper == pytest.approx(0.4)
    assert 0.5 * math.pi < door.upper < 0.55 * math.pi  # the open drawer's side is 2 cm past the hinge
    both = {door.name: door.upper, drawer.name: drawer.upper}
    assert _meet(obj, "door", "drawer", both) == 0.0
    assert _meet(obj, "door", "drawer", {door.name: 0.6 * math.pi, drawer.name: drawer.upper}) > 1e-7


def test_a_rack_behind_a_door_is_swept_with_the_door_open():
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("body", "body", [g.box_between([-0.3, -0.3, 0.0], [0.3, 0.3, 0.1], "m"),
                            g.box_between([-0.3, -0.3, 0.5], [0.3, 0.3, 0.52], "m")])
    bp.add("door", "door", [g.box_between([0.302, -0.3, 0.1], [0.322, 0.3, 0.5], "m")])
    bp.join(J.revolute("body", "door", (0.322, 0.3, 0.1), (0, 0, 1), 0.0, math.pi / 2))
    bp.add("rack", "rack", [g.box_between([-0.25, -0.25, 0.15], [0.28, 0.25, 0.2], "m")])
    bp.join(J.prismatic("body", "rack", (0.28, 0, 0.15), (1, 0, 0), 0.0, 0.3, requires_open="door"))
    obj = _make(bp)
    assert _joint(obj, "rack").upper == pytest.approx(0.3)  # the closed door does not stop it
    # without the gate, the closed door is in the way: the rack stops before it
    bp.joints[-1] = J.prismatic("body", "rack", (0.28, 0, 0.15), (1, 0, 0), 0.0, 0.3)
    rack = _joint(_make(bp), "rack")
    assert rack.upper == pytest.approx(0.302 - 0.28 - CLEARANCE, abs=2e-4)


def test_a_lid_leaning_back_over_its_hinge_is_pressed_onto_its_stop():
    # a lid hinged at the back top edge with its centre of mass behind the hinge line: declared
    # two-sided, the core keeps the side that lifts it (here: flips the axis) and rests it on a stop
    bp = Blueprint("t", materials={"m": "painted", "knob": "plastic:black"})
    bp.add("box", "body", [g.box_between([-0.2, -0.2, 0.0], [0.2, 0.2, 0.3], "m")])
    lid = [g.box_between([-0.5, -0.2, 0.302], [0.2, 0.2, 0.322], "m"),
           g.box_between([0.0, -0.02, 0.322], [0.04, 0.02, 0.34], "knob")]
    bp.add("lid", "lid", lid)
    bp.join(J.revolute("box", "lid", (-0.2, 0, 0.322), (0, 1, 0), -0.3, 0.4))
    obj = _make(bp)
    joint = _joint(obj, "lid")
    torque, mass, _ = gravity_torque(obj.links, obj.joints, joint)
    assert joint.lower == 0.0 and joint.upper > 0
    assert torque < -BALANCED * 9.81 * mass  # gravity presses it toward q < 0: onto the rest stop
    assert np.allclose(joint.axis, (0, -1, 0))  # flipped: the declared +q lowered the lid


def test_a_lever_that_gravity_pulls_off_its_stop_gets_a_counterweight():
    bp = Blueprint("t", materials={"m": "painted", "chrome": "chrome"})
    bp.add("plate", "body", [g.box_between([-0.1, -0.1, 0.0], [0.0, 0.1, 0.3], "m")])
    # a grip to +Y of an axis along X: gravity turns it down (toward +q about +X... -Y side up)
    lever = [g.cylinder([0.002, 0, 0.2], [0.05, 0, 0.2], 0.01, "chrome", 16),
             g.box_between([0.035, 0.0, 0.195], [0.05, 0.12, 0.205], "chrome")]
    bp.add("lever", "lever", lever)
    bp.join(J.revolute("plate", "lever", (0.002, 0, 0.2), (-1, 0, 0), 0.0, math.pi / 4, role="hinge"))
    before = sum(p.volume() for p in lever)
    obj = _make(bp)
    link, joint = obj.link("lever"), _joint(obj, "lever")
    heel = [p for p in link.pieces if p.name == "counterweight"]
    assert len(heel) == 1
    assert heel[0].bounds[1, 1] <= 1e-9  # opposite the grip
    torque, mass, com = gravity_torque(obj.links, obj.joints, joint)
    assert abs(torque) < 1e-9 and sum(p.volume() for p in link.pieces) > before
    assert (joint.lower, joint.upper) == (0.0, pytest.approx(math.pi / 4))


def test_a_sprung_button_that_gravity_pulls_off_its_stop_is_held_by_its_spring_not_a_counterweight():
    # a mouse button on its rear hinge: its front presses down (+q), the way gravity turns it; the return
    # spring holds it on its rest stop, so no counterweight heel grows behind the hinge into the body
    bp = Blueprint("t", materials={"m": "plastic:black"})
    bp.add("shell", "body", [g.box_between([-0.06, -0.03, 0.0], [0.06, 0.03, 0.02], "m")])
    button = [g.box_between([0.0, 0.002, 0.021], [0.05, 0.028, 0.0235], "m")]
    bp.add("button", "button", button)
    bp.join(J.revolute("shell", "button", (0.0, 0.015, 0.021), (0, 1, 0), 0.0, math.radians(2.0), role="button"))
    obj = _make(bp)
    link, joint = obj.link("button"), _joint(obj, "button")
    assert not [p for p in link.pieces if p.name == "counterweight"]
    torque, mass, _ = gravity_torque(obj.links, obj.joints, joint)
    assert torque > BALANCED * 9.81 * mass  # gravity still turns it toward +q: off its rest stop
    # the spring's zero lies beyond the rest stop, far enough that at q = 0 it presses harder than gravity pulls
    assert joint.stiffness > 0 and joint.stiffness * (0.0 - joint.spring_ref) > torque


def test_a_swivel_about_z_is_neutral_and_untouched():
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("base", "body", [g.box_between([-0.1, -0.1, 0.0], [0.1, 0.1, 0.1], "m")])
    bp.add("arm", "arm", [g.box_between([-0.02, -0.02, 0.102], [0.4, 0.02, 0.14], "m")])
    bp.join(J.revolute("base", "arm", (0, 0, 0.102), (0, 0, 1), -1.0, 1.0, role="swivel"))
    obj = _make(bp)
    joint = _joint(obj, "arm")
    assert (joint.lower, joint.upper) == (-1.0, 1.0) and np.allclose(joint.axis, (0, 0, 1))
    assert not [p for p in obj.link("arm").pieces if p.name == "counterweight"]


def _drawer_before_a_stop(room: float):
    """A drawer that slides out (+X) toward a fixed stop ``room`` m beyond the 1 mm clearance."""
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("body", "body", [g.box_between([-0.3, -0.3, 0.0], [0.3, 0.3, 0.02], "m")])
    bp.add("drawer", "drawer", [g.box_between([-0.25, -0.2, 0.03], [0.3, 0.2, 0.2], "m")])
    bp.join(J.prismatic("body", "drawer", (0.3, 0, 0.03), (1, 0, 0), 0.0, 0.3))
    bp.add("stop", "body", [g.box_between([0.3 + CLEARANCE + room, -0.3, 0.0], [0.35, 0.3, 0.25], "m")])
    bp.join(J.fixed("body", "stop"))
    return bp


def test_a_joint_the_clearance_pass_leaves_under_a_millimetre_is_fixed_and_noted(tmp_path):
    import json

    import infmob_usd

    obj = _make(_drawer_before_a_stop(0.0004))
    drawer = _joint(obj, "drawer")
    assert drawer.type == "fixed" and not drawer.movable, (drawer.type, drawer.lower, drawer.upper)
    assert len(obj.notes) == 1 and drawer.name in obj.notes[0] and "made fixed" in obj.notes[0]
    meta = json.loads((infmob_usd.save(obj, tmp_path) / "metadata.json").read_text())
    assert meta["notes"] == obj.notes
    assert meta["counts"]["movable_joints"] == 0
    # 3 mm of travel is a mechanism: kept, nothing noted
    obj = _make(_drawer_before_a_stop(0.003))
    assert _joint(obj, "drawer").upper == pytest.approx(0.003, abs=2e-4) and obj.notes == []
