"""Part libraries: a messy PartNet-Mobility-style source imported, the built-in parts exported,
objects generated with every retrieved part and validated in simulation, bad input refused."""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh

from infmob_usd import generate, save
from infmob_usd.categories.parts import doors, hardware, seating, tables
from infmob_usd.categories.parts import vessel as V
from infmob_usd.cli import main
from infmob_usd.partlib import import_parts, load_library
from infmob_usd.parts_tools import study, summary

# every category whose layouts attach a part retrieval can replace (a handle, knob, table leg or caster wheel
# with support points)
RETRIEVABLE = ("bar_chair", "beverage_fridge", "cocktail_table", "dining_table", "dishwasher", "door",
               "kitchen_cabinet", "microwave", "office_chair", "oven", "pan", "pot")
_N = int(os.environ.get("INFMOB_PARTS_SEEDS", "0"))
SEEDS = {"messy": range(_N or 1), "builtin": range(_N or 1)}
"""Seeds per category in the sim test: 1 with each library, to keep the test short;
``INFMOB_PARTS_SEEDS=5`` runs 5 of each (the check quoted in docs/benchmarks.md)."""


def _mesh(asm) -> trimesh.Trimesh:
    return trimesh.util.concatenate([trimesh.Trimesh(p.vertices, p.faces, process=False) for p in asm.pieces])


def _messy(mesh: trimesh.Trimesh, turn: np.ndarray, at, flip: str) -> trimesh.Trimesh:
    """Turned, moved, then made Y-up, in centimetres, with every face on its own vertices and
    some faces (or all) the wrong way round."""
    v = mesh.vertices @ turn.T + np.asarray(at, float)
    v = np.column_stack([v[:, 0], v[:, 2], -v[:, 1]]) * 100.0  # Z-up metres -> Y-up centimetres
    f = mesh.faces.copy()
    if flip == "all":
        f = f[:, ::-1]
    elif flip == "some":
        f[::3] = f[::3, ::-1]
    tri = v[f]
    return trimesh.Trimesh(tri.reshape(-1, 3), np.arange(len(f) * 3).reshape(-1, 3), process=False)


def _write_object(root: Path, oid: str, handles: list[tuple[str, trimesh.Trimesh]]) -> None:
    """One PartNet-Mobility object: a door board and its handles, links placed by joint origins that the
    visual origins cancel (as PartNet-Mobility writes them)."""
    d = root / oid
    (d / "textured_objs").mkdir(parents=True)
    board = trimesh.creation.box((2.0, 60.0, 40.0))  # already Y-up centimetres
    board.export(d / "textured_objs" / "original-1.obj")
    links = ['<link name="base"/>', '<link name="link_0"><visual><origin xyz="0 0 0"/><geometry>'
             '<mesh filename="textured_objs/original-1.obj"/></geometry></visual></link>']
    joints = ['<joint name="joint_0" type="revolute"><origin xyz="0.3 0 0"/><parent link="base"/>'
              '<child link="link_0"/><axis xyz="0 1 0"/><limit lower="0" upper="1.5"/></joint>']
    sem = ["link_0 hinge door"]
    for i, (label, mesh) in enumerate(handles, 1):
        name = f"original-{i + 1}.obj"
        mesh.export(d / "textured_objs" / name)
        links.append(f'<link name="link_{i}"><visual><origin xyz="-0.3 0 0"/><geometry>'
                     f'<mesh filename="textured_objs/{name}"/></geometry></visual></link>')
        joints.append(f'<joint name="joint_{i}" type="fixed"><origin xyz="0 0 0"/><parent link="link_0"/>'
                      f'<child link="link_{i}"/></joint>')
        sem.append(f"link_{i} fixed {label}")
    # the joint of link_0 moves it by +0.3 m (x), the handles' visual origins take it back
    (d / "mobility.urdf").write_text('<?xml version="1.0"?><robot name="cabinet">' + "".join(links + joints)
                                     + "</robot>")
    (d / "semantics.txt").write_text("\n".join(sem) + "\n")
    (d / "result.json").write_text(json.dumps([{"id": 0, "text": "Cabinet", "children": []}]))


