"""The golden files: sha256 of every file that ``generate`` + ``save`` write for a few seeds of every category.

A change of output is then a reviewed diff of ``hashes.txt``, not a claim in a commit message.

    python tests/golden/golden.py            # compare, print the files that differ (exit 1 if any)
    python tests/golden/golden.py --update   # rewrite hashes.txt from the current code; review `git diff`
    python tests/golden/golden.py --dump DIR # also keep the files in DIR (for tests/golden/compare.py)

``tests/test_golden.py`` runs the comparison in CI. The bytes depend on the versions of the libraries that
write them (usd-core, OpenCV, zlib, numpy); ``make test`` installs the pinned versions in constraints.txt.
"""

from __future__ import annotations

import hashlib
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
HASHES = HERE / "hashes.txt"
SEEDS = (0, 1, 2)
TEXTURE_SIZE = 64
FORMATS = "usd,urdf,mjcf,glb"


def current(categories=None, seeds=SEEDS, keep: Path | None = None) -> dict[tuple[str, int, str], str]:
    """``{(category, seed, relative path): sha256}`` of every file written for each category and seed
    (the files kept under ``keep`` when given)."""
    import infmob_usd

    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = keep or tmp
        for category in categories or infmob_usd.list_categories():
            for seed in seeds:
                obj = infmob_usd.generate(category, seed=seed, texture_size=TEXTURE_SIZE)
                folder = infmob_usd.save(obj, Path(tmp) / f"{category}_{seed}", formats=FORMATS)
                for f in sorted(p for p in folder.rglob("*") if p.is_file()):
                    rel = f.relative_to(folder).as_posix()
                    out[(category, seed, rel)] = hashlib.sha256(f.read_bytes()).hexdigest()
    return out


def stored() -> dict[tuple[str, int, str], str]:
    out = {}
    for line in HASHES.read_text().splitlines():
        if line and not line.startswith("#"):
            category, seed, rel, digest = line.split(" ")
            out[(category, int(seed), rel)] = digest
    return out


def write(hashes: dict) -> None:
    lines = ["# category seed file sha256: written by tests/golden/golden.py --update; review changes as a diff"]
    lines += [f"{c} {s} {r} {h}" for (c, s, r), h in sorted(hashes.items())]
    HASHES.write_text("\n".join(lines) + "\n")


def differences(want: dict, got: dict) -> list[str]:
    """One line per file that is missing, new or changed, sorted."""
    lines = []
    for key in sorted(set(want) | set(got)):
        c, s, r = key
        if key not in got:
            lines.append(f"missing  {c} {s} {r}")
        elif key not in want:
            lines.append(f"new      {c} {s} {r}")
        elif want[key] != got[key]:
            lines.append(f"changed  {c} {s} {r}")
    return lines


def main(argv: list[str]) -> int:
    keep = Path(argv[argv.index("--dump") + 1]) if "--dump" in argv else None
    got = current(keep=keep)
    if "--update" in argv:
        write(got)
        print(f"wrote {len(got)} hashes to {HASHES}")
        return 0
    diff = differences(stored(), got)
    print("\n".join(diff) if diff else f"all {len(got)} files identical")
    return 1 if diff else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
