"""The core's lift-off rule: a part that rests on a seat and lifts off it (a lid, a stopper, a vase's liner, a
cistern lid, a pull-off pan handle) is lifted a hand's lift when open, not slid through the air."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd.api import blueprint
from infmob_usd.blueprint import dof_motion
from infmob_usd.lift_off import LIFT_OFF, ROLE

CASES = [("toilet", s) for s in range(4)] + [("vase", s) for s in (0, 1, 2, 7301)] + \
    [("pot", s) for s in range(3)] + [("pan", s) for s in (0, 7302)] + [("jar", 0), ("bottle", 0)]


def lift_offs(bp):
    for j in bp.joints:
        for i, d in enumerate(j.dofs):
            if d.type == "prismatic" and j.role == ROLE:
                yield j, i, d


@pytest.mark.parametrize("category,seed", CASES)
def test_open_lift_off_parts_stay_within_a_hands_lift_of_their_seat(category, seed):
    bp = blueprint(category, seed)
    for j, _, d in lift_offs(bp):
        # the child's points at the open limit are at most LIFT_OFF from where they rest
        m = dof_motion(d, d.upper)
        pts = np.vstack([pc.vertices for pc in bp.parts[j.child].pieces])
        moved = pts @ m[:3, :3].T + m[:3, 3]
        assert np.linalg.norm(moved - pts, axis=1).max() <= LIFT_OFF + 1e-9, (j.child, d.upper)
        assert d.upper > 0.0


def test_every_named_lift_off_is_declared_as_one():
    """The parts the rule is for carry a lift-off role, so the rule reaches them."""
    want = {("toilet", 0): "tank_lid", ("vase", 7301): "liner", ("pan", 7302): "handle", ("pot", 0): "lid"}
    for (category, seed), child in want.items():
        bp = blueprint(category, seed)
        assert child in {j.child for j, _, _ in lift_offs(bp)}, (category, seed, child)
