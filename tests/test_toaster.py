"""Toaster (the category, not the docs example): what one sees down a bread slot is the heating element of
each of its long sides (a mica card wound with nichrome behind guard wires), and the carriage lever's slot is
dark behind its stem."""

from __future__ import annotations

import numpy as np
import pytest

from helpers import maker

make = maker("toaster")


@pytest.mark.parametrize("design", ["two_slot", "four_slot", "long_slot"])
def test_each_slot_shows_an_element_on_both_long_sides_under_its_guard_wires(design):
    for seed in range(2):
        _, bp = make(seed, design=design)
        pieces = bp.parts["body"].pieces
        cards = [pc for pc in pieces if pc.material == "mica"]
        ribbons = [pc for pc in pieces if pc.material == "element"]
        slots = {"two_slot": 2, "four_slot": 4, "long_slot": 2}[design]
        assert len(cards) == len(ribbons) == 2 * slots
        top = max(pc.bounds[1][2] for pc in pieces)
        for card, ribbon in zip(cards, ribbons, strict=True):
            (lo, hi), long_axis = card.bounds, int(np.argmax(np.ptp(card.vertices[:, :2], axis=0)))
            assert hi[2] > top - 0.03 and hi[2] - lo[2] > 0.1  # from just under the top, most of the way down
            # the ribbon zig-zags up and down the card along its length
            z = ribbon.vertices[:, 2]
            assert np.ptp(z) > 0.8 * (hi[2] - lo[2]) and np.ptp(ribbon.vertices[:, long_axis]) > 0.08
        guards = [pc for pc in pieces if pc.material == "trim" and np.ptp(pc.vertices[:, 2]) > 0.1]
        assert len(guards) >= 2 * 2 * slots  # at least two guard wires in front of each element


@pytest.mark.parametrize("face", ["front", "end"])
def test_the_lever_slot_is_dark_behind_the_lever_and_clear_of_it(face):
    for seed in range(3):
        _, bp = make(seed, control_face=face)
        guides = [pc for pc in bp.parts["body"].pieces if pc.material == "carriage"]
        levers = [name for name in bp.parts if name.startswith("lever_")]
        assert guides and len(guides) == len(levers)
        for name in levers:
            lo = np.min([pc.bounds[0] for pc in bp.parts[name].pieces], axis=0)
            hi = np.max([pc.bounds[1] for pc in bp.parts[name].pieces], axis=0)
            lo[2] -= 0.1  # the lever's whole path down its slot
            for g in guides:  # behind the stem's end, not in the way
                assert (g.bounds[1] < lo).any() or (g.bounds[0] > hi).any()
            near = min(guides, key=lambda g: np.linalg.norm(g.bounds.mean(0)[:2] - (lo[:2] + hi[:2]) / 2))
            assert np.linalg.norm(near.bounds.mean(0)[:2] - (lo[:2] + hi[:2]) / 2) < 0.04  # right behind it


@pytest.mark.parametrize("design", ["two_slot", "long_slot"])
def test_an_end_on_toaster_has_its_lever_in_a_vertical_slot_up_its_short_front(design):
    """Dualit, Smeg and KitchenAid toasters carry the carriage lever on the short end, which is their front:
    the casing is deeper than wide, the slots run front to back and the lever slides straight down a slot up
    the front's middle; dial and keys stay clear of its path."""
    from infmob_usd.categories.parts import toasters as T

    seen = 0
    for seed in range(6):
        p, bp = make(seed, design=design, control_face="end")
        levers = [n for n in bp.parts if n.startswith("lever_")]
        if len(levers) != 1:  # a dual-control long-slot toaster keeps its long front
            continue
        seen += 1
        body = np.array([pc.bounds for pc in bp.parts["body"].pieces])
        size = body[:, 1].max(0) - body[:, 0].min(0)
        assert size[0] > size[1]  # deeper than wide: the short end is the front
        cards = [pc for pc in bp.parts["body"].pieces if pc.material == "mica"]
        assert all(np.ptp(pc.vertices[:, 0]) > np.ptp(pc.vertices[:, 1]) for pc in cards)  # slots front to back
        j = {j.child: j for j in bp.joints}[levers[0]]
        lo = np.min([pc.bounds[0] for pc in bp.parts[levers[0]].pieces], axis=0)
        hi = np.max([pc.bounds[1] for pc in bp.parts[levers[0]].pieces], axis=0)
        assert lo[0] > body[:, 1, 0].max() - T.LEVER.paddle[2] - T.LEVER.reach - 0.02  # on the front
        assert np.allclose(j.dofs[0].axis, (0, 0, -1)) and abs((lo[1] + hi[1]) / 2) < 0.005  # down its middle
    assert seen >= 2
