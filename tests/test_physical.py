import math
from dataclasses import replace

import numpy as np
import pytest

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.api import assemble
from infmob_usd.blueprint import Blueprint
from infmob_usd.errors import ModelError
from infmob_usd.physical import DYNAMICS, GROUND_TOL, gap_size

from collide import overlap


def _lowest(obj, q):
    """Lowest z of every collision hull with joints at ``q``, by the object's own forward kinematics
    (independent of how limit_to_ground moves a subtree)."""
    poses = obj.poses(q)
    return min(float((v @ poses[link.name][2, :3] + poses[link.name][2, 3]).min())
               for link in obj.links for p in link.pieces for v, _ in p.hulls())


def _make(bp):
    return assemble(bp, 0, np.random.default_rng(0), 16)


def test_a_bottom_hinged_door_on_a_low_body_gets_a_reduced_limit():
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("body", "body", [g.box_between([-0.3, -0.3, 0.0], [0.3, 0.3, 0.1], "m")])
    # a 0.5 m door hinged 0.1 m above the floor, allowed to open 135 deg: its top edge would
    # sweep 0.25 m below the floor; it may only pass horizontal by about asin(0.1 / 0.5)
    bp.add("door", "door", [g.box_between([0.302, -0.25, 0.1], [0.322, 0.25, 0.6], "m")])
    bp.join(J.revolute("body", "door", (0.322, 0, 0.1), (0, 1, 0), 0.0, 0.75 * math.pi))
    obj = _make(bp)
    door = obj.joints[0]
    assert math.pi / 2 < door.upper < math.pi / 2 + math.asin(0.1 / 0.5) + 0.01
    assert _lowest(obj, {door.name: door.upper}) >= -GROUND_TOL
    assert _lowest(obj, {door.name: door.upper + 0.02}) < -GROUND_TOL  # the limit is tight


def test_a_continuous_joint_through_the_ground_is_an_error():
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("body", "body", [g.box_between([-0.1, -0.1, 0.0], [0.1, 0.1, 0.05], "m")])
    bp.add("arm", "arm", [g.box_between([0.11, -0.02, 0.0], [0.5, 0.02, 0.04], "m")])
    bp.join(J.continuous("body", "arm", (0.11, 0, 0.02), (0, 1, 0)))
    with pytest.raises(ModelError, match="raise it"):
        _make(bp)


def test_a_drawer_flush_with_its_carcass_gets_eroded_collision_not_visuals():
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("carcass", "body", [g.box_between([-0.3, -0.3, 0.0], [0.3, 0.3, 0.02], "m")])
    # the drawer sits directly on the carcass bottom (zero clearance)
    drawer = g.box_between([-0.25, -0.2, 0.02], [0.3, 0.2, 0.2], "m")
    bp.add("drawer", "drawer", [drawer])
    bp.join(J.prismatic("carcass", "drawer", (0.3, 0, 0.02), (1, 0, 0), 0.0, 0.3))
    obj = _make(bp)
    link = obj.link("drawer")
    hull = link.pieces[0].convex[0] + link.origin
    gap = gap_size(np.ptp(drawer.vertices, axis=0))
    assert gap == pytest.approx(0.02 * 0.18)
    assert hull[:, 2].min() >= 0.02 + gap - 1e-9  # collision lifted clear of the carcass
    assert np.allclose(link.pieces[0].vertices + link.origin, drawer.vertices)  # visual unchanged
    rest = obj.poses()
    assert overlap(obj.link("carcass"), rest["carcass"], link, rest["drawer"], pad=0) == 0


def test_dynamics_have_a_role_for_every_joint_family():
    for role in ("hinge", "slide", "knob", "button", "wheel", "lid", "swivel", "telescope"):
        d = DYNAMICS[role]
        assert d.damping > 0 and d.friction >= 0 and d.effort > 0 and d.velocity > 0


def test_sheet_parts_weigh_their_wall_not_their_volume():
    from infmob_usd.mass import inertial

    solid = g.box([0.5, 0.5, 0.01], [0, 0, 0], "m")
    sheet = g.box([0.5, 0.5, 0.01], [0, 0, 0], "m").replace(sheet=0.001)
    m_solid = inertial([(solid, 7850.0)])[0]
    m_sheet = inertial([(sheet, 7850.0)])[0]
    assert m_solid == pytest.approx(0.25 * 0.01 * 7850)
    # half the surface (0.25 m^2 + thin edges) x 1 mm of steel
    assert m_sheet == pytest.approx((0.25 + 0.01) * 0.001 * 7850, rel=1e-6)


def test_material_variants_restrict_the_palette():
    from infmob_usd.materials import sample_look

    rng = np.random.default_rng(0)
    assert {sample_look("plastic:black", rng).variant for _ in range(20)} == {"black"}
    assert {sample_look("plastic:black|white", rng).variant for _ in range(40)} == {"black", "white"}
    with pytest.raises(ValueError, match="its variants"):
        sample_look("plastic:mauve", rng)


