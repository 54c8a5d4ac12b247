import math

import numpy as np
import pytest

import infmob_usd
from infmob_usd import joints as J
from infmob_usd.errors import ModelError
from infmob_usd.mass import DUMMY_CARRY_RATIO, DUMMY_MASS

from zoo import zoo, zoo_blueprint

CHAIN = {"fixed_part": 1, "rev_part": 1, "cont_part": 1, "pris_part": 1, "rp_part": 2, "cp_part": 2,
         "lp_part": 3, "lf_part": 3, "fr_part": 2}


def test_every_kind_expands_into_its_chain():
    obj = zoo()
    for group, n in CHAIN.items():
        chain = [j for j in obj.joints if j.group == group]
        assert len(chain) == n, group
        assert tuple(j.type for j in chain) == (J.KINDS[chain[0].kind] or ("fixed",))
        assert chain[-1].child == group
        for a, b in zip(chain, chain[1:]):  # consecutive through dummy links
            assert a.child == b.parent and obj.link(a.child).dummy
    assert obj.joint_kinds() == {k: 1 for k in J.KINDS if k != "fixed"}


def test_dummy_links_are_light_but_never_zero():
    obj = zoo()
    dummies = [link for link in obj.links if link.dummy]
    assert len(dummies) == sum(n - 1 for n in CHAIN.values())
    for d in dummies:
        assert d.mass >= DUMMY_MASS > 0
        assert np.all(np.linalg.eigvalsh(d.inertia) > 0)
        assert not d.pieces


def test_links_sit_at_their_pivots_and_masses_follow_density():
    obj = zoo()
    rev = obj.link("rev_part")
    assert np.allclose(rev.origin[:2], [0, np.linspace(-0.85, 0.85, 9)[1]])
    # a 6 cm plastic cube: a moulded box, massed as a shell of the plastic family's wall and density
    from infmob_usd.materials import FAMILIES

    plastic = FAMILIES["plastic"]
    assert 0 < plastic.wall < 0.01
    assert rev.mass == pytest.approx(6 * 0.06**2 * plastic.wall * plastic.density, rel=1e-6)
    assert np.allclose(rev.com, 0, atol=1e-9)  # the cube's centre is the pivot
    for link in obj.links:
        assert np.all(np.linalg.eigvalsh(link.inertia) > 0)


def test_object_rests_on_the_ground():
    obj = zoo()
    assert obj.bounds()[0, 2] == pytest.approx(0.0, abs=1e-12)


def test_forward_kinematics_moves_children_along_axes():
    obj = zoo()
    p = obj.poses({"joint_pris_part": 0.2, "joint_rev_part": math.pi / 2})
    rest = obj.poses()
    assert np.allclose(p["pris_part"][:3, 3] - rest["pris_part"][:3, 3], [0.2, 0, 0])
    r = p["rev_part"][:3, :3]
    assert np.allclose(r @ [1, 0, 0], [0, 1, 0])  # +90 deg about +Z


def test_flip_revolute_has_two_distinct_hinge_lines():
    obj = zoo()
    a, b = [j for j in obj.joints if j.group == "fr_part"]
    assert not np.allclose(a.origin, b.origin)


def test_bad_joint_specs_are_rejected():
    with pytest.raises(ModelError, match="contain the rest value"):
        J.revolute("a", "b", (0, 0, 0), (0, 0, 1), 0.5, 1.0)
    with pytest.raises(ModelError, match="axis must not be zero"):
        J.prismatic("a", "b", (0, 0, 0), (0, 0, 0), 0.0, 1.0)
    with pytest.raises(ModelError, match="unknown joint kind"):
        J.JointSpec("screw", "a", "b")
    bp = zoo_blueprint()
    with pytest.raises(ModelError, match="already has a parent"):
        bp.join(J.fixed("base", "rev_part"))
    with pytest.raises(ModelError, match="no part named"):
        bp.join(J.fixed("base", "ghost"))


def test_blueprint_poses_agree_with_the_built_model():
    bp = zoo_blueprint()
    obj = zoo()  # the same blueprint, grounded and framed (grounding only lifts z)
    q_bp = {("rev_part", 0): 0.7, ("rp_part", 0): 0.05, ("rp_part", 1): -0.4, ("fr_part", 1): 0.3}
    q_obj = {"joint_rev_part": 0.7, "joint_rp_part_0": 0.05, "joint_rp_part_1": -0.4, "joint_fr_part_1": 0.3}
    motion = bp.poses(q_bp)
    frames = obj.poses(q_obj)
    lift = obj.bounds()[0, 2] - bp.bounds()[0, 2]
    for name in ("rev_part", "rp_part", "fr_part"):
        world_rest = bp.parts[name].pieces[0].vertices[:4]
        via_bp = world_rest @ motion[name][:3, :3].T + motion[name][:3, 3] + [0, 0, lift]
        link = obj.link(name)
        via_obj = link.pieces[0].vertices[:4] @ frames[name][:3, :3].T + frames[name][:3, 3]
        assert np.allclose(via_bp, via_obj, atol=1e-9)


