"""Toaster oven: what a user relies on beyond the contract tests: the racks slide out only with the door open,
the door drops forward about its bottom edge, the knobs sit in the control column to the right of the door."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers import maker, part_points

from zoo import object_limits

make = maker("toaster_oven")


@pytest.mark.parametrize("design", ["compact", "six_slice", "air_fry"])
def test_racks_require_the_door_and_the_door_drops_forward(design):
    for seed in range(3):
        p, bp = make(seed, design=design)
        joints = {j.child: j for j in bp.joints}
        racks = [j for j in bp.joints if j.child.startswith("rack_")]
        assert racks, "every toaster oven has a rack"
        for rack in racks:
            assert rack.kind == "prismatic" and rack.requires_open == "door"
            assert np.allclose(rack.dofs[0].axis, (1, 0, 0)) and rack.dofs[0].upper > 0.05  # out of the front
        door = joints["door"]
        assert door.kind == "revolute" and abs(door.dofs[0].axis[1]) == 1  # about the bottom edge, along Y
        door_lo = np.array([pc.bounds for pc in bp.parts["door"].pieces])[:, 0].min(0)
        assert door.dofs[0].origin[2] == pytest.approx(door_lo[2], abs=0.002)  # the hinge is at the bottom


def test_controls_are_right_of_the_door():
    for seed in range(6):
        _, bp = make(seed)
        door_hi = np.array([pc.bounds for pc in bp.parts["door"].pieces])[:, 1].max(0)
        knobs = [name for name in bp.parts if name.startswith("knob_")]
        assert 2 <= len(knobs) <= 3
        for name in knobs:
            lo = np.array([pc.bounds for pc in bp.parts[name].pieces])[:, 0].min(0)
            assert lo[1] > door_hi[1]  # +Y: the right-hand side as one faces the front


@pytest.mark.parametrize("design", ["compact", "six_slice", "air_fry"])
def test_the_door_drops_to_horizontal_with_its_handle_over_the_counter(design):
    """A real toaster oven's door lies flat when open, its bar clear of the counter and no lower than the
    casing's bottom: the ground pass must not have to stop the door short of horizontal."""
    for seed in range(2):
        p, bp = make(seed, design=design)
        bp = object_limits("toaster_oven", seed, bp, design=design)
        door = next(j for j in bp.joints if j.child == "door").dofs[0]
        assert door.upper == pytest.approx(np.pi / 2, abs=0.01)  # horizontal, not cut by the counter
        open_door = part_points(bp, "door", bp.poses({("door", 0): door.upper})["door"])
        casing_bottom = min(pc.bounds[0][2] for pc in bp.parts["body"].pieces if pc.material != "feet")
        assert open_door[:, 2].min() >= casing_bottom


@pytest.mark.parametrize("design", ["compact", "six_slice", "air_fry"])
def test_heating_tubes_run_under_the_roof_and_over_the_floor_in_their_sockets(design):
    """A toaster oven's defining feature: quartz tubes across the cavity, two over the floor and two under the
    roof, each end in a metal cap on the side walls, light against the dark cavity."""
    from infmob_usd.categories.parts import toaster_ovens as TO

    _, bp = make(0, design=design)
    pieces = bp.parts["body"].pieces
    tubes = [pc for pc in pieces if pc.material == "element"]
    caps = [pc for pc in pieces if pc.material == "trim" and not pc.convex]
    assert len(tubes) == 4 and len(caps) == 4 * 2 * 2  # a cap and a bracket at both ends of each
    z = sorted(pc.bounds[0][2] for pc in tubes)
    assert z[1] < z[2] - 0.05  # two low, two high
    assert all(np.ptp(pc.vertices[:, 1]) > 0.15 and np.ptp(pc.vertices[:, 2]) <= 2 * TO.ELEMENT_R + 1e-6
               for pc in tubes)