def _rot(axis: str, deg: float) -> np.ndarray:
    return trimesh.transformations.rotation_matrix(np.radians(deg), {"x": [1, 0, 0], "y": [0, 1, 0],
                                                                      "z": [0, 0, 1]}[axis])[:3, :3]


def build_messy(root: Path) -> Path:
    """Two objects: a vertical bar pull on a door face (+X), a horizontal pull facing -Y, a lid knob, a
    door knob facing down and a pull with a fin (non-manifold: one edge of three faces), all Y-up,
    centimetres, duplicate vertices, flipped faces."""
    src = root / "pm"
    bar = _mesh(hardware.bar_handle(0.192, "m"))
    pull = _mesh(hardware.edge_pull(0.24, "m"))
    knob = _mesh(V.lid_knob(0.017, "m"))
    # mount normal local z -> +X, bar local x -> +Z: a vertical pull on a front face
    to_front = np.column_stack([[0, 0, 1], [0, -1, 0], [1, 0, 0]]).astype(float)
    _write_object(src, "7001", [("handle", _messy(bar, to_front, (0.31, 0.1, 0.5), "some")),
                                ("knob", _messy(knob, _rot("y", 90), (0.31, -0.2, 0.4), "all"))])
    finned = _mesh(hardware.bar_handle(0.128, "m"))
    a, b = finned.faces[0][:2]
    fin_v = np.vstack([finned.vertices, [[0.0, 0.0, 0.2]]])
    fin_f = np.vstack([finned.faces, [[a, b, len(fin_v) - 1]]])  # a third face on edge (a, b)
    finned = trimesh.Trimesh(fin_v, fin_f, process=False)
    door_knob = _mesh(doors.knob_part(0.029))
    _write_object(src, "7002", [("handle", _messy(pull, _rot("z", -90), (0.0, -0.3, 0.8), "all")),
                                ("handle", _messy(finned, np.eye(3), (0.31, 0.0, 0.3), "none")),
                                ("knob", _messy(door_knob, _rot("x", 180), (-0.01, 0.2, 0.9), "some"))])
    # a table and a chair base: a splayed turned leg (8 degrees off upright), a tapered leg with a 30 mm
    # hanger bolt on top (its support is the shoulder, not the bolt's end), a caster wheel on its side
    turned = _mesh(tables.leg_part("turned", 0.03, 0.70, "m", kind="dining"))
    bolt = trimesh.creation.cylinder(0.004, 0.032, sections=12,
                                     transform=trimesh.transformations.translation_matrix([0, 0, 0.38 + 0.014]))
    stud = trimesh.boolean.union([_mesh(tables.leg_part("tapered", 0.022, 0.38, "m")), bolt], engine="manifold")
    w = seating.wheels(seating.caster("single", 0.03))[0]
    tyre = w.placed(w.anchor("part_frame").inverse()).pieces[0]  # axle along z, centred
    tyre = trimesh.Trimesh(tyre.vertices, tyre.faces, process=False)
    boss = trimesh.creation.cylinder(0.012, np.ptp(tyre.vertices[:, 2]) + 0.006, sections=16)  # 3 mm proud a side
    wheel = trimesh.boolean.union([tyre, boss], engine="manifold")
    _write_object(src, "7003", [("leg", _messy(turned, _rot("x", 8), (0.2, 0.3, -0.7), "some")),
                                ("leg", _messy(stud, np.eye(3), (-0.2, 0.3, -0.4), "all")),
                                ("wheel", _messy(wheel, _rot("y", 90), (0.1, -0.2, -0.5), "some"))])
    return src


