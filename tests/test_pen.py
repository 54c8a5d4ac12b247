"""A click pen's point comes out of its nose when its button is pressed (the refill follows the button), and
a capped pen's cap pulls clear of the point: checked on the grounded blueprint."""

from __future__ import annotations

import numpy as np

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


def test_the_pocket_clip_stands_off_the_barrel_along_its_length():
    for design, part, barrel in (("click", "body", "barrel"), ("capped", "cap", "cap"),
                                 ("multi", "body", "upper_barrel")):
        for seed in range(3):
            _, bp = make(seed, design=design)
            pieces = bp.parts[part].pieces
            strip = next(pc.vertices for pc in pieces if pc.name == "clip")
            tube = next(pc.vertices for pc in pieces if pc.name == barrel)
            (y0, y1), (z0, z1) = ((tube[:, k].min(), tube[:, k].max()) for k in (1, 2))
            radial = np.hypot(strip[:, 1] - (y0 + y1) / 2, strip[:, 2] - (z0 + z1) / 2)
            # the strip's underside at its two ends (its vertices at the least and most x): the gap a pocket's
            # cloth goes in is a millimetre or more along the clip's middle
            x = strip[:, 0]
            lo = [radial[np.isclose(x, e)].min() for e in (x.min(), x.max())]
            assert (lo[0] + lo[1]) / 2 - (z1 - z0) / 2 >= 0.001, (design, seed, lo, (z1 - z0) / 2)