def test_passes_return_new_objects_and_leave_their_inputs_alone():
    from infmob_usd import physical
    from infmob_usd.model import build

    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("carcass", "body", [g.box_between([-0.3, -0.3, 0.1], [0.3, 0.3, 0.12], "m")])
    bp.add("drawer", "drawer", [g.box_between([-0.25, -0.2, 0.12], [0.3, 0.2, 0.3], "m")])
    bp.add("door", "door", [g.box_between([0.302, -0.25, 0.12], [0.322, 0.25, 0.8], "m")])
    bp.join(J.prismatic("carcass", "drawer", (0.3, 0, 0.12), (1, 0, 0), 0.0, 0.3))
    bp.join(J.revolute("carcass", "door", (0.322, 0, 0.12), (0, 1, 0), 0.0, 0.75 * math.pi))
    before = bp.bounds().copy()
    grounded = physical.rest_on_ground(bp)
    assert grounded is not bp and np.allclose(bp.bounds(), before)  # the input stays where it was
    assert grounded.bounds()[0, 2] == pytest.approx(0.0)
    links, joints = build(grounded, {"m": 700.0})
    hulls = [c.copy() for link in links for p in link.pieces for c in p.convex]
    limits = [(j.lower, j.upper) for j in joints]
    gapped = physical.ensure_gaps(links, joints)
    after = [c for link in links for p in link.pieces for c in p.convex]
    assert all(np.array_equal(a, b) for a, b in zip(after, hulls, strict=True))  # untouched
    assert gapped[1] is not links[1] and gapped[0] is links[0]  # the drawer eroded, the carcass kept
    assert gapped[1].pieces[0].convex[0][:, 2].min() > links[1].pieces[0].convex[0][:, 2].min()
    limited = physical.limit_to_ground(gapped, joints)
    assert [(j.lower, j.upper) for j in joints] == limits  # untouched
    door = next(j for j in limited if j.child == "door")
    assert door.upper < 0.75 * math.pi and next(j for j in limited if j.child == "drawer").upper == 0.3


def test_a_coupled_second_axis_is_carried_into_the_ground_check():
    """A dual-axis hinge (a 360-degree laptop's): a link turns about a low axis and the lid about a high one,
    coupled 1:1. Each alone stays above the floor up to 180 degrees, together they fold the lid under the base:
    the leader is limited where the pair meets the ground (half of about 180 degrees in all)."""
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("base", "base", [g.box_between([-0.1, -0.1, 0.0], [0.1, 0.1, 0.02], "m")])
    bp.add("link", "hinge", [g.box_between([-0.106, -0.01, 0.008], [-0.102, 0.01, 0.03], "m")])
    bp.add("lid", "lid", [g.box_between([-0.1, -0.1, 0.024], [0.1, 0.1, 0.03], "m")])
    bp.join(J.revolute("base", "link", (-0.104, 0, 0.01), (0, -1, 0), 0.0, math.pi))
    bp.join(J.revolute("link", "lid", (-0.104, 0, 0.027), (0, -1, 0), 0.0, math.pi))
    bp.joints[-1] = replace(bp.joints[-1], mimic=J.Mimic("link", 1.0, 0.0))
    obj = _make(bp)
    lead, lid = obj.joints
    assert lead.upper < math.pi / 2 + 0.1  # not the 180 degrees each allows alone
    assert _lowest(obj, {lead.name: lead.upper, lid.name: lid.upper}) >= -GROUND_TOL


def test_a_turn_past_half_a_revolution_is_swept_for_the_ground():
    """A lid allowed a full turn (a convertible laptop's) is back at rest at its limit, but on the way it swings
    through the floor: its limit is where it first meets the ground, not the full turn."""
    bp = Blueprint("t", materials={"m": "painted"})
    bp.add("base", "base", [g.box_between([-0.1, -0.1, 0.0], [0.1, 0.1, 0.02], "m")])
    bp.add("lid", "lid", [g.box_between([-0.1, -0.1, 0.024], [0.1, 0.1, 0.03], "m")])
    bp.join(J.revolute("base", "lid", (-0.1, 0, 0.027), (0, -1, 0), 0.0, 2 * math.pi))
    lid = _make(bp).joints[0]
    assert math.pi < lid.upper < math.pi + math.asin(0.03 / 0.2) + 0.01


def test_a_holding_hinge_has_the_friction_to_hold_its_load_and_the_effort_to_move_it():
    """A lid on a ``holding`` (friction) hinge: its friction is 1.3 x the largest gravity torque of the lid about
    the hinge, and its effort beats that friction; on a plain ``hinge`` it is the role's 0.5 N m."""
    from infmob_usd.effort import HOLD_MARGIN

    def lid(role):
        bp = Blueprint("t", materials={"m": "painted"})
        bp.add("base", "base", [g.box_between([-0.2, -0.2, 0.0], [0.2, 0.2, 0.02], "m")])
        bp.add("lid", "lid", [g.box_between([-0.2, -0.2, 0.021], [0.2, 0.2, 0.041], "m")])
        bp.join(J.revolute("base", "lid", (-0.2, 0, 0.031), (0, -1, 0), 0.0, math.radians(135), role))
        obj = _make(bp)
        return obj.joints[0], next(link for link in obj.links if link.name == "lid")

    j, link = lid("holding")
    load = link.mass * 9.81 * 0.2  # the centre of mass 0.2 m from the axis, level with it
    assert j.friction == pytest.approx(HOLD_MARGIN * load, rel=0.02)
    assert j.effort > j.friction
    assert lid("hinge")[0].friction == DYNAMICS["hinge"].friction < j.friction
