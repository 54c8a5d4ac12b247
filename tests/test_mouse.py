"""A mouse's main buttons click down about their rear hinge and its thumb buttons press straight into the shell:
checked on the grounded blueprint."""

from __future__ import annotations

import numpy as np

from helpers import maker
from helpers import part_points as _points

make = maker("mouse")


def test_main_buttons_click_down_at_the_front_and_the_side_buttons_press_across():
    _, bp = make(0, design="gaming", has_right_thumb=True)
    kinds = {s.child: s.dofs[0] for s in bp.joints if s.movable}
    body = _points(bp, "body")
    for name in ("left_button", "right_button"):
        d = kinds[name]
        assert d.type == "revolute" and np.allclose(np.abs(d.axis), (0, 1, 0))
        rest = _points(bp, name)
        pressed = _points(bp, name, bp.poses({(name, 0): d.upper})[name])
        front, back = rest[:, 0].argmax(), rest[:, 0].argmin()
        # the tip goes down 1.5-2 mm onto its switch; the hinge end stays where it is
        assert 0.0015 < rest[front, 2] - pressed[front, 2] < 0.0021
        assert abs(rest[back, 2] - pressed[back, 2]) < 2e-4
        assert d.origin[0] < rest[:, 0].min() + 1e-3  # hinged across its rear edge
    assert kinds["wheel"].type == "continuous" and np.allclose(np.abs(kinds["wheel"].axis), (0, 1, 0))
    sides = [n for n in kinds if n.startswith(("side_button", "right_side_button"))]
    assert len(sides) >= 4
    for name in sides:  # pressed square to the mouse's side, toward its middle
        d = kinds[name]
        y = _points(bp, name)[:, 1].mean()
        assert d.type == "prismatic" and abs(d.axis[1]) > 0.999 and np.sign(d.axis[1]) == -np.sign(y)
        assert abs(y) > 0.4 * np.ptp(body[:, 1])  # on a wall, not the top


def test_the_buttons_are_moulded_in_the_shells_colour():
    from categories.mouse import CATEGORY

    for finish in next(p for p in CATEGORY.params if p.name == "finish").choices:
        spec = CATEGORY.resolve_materials({**make(0)[0], "finish": finish})
        # one variant: the shell and the buttons are drawn from the same colour, never two of a list
        assert "|" not in spec["shell"] and spec["buttons"] == spec["shell"], finish


def test_the_plan_ranges_from_an_even_office_mouse_to_an_egg():
    widths = {}
    for taper in (0.0, 1.0):
        _, bp = make(3, design="wired", taper=taper, size=0.5, width=0.5)
        shell = [pc.vertices for pc in bp.parts["body"].pieces if pc.name in ("palm", "wall")]
        body = np.vstack([*shell, _points(bp, "left_button"), _points(bp, "right_button")])
        x0, x1 = body[:, 0].min(), body[:, 0].max()
        front = body[body[:, 0] > x0 + 0.8 * (x1 - x0)]
        back = body[body[:, 0] < x0 + 0.4 * (x1 - x0)]
        widths[taper] = np.ptp(front[:, 1]) / np.ptp(back[:, 1])
    assert widths[1.0] < widths[0.0] - 0.08, widths  # the egg's front fifth is clearly narrower
