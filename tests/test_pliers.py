"""Pliers lie flat and open about the pivot; a slip joint's pivot slides between its holes, a locking plier's
release lever turns on the moving handle: checked on the grounded blueprint."""

from __future__ import annotations

import pytest

from helpers import maker
from helpers import part_points as _points

make = maker("pliers")


@pytest.mark.parametrize("design,kinds", [
    ("combination", {("body", "jaw"): "revolute"}),
    ("slip_joint", {("body", "pivot"): "prismatic", ("pivot", "jaw"): "revolute"}),
    ("locking", {("body", "jaw"): "revolute", ("jaw", "lever"): "revolute"}),
])
def test_joints_of_each_design(design, kinds):
    _, bp = make(0, design=design)
    got = {(s.parent, s.child): s.dofs[0].type for s in bp.joints if s.movable}
    assert got == kinds
    for s in bp.joints:  # everything moves in the table's plane or along it: nothing lifts off the table
        assert abs(s.dofs[0].axis[2]) in (0.0, 1.0) and (s.dofs[0].type == "prismatic") == (s.dofs[0].axis[2] == 0)
    body, jaw = _points(bp, "body"), _points(bp, "jaw")
    assert abs(body[:, 2].min()) < 1e-6 and jaw[:, 2].min() > 5e-4  # the moving half rides clear of the table
    (hinge,) = [s for s in bp.joints if s.child == "jaw"]
    opened = _points(bp, "jaw", bp.poses({("jaw", 0): hinge.dofs[0].upper})["jaw"])
    tip = jaw[:, 0].argmax()
    assert opened[tip, 1] > jaw[tip, 1] + 0.01  # the jaw swings open to +y


def test_slip_joint_moves_the_pivot_between_its_holes():
    _, bp = make(0, design="slip_joint")
    (slip,) = [s for s in bp.joints if s.child == "pivot"]
    assert 0.004 <= slip.dofs[0].upper <= 0.008  # Channellock-type slots: 5-7 mm between the holes
