"""Safe: what a user relies on beyond the contract tests: the door carries its locking bolts on both upright
edges (live bolts on the free edge, dead bolts on the hinge edge), within its thickness."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd.categories.parts import safes as S

from helpers import maker

make = maker("safe")


@pytest.mark.parametrize("design", ["home_safe", "hotel_safe", "gun_cabinet"])
def test_the_door_shows_its_bolts_on_both_upright_edges(design):
    for seed in range(2):
        _, bp = make(seed, design=design)
        # the door's own edges: its bolts and its hinges' leaves and knuckles (outside its hinge edge) left out
        door = np.array([pc.bounds for pc in bp.parts["door"].pieces if pc.material not in ("handle", "hinge")])
        (x0, y0, _), (x1, y1, _) = door[:, 0].min(0), door[:, 1].max(0)
        bolts = [pc.bounds for pc in bp.parts["door"].pieces if pc.material == "handle"]
        b = S.BUILD[design]
        for edge, side in ((y0, -1), (y1, 1)):
            heads = [bb for bb in bolts if (bb[0][1] if side > 0 else -bb[1][1]) < side * edge
                     and (bb[1][1] if side > 0 else -bb[0][1]) > side * edge]
            assert len(heads) == b.bolts
            assert all(x0 < bb[0][0] and bb[1][0] < x1 for bb in heads)  # inside the door's thickness
            assert 2 * b.bolt_r >= 0.015


@pytest.mark.parametrize("design", ["home_safe", "gun_cabinet"])
def test_inside_is_lined_in_felt_and_a_gun_cabinet_has_a_barrel_rest(design):
    """Inside a home safe or gun cabinet: felt on the floor, back and sides (not bare black steel); a gun cabinet
    carries a comb across its back the barrels lean into, its teeth ~5-6 cm apart."""
    _, bp = make(2, design=design)
    felt = [pc for pc in bp.parts["body"].pieces if pc.material == "lining"]
    assert len(felt) >= 4
    if design == "gun_cabinet":
        teeth = [pc for pc in felt if np.ptp(pc.vertices[:, 1]) < 0.03 and np.ptp(pc.vertices[:, 0]) > 0.03]
        assert len(teeth) >= 4
        ys = np.sort([pc.vertices[:, 1].mean() for pc in teeth])
        assert 0.03 < np.median(np.diff(ys)) < 0.08


def test_safes_are_dark_steel():
    """Safes come black, graphite or anthracite (SentrySafe, Stack-On, Elsafe ranges), not white."""
    from categories.safe import MATERIALS

    assert "white" not in MATERIALS["body"]
