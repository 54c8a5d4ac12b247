"""A windproof lighter's wheel turns only with its lid open, the lid swinging back about its rear hinge; a
utility lighter's trigger pulls back only once its safety slider is forward: checked on the grounded
blueprint."""

from __future__ import annotations

import numpy as np

from helpers import maker
from helpers import part_points as _points

make = maker("lighter")


def test_the_windproof_lid_opens_back_and_uncovers_the_wheel():
    _, bp = make(0, design="windproof")
    spec = {s.child: s for s in bp.joints if s.movable}
    assert spec["wheel"].dofs[0].type == "continuous" and spec["wheel"].requires_open == "lid"
    lid = spec["lid"].dofs[0]
    assert lid.origin[0] < _points(bp, "body")[:, 0].min() + 0.003  # hinged at the rear
    opened = _points(bp, "lid", bp.poses({("lid", 0): lid.upper})["lid"])
    wheel_top = _points(bp, "wheel")[:, 2].max()
    front = _points(bp, "body")[:, 0].max()
    assert np.degrees(lid.upper) > 90 and opened[:, 0].max() < front - 0.01  # swung back off the chimney
    assert not np.any((opened[:, 2] < wheel_top) & (opened[:, 0] > _points(bp, "wheel")[:, 0].min()))


def test_the_utility_trigger_waits_for_its_safety():
    _, bp = make(0, design="utility", has_safety=True)
    spec = {s.child: s for s in bp.joints if s.movable}
    assert spec["trigger"].requires_open == "safety" and spec["trigger"].role == "button"
    assert spec["trigger"].dofs[0].axis[0] < -0.99 and spec["safety"].dofs[0].axis[0] > 0.99
    _, bp = make(0, design="utility", has_safety=False)
    assert {s.child: s for s in bp.joints if s.movable}["trigger"].requires_open is None


def test_the_disposables_hood_sits_on_its_tank_without_overhanging_it():
    from scipy.spatial import ConvexHull

    for seed in range(3):
        _, bp = make(seed, design="disposable")
        pieces = bp.parts["body"].pieces
        tank = next(pc.vertices for pc in pieces if pc.name == "tank")
        plan = ConvexHull(tank[:, :2])
        hood = np.vstack([pc.vertices for pc in pieces if pc.name in ("cheek", "chimney_front", "chimney_top")])
        # a BIC's steel hood is crimped onto the tank's shoulder inside its outline, not a box on top of it
        assert (hood[:, :2] @ plan.equations[:, :2].T + plan.equations[:, 2]).max() <= 1e-6, seed
        assert hood[:, 2].min() >= tank[:, 2].max() - 0.002  # crimped at most 2 mm down over the tank


def test_the_windproof_wheel_stands_over_the_chimney():
    for seed in range(3):
        _, bp = make(seed, design="windproof")
        chimney = next(pc.vertices for pc in bp.parts["body"].pieces if pc.name == "chimney")
        assert _points(bp, "wheel")[:, 2].max() >= chimney[:, 2].max() + 0.001, seed
