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


def test_the_lever_slot_is_dark_behind_the_lever_and_clear_of_it():
    for seed in range(3):
        _, bp = make(seed)
        guides = [pc for pc in bp.parts["body"].pieces if pc.material == "carriage"]
        levers = [name for name in bp.parts if name.startswith("lever_")]
        assert guides and len(guides) == len(levers)
        for name in levers:
            stem_back = min(pc.bounds[0][0] for pc in bp.parts[name].pieces)
            assert all(g.bounds[1][0] < stem_back for g in guides)
