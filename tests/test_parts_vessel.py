"""The vessel parts (categories/parts/vessel.py) and the core pieces they added: auto choices,
(parameter, table) material slots, Assembly.pieces."""

from __future__ import annotations

import math

import numpy as np
import pytest

from infmob_usd.assembly import Assembly
from infmob_usd.blueprint import Blueprint
from infmob_usd.categories.parts import vessel as V
from infmob_usd.categories.parts import vessel_sizes as S
from infmob_usd.category import Category
from infmob_usd.errors import ModelError
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Float


def _vase(height=0.3, radius=0.06, wall=0.004):
    shape = S.VASE_SHAPES["bottle_neck"]
    return V.vase_body(shape, height, radius, wall, [0.0] * len(shape), "body")


def test_body_anchors_and_supports_in_its_local_frame():
    body, prof = _vase()
    assert np.allclose(body.anchor("base").origin, 0) and np.allclose(body.anchor("rim").origin, (0, 0, 0.3))
    assert np.allclose(body.anchor("lid_seat").z, (0, 0, 1))
    feet = np.array(list(body.supports.values()))
    assert np.allclose(feet[:, 2], 0) and np.allclose(np.hypot(feet[:, 0], feet[:, 1]), prof.base_radius)
    # the wall's collision is flat-faced 8-corner wedges (PhysX: no snapped near-coplanar faces)
    assert all(len(c) == 8 for c in body.parts["main"].pieces[0].convex)


def test_lift_off_lid_seats_on_the_rim_and_its_plug_clears_the_mouth():
    body, prof = _vase()
    lid = V.lift_off_lid(prof, 0.005, 0.2, "body")
    assert np.allclose(lid.anchor("seat").origin, 0)  # the seat is the lid's origin
    placed = lid.attached("seat", to=body.anchor("lid_seat"))
    pts = np.vstack([c for pc in placed.pieces for c in pc.convex])
    assert pts[:, 2].min() < 0.3 - 0.01  # the plug reaches into the mouth
    plug = pts[pts[:, 2] < 0.3]
    assert np.hypot(plug[:, 0], plug[:, 1]).max() < prof.free_radius(0.27, 0.3)


def test_seat_joint_lifts_along_the_seat_and_turns_about_it():
    bp = Blueprint("t")
    body, prof = _vase()
    b = bp.place(body.placed(Frame.at((0.1, 0.2, 0.0))), "body")
    cap = bp.place(V.stopper(prof, "cork").attached("seat", to=b.anchor("lid_seat")), "cap")
    j = V.seat_joint(b.root, cap, 0.01)
    assert j.kind == "continuous_prismatic" and j.role == "lift_off"
    assert all(np.allclose(d.origin, (0.1, 0.2, 0.3)) and np.allclose(d.axis, (0, 0, 1)) for d in j.dofs)
    assert j.dofs[0].lower == 0.0 and j.dofs[0].upper == pytest.approx(0.01)
    assert V.seat_joint(b.root, cap, 0.01, turns=False).kind == "prismatic"


def test_hinged_lid_rests_closed_and_opens_upward():
    lid = V.hinged_lid(0.05, 0.004, 0.006, "lid", knob=0.008)
    (j,) = lid.joints
    assert j.kind == "revolute" and (j.parent, j.child) == ("main", "lid") and j.role == "lid"
    d = j.dofs[0]
    assert d.lower == 0.0 and math.radians(90) < d.upper < math.radians(130)
    plate = lid.parts["lid"].pieces[0].vertices
    assert plate[:, 2].min() == pytest.approx(0.0)  # closed: on its seat
    # turning by +90 degrees about the hinge stands the far edge up above the hinge
    hinge = Frame.at(d.origin, z=d.axis)
    moved = (hinge @ Frame.at().turned("z", math.pi / 2) @ hinge.inverse()).point(plate)
    assert moved[:, 2].max() > 0.09