@pytest.fixture(scope="module")
def libs(tmp_path_factory):
    root = tmp_path_factory.mktemp("partlib")
    lines = []
    # no units given: the centimetre source is recognised by its part sizes (test_units_inferred_or_refused)
    messy, rejected = import_parts(build_messy(root), root / "messy", up="y", log=lines.append)
    builtin = root / "builtin"
    assert main(["parts", "export-builtin", str(builtin)]) == 0
    return {"messy": messy, "rejected": rejected, "log": lines, "builtin": builtin, "root": root}


def test_import_repairs_and_rejects(libs):
    lib = load_library(libs["messy"])
    # the non-manifold pull is refused with one line naming it and why; the seven others are in
    assert len(libs["rejected"]) == 1
    assert "7002" in libs["rejected"][0] and "non-manifold" in libs["rejected"][0]
    assert "\n" not in libs["rejected"][0]
    assert sorted((p.label, sorted(p.supports)) for p in lib.parts) == [
        ("handle", ["mount_a", "mount_b"]), ("handle", ["mount_a", "mount_b"]), ("knob", ["stem"]), ("knob", ["stem"]),
        ("leg", ["foot", "top"]), ("leg", ["foot", "top"]), ("wheel", ["axle_a", "axle_b"])]
    door_knob = next(p for p in lib.parts if p.id == "7002_link_3")
    assert abs(np.ptp(door_knob.vertices[:, 2]) - 0.056) < 1e-6  # stem foot to cap along z, the right way up
    assert door_knob.vertices[:, 2].min() == 0.0 and np.ptp(door_knob.vertices[:, 0]) > 0.05
    for p in lib.parts:
        m = trimesh.Trimesh(p.vertices, p.faces, process=False)
        # centimetres -> metres: the largest is the 240 mm pull, every part under 0.3 m; legs 0.41 and 0.70 m
        assert 0.02 < np.ptp(p.vertices, axis=0).max() < (0.75 if p.label == "leg" else 0.3)
        # duplicates merged: the repaired mesh is closed and points outward (every piece was closed)
        assert m.is_watertight and m.volume > 0
        for c in p.convex:
            assert 4 <= len(c) <= 255
        if p.label in ("leg", "wheel"):
            continue
        # support points on the mounting plane z = 0, under the part, the part above it
        for s in p.supports.values():
            assert abs(s[2] - p.vertices[:, 2].min()) < 1e-9
        assert p.vertices[:, 2].max() > 0.01
    bars = [p for p in lib.parts if p.kind == frozenset({"mount_a", "mount_b"})]
    lengths = sorted(round(float(np.ptp(p.vertices[:, 0])), 3) for p in bars)
    assert lengths == [0.192, 0.24]  # long axis found along x whatever its direction in the source
    pull = next(p for p in bars if abs(np.ptp(p.vertices[:, 0]) - 0.24) < 1e-3)
    assert abs(np.ptp(pull.vertices[:, 2]) - 0.018) < 1e-6  # depth out of the face along z
    # legs: upright (the splayed one straightened), foot on the origin, top on the z axis; the bolted leg's
    # top support at its shoulder, 30 mm under the bolt's end
    legs = {p.id: p for p in lib.parts if p.label == "leg"}
    splayed, bolted = legs["7003_link_1"], legs["7003_link_2"]
    for p in legs.values():
        assert np.abs(p.supports["foot"]).max() < 1e-9 and p.vertices[:, 2].min() == 0.0
        assert np.abs(p.supports["top"][:2]).max() < 1e-9
    assert abs(np.ptp(splayed.vertices[:, 2]) - 0.70) < 0.002 and abs(splayed.supports["top"][2] - 0.70) < 0.002
    assert abs(bolted.supports["top"][2] - 0.38) < 1e-6 and abs(bolted.vertices[:, 2].max() - 0.41) < 1e-6
    # the bolt goes into the table top: its collider is cut at the shoulder (a part joined to the top by a
    # joint would otherwise collide with it)
    assert max(c[:, 2].max() for c in bolted.convex) < 0.38 + 1e-6
    # the wheel: axle along z whatever its direction in the source, its ends on the hub faces, an axis hint
    wheel = next(p for p in lib.parts if p.label == "wheel")
    ext = np.ptp(wheel.vertices, axis=0)
    assert abs(ext[0] - 0.06) < 1e-6 and abs(ext[1] - 0.06) < 1e-6 and abs(ext[2] - 0.030) < 1e-6
    assert abs(wheel.supports["axle_b"][2] - wheel.supports["axle_a"][2] - ext[2]) < 1e-9
    assert wheel.axis is not None and abs(abs(wheel.axis[1][2]) - 1.0) < 1e-9


