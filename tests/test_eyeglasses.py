"""Eyeglasses lie lenses down with the temples folded, one over the other; each temple opens up past square
about its end piece's hinge, and a folding reader's front folds up at its bridge: checked on the grounded
blueprint."""

from __future__ import annotations

import math

import numpy as np
import pytest

from helpers import maker
from helpers import part_points as _points

make = maker("eyeglasses")


def _joint(bp, child):
    (spec,) = [s for s in bp.joints if s.child == child]
    return spec


@pytest.mark.parametrize("design", ["full_rim", "rimless"])
def test_temples_fold_one_over_the_other_and_open_past_square(design):
    _, bp = make(0, design=design, hinge="spring")
    under, over = _joint(bp, "temple"), _joint(bp, "over_temple")
    # the temple folded first opens once the one lying on it has
    assert under.requires_open == "over_temple" and over.requires_open is None
    for spec in (under, over):
        d = spec.dofs[0]
        assert np.allclose(np.abs(d.axis), (1, 0, 0))  # about the end piece's hinge screw (the frame's height)
        assert d.upper > math.radians(90)  # past square: a spring hinge flexes on
    body, a, b = _points(bp, "body"), _points(bp, "temple"), _points(bp, "over_temple")
    assert abs(body[:, 2].min()) < 1e-6  # the front lies on the table
    assert a[:, 2].min() > 3e-3 and b[:, 2].max() > a[:, 2].max() + 2e-3  # folded on its back, one over the other
    # opened square, a temple stands up off the front: its tip far above the table
    up = _points(bp, "temple", bp.poses({("temple", 0): math.radians(90)})["temple"])
    assert up[:, 2].max() > 0.1


def test_folding_readers_fold_at_the_bridge():
    _, bp = make(0, design="folding_readers")
    fold = _joint(bp, "front_half")
    assert fold.parent == "body" and _joint(bp, "over_temple").parent == "front_half"
    d = fold.dofs[0]
    assert abs(d.origin[1]) < 1e-9 and np.allclose(np.abs(d.axis), (1, 0, 0))  # the bridge hinge, on the middle
    half = _points(bp, "front_half")
    assert half[:, 1].max() < 0.002 and half[:, 1].min() < -0.05  # the -Y half (its knuckle on the axis)
    up = _points(bp, "front_half", bp.poses({("front_half", 0): math.radians(90)})["front_half"])
    assert up[:, 2].max() > 0.04  # turned up off the table over the other half


def test_a_folding_readers_front_folds_only_with_its_temples_folded(tmp_path):
    """The bridge hinge ``requires_closed`` both temples (written both ways), so the all-open state the checks
    and previews use is the glasses worn: temples open, front flat; never the front folded with temples out."""
    import json

    import infmob_usd
    from infmob_usd.validate.posing import _qpos_for, _read_object

    assert set(_joint(make(0, design="folding_readers")[1], "front_half").requires_closed) == {"temple", "over_temple"}
    obj = infmob_usd.generate("eyeglasses", 0, texture_size=16, design="folding_readers")
    folder = infmob_usd.save(obj, tmp_path, formats="urdf")
    joints = {j["child"]: j for j in json.loads((folder / "metadata.json").read_text())["joints"]}
    assert joints["front_half"]["requires_closed"] == ["over_temple", "temple"]
    assert joints["temple"]["requires_closed"] == joints["over_temple"]["requires_closed"] == ["front_half"]
    q = _qpos_for(_read_object(folder), 1.0)
    assert q[joints["front_half"]["name"]] == 0.0
    assert q[joints["temple"]["name"]] > 1.5 and q[joints["over_temple"]["name"]] > 1.5
