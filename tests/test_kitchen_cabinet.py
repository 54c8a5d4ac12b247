import numpy as np
import pytest

import infmob_usd

from collide import overlap

SEEDS = range(8)


@pytest.fixture(scope="module", params=SEEDS)
def cabinet(request):
    return infmob_usd.generate("kitchen_cabinet", seed=request.param, texture_size=16)


def test_parts_and_labels(cabinet):
    labels = {link.label for link in cabinet.links}
    assert "body" in labels
    assert labels <= {"body", "drawer", "door"}
    assert cabinet.links[0].name == "carcass"


def test_drawers_slide_out_along_x_and_doors_hinge_about_z(cabinet):
    for j in cabinet.movable_joints:
        if j.child.startswith("drawer"):
            assert j.type == "prismatic" and np.allclose(j.axis, [1, 0, 0])
            assert j.lower == 0 and 0 < j.upper <= 0.75 * cabinet.params["depth"]
        else:
            assert j.type == "revolute" and abs(abs(j.axis[2]) - 1) < 1e-9
            assert j.lower == 0 and 1.2 <= j.upper <= cabinet.params["door_angle"] + 1e-9


def test_moving_parts_never_enter_the_carcass(cabinet):
    carcass = cabinet.link("carcass")
    rest = cabinet.poses()
    for j in cabinet.movable_joints:
        child = cabinet.link(j.child)
        base = overlap(carcass, rest["carcass"], child, rest[j.child])
        assert base < 1e-9, f"{j.child} is embedded in the carcass at rest"
        for f in (0.25, 0.5, 0.75, 1.0):
            pose = cabinet.poses({j.name: j.lower + f * (j.upper - j.lower)})
            v = overlap(carcass, pose["carcass"], child, pose[j.child])
            assert v < 1e-7, f"{j.child} at {f:.0%} of its range overlaps the carcass by {v * 1e6:.1f} cm^3"


def test_doors_swing_outward(cabinet):
    front = cabinet.params["depth"] / 2
    for j in cabinet.movable_joints:
        if j.type != "revolute":
            continue
        pose = cabinet.poses({j.name: j.upper})[j.child]
        pts = np.vstack([v for p in cabinet.link(j.child).pieces for v, _ in p.hulls()])
        x = pts @ pose[:3, :3].T + pose[:3, 3]
        assert x[:, 0].min() > front - 1e-6  # the whole door is in front of the carcass


def test_no_two_fronts_touch_at_rest(cabinet):
    rest = cabinet.poses()
    movers = [cabinet.link(j.child) for j in cabinet.movable_joints]
    for i, a in enumerate(movers):
        for b in movers[i + 1:]:
            assert overlap(a, rest[a.name], b, rest[b.name], pad=0.001) < 1e-9, (a.name, b.name)


def test_overrides_shape_the_cabinet():
    obj = infmob_usd.generate("kitchen_cabinet", seed=1, texture_size=16, column_count=2, has_handles=False,
                              width=1.5)
    assert obj.params["column_count"] == 2
    assert not any(p.name == "handle" for link in obj.links for p in link.pieces)
    lo, hi = obj.bounds()
    assert hi[1] - lo[1] == pytest.approx(1.5, abs=0.02)
    # double doors: a door column wider than 0.6 m gets two leaves
    wide = infmob_usd.generate("kitchen_cabinet", seed=2, texture_size=16, column_count=1, width=1.4)
    doors = [link for link in wide.links if link.label == "door"]
    assert len(doors) in (0, 2)


def test_doors_beside_another_column_stay_within_their_column_when_open(cabinet):
    """An open leaf and its handle never sweep into the neighbouring column (its drawers or door)."""
    carcass = cabinet.link("carcass")
    ys = np.vstack([v for p in carcass.pieces for v, _ in p.hulls()])[:, 1] + carcass.origin[1]
    for j in cabinet.movable_joints:
        if j.type != "revolute" or abs(j.origin[1] - ys.min()) < 0.01 or abs(j.origin[1] - ys.max()) < 0.01:
            continue  # a door hinged at the cabinet's outer side may open wider
        assert j.upper < np.pi / 2 + 1e-9
        pose = cabinet.poses({j.name: j.upper})[j.child]
        pts = np.vstack([v for p in cabinet.link(j.child).pieces for v, _ in p.hulls()])
        y = pts @ pose[:3, :3].T + pose[:3, 3]
        rest = np.vstack([v for p in cabinet.link(j.child).pieces for v, _ in p.hulls()]) + cabinet.link(j.child).origin
        assert y[:, 1].min() >= rest[:, 1].min() - 1e-6 and y[:, 1].max() <= rest[:, 1].max() + 1e-6
