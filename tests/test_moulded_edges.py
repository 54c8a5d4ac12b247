"""Real casings have rounded or rolled edges, not the sharp corners of a CAD box: a square bin's upright corners
are moulded round (30-45 mm) and its rim rolled, a safe's steel body has rolled edges and a gun cabinet's door
is deep enough for its locking bolts, a utility knife's die-cast halves and a barbecue lighter's moulded grip
have rounded outer edges. Checked on the grounded blueprint's drawn meshes."""

from __future__ import annotations

import numpy as np

from categories.parts import bins as B
from categories.parts import safes as S

from helpers import maker


def _vertices(bp, part, skip=("hinge",)):
    return np.vstack([pc.vertices for pc in bp.parts[part].pieces if not pc.name.startswith(skip)])


def test_a_square_bins_upright_corners_are_rounded():
    make = maker("trash_can")
    for design in ("open_bin", "pedal_bin", "sensor_bin"):
        for seed in range(3):
            p, bp = make(seed, design=design, shape="square")
            v = _vertices(bp, "body")
            lo, hi = v.min(0), v.max(0)
            hx, hy = (hi[0] - lo[0]) / 2, (hi[1] - lo[1]) / 2
            c = (lo + hi) / 2
            # how far the corner is cut back along the diagonal: a sharp box's corner reaches hx + hy
            reach = (np.abs(v[:, 0] - c[0]) + np.abs(v[:, 1] - c[1])).max()
            assert reach < hx + hy - 0.003, (design, seed)
            size = B.BinSize("square", p["width"], p["width"] * p["depth_ratio"], 1.0)
            assert 0.02 <= B.corner(size) <= B.ROUND["corner"]


def test_a_safes_body_edges_are_rolled_and_a_cabinets_door_is_deep():
    make = maker("safe")
    for design in ("home_safe", "hotel_safe", "gun_cabinet"):
        _, bp = make(0, design=design)
        v = _vertices(bp, "body")
        hi = v.max(0)
        e = min(S.EDGE * S.BUILD[design].wall, S.EDGE_MAX)
        # the top's front edge: a sharp one reaches x + z = front + top
        assert (v[:, 0] + v[:, 2]).max() < hi[0] + hi[2] - 0.5 * e
        door = np.vstack([pc.vertices for pc in bp.parts["door"].pieces
                          if pc.material not in ("handle", "hinge")])
        assert np.ptp(door[:, 0]) >= 0.04 if design == "gun_cabinet" else True  # folded 40-50 mm door


def test_a_utility_knifes_halves_have_rounded_outer_edges():
    make = maker("knife")
    for seed in range(3):
        _, bp = make(seed, design="utility")
        halves = [pc for pc in bp.parts["body"].pieces if pc.name == "half"]
        assert len(halves) == 2
        for pc in halves:
            v = pc.vertices
            outer = v[:, 2].argmax() if v[:, 2].mean() > 0.005 else v[:, 2].argmin()
            face = v[np.isclose(v[:, 2], v[outer, 2])]  # the outer face, inset from the half's outline
            assert np.ptp(face[:, 1]) < np.ptp(v[:, 1]) - 0.001


def test_a_barbecue_lighters_grip_is_rounded():
    make = maker("lighter")
    for seed in range(3):
        _, bp = make(seed, design="utility")
        grip = next(pc for pc in bp.parts["body"].pieces if pc.name == "grip").vertices
        for z in (grip[:, 2].min(), grip[:, 2].max()):  # both faces inset from the grip's outline
            face = grip[np.isclose(grip[:, 2], z)]
            assert np.ptp(face[:, 1]) < np.ptp(grip[:, 1]) - 0.004
