"""Square rims (infmob_usd.physical.rims): a thin hull's flare at a face that looks onto a parallel face of
another link's hull a few millimetres away is cut square, because PhysX's contact manifold misreads the pair."""

from types import SimpleNamespace

import numpy as np
import pytest

from infmob_usd import geometry as g
from infmob_usd.model import Link
from infmob_usd.physical import square_rims
from infmob_usd.physical.rims import NEAR

R0, R1, T = 0.02446, 0.025967, 0.005856  # a pepper grinder head's lowest band: flares out 1.5 mm over 5.9 mm


def _links(gap: float, thickness: float = T, flare: float = R1 - R0):
    band = g.revolve([(0, 0), (R0, 0), (R0 + flare, thickness), (0, thickness)], "m")
    slab = g.box_between([0.015, -0.01, -gap - 0.01], [0.04, 0.01, -gap], "m")  # reaches out under the flare

    def link(name, piece):
        return Link(name, name, np.zeros(3), [piece], 0.1, np.zeros(3), np.eye(3) * 1e-5)
    return [link("body", slab), link("head", band)]


def _band(links) -> np.ndarray:
    return links[1].pieces[0].convex[0]


def test_a_flared_band_over_a_near_parallel_face_gets_upright_sides():
    links = _links(0.0015)
    out = square_rims(links, [])
    assert out[0] is links[0]  # the slab's sides are upright already
    band = _band(out)
    r = np.hypot(band[:, 0], band[:, 1])
    assert r.max() <= R0 + 1e-9  # nothing beyond the bottom face's outline
    assert band[:, 2].min() == pytest.approx(0.0) and band[:, 2].max() == pytest.approx(T)  # as thick as before
    top = band[band[:, 2] > T - 1e-9]
    assert np.hypot(top[:, 0], top[:, 1]).max() == pytest.approx(R0, abs=1e-6)  # the top as wide as the bottom
    assert _band(links) is not band and np.hypot(*_band(links)[:, :2].T).max() > R1 - 1e-9  # input untouched


@pytest.mark.parametrize("case", ["far", "thick", "upright", "jointed", "mostly_overhang"])
def test_what_is_left_alone(case):
    """Faces farther apart than NEAR, a hull thicker than PCM's witness tolerance, a band that rises square
    already, a link against the one it is jointed to (PhysX never tests that pair), and a band that would
    keep under KEEP of itself (flared out 15 mm: 57 %)."""
    links = {"far": _links(NEAR + 0.001), "thick": _links(0.0015, thickness=0.012),
             "upright": _links(0.0015, flare=0.0), "jointed": _links(0.0015),
             "mostly_overhang": _links(0.0015, flare=0.015)}[case]
    joints = [SimpleNamespace(name="turn", type="revolute", parent="body", child="head")] if case == "jointed" else []
    out = square_rims(links, joints)
    assert all(a is b for a, b in zip(out, links, strict=True))


KEY_W, KEY_TOP, KEY_H = 0.0034, 0.00276, 0.0021  # a phone key: 6.8 mm square, 0.64 mm chamfer round its top


def _key_and_slide(gap: float, travel: float):
    """A chamfered key (resting on the body by a press joint) and a bar on a slide: at rest the bar is 30 mm
    to the side, ``gap`` above the key's top; the slide carries it ``travel`` towards and over the key."""
    pts = np.array([[sx * w, sy * w, z] for w, z in ((KEY_W, 0.0), (KEY_W, KEY_H - (KEY_W - KEY_TOP)), (KEY_TOP, KEY_H))
                    for sx in (-1, 1) for sy in (-1, 1)])
    key = g.from_trimesh(g.convex_hull(pts), "m")
    bar = g.box_between([0.028, -0.02, KEY_H + gap], [0.032, 0.02, KEY_H + gap + 0.0034], "m")
    body = g.box_between([-0.05, -0.03, -0.01], [0.05, 0.03, -0.001], "m")

    def link(name, piece):
        return Link(name, name, np.zeros(3), [piece], 0.01, np.zeros(3), np.eye(3) * 1e-7)
    joints = [SimpleNamespace(name="press", type="prismatic", parent="body", child="key", axis=np.array([0, 0, -1.0]),
                              lower=0.0, upper=0.0012),
              SimpleNamespace(name="slide", type="prismatic", parent="body", child="bar", axis=np.array([-1.0, 0, 0]),
                              lower=0.0, upper=travel)]
    return [link("body", body), link("key", key), link("bar", bar)], joints


def test_a_slide_that_carries_a_face_over_a_thin_key_squares_the_key_top():
    """Phone seed 12: the slide's bar passed 6.7 mm over a 2.1 mm key with a chamfered top; SAPIEN reported an
    8.8 mm contact (gap plus key) and the slide stopped half way. At rest the two do not overlap seen from
    above, so only the slide's path finds the pair; the key keeps 70 % of itself, its top's outline."""
    links, joints = _key_and_slide(0.0067, 0.04)
    out = square_rims(links, joints)
    assert out[0] is links[0] and out[2] is links[2]
    key = out[1].pieces[0].convex[0]
    assert np.abs(key[:, :2]).max() == pytest.approx(KEY_TOP, abs=1e-6)  # upright sides over the top face
    assert key[:, 2].min() == pytest.approx(0.0) and key[:, 2].max() == pytest.approx(KEY_H)


@pytest.mark.parametrize("travel", [0.01, 0.0])
def test_a_slide_that_stops_short_of_the_key_leaves_it(travel):
    links, joints = _key_and_slide(0.0067, travel)
    assert all(a is b for a, b in zip(square_rims(links, joints), links, strict=True))


@pytest.mark.sim
def test_phone_12_slide_passes_over_the_keys_in_sapien(tmp_path):
    """Its slide stopped at 0.026 of 0.049 m over a key (the key's far face taken for its top: -8.8 mm)."""
    pytest.importorskip("sapien")
    import infmob_usd
    from infmob_usd.validate.sim import check_sapien

    # the design pinned: seed 12 was a slider before the bar phone joined the draw
    folder = infmob_usd.save(infmob_usd.generate("phone", seed=12, texture_size=16, design="slider"), tmp_path)
    res = {c.name: c for c in check_sapien(folder, checks=["reach"])}
    assert res["reach"].ok, res["reach"].detail


@pytest.mark.sim
def test_pepper_grinder_30_head_turns_in_sapien(tmp_path):
    """Its head's lowest band flared 14 degrees over the body's window bars 1.5 mm below: SAPIEN reported a
    7.4 mm contact (the gap plus the band's thickness) and the head stopped at 0.75 of 1.57 rad."""
    pytest.importorskip("sapien")
    import infmob_usd
    from infmob_usd.validate.sim import check_sapien

    folder = infmob_usd.save(infmob_usd.generate("pepper_grinder", seed=30, texture_size=16), tmp_path)
    res = {c.name: c for c in check_sapien(folder, checks=["reach"])}
    assert res["reach"].ok, res["reach"].detail
