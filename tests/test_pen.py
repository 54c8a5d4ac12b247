"""A click pen's point comes out of its nose when its button is pressed (the refill follows the button), and
a capped pen's cap pulls clear of the point: checked on the grounded blueprint."""

from __future__ import annotations

from helpers import maker
from helpers import part_points as _points

make = maker("pen")


def test_pressing_the_button_brings_the_point_out_of_the_nose():
    _, bp = make(0, design="click")
    spec = {s.child: s for s in bp.joints if s.movable}
    button, refill = spec["button"], spec["refill"]
    assert button.dofs[0].axis[0] > 0.99 and button.role == "button"  # pressed into the rear end, toward the tip
    assert refill.mimic.leader == "button" and refill.mimic.ratio > 0
    nose = _points(bp, "body")[:, 0].max()
    assert _points(bp, "refill")[:, 0].max() < nose  # retracted at rest
    pressed = button.dofs[0].upper
    out = _points(bp, "refill", bp.poses({("refill", 0): refill.mimic.ratio * pressed})["refill"])[:, 0].max()
    assert out > nose + 0.001  # a millimetre of point or more out of the hole


def test_the_cap_pulls_clear_of_the_point():
    _, bp = make(0, design="capped")
    cap = next(s for s in bp.joints if s.child == "cap")
    assert cap.role == "lift_off" and cap.dofs[0].axis[0] > 0.99
    tip = _points(bp, "body")[:, 0].max()
    off = _points(bp, "cap", bp.poses({("cap", 0): cap.dofs[0].upper})["cap"])[:, 0].min()
    assert off > tip  # the cap's mouth is past the point: it is off