def test_blueprint_poses_rejects_keys_that_name_no_dof():
    import pytest

    from zoo import zoo_blueprint

    bp = zoo_blueprint()
    child = next(j.child for j in bp.joints if j.dofs)
    assert set(bp.poses({(child, 0): 0.1})) == set(bp.parts)
    with pytest.raises(KeyError, match="name no DoF"):
        bp.poses({child: 0.1})
    with pytest.raises(KeyError, match="name no DoF"):
        bp.poses({(child, 7): 0.1})


@pytest.mark.parametrize("category", ["lamp", "tap", "office_chair"])
def test_no_link_is_light_against_what_it_carries(category):
    """A thin link between joints carrying a heavy one loses PhysX's drives (fuzz: lamp poles under
    their heads); every principal moment is at least 1/100 of the largest below it."""
    from infmob_usd import generate
    from infmob_usd.mass import CHAIN_INERTIA_RATIO

    for seed in range(3):
        obj = generate(category, seed=seed, texture_size=16)
        links = {link.name: link for link in obj.links}
        kids: dict[str, list[str]] = {}
        for j in obj.joints:
            kids.setdefault(j.parent, []).append(j.child)

        def below(name, links=links, kids=kids):
            return max((max(np.linalg.eigvalsh(links[c].inertia)[-1], below(c)) for c in kids.get(name, ())),
                       default=0.0)

        for name, link in links.items():
            assert np.linalg.eigvalsh(link.inertia)[0] >= CHAIN_INERTIA_RATIO * below(name) * (1 - 1e-9), name
            assert np.allclose(link.inertia, link.inertia.T)


def _button_on(body_side: float):
    """Link masses of a cube body (side ``body_side`` m, 1000 kg/m^3) with a 0.5 g button on a slide."""
    from infmob_usd import geometry as g
    from infmob_usd.blueprint import Blueprint
    from infmob_usd.model import build

    bp = Blueprint("tiny", materials={"body": "plastic", "part": "plastic"})
    s = body_side
    bp.add("body", "body", [g.box([s, s, s], [0.0, 0.0, s / 2], "body")])
    button = 0.0005 / 1000.0  # m^3 of a 0.5 g button at 1000 kg/m^3
    side = button ** (1 / 3)
    bp.add("button", "button", [g.box([side] * 3, [s / 2 + side, 0.0, s / 2], "part")])
    bp.join(J.prismatic("body", "button", (s / 2, 0, s / 2), (-1, 0, 0), 0.0, 0.002, "button"))
    links, _ = build(bp, {"body": 1000.0, "part": 1000.0})
    return {link.name: link.mass for link in links}


def test_a_small_objects_light_parts_keep_their_mass():
    from infmob_usd.mass import LEAST_MASS, MIN_MASS

    pen = _button_on(0.0215)  # a 10 g object: its 0.5 g button is floored at 1 g (the least link), not 5 g
    assert pen["body"] == pytest.approx(0.01, rel=0.01)
    assert pen["button"] == pytest.approx(LEAST_MASS)
    big = _button_on(0.1)  # a 1 kg object: the same button is floored at 5 g, as every link of one is
    assert big["button"] == MIN_MASS


def test_a_dummy_link_weighs_a_hundredth_of_what_it_carries():
    """Solvers converge badly on a 10 g body under 16 kg (a television's slide-and-swivel post sank through its stop
    in Newton's XPBD): a dummy weighs at least DUMMY_CARRY_RATIO of the links below it, and no less than DUMMY_MASS."""
    obj = infmob_usd.generate("tv", seed=3, texture_size=16)
    below: dict[str, list[str]] = {}
    for j in obj.joints:
        below.setdefault(j.parent, []).append(j.child)

    def carried(name: str) -> float:
        return sum(obj.link(c).mass + carried(c) for c in below.get(name, ()))

    dummies = [link for link in obj.links if link.dummy]
    assert dummies
    for d in dummies:
        assert d.mass == pytest.approx(max(DUMMY_MASS, DUMMY_CARRY_RATIO * carried(d.name)), rel=1e-9), d.name
    assert max(d.mass for d in dummies) > 10 * DUMMY_MASS
