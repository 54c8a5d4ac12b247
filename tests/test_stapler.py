"""A stapler's head lifts off its base about the rear pin and its magazine loads: checked on the grounded
blueprint."""

from __future__ import annotations

import numpy as np
import pytest

from helpers import maker
from helpers import part_points as _points

make = maker("stapler")


@pytest.mark.parametrize("design,loading,tree", [
    ("desk", "top_loading", {("body", "magazine"): "revolute", ("magazine", "arm"): "revolute"}),
    ("desk", "front_loading", {("body", "arm"): "revolute", ("arm", "magazine"): "prismatic"}),
    ("plier", "top_loading", {("body", "arm"): "revolute", ("arm", "magazine"): "prismatic"}),
])
def test_head_lifts_about_the_rear_pin(design, loading, tree):
    _, bp = make(0, design=design, loading=loading)
    assert {(s.parent, s.child): s.dofs[0].type for s in bp.joints if s.movable} == tree
    base = _points(bp, "body")
    assert abs(base[:, 2].min()) < 1e-6  # it stands on its base
    for s in bp.joints:
        d = s.dofs[0]
        if d.type == "revolute":  # about a pin across the stapler at its back, lifting the front
            assert np.allclose(np.abs(d.axis), (0, 1, 0)) and d.origin[0] < base[:, 0].min() + 0.03
            child = _points(bp, s.child)
            lifted = _points(bp, s.child, bp.poses({(s.child, 0): min(d.upper, 0.5)})[s.child])
            front = child[:, 0].argmax()
            assert lifted[front, 2] > child[front, 2] + 0.02
        else:  # the magazine pulls out of the front
            assert d.axis[0] > 0.99 and d.upper > 0.05
