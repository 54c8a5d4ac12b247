"""Every category x seeds 3 and 4: generate, save, validate (USD, SAPIEN, geometry, ManiSkill); determinism.

Seeds 0-2 of every category go through the same physics and simulator checks in tests/test_physics_checks.py
(and their bytes through tests/test_golden.py); ``infmob validate --sim --sweep N`` runs the wide sweep."""

import functools
import hashlib

import pytest

import infmob_usd
from infmob_usd.validate import validate_object

SEEDS = (3, 4)
CATEGORIES = infmob_usd.list_categories()


def _digest(folder):
    h = hashlib.sha256()
    for f in sorted(p for p in folder.rglob("*") if p.is_file()):
        h.update(str(f.relative_to(folder)).encode())
        h.update(f.read_bytes())
    return h.hexdigest()


@pytest.mark.sim
@pytest.mark.parametrize("category", CATEGORIES)
@pytest.mark.parametrize("seed", SEEDS)
def test_generate_save_validate(category, seed, tmp_path):
    pytest.importorskip("sapien")
    obj = infmob_usd.generate(category, seed=seed, texture_size=64)
    assert all(link.label for link in obj.links)
    folder = infmob_usd.save(obj, tmp_path)
    report = validate_object(folder, sim=True, physics=True)
    assert report.ok, "; ".join(f"{c.name}: {c.detail}" for c in report.failed)


@pytest.mark.parametrize("category", CATEGORIES)
def test_same_call_gives_identical_bytes(category, tmp_path):
    a = infmob_usd.save(infmob_usd.generate(category, seed=11, texture_size=64), tmp_path / "a")
    b = infmob_usd.save(infmob_usd.generate(category, seed=11, texture_size=64), tmp_path / "b")
    assert _digest(a) == _digest(b)
    c = infmob_usd.save(infmob_usd.generate(category, seed=12, texture_size=64), tmp_path / "c")
    assert _digest(a) != _digest(c)


@functools.cache
def _glance(category: str, seed: int) -> tuple[tuple, int]:
    """What tells two objects apart at a glance: their box to the millimetre, their moving parts (two drip
    coffee machines of one size differ by their keys) and their finishes (kitchen shears of one length in red and
    in teal handles); and how many joints move."""
    obj = infmob_usd.generate(category, seed=seed, texture_size=16)
    finishes = tuple(sorted((look.family, look.variant) for look in obj.materials.values()))
    glance = (tuple(obj.bounds().round(3).ravel()), tuple(sorted(obj.joint_kinds().items())), finishes)
    return glance, len(obj.movable_joints)


# one worker takes both tests of a category, so each object is generated once
_GLANCE = [pytest.param(c, marks=pytest.mark.xdist_group(f"glance-{c}")) for c in CATEGORIES]


@pytest.mark.parametrize("category", _GLANCE)
def test_seeds_give_visibly_different_objects(category):
    looks = {_glance(category, s)[0] for s in range(6)}
    assert len(looks) == 6, category


@pytest.mark.parametrize("category", _GLANCE)
def test_every_category_moves(category):
    """Some objects may lack every optional moving part (a pan or vase without its lid), not most."""
    counts = [_glance(category, s)[1] for s in range(12)]
    assert sum(c > 0 for c in counts) >= 4, counts
