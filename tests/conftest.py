import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))  # tests/zoo.py

_SHARED = ("module", "package", "session")


def _uses_a_shared_fixture_of_its_module(item) -> bool:
    info = getattr(item, "_fixtureinfo", None)
    if info is None:
        return False
    for defs in info.name2fixturedefs.values():
        d = defs[-1]
        if d.scope in _SHARED and getattr(d.func, "__module__", None) == item.module.__name__:
            return True
    return False


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """Under pytest-xdist's ``--dist loadgroup`` (``make test``), the tests sharing a module-scoped fixture run on
    one worker, so what the fixture builds (objects of every category, a dataset, a server) is built once; a test
    with its own ``xdist_group`` (one group per generated case) keeps it."""
    for item in items:
        if item.get_closest_marker("xdist_group") is None and _uses_a_shared_fixture_of_its_module(item):
            item.add_marker(pytest.mark.xdist_group(item.module.__name__))
