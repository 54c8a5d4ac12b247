"""Kettle: what a user relies on beyond the contract tests: water pours from an open spout whose tip stands over
the fill line, and the side handle is a hand-sized grip held to the body at both ends."""

from __future__ import annotations

import numpy as np
import pytest

from infmob_usd.categories.parts import kettles as K

from helpers import maker

make = maker("kettle")


def _winding(v, f, q):
    """The generalised winding number of the closed mesh (``v``, ``f``) about point ``q``: 1 inside its solid,
    0 outside (van Oosterom-Strackee solid angles)."""
    a, b, c = (v[f[:, i]] - q for i in range(3))
    la, lb, lc = (np.linalg.norm(x, axis=1) for x in (a, b, c))
    num = np.einsum("ij,ij->i", a, np.cross(b, c))
    den = la * lb * lc + np.einsum("ij,ij->i", a, b) * lc + np.einsum("ij,ij->i", b, c) * la \
        + np.einsum("ij,ij->i", c, a) * lb
    return abs(float(np.arctan2(num, den).sum()) / (2 * np.pi))


def _pieces(bp, material):
    return [pc for pc in bp.parts["body"].pieces if pc.material == material]


@pytest.mark.parametrize("design", ["electric", "whistling", "camping"])
def test_the_spout_is_open_and_rises_from_low_on_the_body_over_the_fill_line(design):
    for seed in range(3):
        p, bp = make(seed, design=design)
        k = K.kettle(design, p["girth"], p["tallness"])
        sp = K.spout_of(k)
        root, tip = sp.point(np.array([0.0, 1.0]))
        h = k.height - k.z0
        assert tip[2] >= k.z0 + K.FILL_LINE * h and root[2] <= k.z0 + 0.5 * h
        spout = next(pc for pc in _pieces(bp, "body") if pc.bounds[1][0] > k.radius + 0.01)
        for q in sp.point(np.array([0.5, 0.7, 0.9, 0.99])):  # a bore runs out of its tip: no end cap, no rod
            assert _winding(spout.vertices, spout.faces, q) < 0.5
        assert np.linalg.norm(spout.vertices - tip, axis=1).min() < max(sp.across[1], sp.along[1]) + 1e-3


@pytest.mark.parametrize("design", ["electric", "whistling", "camping"])
def test_the_spout_tapers_from_a_root_moulded_into_the_wall_to_a_narrow_tip(design):
    """A real spout is wide where it leaves the body and narrow at the tip (not a constant-width tube stuck
    on): its section at the root is at least twice its tip's, and the root's wide section meets the wall."""
    for seed in range(3):
        p, bp = make(seed, design=design)
        k = K.kettle(design, p["girth"], p["tallness"])
        sp = K.spout_of(k)
        a, b = sp.half_widths(np.linspace(0, 1, 5))
        assert (np.diff(a) < 0).all() and (np.diff(b) < 0).all()
        assert a[0] * b[0] >= 4 * a[-1] * b[-1]
        root = sp.point(np.array([0.0]))[0]
        assert root[0] < K._r_at(k, root[2]) < root[0] + b[0]  # the root's centre inside the wall, its rim out


@pytest.mark.parametrize("design", ["electric", "whistling"])
def test_the_handle_is_a_grip_held_at_both_ends(design):
    for seed in range(3):
        p, bp = make(seed, design=design)
        k = K.kettle(design, p["girth"], p["tallness"])
        path = np.array(K.handle_path(k))
        upright = path[3, 2] - path[2, 2]  # the grip's straight length
        assert path[2, 0] == path[3, 0] and abs(upright) >= K.GRIP - 1e-9 and 2 * K.HANDLE_R >= 0.025
        for end in (path[0], path[-1]):  # each arm's end lies inside the wall's outer surface
            assert abs(end[0]) < K._r_at(k, end[2])
