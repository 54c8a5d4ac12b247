"""Dataset exports (infmob export / infmob_usd.export): PartNet-Mobility layout read back, loaded by SAPIEN and by
ManiSkill's PartNet-Mobility path, CAGE's train.json, GAPartNet's files, splits, resume and hostile sources."""

from __future__ import annotations

import json
import math
import os
import shutil
from pathlib import Path

import numpy as np
import pytest

import infmob_usd
from infmob_usd.cli import main
from infmob_usd.export import ExportError, export
from infmob_usd.validate.files import parse_urdf

CATEGORIES = infmob_usd.list_categories()
SEEDS = (0, 1)


@pytest.fixture(scope="module")
def src(tmp_path_factory) -> Path:
    """Every category x 2 seeds, laid out as `infmob generate` writes them (SRC/CATEGORY/NAME)."""
    root = tmp_path_factory.mktemp("export_src") / "objects"
    for c in CATEGORIES:
        for s in SEEDS:
            infmob_usd.save(infmob_usd.generate(c, s, texture_size=16), root / c)
    return root


@pytest.fixture(scope="module")
def pm(src, tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("export_pm") / "pm"
    res = export("partnet-mobility", src, out, split="train=0.5,test=0.5", workers=2)
    assert res == {"objects": len(CATEGORIES) * len(SEEDS), "exported": len(CATEGORIES) * len(SEEDS),
                   "splits": {"train": len(CATEGORIES), "test": len(CATEGORIES)}}
    return out


def _objects(out: Path) -> dict[tuple[str, int], Path]:
    found = {}
    for d in out.iterdir():
        if d.is_dir() and d.name.isdigit():
            meta = json.loads((d / "meta.json").read_text())["infmob"]
            found[meta["category"], meta["seed"]] = d
    return found


def _semantics(path: Path) -> dict[str, tuple[str, str]]:
    return {w[0]: (w[1], w[2]) for w in (line.split() for line in path.read_text().splitlines()) if w}


def _world_inertia(link, pose) -> np.ndarray:
    xx, xy, xz, yy, yz, zz = link.inertia
    rot = pose[:3, :3]
    return rot @ np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]) @ rot.T


def _check_round_trip(source: Path, dst: Path) -> None:
    meta = json.loads((dst / "meta.json").read_text())["infmob"]
    s_model = parse_urdf(next(source.glob("*.urdf")))
    e_model = parse_urdf(dst / "mobility.urdf")
    links, joints = meta["links"], meta["joints"]
    assert set(links) == set(s_model.links) and set(joints) == set(s_model.joints)
    assert len(e_model.links) == len(s_model.links) + 1 and len(e_model.joints) == len(s_model.joints) + 1
    sp, ep = s_model.poses(), e_model.poses()
    for name, j in s_model.joints.items():
        e = e_model.joints[joints[name]]
        assert (e.type, e.lower, e.upper, e.effort, e.velocity, e.damping, e.friction) == (
            j.type, j.lower, j.upper, j.effort, j.velocity, j.damping, j.friction), name
        assert (e.parent, e.child) == (links[j.parent], links[j.child])
        np.testing.assert_allclose(ep[e.child][:3, :3] @ e.unit_axis, sp[j.child][:3, :3] @ j.unit_axis, atol=1e-9)
    for name, link in s_model.links.items():
        e = e_model.links[links[name]]
        np.testing.assert_allclose(ep[e.name][:3, 3], sp[name][:3, 3], atol=1e-9)
        assert e.mass == link.mass and len(e.collisions) == len(link.collisions)
        assert len(e.visuals) == len(link.visuals)
        if link.inertia is not None:
            np.testing.assert_allclose(_world_inertia(e, ep[e.name]), _world_inertia(link, sp[name]), atol=1e-9)
    s_sem, e_sem = _semantics(source / "semantics.txt"), _semantics(dst / "semantics.txt")
    assert {links[n]: v for n, v in s_sem.items()} == e_sem
    _check_mobility_v2(dst, e_model, e_sem)


