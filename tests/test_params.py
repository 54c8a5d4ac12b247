import numpy as np
import pytest

from infmob_usd.errors import ParameterError
from infmob_usd.params import Choice, Flag, Float, Int, Schema, parse_assignment

SCHEMA = Schema((
    Float("width", "w", "m", 1.0, 2.0),
    Float("ratio", "r", "", 0.3, 0.8, dist="loguniform"),
    Int("count", "n", "", 1, 4),
    Int("auto_count", "n", "", 1, 4, auto=True),
    Choice("style", "s", choices=("a", "b")),
    Flag("has_lid", "l", p=0.5),
))


def test_sample_is_in_range_and_deterministic():
    for seed in range(50):
        p = SCHEMA.sample(np.random.default_rng(seed))
        assert 1.0 <= p["width"] <= 2.0 and 0.3 <= p["ratio"] <= 0.8
        assert p["count"] in range(1, 5) and p["auto_count"] is None
        assert p["style"] in ("a", "b") and isinstance(p["has_lid"], bool)
        assert p == SCHEMA.sample(np.random.default_rng(seed))


def test_override_does_not_reshuffle_other_parameters():
    a = SCHEMA.sample(np.random.default_rng(7))
    b = SCHEMA.sample(np.random.default_rng(7), {"width": "1.5"})
    assert b["width"] == 1.5
    assert {k: v for k, v in a.items() if k != "width"} == {k: v for k, v in b.items() if k != "width"}


def test_overrides_are_coerced_from_cli_strings():
    got = SCHEMA.validate({"count": "3", "style": "b", "has_lid": "false", "auto_count": 2})
    assert got == {"count": 3, "style": "b", "has_lid": False, "auto_count": 2}


@pytest.mark.parametrize("name,value,needle", [
    ("width", 5, "[1, 2]"), ("width", "abc", "a number"), ("width", True, "a number"),
    ("width", float("nan"), "a number"), ("count", 2.5, "an integer in [1, 4]"), ("count", 9, "[1, 4]"),
    ("style", "c", "one of a, b"), ("has_lid", "maybe", "true or false"),
])
def test_bad_values_say_the_range(name, value, needle):
    with pytest.raises(ParameterError, match=name) as e:
        SCHEMA.validate({name: value})
    assert needle in str(e.value)


def test_unknown_parameter_lists_valid_names():
    with pytest.raises(ParameterError, match="valid parameters: width, ratio"):
        SCHEMA.validate({"widht": 1})


def test_table_lists_every_parameter():
    table = SCHEMA.table()
    for name in SCHEMA.names:
        assert name in table
    assert "logU(0.3, 0.8)" in table


def test_parse_assignment():
    assert parse_assignment("a=b=c") == ("a", "b=c")
    with pytest.raises(ParameterError, match="NAME=VALUE"):
        parse_assignment("novalue")


def test_types_are_strict_and_the_same_for_api_values_and_cli_text():
    assert SCHEMA.validate({"count": 3}) == SCHEMA.validate({"count": "3"}) == {"count": 3}
    assert SCHEMA.validate({"has_lid": True}) == SCHEMA.validate({"has_lid": "TRUE"}) == {"has_lid": True}
    for name, value in [("count", 2.0), ("count", "2.0"), ("has_lid", "off"), ("has_lid", "yes"), ("has_lid", 1),
                        ("width", None), ("width", [1.5])]:
        with pytest.raises(ParameterError, match=name):
            SCHEMA.validate({name: value})


@pytest.mark.parametrize("category", ["kitchen_cabinet", "tv", "tap"])
def test_printed_bounds_are_exact_and_accepted(category):
    """Every bound `infmob params` prints reads back as a value the schema accepts (was rounded, then rejected)."""
    import re

    from infmob_usd.api import get_category
    from infmob_usd.params import Float

    schema = get_category(category).schema
    for p in schema.params:
        if isinstance(p, Float):
            low, high = re.fullmatch(r"(?:log)?U\((.+), (.+)\)", p.describe()).groups()
            assert float(low) == p.low and float(high) == p.high
            assert schema.validate({p.name: low})[p.name] == p.low
            assert schema.validate({p.name: high})[p.name] == p.high
            assert schema.validate({p.name: round(p.high, 9)})[p.name] == p.high  # as metadata rounds