def test_cookware_lid_handles_and_ring_fit_the_pot():
    body, pot = V.cookware_body(0.12, 0.1, 0.015, 0.05, 0.002, 0.005, 0.0025, "body", "rim")
    assert body.anchor("lid_seat").origin[2] == pytest.approx(0.1 + S.LID_GAP)
    ring, room = V.hanging_ring(0.03, 0.014, "h")
    h = V.long_handle(pot, 0.2, 0.2, 0.03, 0.014, "h", end_room=room)
    tip = V.hanging_ring(0.03, 0.014, "h")[0].attached("start", to=h.anchor("end"))
    lid, _ = V.dome_lid(pot, 0.02, 0.002, "body", "rim")
    pts = np.vstack([c for pc in h.pieces + tip.pieces for c in pc.convex])
    near = np.hypot(pts[:, 0], pts[:, 1]) < lid.bounds()[1, 0] + 0.002
    assert (pts[near, 2] < pot.rim_bottom).all()  # under the rim out past the lid's edge
    assert 0.15 < pts[:, 0].max() - 0.12 < 0.25  # reaches out about its length from the wall


def test_assembly_pieces_are_every_part_in_order():
    a = V.hinged_lid(0.05, 0.004, 0.006, "lid")
    assert a.pieces == a.parts["main"].pieces + a.parts["lid"].pieces


# -- core additions: auto choices and (parameter, table) material slots ---------------------


def _grammar(auto):
    return Grammar("box", {"box": Node(label="body", required=("lid",)),
                           "lid": Node(one_of={"flat": 1.0, "dome": 1.0}, choice="lid_kind", auto=auto),
                           "flat": Node(label="lid"), "dome": Node(label="lid")})


class _BoxLayout(Layout):
    def box(self, node):
        self.add("body", "body", _vase()[0].pieces)
        self.grow(node.one("lid"))

    def lid(self, node):
        self.grow(node.one(node.choice))

    def flat(self, node):
        self.add("lid", "lid", [V.hinged_lid(0.02, 0.003, 0.004, "lid").pieces[1]])

    dome = flat


def test_auto_choice_follows_the_other_parameters_and_can_be_forced():
    cat = Category("box", "a box", (Float("size", "size", "m", 0.1, 0.5),),
                   _grammar(lambda p: "dome" if p["size"] > 0.3 else "flat"), _BoxLayout,
                   materials={"lid": ("lid_kind", {"flat": "wood", "dome": "chrome"})})
    rng = np.random.default_rng(0)
    assert cat.schema["lid_kind"].choices == ("auto", "flat", "dome")
    p = cat.schema.sample(rng, {"size": 0.4})
    assert p["lid_kind"] == "auto"
    assert cat.resolve_materials(p)["lid"] == "chrome"
    tree = cat.grammar.grow(p, rng)
    assert tree.one("lid").choice == "dome"
    forced = cat.schema.sample(rng, {"size": 0.4, "lid_kind": "flat"})
    assert cat.grammar.grow(forced, rng).one("lid").choice == "flat"
    assert cat.resolve_materials(forced)["lid"] == "wood"
    bp = cat.build(p, np.random.default_rng(1), np.random.default_rng(2))  # grows, builds, checks
    assert p["lid_kind"] == "dome" and bp.materials["lid"] == "chrome"  # the recorded value is what was built


def test_bad_auto_and_material_tables_are_errors():
    with pytest.raises(ModelError, match="auto"):
        Grammar("x", {"x": Node(label="a", auto=lambda p: "a")})
    bad = Category("box", "a box", (), _grammar(lambda p: "round"), _BoxLayout)
    with pytest.raises(ModelError, match="auto picked 'round'"):
        bad.grammar.resolve({"lid_kind": "auto"})
    with pytest.raises(ModelError, match="must name a parameter"):
        Category("box", "a box", (), _grammar(lambda p: "flat"), _BoxLayout, materials={"lid": ("colour", {})})


def test_every_closure_is_an_assembly_seated_at_its_origin():
    _, prof = _vase()
    bottle = V.bottle_profile("beer", "crown", 0.23, 0.03, 0.003)
    for closure in (V.crown_cap(bottle, "cap"), V.screw_cap(V.bottle_profile("soda", "screw", 0.25, 0.035, 0.003),
                                                               "cap"),
                    V.capsule(V.bottle_profile("champagne", "capsule", 0.3, 0.045, 0.003), True, "cap", "cork"),
                    V.stopper(prof, "cork"), V.lift_off_lid(prof, 0.004, 0.1, "body")):
        assert isinstance(closure, Assembly)
        assert np.allclose(closure.anchor("seat").matrix, np.eye(4))
        assert closure.anchor("top").origin[2] > 0
