"""The refrigerator category: each design's doors and drawers, what a door gates, static door bins, the
dispenser's sprung paddle, and clearances at the states a robot reaches."""

from __future__ import annotations

import pytest

from collide import contacts
from helpers import labelled_states, maker
from zoo import by_child, movable, object_limits

DESIGNS = ("top_freezer", "bottom_freezer", "french_door", "side_by_side")
DOORS = {"top_freezer": {"door", "freezer_door"}, "bottom_freezer": {"door"},
         "french_door": {"door", "right_door"}, "side_by_side": {"door", "freezer_door"}}
VOL = 1e-7  # m^3: the validators' contact volume

make = maker("refrigerator")


def opened(bp, q):
    """``q`` with a gating door fully open wherever a part behind it moves (as the validators do)."""
    out = dict(q)
    for j in bp.joints:
        if j.requires_open and q.get((j.child, 0), 0.0) != 0.0:
            out[(j.requires_open, 0)] = by_child(bp, j.requires_open).dofs[0].upper
    return out


@pytest.mark.parametrize("design", DESIGNS)
def test_each_design_has_its_doors_and_what_they_gate(design):
    """Doors are hinges; every shelf, crisper, deli drawer and basket behind a door opens only with that door
    open; freezer drawers pull out on their own."""
    p, bp = make(4, design=design, has_dispenser=False)
    doors = {j.child for j in movable(bp) if j.child in DOORS[design]}
    assert doors == DOORS[design]
    assert all(by_child(bp, d).dofs[0].type == "revolute" and bp.parts[d].label == "door" for d in doors)
    gated = [j for j in movable(bp) if j.requires_open]
    assert gated and all(j.requires_open in doors and j.dofs[0].type == "prismatic" for j in gated)
    assert {j.child.split("_")[0] for j in gated} <= {"shelf", "crisper", "deli", "freezer"}
    drawers = [j for j in movable(bp) if j.child.startswith("freezer_drawer")]
    if design in ("bottom_freezer", "french_door"):
        assert len(drawers) == p["freezer_drawer_count"] and not any(j.requires_open for j in drawers)
    else:
        assert not drawers


def test_french_door_crispers_open_with_their_own_door_and_shelves_are_fixed():
    p, bp = make(2, design="french_door")
    assert by_child(bp, "crisper_0").requires_open == "door"
    assert by_child(bp, "crisper_1").requires_open == "right_door"
    shelves = [n for n, part in bp.parts.items() if part.label == "shelf"]
    assert len(shelves) == p["shelf_count"] and all(by_child(bp, s).kind == "fixed" for s in shelves)


def test_door_bins_are_static_parts_of_their_door():
    p, bp = make(1, design="top_freezer", bin_count=3)
    assert not any(part.label == "bin" for part in bp.parts.values())
    for door in ("door", "freezer_door"):
        bins = [pc for pc in bp.parts[door].pieces if pc.material == "bin"]
        assert len(bins) == 3 * 5  # a bin is an open box: a bottom and four walls


@pytest.mark.parametrize("design", ("french_door", "side_by_side"))
def test_dispenser_paddle_is_sprung_on_its_door(design):
    _, bp = make(3, design=design, has_dispenser=True, key_count=3)
    door = "door" if design == "french_door" else "freezer_door"
    paddle = by_child(bp, "paddle")
    assert paddle.parent == door and paddle.role == "lever" and paddle.dofs[0].type == "revolute"
    keys = [j for j in movable(bp) if j.child.startswith("key_")]
    assert len(keys) == 3 and all(j.parent == door and j.role == "button" for j in keys)


@pytest.mark.parametrize("design", DESIGNS)
def test_no_overlap_at_sampled_states(design):
    seed = 6
    over = {"design": design, "has_dispenser": True, "has_deli_drawer": True}
    _, bp = make(seed, **over)
    bp = object_limits("refrigerator", seed, bp, **over)
    for label, q in labelled_states(bp):
        bad = contacts(bp, opened(bp, q), VOL)
        assert not bad, f"(part, part, m^3) overlapping at {label}: {bad}"
