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