def _check_mobility_v2(dst: Path, model, sem) -> None:
    mob = json.loads((dst / "mobility_v2.json").read_text())
    assert [m["id"] for m in mob] == list(range(len(mob))) == sorted(int(n.split("_")[1]) for n in sem)
    leaves = {leaf["id"]: leaf["objs"] for node in json.loads((dst / "result.json").read_text())[0]["children"]
              for leaf in node["children"]}
    for m in mob:
        kind, label = sem[f"link_{m['id']}"]
        assert m["name"] == label and m["joint"] == ("heavy" if m["parent"] == -1 else kind)
        assert all((dst / "textured_objs" / f"{leaves[p['id']][0]}.obj").is_file() for p in m["parts"])
        if m["jointData"]:
            joint = model.joints[f"joint_{m['id']}"] if m["joint"] else None
            lim = m["jointData"]["limit"]
            if joint is not None and joint.type == "revolute" and m["joint"] == "hinge":
                assert (lim["a"], lim["b"]) == pytest.approx((math.degrees(joint.lower), math.degrees(joint.upper)))
            if joint is not None and joint.type == "prismatic" and m["joint"] == "slider":
                assert (lim["a"], lim["b"]) == (joint.lower, joint.upper)


@pytest.mark.parametrize("category", CATEGORIES)
def test_joints_limits_and_labels_read_back_equal_the_source(src, pm, category):
    objs = _objects(pm)
    for seed in SEEDS:
        name = f"{category}_{seed:06d}"
        _check_round_trip(src / category / name, objs[category, seed])


def test_layout_ids_splits_and_card(src, pm):
    objs = _objects(pm)
    ids = sorted(int(d.name) for d in objs.values())
    assert ids == list(range(200000, 200000 + len(objs)))
    for d in objs.values():
        for f in ("mobility.urdf", "mobility_cvx.urdf", "mobility_v2.json", "result.json", "semantics.txt",
                  "meta.json", "bounding_box.json"):
            assert (d / f).is_file(), f
        box = json.loads((d / "bounding_box.json").read_text())
        assert all(lo < hi for lo, hi in zip(box["min"], box["max"]))
        assert not list(d.rglob("*.usd*")) and (d / "collision").is_dir()
    splits = json.loads((pm / "splits.json").read_text())
    assert sorted(splits) == ["test", "train"] and sorted(map(int, splits["train"] + splits["test"])) == ids
    card = (pm / "DATASET.md").read_text()
    assert f"{len(objs)} articulated objects" in card and "Apache-2.0" in card
    for c in CATEGORIES:
        assert f"| {c} | 1 | 1 |" in card  # one object per split per category
    assert "| revolute |" in card and "| prismatic |" in card
    again = export("partnet-mobility", src, pm, split="train=0.5,test=0.5", workers=1)
    assert again["exported"] == 0 and json.loads((pm / "splits.json").read_text()) == splits


def _com_positions(urdf: Path, sim) -> dict[str, np.ndarray]:
    _, art = sim.load_sapien(urdf)
    art.set_qpos(np.zeros(art.dof))
    return {link.name: np.asarray((link.entity_pose * link.cmass_local_pose).p) for link in art.links}


@pytest.mark.sim
def test_sapien_loads_the_export_as_the_source(src, pm):
    pytest.importorskip("sapien")
    from infmob_usd.validate import sim

    for (category, seed), d in sorted(_objects(pm).items()):
        if seed != SEEDS[0]:  # one object per category: two SAPIEN loads each (the round trip covers both seeds)
            continue
        links = json.loads((d / "meta.json").read_text())["infmob"]["links"]
        source = next((src / category / f"{category}_{seed:06d}").glob("*.urdf"))
        a, b = _com_positions(source, sim), _com_positions(d / "mobility.urdf", sim)
        for name, new in links.items():
            np.testing.assert_allclose(b[new], a[name], atol=2e-5, err_msg=f"{d.name} {category} {name}")


