"""The bar chair category: bases, joints, clearances at every joint state, overrides, seeds."""

from __future__ import annotations

import numpy as np
import pytest
from test_office_chair import _box, assert_clear, rest_overlaps

from infmob_usd.model import build as build_model

from helpers import maker, states
from zoo import by_child, movable

SEEDS = range(4)
LABELS = {"base", "caster", "wheel", "lift", "seat", "back", "lever", "foot_ring", "arm", "knob"}


make = maker("bar_chair")


@pytest.mark.parametrize("seed", SEEDS)
def test_parts_labels_sizes(seed):
    p, bp = make(seed)
    assert bp.root == "base"
    assert {part.label for part in bp.parts.values()} <= LABELS
    assert {pc.material for part in bp.parts.values() for pc in part.pieces} <= set(bp.materials)
    seat = np.array([pc.bounds for n in ("seat", "seat_pan") if n in bp.parts for pc in bp.parts[n].pieces
                     if pc.material == "seat"])
    assert seat[:, 1, 2].max() == pytest.approx(p["seat_height"], abs=1e-6)
    assert 0.6 <= p["seat_height"] <= 0.85
    assert bp.bounds()[0, 2] == pytest.approx(0.0, abs=1e-9)
    links, _ = build_model(bp, {k: 1000.0 for k in bp.materials})
    assert all(link.mass > 0 for link in links)


@pytest.mark.parametrize("base_type", ["wheeled", "disc"])
def test_joints(base_type):
    p, bp = make(1, base_type=base_type, has_back=True, back_mount="hinged", has_lever=False, has_seat_tilt=False)
    lift = by_child(bp, "lift")
    assert lift.kind == "prismatic" and lift.dofs[0].axis == pytest.approx((0, 0, 1))
    assert lift.dofs[0].lower == 0.0 and 0.05 < lift.dofs[0].upper <= 0.12
    seat = by_child(bp, "seat")
    assert seat.kind == "continuous" and seat.dofs[0].axis == pytest.approx((0, 0, 1))
    back = by_child(bp, "back")
    assert back.kind == "revolute" and back.dofs[0].axis == pytest.approx((0, -1, 0)) and back.dofs[0].lower == 0
    casters = [n for n, part in bp.parts.items() if part.label == "caster"]
    wheels = [n for n, part in bp.parts.items() if part.label == "wheel"]
    if base_type == "disc":
        assert not casters and not wheels and len(movable(bp)) == 3
    else:
        assert 3 <= len(casters) <= 10 and len(wheels) >= len(casters)
        for n in wheels:
            assert min(pc.bounds[0, 2] for pc in bp.parts[n].pieces) == pytest.approx(0.0, abs=1e-9)
            assert by_child(bp, n).kind == "continuous"
        for n in casters:
            assert by_child(bp, n).dofs[0].axis == pytest.approx((0, 0, 1))
    _, bp = make(1, has_back=True, back_mount="fixed")
    assert by_child(bp, "back").kind == "fixed"


def test_foot_ring_on_the_disc_base():
    _, bp = make(2, base_type="disc")
    ring = [pc for pc in bp.parts["base"].pieces if pc.material == "ring"]
    assert ring
    z = max(pc.bounds[1, 2] for pc in ring)
    assert 0.15 < z < bp.parts["seat"].pieces[0].bounds[0, 2]
    _, bp = make(2, base_type="wheeled", has_ring_slide=False)
    assert not any(pc.material == "ring" for pc in bp.parts["base"].pieces) and "foot_ring" not in bp.parts


@pytest.mark.parametrize("over", [dict(base_type="wheeled", leg_count=5, has_back=True, back_mount="hinged",
                                       seat_shape="square"),
                                  dict(base_type="disc", has_back=True, back_mount="hinged", seat_shape="round"),
                                  dict(base_type="wheeled", has_ring_slide=True, has_lever=True, seat_shape="round"),
                                  dict(base_type="four_leg", has_back=True, back_mount="hinged", seat_shape="square"),
                                  dict(base_type="disc", has_lever=True, has_seat_tilt=True, seat_shape="square"),
                                  dict(base_type="wheeled", has_seat_tilt=True, has_back=True, seat_shape="round")])
def test_no_collisions_or_ground_at_any_sampled_state(over):
    _, bp = make(3, **over)
    rest_pc = rest_overlaps(bp)
    for q in states(bp):
        ps = bp.poses(q)
        assert min(_box(bp.parts[n], ps[n])[0][2] for n in bp.parts) >= -5e-4
        assert_clear(bp, ps, rest_pc, q)


def test_variety():
    made = [make(s)[0] for s in range(12)]
    for name in ("base_type", "seat_shape", "has_back", "base_finish"):
        assert len({p[name] for p in made}) > 1, name


