"""The core's lift-off rule: a part that rests on a seat and lifts off it (a lid, a stopper, a vase's liner, a
cistern lid, a pull-off pan handle) is lifted a hand's lift when open, not slid through the air."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd import joints as J
from infmob_usd.api import blueprint
from infmob_usd.blueprint import dof_motion
from infmob_usd.errors import ModelError
from infmob_usd.lift_off import FREE, LIFT_OFF, ROLE, capped_joint, lift

CASES = [("toilet", s) for s in range(4)] + [("vase", s) for s in (0, 1, 2, 7301)] + \
    [("pot", s) for s in range(3)] + [("pan", s) for s in (0, 7302)] + [("jar", 0), ("bottle", 0)] + \
    [("plate_rack", s) for s in range(7300, 7304)] + [("oven", 7303), ("dishwasher", 7300), ("beverage_fridge", 7300)]


def lift_offs(bp):
    for j in bp.joints:
        for i, d in enumerate(j.dofs):
            if d.type == "prismatic" and j.role == ROLE:
                yield j, i, d


@pytest.mark.parametrize("category,seed", CASES)
def test_open_lift_off_parts_stay_within_a_hands_lift_of_their_seat(category, seed):
    bp = blueprint(category, seed)
    for j, _, d in lift_offs(bp):
        # the child's points at the open limit are at most a hand's lift (or its seat's engagement and a
        # margin) from where they rest
        m = dof_motion(d, d.upper)
        pts = np.vstack([pc.vertices for pc in bp.parts[j.child].pieces])
        moved = pts @ m[:3, :3].T + m[:3, 3]
        assert np.linalg.norm(moved - pts, axis=1).max() <= lift(j.engagement) + 1e-9, (j.child, d.upper)
        assert d.upper > 0.0


def test_every_named_lift_off_is_declared_as_one():
    """The parts the rule is for carry a lift-off role, so the rule reaches them."""
    want = {("toilet", 0): "tank_lid", ("vase", 7301): "liner", ("pan", 7302): "handle", ("pot", 0): "lid",
            ("plate_rack", 7300): "cup_0", ("plate_rack", 7301): "glass_0", ("plate_rack", 7302): "caddy_0",
            ("oven", 7303): "grate_0", ("dishwasher", 7300): "basket_0", ("beverage_fridge", 7300): "door_bin_0"}
    for (category, seed), child in want.items():
        bp = blueprint(category, seed)
        assert child in {j.child for j, _, _ in lift_offs(bp)}, (category, seed, child)


def test_a_seat_depth_sets_the_lift_free_of_it():
    """A part whose seat depth is known (a mug on a 55 mm peg) lifts that far and a margin, then is free; one
    without lifts a hand's lift; only a lift-off joint has a seat depth."""
    def spec(upper, engagement=None):
        return J.prismatic("rack", "cup", (0, 0, 0), (0, 0, 1), 0.0, upper, role=ROLE, engagement=engagement)

    assert capped_joint(spec(0.2, 0.055)).dofs[0].upper == pytest.approx(0.055 + FREE)
    assert capped_joint(spec(0.2)).dofs[0].upper == LIFT_OFF
    assert capped_joint(spec(0.01, 0.055)).dofs[0].upper == 0.01  # a shorter declared travel is kept
    with pytest.raises(ModelError, match="engagement"):
        J.prismatic("rack", "cup", (0, 0, 0), (0, 0, 1), 0.0, 0.1, role="slide", engagement=0.05)
    with pytest.raises(ModelError, match="engagement"):
        spec(0.1, -0.01)
