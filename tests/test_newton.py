"""Newton (CPU) reads what the USD says of our joints, and holds every object at rest.

Skipped where newton is not installed (``pip install -e .[newton]``; its CPU kernels compile once,
minutes, then warp caches them). ``INFMOB_NEWTON_SEEDS=5`` widens the rest sweep (default: seed 0).
"""

from __future__ import annotations

import math
import os

import pytest

import infmob_usd

pytest.importorskip("newton")
pytest.importorskip("newton_usd_schemas")
pytestmark = pytest.mark.sim

from infmob_usd.validate.newton_sim import SOLVERS, moved, rest_motion, spring_targets  # noqa: E402

SEEDS = range(int(os.environ.get("INFMOB_NEWTON_SEEDS", "1")))


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    out = tmp_path_factory.mktemp("newton")
    cache = {}

    def get(category, seed):
        if (category, seed) not in cache:
            obj = infmob_usd.generate(category, seed=seed, texture_size=16)
            cache[category, seed] = (infmob_usd.save(obj, out / category, formats="usd"), obj)
        return cache[category, seed]

    return get


def test_newton_reads_armature_velocity_and_springs(folders):
    """``newton:armature`` / ``newton:velocityLimit`` and the spring's drive reach Newton's model (before
    they were written it read armature 0 and its default velocity limit); the spring's target needs the
    loader recipe (:func:`spring_targets`)."""
    import newton

    folder, obj = folders("microwave", 0)
    b = newton.ModelBuilder()
    b.add_usd(str(folder / f"{folder.name}.usda"))
    model = b.finalize(device="cpu")
    native = model.joint_target_q.numpy().copy()
    assert spring_targets(model, folder / f"{folder.name}.usda") == sum(j.stiffness > 0 for j in obj.movable_joints)
    labels = [str(x).rsplit("/", 1)[-1] for x in model.joint_label]
    starts = model.joint_qd_start.numpy()
    armature, velocity = model.joint_armature.numpy(), model.joint_velocity_limit.numpy()
    ke, target = model.joint_target_ke.numpy(), model.joint_target_q.numpy()
    checked = 0
    for j in obj.movable_joints:
        k = starts[labels.index(j.name)]
        assert armature[k] == pytest.approx(j.armature, rel=1e-5), j.name
        if j.type != "continuous":
            assert velocity[k] == pytest.approx(j.velocity, rel=1e-4), j.name
        if j.stiffness > 0:
            assert ke[k] == pytest.approx(j.stiffness, rel=1e-4), j.name
            assert target[k] == pytest.approx(j.spring_ref, rel=1e-4, abs=1e-9), j.name
            # what Newton's builder makes of a target beyond the rest stop, without the recipe
            assert native[k] == pytest.approx(0.5 * (j.lower + j.upper), rel=1e-4), j.name
        checked += 1
    assert checked and any(j.stiffness > 0 for j in obj.movable_joints)


@pytest.mark.parametrize("solver,category,seed", [pytest.param(solver, c, s, id=f"{solver}-{c}-{s}")
                                                   for solver in SOLVERS for c in infmob_usd.list_categories()
                                                   for s in SEEDS])
def test_newton_rest(folders, solver, category, seed):
    """Every joint stays within 1 mm / 1 degree of rest for 0.5 s, no NaN, with either solver (XPBD with the
    loader recipe of :func:`~infmob_usd.validate.newton_sim.load`, iterations and relaxation: with Newton's
    defaults a dining table went NaN and a pot lid sank 1.3 mm through its stop)."""
    folder, obj = folders(category, seed)
    motion, prismatic = rest_motion(folder / f"{folder.name}.usda", solver)
    assert set(motion) == {j.name for j in obj.movable_joints}  # continuous joints: revolute without limits
    assert not any(math.isnan(m) for m in motion.values()), motion
    assert not moved(motion, prismatic), moved(motion, prismatic)


def test_a_heavy_part_on_a_slide_and_swivel_holds_in_xpbd(folders):
    """A television's post slides up and swivels through a dummy link carrying 16 kg of post and screen: at 10 g
    XPBD let it sink 5.4 mm through its stop in 0.5 s; at a hundredth of what it carries it holds."""
    folder, obj = folders("tv", 3)
    assert any(link.dummy for link in obj.links)
    motion, prismatic = rest_motion(folder / f"{folder.name}.usda", "xpbd")
    assert not moved(motion, prismatic), moved(motion, prismatic)
