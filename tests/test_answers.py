"""Every category of PartNet-Mobility, Infinigen-Sim, RoboCasa's articulated fixtures and the Infinite Mobility paper
is answered by a category we generate, and docs/categories.md says which answers which."""

import infmob_usd
from infmob_usd.answers import _MAP, PARTNET_MOBILITY, answers, unanswered


def test_the_union_of_the_four_lists_is_generated():
    missing = {k: v for k, v in unanswered(infmob_usd.list_categories()).items() if v}
    assert not missing, f"no category answers {missing}"


def test_every_category_is_placed_against_the_lists():
    """A new category says what it answers (or that it answers none: an empty entry), so the table stays true."""
    cats = set(infmob_usd.list_categories())
    assert cats <= set(_MAP), f"add {sorted(cats - set(_MAP))} to infmob_usd/answers.py _MAP"
    assert set(_MAP) <= cats, f"{sorted(set(_MAP) - cats)} in infmob_usd/answers.py are not categories"
    assert len(PARTNET_MOBILITY) == 46 and answers("microwave") == (
        "PartNet-Mobility Microwave; Infinigen-Sim microwave; RoboCasa microwave; Infinite Mobility")
