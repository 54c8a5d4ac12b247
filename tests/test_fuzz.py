"""Property test: any category x seed x valid overrides, schema extremes included,
gives a ParameterError up front or an object that passes the USD checks and SAPIEN ``reach``.

Hypothesis draws the cases (derandomized: CI runs the same examples every time). Two budgets:
many cases generated in memory (no crash, finite bounds and joint limits), fewer written and validated
with the USD checks and SAPIEN. Raise them with ``INFMOB_FUZZ_EXAMPLES=N`` (generation) and
``INFMOB_FUZZ_SIM_EXAMPLES=N`` (full checks); ``infmob fuzz N`` runs the full property for long runs.
"""

import os

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from infmob_usd import generate, get_category, list_categories
from infmob_usd.errors import ParameterError
from infmob_usd.fuzz import check_case, draw_case, reproduce
from infmob_usd.params import Choice, Flag, Float, Int

GEN_EXAMPLES = int(os.environ.get("INFMOB_FUZZ_EXAMPLES", "100"))
SIM_EXAMPLES = int(os.environ.get("INFMOB_FUZZ_SIM_EXAMPLES", "20"))


def _value(p):
    if isinstance(p, Float):
        return st.one_of(st.just(p.low), st.just(p.high), st.floats(p.low, p.high))
    if isinstance(p, Int):
        return st.one_of(st.just(p.low), st.just(p.high), st.integers(p.low, p.high))
    if isinstance(p, Choice):
        return st.sampled_from(p.choices)
    if isinstance(p, Flag):
        return st.booleans()
    raise TypeError(type(p).__name__)


@st.composite
def cases(draw):
    category = draw(st.sampled_from(list_categories()))
    schema = get_category(category).schema
    names = draw(st.lists(st.sampled_from(schema.names), unique=True, max_size=len(schema.names)))
    overrides = {n: draw(_value(schema[n])) for n in names}
    return category, draw(st.integers(0, 10**6)), overrides


def _common(n):
    return settings(max_examples=n, deadline=None, derandomize=True, database=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@_common(GEN_EXAMPLES)
@given(cases())
def test_valid_overrides_generate_an_object_or_are_rejected_up_front(case):
    category, seed, overrides = case
    try:
        get_category(category).schema.validate(overrides)
    except ParameterError:
        return  # rejected up front: the property holds
    obj = generate(category, seed=seed, texture_size=16, **overrides)  # anything raised here is a bug
    assert obj.links and np.isfinite(obj.bounds()).all(), reproduce(case)
    for j in obj.movable_joints:
        if j.type != "continuous":
            assert np.isfinite([j.lower, j.upper]).all() and j.lower < j.upper, f"{j.name}: {reproduce(case)}"


@_common(SIM_EXAMPLES)
@given(cases())
def test_valid_overrides_give_an_object_that_passes_usd_checks_and_reach(case):
    res = check_case(case, texture_size=16, sim=True)
    assert res["outcome"] in ("valid", "rejected"), f"{res['outcome']}: {reproduce(case)}\n{res['detail']}"


def test_fuzz_draws_are_valid_seeded_and_replayable():
    rng = lambda: np.random.default_rng(5)  # noqa: E731
    a = [draw_case(rng(), list_categories()) for _ in range(1)]
    assert a == [draw_case(rng(), list_categories())]
    category, seed, overrides = a[0]
    assert get_category(category).schema.validate(overrides) == overrides
    assert reproduce(a[0]).startswith(f"infmob generate {category} --seed {seed}")
