"""The cart: on a two-swivel plan the casters at the handle end swivel while the front wheels roll straight ahead
only; a hand truck's toe plate lies on the floor at rest and folds up to the rails."""

from __future__ import annotations

import json
import math

import pytest

import infmob_usd


def _meta(tmp_path, **overrides):
    obj = infmob_usd.generate("cart", seed=2, texture_size=16, **overrides)
    folder = infmob_usd.save(obj, tmp_path / "cart", formats="urdf")
    return json.loads((folder / "metadata.json").read_text())


def test_rigid_casters_roll_straight_ahead_and_the_handle_end_swivels(tmp_path):
    meta = _meta(tmp_path, design="utility_cart", caster_plan="two_swivel")
    swivels = [j for j in meta["joints"] if j["role"] == "swivel"]
    assert len(swivels) == 2 and all(j["axis"] == pytest.approx([0, 0, 1]) for j in swivels)
    rigid = [j for j in meta["joints"] if j["role"] == "wheel" and j["parent"] == "body"]
    assert len(rigid) == 2, "two wheels on rigid forks, jointed to the frame itself"
    for j in rigid:
        assert abs(j["axis"][1]) == pytest.approx(1.0), "a rigid caster's axle runs across the cart"
    assert all(j["origin"][0] > 0 for j in rigid), "the rigid pair is at the front, away from the push handle"
    assert all(j["origin"][0] < 0 for j in swivels), "the swivel pair is at the handle end"


def test_the_toe_plate_lies_on_the_floor_and_folds_up(tmp_path):
    meta = _meta(tmp_path, design="hand_truck")
    toe = next(j for j in meta["joints"] if j["child"] == "toe_plate")
    assert toe["type"] == "revolute" and toe["upper"] == pytest.approx(math.radians(90), abs=0.02)
    bounds = meta["bounds"]
    assert bounds[0][2] == pytest.approx(0.0, abs=1e-6), "the truck stands on the floor"
    wheels = [j for j in meta["joints"] if j["role"] == "wheel"]
    assert len(wheels) == 2 and all(j["parent"] == "body" for j in wheels)
