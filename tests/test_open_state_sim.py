"""In SAPIEN, every part of a kitchen closes and opens again from the all-open state (a robot that opened
everything and now closes one part), not only from rest: seeds 0-2, where wall-cabinet doors, racks in
doors and a flap used to stop on a neighbour left open."""

from __future__ import annotations

import pytest

pytest.importorskip("sapien")

import infmob_usd  # noqa: E402
from infmob_usd.physical import clearance  # noqa: E402
from infmob_usd.validate import sim  # noqa: E402

pytestmark = pytest.mark.sim


def _reach(folder):
    return {c.name: c for c in sim.check_sapien(folder, checks=["reach"])}["reach"]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_every_kitchen_part_closes_and_reopens_from_the_all_open_state(seed, tmp_path):
    folder = infmob_usd.save(infmob_usd.generate("kitchen_cabinet", seed, texture_size=16), tmp_path)
    reach = _reach(folder)
    assert reach.ok, reach.detail
    assert "from rest and from all open" in reach.detail


def test_reach_fails_a_kitchen_whose_parts_only_move_from_rest(tmp_path, monkeypatch):
    def rest_only(obj):  # the clearance pass without its all-open step
        c = clearance._Clearance(obj)
        c.sweep_alone()
        path = c.pairs()
        if path:
            c.together(path)
        return c

    monkeypatch.setattr(clearance, "_clearance", rest_only)
    folder = infmob_usd.save(infmob_usd.generate("kitchen_cabinet", 0, texture_size=16), tmp_path)
    reach = _reach(folder)
    assert not reach.ok
    # a wall-cabinet door stops on its open neighbour, about 0.3 rad short of closed
    assert "joint_door_5_0 -> lower from all open 0: stopped at 0.3" in reach.detail, reach.detail


# `infmob fuzz 300 --seed 12345`, draws 14 and 137: both missed a target from rest. The pot's was a
# pasta insert thrown off its seat at rest: a 0.3 mm sheet of its collar cooked by PhysX into a degenerate
# hull "touching" the side handle 15 mm away (fixed in the core: every collision hull is at least
# physical.MIN_HULL_WIDTH thick). The kitchen's was a double door's leaf stalling 0.09 rad from closed on its
# twin: the back corner of its meeting edge passed 2 mm from the twin (3 mm apart closed), where PhysX's
# persistent contact manifold reported -0.1 mm (fixed in the core: physical.keep_meeting_gaps).
FUZZ_12345_FIXED = {
    "kitchen_door_stalls_on_its_twin_leaf": (
        "kitchen_cabinet", 863838, dict(base_depth=0.55, sink_width=0.9481771266264848, front_thickness=0.022,
                                        handle_style="knob", design="corner", stand_style="plinth")),
    "pot_lid_on_a_pasta_insert": ("pot", 257514, dict(
        radius=0.18, bead=0.0026711065058312067, lid_thickness=0.002154414011149703, handle_angle=0.4,
        handle_thickness=0.01, side_handle_reach=0.019595804473540698, knob_radius=0.021904456923979625,
        tier_height=0.5460914116466911, pasta_collar=0.2215147139716876, body_finish="brushed_metal",
        has_pasta=True)),
}


@pytest.mark.parametrize("name", sorted(FUZZ_12345_FIXED))
def test_fuzz_12345_fixed_draws_reach_every_target(name, tmp_path):
    category, seed, overrides = FUZZ_12345_FIXED[name]
    folder = infmob_usd.save(infmob_usd.generate(category, seed, texture_size=16, **overrides), tmp_path)
    reach = _reach(folder)
    assert reach.ok, reach.detail


def test_a_leaf_swinging_shut_keeps_the_meeting_gap_from_its_twin():
    import numpy as np

    from collide import overlap

    # the fuzz draw's corner unit no longer has a double door (a column beside a corner is column_width wide,
    # at most 0.6 m): the same fronts on a sink base's double door
    _, _, overrides = FUZZ_12345_FIXED["kitchen_door_stalls_on_its_twin_leaf"]
    overrides = {k: v for k, v in overrides.items() if k not in ("design", "sink_width")}
    obj = infmob_usd.generate("kitchen_cabinet", 0, texture_size=16, **overrides)
    leaf, twin = obj.link("door_sink_1"), obj.link("door_sink_0")  # the twin on the leaf's -Y side
    assert twin.origin[1] < leaf.origin[1]
    nearer = obj.poses({})["door_sink_0"].copy()
    nearer[1, 3] += 0.0025  # the twin moved 2.5 mm towards the leaf: the leaf must still pass it
    for a in np.linspace(0.0, 0.15, 11):
        pose = obj.poses({"joint_door_sink_1": float(a)})["door_sink_1"]
        assert overlap(leaf, pose, twin, nearer) < 1e-10, a


def test_no_collision_hull_is_thinner_than_physx_cooks_faithfully():
    from infmob_usd.physical import MIN_HULL_WIDTH
    from infmob_usd.physical.hulls import _face_normals

    category, seed, overrides = FUZZ_12345_FIXED["pot_lid_on_a_pasta_insert"]
    obj = infmob_usd.generate(category, seed, texture_size=16, **overrides)
    widths = []
    for link in obj.links:
        for piece in link.pieces:
            for c, (hv, hf) in zip(piece.convex, piece.hulls(), strict=True):
                p = c @ _face_normals(hv, hf).T
                widths.append(float((p.max(0) - p.min(0)).min()))
    assert min(widths) >= MIN_HULL_WIDTH - 1e-9, min(widths)
