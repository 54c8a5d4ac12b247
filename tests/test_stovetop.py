"""The stovetop category: a knob per zone, gas grates that lift off their seats, touch keys on the glass
top's front edge, and a counter cooker's two zones."""

from __future__ import annotations

import numpy as np
import pytest

from helpers import maker
from zoo import movable

make = maker("stovetop")


@pytest.mark.parametrize("n", (2, 4, 6))
def test_gas_hob_has_a_knob_per_burner_and_grates_that_lift_off(n):
    p, bp = make(1, design="gas", mount="built_in", zone_count=n)
    knobs = [j for j in movable(bp) if j.child.startswith("knob_")]
    assert len(knobs) == n and all(j.role == "knob" and j.dofs[0].type == "revolute" for j in knobs)
    # knobs on a built-in hob stand on its top: they turn about the vertical
    assert all(abs(abs(j.dofs[0].axis[2]) - 1.0) < 1e-9 for j in knobs)
    grates = [j for j in movable(bp) if j.child.startswith("grate_")]
    assert grates and all(j.role == "lift_off" and j.dofs[0].type == "prismatic" for j in grates)
    assert all(j.dofs[0].axis[2] > 0.99 and 0.0 < j.dofs[0].upper <= 0.03 + 1e-9 for j in grates)


@pytest.mark.parametrize("mount", ("built_in", "counter"))
def test_induction_touch_keys_sit_on_the_glass_front_edge_and_press_down(mount):
    """Touch keys belong on the glass top's front edge, where a hob sunk into a worktop shows them (not on a
    side skirt hidden in the cut-out); they press down through it and sit in front of every zone."""
    p, bp = make(2, design="induction", induction_controls="keys", mount=mount, key_count=4)
    assert p["mount"] == mount
    keys = [j for j in movable(bp) if j.child.startswith("key_")]
    assert len(keys) == 4 and all(j.role == "button" and j.dofs[0].axis[2] < -0.99 for j in keys)
    assert not any(j.child.startswith("knob_") for j in movable(bp))
    top = max(pc.bounds[1][2] for pc in bp.parts["body"].pieces if pc.material == "top")
    front = max(pc.bounds[1][0] for pc in bp.parts["body"].pieces if pc.material == "top")
    rings = [pc.bounds for pc in bp.parts["body"].pieces if pc.material == "display"]
    for j in keys:
        lo = np.array([pc.bounds[0] for pc in bp.parts[j.child].pieces]).min(0)
        hi = np.array([pc.bounds[1] for pc in bp.parts[j.child].pieces]).max(0)
        assert top - 0.001 < hi[2] < top + 0.01 and hi[0] < front  # on the glass, inside its front edge
        assert all(lo[0] > r[1][0] for r in rings)  # in front of the zones


@pytest.mark.parametrize("design", ("gas", "coil", "induction"))
def test_a_counter_cooker_has_at_most_two_zones_and_knobs_on_its_front(design):
    _, bp = make(3, design=design, mount="counter", zone_count=5, induction_controls="knobs")
    knobs = [j for j in movable(bp) if j.child.startswith("knob_")]
    assert len(knobs) == 2 and all(j.dofs[0].axis[0] > 0.99 for j in knobs)


@pytest.mark.parametrize("mount", ("built_in", "counter"))
def test_a_coil_is_a_spiral_tube_standing_over_a_lipped_drip_pan(mount):
    """An electric coil is a sheathed tube wound in 3 or more turns, gaps between them, standing on its
    support over a drip pan whose lip rises round it: not flat rings printed on the pan."""
    import numpy as np

    _, bp = make(2, design="coil", mount=mount)
    pieces = bp.parts["body"].pieces
    pans = [pc for pc in pieces if pc.material == "trim" and pc.convex]
    lips = [pc for pc in pieces if pc.material == "trim" and not pc.convex]
    coils = [pc for pc in pieces if pc.material == "element" and np.ptp(pc.vertices[:, 0]) > 0.1]
    assert pans and len(lips) == len(pans) and len(coils) == len(pans)
    for coil in coils:
        pan = min(pans, key=lambda pc: np.linalg.norm(pc.vertices[:, :2].mean(0) - coil.vertices[:, :2].mean(0)))
        c = (pan.vertices[:, :2].min(0) + pan.vertices[:, :2].max(0)) / 2  # the coil is wound round the pan's centre
        assert coil.vertices[:, 2].min() > pan.vertices[:, 2].max() + 0.002  # on its support, over the pan
        # the wound tube: a ray out from the centre crosses it 3 times or more, at growing radii
        d = coil.vertices[:, :2] - c
        ang, rad = np.arctan2(d[:, 1], d[:, 0]), np.linalg.norm(d, axis=1)
        for ray in (0.5, 2.0, -2.5):
            near = np.sort(rad[np.abs(np.angle(np.exp(1j * (ang - ray)))) < 0.12])
            crossings = 1 + int(np.sum(np.diff(near) > 0.004)) if len(near) else 0
            assert crossings >= 3, (ray, crossings)


@pytest.mark.parametrize("design", ("coil", "induction"))
@pytest.mark.parametrize("n", (2, 3, 4, 5, 6))
def test_zones_keep_real_spacing_and_sizes(design, n):
    """Zones never touch: every pair of zones (a coil measured to its drip pan's lip, an induction zone to its
    ring) keeps >= 50 mm of bare top between them, and every zone is a real one (>= 110 mm across: a 6 in
    coil's smaller sibling on a crowded hob), all inside the top."""
    from infmob_usd.categories.parts import hobs as HB

    for seed, width in ((0, 0.58), (1, 0.75), (2, 0.92)):
        _, bp = make(seed, design=design, mount="built_in", zone_count=n, width=width, induction_controls="knobs")
        pieces = bp.parts["body"].pieces
        if design == "coil":
            rings = [pc for pc in pieces if pc.material == "trim" and not pc.convex]  # the pans' lips
        else:
            rings = [pc for pc in pieces if pc.material == "display"]
        assert len(rings) == n
        discs = [((pc.bounds[0][:2] + pc.bounds[1][:2]) / 2, float(np.ptp(pc.vertices[:, 0])) / 2) for pc in rings]
        for i, (c, r) in enumerate(discs):
            assert r >= 0.055
            for c2, r2 in discs[i + 1:]:
                assert np.linalg.norm(c - c2) - r - r2 >= HB.HOB["zone"]["gap"] - 1e-6
        top = next(pc for pc in pieces if pc.material == "top")
        lo, hi = top.bounds
        assert all((c - r > lo[:2]).all() and (c + r < hi[:2]).all() for c, r in discs)