def test_designs_grow_their_mechanisms():
    """Drafting stool: the foot ring slides on the column; four-leg stool: the seat swivels on the frame
    (no lift); a gas-lift stool's height lever lifts its paddle."""
    _, bp = make(4, base_type="wheeled", has_ring_slide=True)
    j = by_child(bp, "foot_ring")
    assert j.kind == "prismatic" and j.parent == "base" and j.dofs[0].axis == pytest.approx((0, 0, 1))
    assert j.dofs[0].upper > 0.03
    _, bp = make(4, base_type="four_leg", has_back=False)
    assert set(bp.parts) == {"base", "seat"} and by_child(bp, "seat").kind == "continuous"
    assert by_child(bp, "seat").parent == "base"
    feet = [pc for pc in bp.parts["base"].pieces if pc.material == "caster"]
    assert len(feet) == 4 and all(pc.bounds[0, 2] == pytest.approx(0.0, abs=1e-9) for pc in feet)
    _, bp = make(4, base_type="disc", has_lever=True)
    j = by_child(bp, "lever")
    assert j.kind == "revolute" and j.parent == "seat" and j.dofs[0].axis == pytest.approx((1, 0, 0))
    assert 0.05 < j.dofs[0].upper <= 0.35
    assert not any(pc.name == "handle" for pc in bp.parts["seat"].pieces)
    _, bp = make(4, base_type="disc", has_seat_tilt=True)
    j = by_child(bp, "seat_pan")
    assert j.kind == "revolute" and j.parent == "seat" and j.dofs[0].axis == pytest.approx((0, 1, 0))
    assert {pc.material for pc in bp.parts["seat_pan"].pieces} == {"seat", "pan"}


@pytest.mark.parametrize("style,base", [("arm_fixed", "disc"), ("arm_height", "wheeled"), ("arm_flip", "four_leg"),
                                        ("arm_flip", "wheeled")])
def test_arms_beside_the_back(style, base):
    """A stool with a back may have two arms on brackets under its seat, beside the back: fixed, sliding up
    their posts, or flipping up and back; every state stays clear. No back, no arms."""
    _, bp = make(5, base_type=base, has_back=True, has_arms=True, arm_style=style, back_mount="hinged",
                 seat_shape="square")
    arms = [n for n, part in bp.parts.items() if part.label == "arm"]
    assert sorted(arms) == ["arm_left", "arm_right"]
    kinds = {by_child(bp, n).kind for n in arms}
    assert kinds == {{"arm_fixed": "fixed", "arm_height": "prismatic", "arm_flip": "revolute"}[style]}
    assert all(by_child(bp, n).parent == "seat" for n in arms)
    ys = [np.array([pc.bounds for pc in bp.parts[n].pieces])[:, :, 1].mean() for n in arms]
    assert ys[0] > 0 > ys[1]
    rest_pc = rest_overlaps(bp)
    for q in states(bp):
        ps = bp.poses(q)
        assert min(_box(bp.parts[n], ps[n])[0][2] for n in bp.parts) >= -5e-4
        assert_clear(bp, ps, rest_pc, q)
    p, bp = make(5, has_back=False, has_arms=True)
    assert not p["has_arms"] and not any(part.label == "arm" for part in bp.parts.values())


@pytest.mark.parametrize("base", ["wheeled", "disc"])
def test_seat_slider_and_tension_knob(base):
    """A gas-lift stool's square pan may slide forward on the mechanism (seat depth) and a stool whose back
    reclines may have a tilt-tension knob at the front of the mechanism; every state stays clear. No slider on
    a round or tilting seat, no knob without a hinged back, neither on a four-leg stool."""
    _, bp = make(6, base_type=base, seat_shape="square", has_seat_slider=True, has_tension_knob=True,
                 has_back=True, back_mount="hinged", has_seat_tilt=False, has_arms=False)
    j = by_child(bp, "seat_pan")
    assert j.kind == "prismatic" and j.parent == "seat" and j.dofs[0].axis == pytest.approx((1, 0, 0))
    assert {pc.material for pc in bp.parts["seat_pan"].pieces} == {"seat", "pan"}
    k = by_child(bp, "tension_knob")
    assert k.kind == "continuous" and k.parent == "seat" and k.dofs[0].axis == pytest.approx((1, 0, 0))
    rest_pc = rest_overlaps(bp)
    for q in states(bp):
        ps = bp.poses(q)
        assert min(_box(bp.parts[n], ps[n])[0][2] for n in bp.parts) >= -5e-4
        assert_clear(bp, ps, rest_pc, q)
    for over in (dict(seat_shape="round"), dict(has_seat_tilt=True), dict(base_type="four_leg")):
        p, _ = make(6, **{**dict(base_type=base, seat_shape="square", has_seat_slider=True), **over})
        assert not p["has_seat_slider"], over
    for over in (dict(back_mount="fixed"), dict(has_back=False), dict(base_type="four_leg")):
        p, _ = make(6, **{**dict(base_type=base, has_back=True, back_mount="hinged", has_tension_knob=True,
                                 has_seat_tilt=False), **over})
        assert not p["has_tension_knob"], over


@pytest.mark.parametrize("seed", [5, 7302])
def test_flip_up_arms_turn_up_beside_the_back(seed):
    from test_office_chair import flip_arm_stays_over_the_seat

    _, bp = make(seed, has_back=True, has_arms=True, arm_style="arm_flip")
    flip_arm_stays_over_the_seat(bp)