@pytest.mark.sim
def test_maniskill_partnet_mobility_path_loads_the_export(pm, monkeypatch, tmp_path):
    """ManiSkill's own loader (get_articulation_builder("partnet-mobility:ID"), as OpenCabinetDrawer calls it),
    with its asset folders pointed at the export: ids from the export's info_*_train.json, URDF from DIR/ID."""
    pytest.importorskip("mani_skill")
    import sapien
    from mani_skill.envs.scene import ManiSkillScene
    from mani_skill.envs.utils.system.backend import parse_sim_and_render_backend
    from mani_skill.utils.building import articulations
    from mani_skill.utils.building.articulations import partnet_mobility as pmod

    assets = tmp_path / "ms_assets" / "partnet_mobility"
    assets.mkdir(parents=True)
    (assets / "dataset").symlink_to(pm.resolve())
    monkeypatch.setattr(pmod, "ASSET_DIR", tmp_path / "ms_assets")
    monkeypatch.setattr(pmod, "PACKAGE_ASSET_DIR", pm / "maniskill")
    monkeypatch.setattr(pmod, "PARTNET_MOBILITY", None)
    drawers = json.loads((pm / "maniskill/partnet_mobility/meta/info_cabinet_drawer_train.json").read_text())
    assert drawers and all(v["scale"] == 1.0 for v in drawers.values())
    backend = parse_sim_and_render_backend("physx_cpu", "none")
    for model_id, info in sorted(drawers.items())[:6]:
        scene = ManiSkillScene([sapien.Scene([sapien.physx.PhysxCpuSystem()])], device=backend.device,
                               backend=backend)
        builder = articulations.get_articulation_builder(scene, f"partnet-mobility:{model_id}")
        builder.initial_pose = sapien.Pose()
        art = builder.build(name=model_id)
        model = parse_urdf(pm / model_id / "mobility.urdf")
        movable = sorted(n for n, j in model.joints.items() if j.movable)
        assert sorted(j.name for j in art.active_joints) == movable
        kinds = [j.type[0] for j in art.active_joints]
        assert kinds.count("prismatic") == info["num_target_links"]
        for _ in range(5):
            scene.step()
        assert np.all(np.isfinite(art.get_qpos().cpu().numpy()))


CAGE_TYPES = {"fixed", "revolute", "prismatic", "screw", "continuous"}