def test_support_points_beat_bounding_boxes(libs):
    for name in ("messy", "builtin"):
        lib = load_library(libs[name])
        rows = study(lib, 100, seed=1)
        s = summary(rows)
        assert s["support"]["placements"] == 100
        assert s["support"]["within_0.5mm"] == 100
        assert s["support"]["max_lateral_mm"] <= 1.0
        assert s["bbox"]["within_0.5mm"] < 100  # bounding boxes leave gaps or penetrations somewhere
        for label in ("leg", "wheel"):  # 100 placements of each new label on procedural legs and wheels
            s = summary(study(lib, 100, seed=1, label=label))
            assert s["support"]["placements"] == 100 and s["support"]["within_0.5mm"] == 100, (name, label, s)
            assert s["support"]["max_lateral_mm"] <= 1.0
    # the bolted leg: its box puts the bolt's end under the table top and leaves the leg 30 mm short of it
    # (scaled); its support points put the shoulder there
    s = summary(study(load_library(libs["messy"]), 100, seed=1, label="leg"))
    assert s["bbox"]["max_gap_mm"] > 10.0 and s["bbox"]["within_0.5mm"] < 100


def _digest(folder: Path) -> str:
    h = hashlib.sha256()
    for f in sorted(folder.rglob("*")):
        if f.is_file():
            h.update(f.name.encode() + f.read_bytes())
    return h.hexdigest()


def test_retrieval_is_deterministic_and_recorded(libs, tmp_path):
    a = save(generate("kitchen_cabinet", 3, 16, parts=libs["messy"], parts_share=1.0), tmp_path / "a")
    b = save(generate("kitchen_cabinet", 3, 16, parts=libs["messy"], parts_share=1.0), tmp_path / "b")
    assert _digest(a) == _digest(b)
    meta = json.loads((a / "metadata.json").read_text())
    got = meta["retrieved_parts"]
    assert got and all(r["source"].startswith("PartNet-Mobility 700") for r in got)
    assert all(r["max_support_gap_mm"] <= 0.5 for r in got)
    plain = save(generate("kitchen_cabinet", 3, 16), tmp_path / "c")
    assert "retrieved_parts" not in json.loads((plain / "metadata.json").read_text())
    none = save(generate("kitchen_cabinet", 3, 16, parts=libs["messy"], parts_share=0.0), tmp_path / "d")
    assert _digest(none) == _digest(plain)  # share 0: the procedural object, byte for byte


