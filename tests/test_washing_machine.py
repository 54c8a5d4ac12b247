"""Washing machine: what a user relies on beyond the contract tests: the porthole door swings out on its left
edge and is glazed where one looks in, the filter cap and drain hose behind the service flap move only with the
flap open, the top loader's lid lifts at its front about a hinge at the back."""

from __future__ import annotations

import numpy as np
import pytest

from categories.washing_machine import MATERIALS
from tests.helpers import maker

make = maker("washing_machine")


def _box(bp, name):
    """A part's bounds, its hinge's knuckles and leaves left out (they stand round the joint's axis)."""
    b = np.array([pc.bounds for pc in bp.parts[name].pieces if not pc.name.startswith("hinge")])
    return b[:, 0].min(0), b[:, 1].max(0)


@pytest.mark.parametrize("design", ["front_loader", "washer_dryer"])
def test_the_porthole_door_swings_out_on_its_left_edge_and_is_glazed_in_the_middle(design):
    for seed in range(3):
        _, bp = make(seed, design=design)
        door = {j.child: j for j in bp.joints}["door"]
        d = door.dofs[0]
        lo, hi = _box(bp, "door")
        assert door.kind == "revolute" and np.allclose(d.axis, (0, 0, -1))  # about the vertical, opening outwards
        assert d.origin[1] == pytest.approx(lo[1], abs=0.002) and d.upper > np.radians(150)  # left edge, wide
        y, z = (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2  # the line one looks in along, through the ring's middle
        near = 0.1  # m: what lies within a hand's width of that line (the ring is 17 cm or more off it)
        on_axis = [pc for pc in bp.parts["door"].pieces
                   if (np.hypot(pc.vertices[:, 1] - y, pc.vertices[:, 2] - z) < near).any()]
        assert on_axis and {pc.material for pc in on_axis} == {"glass"}
    assert MATERIALS["glass"].split(":")[0] == "glass"  # a see-through family (test_door_glass_is_clear)


def test_filter_cap_and_drain_hose_need_the_flap_open():
    _, bp = make(0, design="front_loader", has_service_flap=True, has_drain_hose=True)
    joints = {j.child: j for j in bp.joints}
    flap = joints["filter_flap"]
    assert flap.kind == "revolute" and np.allclose(flap.dofs[0].axis, (0, 1, 0))  # drops forward
    assert flap.dofs[0].origin[2] == pytest.approx(_box(bp, "filter_flap")[0][2], abs=0.002)  # at its bottom edge
    assert joints["filter"].requires_open == "filter_flap" and joints["filter"].kind == "revolute"
    assert joints["drain_hose"].requires_open == "filter_flap"
    assert np.allclose(joints["drain_hose"].dofs[0].axis, (1, 0, 0))  # pulled out of the front


def test_top_loader_lid_lifts_at_its_front():
    for seed in range(3):
        _, bp = make(seed, design="top_loader")
        lid = {j.child: j for j in bp.joints}["lid"]
        lo, hi = _box(bp, "lid")
        d = lid.dofs[0]
        assert np.allclose(d.axis, (0, -1, 0)) and d.origin[0] == pytest.approx(lo[0], abs=0.002)  # hinge at back
        assert "door" not in bp.parts and "drawer" not in bp.parts


def test_the_detergent_drawer_has_its_compartments_and_siphon():
    """A detergent drawer is split into main wash, pre-wash and softener compartments by walls running front to
    back, the softener's siphon cap standing in its compartment: not an empty box."""
    _, bp = make(3, design="front_loader")
    pieces = bp.parts["drawer"].pieces
    ext = np.array([np.ptp(pc.vertices, axis=0) for pc in pieces])
    depth = ext[:, 0].max()
    walls = [e for e, pc in zip(ext, pieces, strict=True)
             if pc.material == "drawer" and e[0] > 0.8 * depth and e[1] < 0.01 and e[2] > 0.03]
    assert len(walls) >= 4  # two sides and two dividers
    siphon = [pc for pc in pieces if pc.material == "knob"]
    assert len(siphon) == 1


def test_door_glass_is_clear():
    """A porthole's glass bowl is clear (a faint blue at most) so the drum shows through it from either side: the
    appliance palette's smoked oven glass, two layers of it, read as an opaque grey disc from inside."""
    spec = MATERIALS["glass"]
    family, variants = spec.split(":")
    assert family == "glass" and set(variants.split("|")) <= {"clear", "clear_blue"}


@pytest.mark.parametrize("wash", ["agitator", "impeller"])
def test_a_top_loader_washes_with_an_agitator_or_an_impeller_in_its_basket(wash):
    """A top loader's basket is not empty: an agitator stands up its middle from a flared skirt on the floor to
    near the rim (a softener cup may sit on its post), or a low finned impeller plate covers most of the floor
    (and then no softener cup: there is no post for it)."""
    from categories.parts import washers as WM

    for seed in range(3):
        p, bp = make(seed, design="top_loader", wash_action=wash, has_softener_cup=True)
        body = bp.parts["body"].pieces
        drum = [pc for pc in body if pc.material == "drum"]
        floor = min(pc.bounds[0][2] for pc in drum)
        rim = max(pc.bounds[1][2] for pc in drum)
        rb = max(np.ptp(pc.vertices[:, 1]) for pc in drum) / 2
        parts = [pc for pc in body if pc.material == "agitator"]
        lo = np.min([pc.bounds[0] for pc in parts], axis=0)
        hi = np.max([pc.bounds[1] for pc in parts], axis=0)
        assert lo[2] == pytest.approx(floor + WM.WALL, abs=0.01)  # standing on the basket floor
        if wash == "agitator":
            assert hi[2] > rim - 0.12 and np.ptp([lo[1], hi[1]]) > 1.2 * rb  # to near the rim, its skirt wide
            assert len(parts) >= 1 + 2 * WM.AGITATOR["vanes"]
        else:
            assert hi[2] - lo[2] < 0.08 and np.ptp([lo[1], hi[1]]) > 1.5 * rb  # low, across most of the floor
            assert "softener_cup" not in bp.parts and len(parts) == 1 + WM.IMPELLER["fins"]
