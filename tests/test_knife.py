"""A knife lies on its side: folding tools turn out of the handle's open side to straight about their pivot pin,
each in its own layer; a utility knife's blade slides out of the nose: checked on the grounded blueprint."""

from __future__ import annotations

import math

import numpy as np

from helpers import maker
from helpers import part_points as _points

make = maker("knife")


def _tools(bp):
    return [s for s in bp.joints if s.movable and s.parent == "body"]


def test_multi_tool_folds_each_tool_into_the_handle_and_out_straight():
    _, bp = make(1, design="multi_tool")
    tools = _tools(bp)
    assert 2 <= len(tools) <= 5
    body = _points(bp, "body")
    x0, x1 = body[:, 0].min(), body[:, 0].max()
    layers = []
    for s in tools:
        d = s.dofs[0]
        assert np.allclose(np.abs(d.axis), (0, 0, 1)) and math.isclose(d.upper, math.pi)  # in the table's plane
        pts = _points(bp, s.child)
        # folded: inside the handle's length and height, between its scales
        assert pts[:, 0].min() >= x0 - 1e-6 and pts[:, 0].max() <= x1 + 1e-6
        assert body[:, 2].min() < pts[:, 2].min() and pts[:, 2].max() < body[:, 2].max()
        layers.append((round(pts[:, 2].min(), 5), round(pts[:, 2].max(), 5)))
        # opened straight, it stands out of the handle's front (blades) or back (openers) end
        out = _points(bp, s.child, bp.poses({(s.child, 0): d.upper})[s.child])
        assert out[:, 0].max() > x1 + 0.02 or out[:, 0].min() < x0 - 0.02
    assert len(set(layers)) == len(layers)  # one tool per layer: they turn past each other


def test_utility_blade_slides_out_of_the_nose():
    _, bp = make(0, design="utility")
    (s,) = _tools(bp)
    d = s.dofs[0]
    assert d.type == "prismatic" and np.allclose(d.axis, (1, 0, 0)) and d.upper > 0.015
    body, blade = _points(bp, "body"), _points(bp, "blade")
    assert blade[:, 0].max() < body[:, 0].max()  # retracted: the point inside the nose
    out = _points(bp, "blade", bp.poses({("blade", 0): d.upper})["blade"])
    assert out[:, 0].max() > body[:, 0].max() + 0.015