@pytest.mark.sim
@pytest.mark.parametrize("name", ["messy", "builtin"])
def test_generated_with_library_validate_in_sim(libs, name, tmp_path):
    out = tmp_path / "objs"
    rc = main(["generate", ",".join(RETRIEVABLE), "--count", str(len(SEEDS[name])), "--out", str(out), "--parts",
               str(libs[name]), "--parts-share", "1", "--texture-size", "16", "--workers", "2"])
    assert rc == 0
    retrieved = {}
    with_parts = []
    for m in sorted(out.glob("*/*/metadata.json")):
        got = bool(json.loads(m.read_text()).get("retrieved_parts"))
        retrieved[m.parent.parent.name] = retrieved.get(m.parent.parent.name, 0) + got
        if got:
            with_parts.append(str(m.parent))
    assert sorted(retrieved) == sorted(RETRIEVABLE)
    # many objects carry a retrieved part (not all: a dish drawer, a barn door or recessed-grip fronts have
    # no handle or knob slot, a pedestal table no leg)
    assert len(with_parts) >= len(RETRIEVABLE) // 3
    got = {r["label"] for m in with_parts for r in json.loads((Path(m) / "metadata.json").read_text())
           ["retrieved_parts"]}
    assert {"leg", "wheel"} <= got  # legs and caster wheels were retrieved somewhere
    # the others drew nothing retrievable: byte for byte the procedural objects the category tests validate
    r = subprocess.run([sys.executable, "-m", "infmob_usd", "validate", "--sim", *with_parts, "--workers", "2"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-2000:]


def _one_line_exit_2(args, capsys, nothing: Path | None = None):
    assert main(args) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("infmob: error:") and "\n" not in err, err
    if nothing is not None:
        assert not nothing.exists()
    return err


def test_bad_input(libs, tmp_path, capsys):
    out = tmp_path / "o"
    err = _one_line_exit_2(["generate", "pot", "--out", str(out), "--parts", str(tmp_path / "nope")], capsys, out)
    assert "nope" in err and "parts import" in err
    broken = tmp_path / "broken"
    shutil.copytree(libs["builtin"], broken)
    (broken / "index.json").write_text("{not json")
    err = _one_line_exit_2(["generate", "pot", "--out", str(out), "--parts", str(broken)], capsys, out)
    assert "index.json" in err and "not valid JSON" in err

    def edited(field, value, name):
        lib = tmp_path / name
        shutil.copytree(libs["builtin"], lib)
        pj = next(lib.glob("handle/*/part.json"))
        d = json.loads(pj.read_text())
        d[field] = value
        pj.write_text(json.dumps(d))
        return lib, pj

    lib, pj = edited("label", "spoon", "label")
    err = _one_line_exit_2(["generate", "pot", "--out", str(out), "--parts", str(lib)], capsys, out)
    assert str(pj) in err and "unknown label 'spoon'" in err
    lib, pj = edited("scale", {"x": [2, 1], "y": [1, 1], "z": [1, 1]}, "scale")
    err = _one_line_exit_2(["parts", "check", str(lib)], capsys)
    assert str(pj) in err and "scale.x" in err
    lib, pj = edited("units", "inch", "units")
    err = _one_line_exit_2(["generate", "pot", "--out", str(out), "--parts", str(lib)], capsys, out)
    assert "units" in err
    lib, pj = edited("mesh", "mesh.obj", "mesh")
    (pj.parent / "mesh.obj").write_bytes(b"\x00\x01garbage")
    err = _one_line_exit_2(["generate", "pot", "--out", str(out), "--parts", str(lib)], capsys, out)
    assert "mesh.obj" in err and ("unreadable" in err or "no triangles" in err)
    err = _one_line_exit_2(["generate", "pot", "--out", str(out), "--parts", str(libs["builtin"]),
                            "--parts-share", "1.5"], capsys, out)
    assert "share" in err
    # import: a source with nothing to import, an unreadable mesh in a PartNet-Mobility object
    target = tmp_path / "newlib"
    err = _one_line_exit_2(["parts", "import", str(tmp_path / "o2"), "--out", str(target)], capsys, target)
    src = tmp_path / "pm"
    shutil.copytree(libs["root"] / "pm" / "7001", src / "7001")
    (src / "7001" / "textured_objs" / "original-2.obj").write_bytes(b"\xff\xfe not a mesh")
    err = _one_line_exit_2(["parts", "import", str(src), "--out", str(target), "--units", "cm"], capsys, target)
    assert "original-2.obj" in err
    csvsrc = tmp_path / "csv"
    csvsrc.mkdir()
    trimesh.creation.box((0.1, 0.02, 0.02)).export(csvsrc / "a.obj")
    (csvsrc / "labels.csv").write_text("file,label\na.obj,teapot\n")
    err = _one_line_exit_2(["parts", "import", str(csvsrc), "--out", str(target)], capsys, target)
    assert "labels.csv" in err and "unknown label 'teapot'" in err


def test_units_inferred_or_refused(libs, tmp_path, capsys):
    # the PartNet-Mobility-style source in centimetres, imported without --units: every mesh is
    # implausible in metres (a 19.2-unit pull, a 70-unit leg) and plausible only in cm; scaled, said once
    said = [line for line in libs["log"] if "read as cm" in line]
    assert len(said) == 1 and "\n" not in said[0] and "--units" in said[0], libs["log"]
    lib = load_library(libs["messy"])
    assert max(np.ptp(p.vertices, axis=0).max() for p in lib.parts) < 0.75
    src = tmp_path / "csv"
    src.mkdir()
    target = tmp_path / "lib"

    def source(size: float, label: str = "handle"):
        trimesh.creation.box((size, size / 8, size / 8)).export(src / "a.obj")
        (src / "labels.csv").write_text(f"file,label\na.obj,{label}\n")

    # a 30-unit handle: 0.3 m in cm, 0.03 m in mm, both plausible: refused, naming --units, nothing written
    source(30.0)
    err = _one_line_exit_2(["parts", "import", str(src), "--out", str(target)], capsys, target)
    assert "--units" in err and "cm and mm" in err
    source(5000.0)  # 5 m, 50 m or 5 km: no unit makes it a handle
    err = _one_line_exit_2(["parts", "import", str(src), "--out", str(target)], capsys, target)
    assert "--units" in err and "no single unit" in err
    # a 12-unit handle is centimetres; a 0.12 one metres (unchanged, nothing said)
    for size, unit in ((12.0, "cm"), (0.12, "m")):
        source(size)
        shutil.rmtree(target, ignore_errors=True)
        assert main(["parts", "import", str(src), "--out", str(target), "--up", "z"]) == 0
        err = capsys.readouterr().err
        assert ("read as cm" in err) == (unit == "cm"), err
        assert abs(np.ptp(load_library(target).parts[0].vertices, axis=0).max() - 0.12) < 1e-6
    # --units given: taken as said, nothing inferred
    source(30.0)
    shutil.rmtree(target)
    assert main(["parts", "import", str(src), "--out", str(target), "--up", "z", "--units", "mm"]) == 0
    assert abs(np.ptp(load_library(target).parts[0].vertices, axis=0).max() - 0.03) < 1e-6


def test_generate_says_why_parts_were_skipped(libs, tmp_path, capsys):
    # a library whose parts are all 1000x too small (its part.json say mm for metre meshes): no part fits
    # any object; generate says so on stderr and in metadata.json instead of silently using none
    lib = tmp_path / "tiny"
    shutil.copytree(libs["messy"], lib)
    for pj in lib.glob("*/*/part.json"):
        pj.write_text(json.dumps({**json.loads(pj.read_text()), "units": "mm"}))
    out = tmp_path / "o"
    assert main(["generate", "dishwasher", "--seed", "1", "--out", str(out), "--parts", str(lib),
                 "--parts-share", "1", "--texture-size", "16", "--formats", "urdf"]) == 0
    err = capsys.readouterr().err
    line = next(x for x in err.splitlines() if "library parts used" in x)
    assert "used for 0 of " in line and "0 of 0" not in line and "scales to its size" in line, line
    meta = json.loads(next(out.glob("*/*/metadata.json")).read_text())
    assert "retrieved_parts" not in meta and meta["retrieval"]["used"] == 0
    assert meta["retrieval"]["retrievable"] == sum(meta["retrieval"]["skipped"].values()) > 0
    # the library as imported: parts used, counted, the rest explained
    out2 = tmp_path / "o2"
    assert main(["generate", "dishwasher", "--seed", "1", "--out", str(out2), "--parts", str(libs["messy"]),
                 "--parts-share", "1", "--texture-size", "16", "--formats", "urdf"]) == 0
    meta = json.loads(next(out2.glob("*/*/metadata.json")).read_text())
    assert meta["retrieval"]["used"] == len(meta["retrieved_parts"]) > 0
    assert f"used for {meta['retrieval']['used']} of {meta['retrieval']['retrievable']}" in capsys.readouterr().err


def test_import_mesh_folder_with_csv(tmp_path, capsys):
    """GLB and PLY files with a labels CSV: millimetres, Z-up, axes given for one, by the rule for the other."""
    src = tmp_path / "meshes"
    src.mkdir()
    bar = _mesh(hardware.bar_handle(0.128, "m"))
    bar.apply_scale(1000.0)
    bar.export(src / "pull.glb")
    knob = _mesh(hardware.knob_handle(0.016, 0.026, "m"))
    knob.apply_scale(1000.0)
    knob.export(src / "knob.ply")
    (src / "labels.csv").write_text("file,label,units,up,front,source,licence\n"
                                    "pull.glb,handle,mm,+z,+x,shop A,CC-BY-4.0\nknob.ply,handle,mm,,,,\n")
    lib = tmp_path / "lib"
    assert main(["parts", "import", str(src), "--out", str(lib), "--up", "z"]) == 0
    out = capsys.readouterr().out
    assert "2 parts" in out and "100/100 within 0.5 mm" in out
    parts = {p.id: p for p in load_library(lib).parts}
    assert set(parts) == {"pull", "knob"}
    assert parts["pull"].licence == "CC-BY-4.0" and parts["knob"].licence == "unknown"
    assert abs(np.ptp(parts["pull"].vertices[:, 0]) - 0.128) < 1e-6
    assert abs(np.ptp(parts["knob"].vertices[:, 2]) - 0.026) < 1e-6
    assert set(parts["knob"].supports) == {"stem"}
    assert main(["parts", "check", str(lib), "--placements", "20"]) == 0
    assert "support placement over 20 placements" in capsys.readouterr().out


def _wheel_joints(lib, seed=0):
    from infmob_usd.api import blueprint
    from infmob_usd.retrieval import ACTIVE, Retriever

    token = ACTIVE.set(Retriever(load_library(lib), 1.0, "office_chair", seed)) if lib else None
    try:
        bp = blueprint("office_chair", seed)
    finally:
        if token is not None:
            ACTIVE.reset(token)
    return {j.child: j.dofs[0] for j in bp.joints if j.child.startswith("wheel")}


def test_wheel_turns_about_the_mesh_axle(libs, tmp_path):
    """A wheel's joint goes through the placed mesh's own axle (its axis hint), not the procedural one."""
    plain, same = _wheel_joints(None), _wheel_joints(libs["builtin"])
    assert plain and set(plain) == set(same)
    for k, d in plain.items():  # the built-in wheels' axles are the procedural ones
        assert np.allclose(same[k].origin, d.origin, atol=1e-9) and np.allclose(same[k].axis, d.axis, atol=1e-9)
    lib = tmp_path / "offset"
    shutil.copytree(libs["builtin"], lib)
    for pj in lib.glob("wheel/*/part.json"):  # every wheel's axle 2 mm off its middle, across the axle
        d = json.loads(pj.read_text())
        d["joint_hints"]["axis"]["point"][0] += 0.002
        pj.write_text(json.dumps(d))
    moved = _wheel_joints(lib)
    for k, d in plain.items():
        off = np.subtract(moved[k].origin, d.origin)
        assert 0.001 < np.linalg.norm(off) < 0.0035  # 2 mm times the wheel's fitted scale
        assert abs(float(off @ np.asarray(d.axis))) < 1e-9  # across the axle, which keeps its direction
        assert np.allclose(np.abs(moved[k].axis), np.abs(d.axis), atol=1e-9)
