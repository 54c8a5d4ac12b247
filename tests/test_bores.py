"""Clear bores (infmob_usd.physical.bores): a push-to-turn shaft keeps no collision hull inside the hole of the
plate it turns in, because PhysX's contact manifold misreads the pair (a dimmer stalled half way round)."""

from types import SimpleNamespace

import numpy as np
import pytest

from infmob_usd import geometry as g
from infmob_usd.model import Link
from infmob_usd.physical import clear_bores

PIVOT = np.array([0.009, 0.0, 0.04])  # the knob's pivot 9 mm in front of the wall, on the plate's face
PUSH = 0.0015  # m the knob is pushed in before it turns


def _switch(joints_between: str = "push_turn"):
    """A 9 mm plate with a square 11 mm hole (four bars) and a knob whose 6 mm 16-gon shaft reaches 8 mm into
    the hole from a disc in front of the plate: plate -> (push along -X) -> dummy -> (turn about X) -> knob."""
    a = np.arange(16) * np.pi / 8
    ring = np.c_[0.003 * np.cos(a), 0.003 * np.sin(a)]
    shaft = g.from_trimesh(g.convex_hull(np.r_[np.c_[np.full(16, -0.008), ring], np.c_[np.full(16, 0.004), ring]]), "m")
    disc = g.box_between([0.003, -0.017, -0.017], [0.007, 0.017, 0.017], "m")
    bars = [g.box_between(lo, hi, "m") for lo, hi in (
        ([0, -0.03, 0.0455], [0.009, 0.03, 0.08]), ([0, -0.03, 0.0], [0.009, 0.03, 0.0345]),
        ([0, -0.03, 0.0345], [0.009, -0.0055, 0.0455]), ([0, 0.0055, 0.0345], [0.009, 0.03, 0.0455]))]

    def link(name, pieces, origin, dummy=False):
        return Link(name, name, origin, pieces, 0.01, np.zeros(3), np.eye(3) * 1e-7, dummy)
    links = [link("plate", bars, np.zeros(3)), link("knob_dummy0", [], PIVOT, True), link("knob", [shaft, disc], PIVOT)]
    turn = SimpleNamespace(name="turn", type="revolute", parent="knob_dummy0", child="knob", origin=PIVOT,
                           axis=np.array([1.0, 0, 0]), lower=0.0, upper=5.24)
    push = SimpleNamespace(name="push", type="prismatic", parent="plate", child="knob_dummy0", origin=PIVOT,
                           axis=np.array([-1.0, 0, 0]), lower=0.0, upper=PUSH)
    if joints_between == "off_axis":  # the turn's axis beside the shaft's: a crank, whose shaft does sweep
        turn = SimpleNamespace(**{**vars(turn), "origin": PIVOT + [0, 0.004, 0]})
    if joints_between == "one_wall":  # the plate's rim above the knob, nothing round it: no bore
        links[0] = link("plate", bars[:1], np.zeros(3))
    if joints_between == "one_joint":  # the knob turns on the plate itself: PhysX never tests the pair
        links, joints = [links[0], links[2]], [SimpleNamespace(**{**vars(turn), "parent": "plate"})]
        return links, joints
    return links, [push, turn]


def test_a_push_to_turn_shaft_ends_outside_the_hole_its_push_clear_of_the_mouth():
    links, joints = _switch()
    out = clear_bores(links, joints)
    assert out[0] is links[0] and out[1] is links[1]
    shaft = out[2].pieces[0].convex[0] + PIVOT
    assert shaft[:, 0].min() == pytest.approx(0.009 + PUSH)  # the plate's face plus the push
    assert shaft[:, 0].max() == pytest.approx(PIVOT[0] + 0.004)  # the end at the disc kept
    assert np.hypot(shaft[:, 1], shaft[:, 2] - PIVOT[2]).max() == pytest.approx(0.003)  # as thick as it was
    assert out[2].pieces[1] is links[2].pieces[1] or np.array_equal(out[2].pieces[1].convex[0],
                                                                     links[2].pieces[1].convex[0])  # disc kept


@pytest.mark.parametrize("case", ["off_axis", "one_joint", "one_wall"])
def test_what_is_left_alone(case):
    """A shaft whose turn is off its axis sweeps the hole (a crank): its contacts are real; a knob jointed to
    the plate itself is never tested against it by PhysX; a knob beside a rim, not in a hole, is one a hand
    may hold there."""
    links, joints = _switch(case)
    out = clear_bores(links, joints)
    assert all(a is b for a, b in zip(out, links, strict=True))


@pytest.mark.sim
def test_switch_dimmer_turns_its_whole_range_in_sapien(tmp_path):
    """Fuzz draw `switch --seed 527534 --set knob_size=1.0`: its push-to-turn dimmer stopped at 2.33 of 5.24 rad
    on a -8.3 mm contact between its shaft and the side of the plate's hole, 2.5 mm away."""
    pytest.importorskip("sapien")
    import infmob_usd
    from infmob_usd.validate.sim import check_sapien

    folder = infmob_usd.save(infmob_usd.generate("switch", seed=527534, texture_size=16, knob_size=1.0), tmp_path)
    res = {c.name: c for c in check_sapien(folder, checks=["reach"])}
    assert res["reach"].ok, res["reach"].detail
