"""The refrigerator category: each design's doors and drawers, what a door gates, static door bins, the
dispenser's sprung paddle, and clearances at the states a robot reaches."""

from __future__ import annotations

import numpy as np
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


@pytest.mark.parametrize("design", DESIGNS)
def test_the_mullion_shows_the_liner_to_both_zones(design):
    """Inside, a zone is lined all round in light plastic: the mullion between fresh food and freezer is no
    patch of the (possibly black) cabinet finish. Every body piece that faces a cavity is liner."""
    _, bp = make(3, design=design)
    body = bp.parts["body"].pieces
    liner = [pc for pc in body if pc.material == "liner"]
    # the cabinet's five liner walls per cavity plus the mullion's two faces
    assert len(liner) >= 7
    cab = [pc for pc in body if pc.material == "body"]
    lo = np.min([pc.vertices.min(0) for pc in liner], axis=0)
    hi = np.max([pc.vertices.max(0) for pc in liner], axis=0)
    inside = [pc for pc in cab if np.all(pc.vertices.min(0)[1:] > lo[1:] + 1e-4)
              and np.all(pc.vertices.max(0)[1:] < hi[1:] - 1e-4)]  # within the liner across (y) and up (z)
    assert len(inside) == 1
    for pc in inside:  # the mullion's core: every face of it but its front is covered by liner skins
        a, b = pc.vertices.min(0), pc.vertices.max(0)
        axis = int(np.argmin(b - a))
        faces = [a[axis], b[axis]]
        touching = [lp for lp in liner if any(abs(lp.vertices[:, axis].min() - f) < 1e-6 or
                                               abs(lp.vertices[:, axis].max() - f) < 1e-6 for f in faces)]
        assert len(touching) >= 2


@pytest.mark.parametrize("design", DESIGNS)
def test_glass_shelves_are_a_pane_with_a_printed_border(design):
    """A shelf is a glass pane (clear middle, a printed border that shows where the pane is) in its trims,
    not a bare frame."""
    _, bp = make(5, design=design)
    shelves = [n for n, part in bp.parts.items() if part.label == "shelf"]
    assert shelves
    for n in shelves:
        mats = [pc.material for pc in bp.parts[n].pieces]
        assert mats.count("glass") == 1 and mats.count("frost") == 4, (n, mats)


def test_fridge_handles_are_stainless_or_plastic():
    """Full-size fridge handles are stainless tube or moulded plastic, never mirror chrome."""
    from infmob_usd.api import get_category
    params = {p.name: p for p in get_category("refrigerator").params}
    assert set(params["handle_finish"].choices) == {"brushed_metal", "plastic"}