@pytest.fixture(scope="module")
def small_src(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("export_small") / "objects"
    for c in ("kitchen_cabinet", "microwave", "bottle", "lamp"):
        infmob_usd.save(infmob_usd.generate(c, 0, texture_size=16), root / c)
    return root


def test_cage_train_json_follows_cage_preprocessing(small_src, tmp_path):
    out = tmp_path / "cage"
    export("cage", small_src, out, split="train=1.0")
    split = json.loads((out / "data_split.json").read_text())
    assert sorted(split["train"]) == sorted(f"{d.parent.name}/{d.name}" for d in out.glob("*/2*"))
    for model_id in split["train"]:
        d = out / model_id
        data = json.loads((d / "train.json").read_text())
        tree = data["diffuse_tree"]
        assert [n["id"] for n in tree] == list(range(len(tree))) and tree[0]["name"] == "base"
        assert data["meta"]["obj_cat"] == model_id.split("/")[0] and data["meta"]["tree_hash"]
        mob = {m["id"]: m for m in json.loads((d / "mobility_v2.json").read_text())}
        buttons = sum(1 for m in mob.values() if m["joint"] == "slider" and "button" in m["name"])
        handles = sum(1 for n in tree if n["name"] == "handle" and n["joint"]["type"] == "fixed" and n["parent"] != -1)
        assert len(tree) == len(mob) - buttons + handles
        for n in tree:
            assert n["joint"]["type"] in CAGE_TYPES and n["joint"]["range"][0] == 0
            assert all((d / o).is_file() for o in n["objs"]) and len(n["aabb"]["size"]) == 3
            if n["parent"] != -1:
                assert n["id"] in tree[n["parent"]]["children"]
        kinds = {n["joint"]["type"] for n in tree}
        if model_id.startswith("Bottle"):
            assert "continuous" in kinds  # the cap (our semantics call a turning-and-rising cap a hinge)
        if model_id.startswith("StorageFurniture"):
            assert {"revolute", "prismatic"} <= kinds and {"door", "drawer"} <= {n["name"] for n in tree}


def test_gapartnet_files(small_src, tmp_path):
    out = tmp_path / "gap"
    export("gapartnet", small_src, out)
    d = next(d for d in out.iterdir() if d.is_dir() and (d / "meta.json").is_file()
             and json.loads((d / "meta.json").read_text())["infmob"]["category"] == "kitchen_cabinet")
    annos = json.loads((d / "link_annotation_gapartnet.json").read_text())
    model = parse_urdf(d / "mobility_annotation_gapartnet.urdf")
    assert {a["link_name"] for a in annos} <= set(model.links)
    classes = {a["category"] for a in annos if a["is_gapart"]}
    assert {"hinge_door", "slider_drawer"} <= classes
    for a in annos:
        if a["is_gapart"]:
            box = np.array(a["bbox"])
            assert box.shape == (8, 3) and np.all(box[1] - box[0] > 0) is not None
    poses = model.poses()
    for a in annos:  # each box holds its link's meshes at rest, in the base (world, Z up) frame
        if not a["is_gapart"]:
            continue
        box = np.array(a["bbox"])
        lo, hi = box.min(0) - 1e-6, box.max(0) + 1e-6
        for m in model.links[a["link_name"]].visuals:
            v = np.array([[float(x) for x in line.split()[1:4]] for line in (d / m.filename).read_text().splitlines()
                          if line.startswith("v ")])
            w = v @ (poses[a["link_name"]] @ m.origin)[:3, :3].T + (poses[a["link_name"]] @ m.origin)[:3, 3]
            assert np.all(w >= lo) and np.all(w <= hi), (a["link_name"], m.filename)
    sem = _semantics(d / "semantics_gapartnet.txt")
    assert set(sem) == {a["link_name"] for a in annos}
    assert "GAPart classes" in (out / "DATASET.md").read_text()


# ----------------------------------------------------------------------------- hostile sources, bad arguments


def _one(small_src: Path, tmp_path: Path) -> Path:
    root = tmp_path / "one"
    shutil.copytree(small_src / "bottle", root / "bottle")
    return root / "bottle" / "bottle_000000"


@pytest.mark.parametrize("attack", ["mesh_outside", "mesh_symlink", "urdf_broken", "meta_not_json", "mtl_texture"])
def test_hostile_source_is_refused_with_one_line_and_nothing_written(small_src, tmp_path, capsys, attack):
    obj = _one(small_src, tmp_path)
    urdf = next(obj.glob("*.urdf"))
    secret = tmp_path / "secret.obj"
    secret.write_text("v 0 0 0\n")
    if attack == "mesh_outside":
        text = urdf.read_text()
        start = text.index('filename="meshes/') + len('filename="')
        urdf.write_text(text[:start] + "../../../secret.obj" + text[text.index('"', start):])
    elif attack == "mesh_symlink":
        mesh = sorted((obj / "meshes").glob("*.obj"))[0]
        mesh.unlink()
        mesh.symlink_to(secret)
    elif attack == "urdf_broken":
        urdf.write_text("<robot")
    elif attack == "meta_not_json":
        (obj / "metadata.json").write_text("{")
    else:
        (tmp_path / "secret.png").write_bytes(b"\x89PNG\r\n\x1a\n")
        for mtl in (obj / "meshes").glob("*.mtl"):  # a texture path out of the object folder, to a real file
            mtl.write_text("newmtl x\nmap_Kd ../../../../secret.png\n")
    out = tmp_path / "out"
    assert main(["export", "partnet-mobility", str(tmp_path / "one"), "--out", str(out), "--workers", "1"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("infmob: error: ") and "\n" not in err, err
    left = sorted(p.name for p in out.iterdir()) if out.exists() else []
    assert not [n for n in left if n.isdigit() or n.endswith(".tmp")], left  # no object, no temporary folder
    assert secret.read_text() == "v 0 0 0\n"


@pytest.mark.parametrize("args,needle", [
    (["--split", "train=0.8,val=0.1"], "sum to 0.9"),
    (["--split", "train=0.8,train=0.2"], "NAME=FRACTION"),
    (["--split", "train=x"], "NAME=FRACTION"),
])
def test_bad_split_is_refused(small_src, tmp_path, capsys, args, needle):
    out = tmp_path / "out"
    assert main(["export", "cage", str(small_src), "--out", str(out), *args]) == 2
    assert needle in capsys.readouterr().err
    assert not out.exists()


def test_out_inside_src_symlinked_src_and_empty_src_are_refused(small_src, tmp_path, capsys):
    assert main(["export", "cage", str(small_src), "--out", str(small_src / "x")]) == 2
    assert not (small_src / "x").exists()
    link = tmp_path / "link"
    link.symlink_to(small_src)
    assert main(["export", "cage", str(link), "--out", str(tmp_path / "o1")]) == 2
    (tmp_path / "empty").mkdir()
    assert main(["export", "cage", str(tmp_path / "empty"), "--out", str(tmp_path / "o2")]) == 2
    err = capsys.readouterr().err
    assert "inside SRC" in err and "symbolic link" in err and "no object folders" in err
    with pytest.raises(ExportError, match="unknown export format"):
        export("urdf", small_src, tmp_path / "o3")


def test_symlinked_object_folders_are_not_entered(small_src, tmp_path):
    root = tmp_path / "src"
    shutil.copytree(small_src / "bottle", root / "bottle")
    (root / "elsewhere").symlink_to(small_src / "microwave")
    res = export("partnet-mobility", root, tmp_path / "out")
    assert res["objects"] == 1


def test_resume_after_a_killed_run_redoes_only_what_is_missing(small_src, tmp_path):
    out = tmp_path / "out"
    export("partnet-mobility", small_src, out)
    rows = (out / "export.jsonl").read_text().splitlines()
    ids = {json.loads(r)["source"]: json.loads(r)["id"] for r in rows}
    # a run killed after publishing one object but before its row, and mid-way through the next row
    (out / "export.jsonl").write_text("\n".join(rows[:2]) + "\n" + rows[2][:20])
    victim = out / str(json.loads(rows[3])["id"])
    shutil.rmtree(victim)
    res = export("partnet-mobility", small_src, out)
    assert res["exported"] == 2 and victim.is_dir()
    again = [json.loads(r) for r in (out / "export.jsonl").read_text().splitlines()]
    assert sorted(r["source"] for r in again) == sorted(ids) and {r["source"]: r["id"] for r in again} == ids
    assert not [p for p in out.iterdir() if p.name.startswith(".") and p.name != ".infmob.lock"]
    assert os.access(out / "DATASET.md", os.R_OK)


@pytest.mark.sim
def test_gapartnet_reads_annotations_json_when_the_source_has_one(tmp_path):
    """Part and handle classes and the handle's oriented box come from annotations.json (schema v1)."""
    root = tmp_path / "objects"
    folder = Path(infmob_usd.save(infmob_usd.generate("kitchen_cabinet", 3, texture_size=16, has_handles=True),
                                  root / "kitchen_cabinet"))
    targets = json.loads((folder / "annotations.json").read_text())["targets"]
    for t in targets:  # classes and boxes the labels and meshes alone would not give: they must be read
        if t["handle_class"]:
            t["handle_class"] = "round_fixed_handle"
            t["box"]["center"] = [c + 0.01 for c in t["box"]["center"]]
    data = json.loads((folder / "annotations.json").read_text())
    (folder / "annotations.json").write_text(json.dumps({**data, "targets": targets}))
    assert any(t["handle_class"] for t in targets)
    export("gapartnet", root, tmp_path / "gap")
    d = next(p for p in (tmp_path / "gap").iterdir() if p.name.isdigit())
    names = json.loads((d / "meta.json").read_text())["infmob"]["links"]
    annos = {a["link_name"]: a for a in json.loads((d / "link_annotation_gapartnet.json").read_text())}
    model = parse_urdf(next(folder.glob("*.urdf")))
    poses = model.poses()
    handles = [a for a in annos.values() if a["category"] in ("line_fixed_handle", "round_fixed_handle")]
    for t in targets:
        assert annos[names[t["link"]]]["category"] == t["part_class"]
        if t["handle_class"]:
            pose = poses[t["link"]]
            center = pose[:3, :3] @ np.array(t["box"]["center"]) + pose[:3, 3]  # base (world) frame
            match = [h for h in handles if np.allclose(np.mean(h["bbox"], axis=0), center, atol=1e-6)]
            assert len(match) == 1 and match[0]["category"] == t["handle_class"], t["link"]
