"""The docs stay true: docs/categories.md's table and the README's list are the discovered categories,
docs/cli.md documents every flag of every command's ``--help``, the README's Python example runs and prints what
its comment says, and every relative link in the docs points at a file (and heading) that exists.

``python tests/test_docs.py`` prints docs/categories.md's table from the code."""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import re
from pathlib import Path

import pytest

import infmob_usd
from infmob_usd.cli import _parser

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
CLI_MD = ROOT / "docs" / "cli.md"
CATEGORIES_MD = ROOT / "docs" / "categories.md"
DOCS = [README, ROOT / "CHANGELOG.md", *sorted((ROOT / "docs").glob("*.md"))]


def category_table() -> list[str]:
    """docs/categories.md's rows: each discovered category with the first line of its description and the
    dataset and benchmark categories it answers (:mod:`infmob_usd.answers`)."""
    from infmob_usd.answers import answers

    return [f"| `{n}` | {infmob_usd.get_category(n).doc.split(':', 1)[-1].strip()} | {answers(n) or '(ours)'} |"
            for n in infmob_usd.list_categories()]


def test_the_category_docs_list_the_discovered_categories():
    names = infmob_usd.list_categories()
    text = CATEGORIES_MD.read_text()
    rows = [ln for ln in text.splitlines() if re.match(r"\| `[a-z_]+` \| ", ln)]
    assert rows == category_table(), "docs/categories.md's table is stale: paste `python tests/test_docs.py`"
    readme = README.read_text()
    listed = next((ln for ln in readme.splitlines() if ln.startswith("`") and " · " in ln), "")
    assert listed == " · ".join(f"`{n}`" for n in names), "README's category list is not the discovered categories"
    for doc in (text, readme):
        assert f"{len(names)} categories, discovered" in doc


def _commands(parser: argparse.ArgumentParser, prefix=()):
    """``{command path: [option strings]}`` of every (sub)command of the ``infmob`` parser."""
    out = {}
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                out[(*prefix, name)] = [s for a in sub._actions if a.help != argparse.SUPPRESS
                                        for s in a.option_strings if s not in ("-h", "--help")]
                out.update(_commands(sub, (*prefix, name)))
    return out


def _sections(text: str) -> dict[str, str]:
    parts = re.split(r"^## (\S+)\s*$", text, flags=re.M)
    return dict(zip(parts[1::2], parts[2::2]))


def test_cli_md_documents_every_flag_of_every_command():
    sections = _sections(CLI_MD.read_text())
    missing = []
    for path, flags in _commands(_parser()).items():
        section = sections.get(path[0])
        if section is None:
            missing.append(f"no '## {path[0]}' section")
            continue
        if len(path) > 1 and f"`{path[1]}" not in section:
            missing.append(f"{' '.join(path)}: the subcommand")
        for flag in flags:
            if not re.search(rf"`{re.escape(flag)}(?![\w-])", section):
                missing.append(f"{' '.join(path)} {flag}")
    assert not missing, "docs/cli.md lacks (add a row to the command's table): " + ", ".join(missing)


@pytest.mark.sim
def test_the_readme_python_example_runs_and_prints_its_comment(tmp_path):
    pytest.importorskip("sapien")
    code = re.search(r"```python\n(.*?)```", README.read_text(), re.S).group(1)
    assert len([ln for ln in code.splitlines() if ln.strip()]) == 5
    want = code.rstrip().splitlines()[-1].split("# ", 1)[1].strip()
    cwd, out = os.getcwd(), io.StringIO()
    os.chdir(tmp_path)
    try:
        with contextlib.redirect_stdout(out):
            exec(compile(code, "README.md", "exec"), {})
    finally:
        os.chdir(cwd)
    assert out.getvalue().strip().splitlines()[-1] == want
    assert (tmp_path / "out" / "kitchen_cabinet_000007" / "kitchen_cabinet_000007.usda").is_file()


def _anchor(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


@pytest.mark.parametrize("doc", DOCS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_relative_links_point_at_files_and_headings_that_exist(doc):
    bad = []
    for target in re.findall(r"\]\(([^)\s]+)\)", doc.read_text()):
        if re.match(r"[a-z]+:", target):
            continue
        file, _, anchor = target.partition("#")
        path = (doc.parent / file).resolve() if file else doc
        if not path.exists():
            bad.append(target)
        elif anchor and path.suffix == ".md":
            headings = {_anchor(h) for h in re.findall(r"^#+ (.+)$", path.read_text(), re.M)}
            if anchor not in headings:
                bad.append(target)
    assert not bad, f"{doc.name}: broken links {bad}"


if __name__ == "__main__":
    print("\n".join(category_table()))
