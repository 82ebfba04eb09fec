"""The Python module against the command line: every number pkmstudio gives must be the one
`pkm` prints for the same design and pose. Run by CTest (python/CMakeLists.txt) with
PYTHONPATH at the build's python/ folder and PKM naming the pkm program."""

import csv
import io
import json
import math
import os
import pydoc
import subprocess
import sys

import numpy as np
import pytest

import pkmstudio

PKM = os.environ.get("PKM", "pkm")
SOURCE_DIR = os.environ.get("PKM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def pkm(*arguments, expect=0):
    done = subprocess.run([PKM, *arguments], capture_output=True, text=True, env={**os.environ, "LC_ALL": "C.UTF-8"})
    assert done.returncode == expect, done.stderr
    return done


def pkm_json(*arguments):
    return json.loads(pkm(*arguments).stdout)


def pkm_message(*arguments, expect):
    """The sentence of a failing pkm command, without its "pkm: " prefix."""
    stderr = pkm(*arguments, expect=expect).stderr.strip()
    assert stderr.startswith("pkm: ")
    return stderr[len("pkm: "):]


def same(python, cli, path="report"):
    """Whether a report from pkmstudio equals pkm's JSON: same keys in the same order, arrays
    equal to the JSON's matrices (NaN where JSON has null), numbers equal to 1e-12."""
    if isinstance(python, np.ndarray):
        expected = np.array(cli, dtype=float)
        assert python.shape == expected.shape, path
        assert np.allclose(python, expected, rtol=1e-12, atol=1e-12, equal_nan=True), path
    elif isinstance(python, dict):
        assert isinstance(cli, dict), path
        assert list(python) == list(cli), path
        for key in python:
            same(python[key], cli[key], path + "." + key)
    elif isinstance(python, list):
        assert isinstance(cli, list) and len(python) == len(cli), path
        for i, (a, b) in enumerate(zip(python, cli)):
            same(a, b, f"{path}[{i}]")
    elif isinstance(python, float) and isinstance(cli, (int, float)):
        assert math.isclose(python, cli, rel_tol=1e-12, abs_tol=1e-12), path
    else:
        assert python == cli, path


PRESETS = [preset["id"] for preset in pkm_json("list", "--json")["presets"]]


def test_presets_and_kinds_are_those_of_pkm_list():
    listed = pkm_json("list", "--json")
    assert [(p["id"], p["mechanism"], p["title"]) for p in pkmstudio.presets()] == [
        (p["id"], p["mechanism"], p["title"]) for p in listed["presets"]
    ]
    assert [(k["id"], k["title"]) for k in pkmstudio.kinds()] == [(k["id"], k["title"]) for k in listed["mechanisms"]]


@pytest.mark.parametrize("preset", PRESETS)
def test_evaluate_gives_every_key_of_pkm_eval(preset):
    design = pkmstudio.load(preset)
    report = design.evaluate()
    cli = pkm_json("eval", preset, "--json")
    same(report, cli)
    # the vectors and matrices of the numeric groups are NumPy arrays
    for group in ("pose", "jacobian", "derived"):
        for key, value in cli[group].items():
            if isinstance(value, list) and value and not isinstance(value[0], str):
                assert isinstance(report[group][key], np.ndarray), f"{group}.{key}"
    assert design.parameters == cli["parameters"]


def test_evaluate_with_modes_and_equations():
    report = pkmstudio.load("moma-3a").evaluate(all_modes=True, equations=True)
    same(report, pkm_json("eval", "moma-3a", "--all-modes", "--equations", "--json"))


def test_at_and_solve_follow_set():
    design = pkmstudio.load("pjoint-prototype")
    same(design.at(theta=30).evaluate(), pkm_json("eval", "pjoint-prototype", "--set", "theta=30", "--json"))
    pose = design.solve(theta=30)
    assert pose["theta"] == pytest.approx(30)
    same(design.evaluate(pose), pkm_json("eval", "pjoint-prototype", "--set", "theta=30", "--json"))
    same(design.evaluate({"theta": 30}), pkm_json("eval", "pjoint-prototype", "--set", "theta=30", "--json"))
    assert list(pose) == [v["name"] for v in design.variables]
    assert set(pose.inputs) | set(pose.outputs) == set(pose.keys())


def test_with_parameters_is_set_and_leaves_the_design_alone():
    design = pkmstudio.load("moma-3a")
    wider = design.with_parameters(l1=210)
    same(wider.evaluate(), pkm_json("eval", "moma-3a", "--set", "l1=210", "--json"))
    assert design.parameters["l1"] != 210 and wider.parameters["l1"] == 210
    crossed = pkmstudio.load("oxglide-prototype").with_parameters(mode="X")
    same(crossed.evaluate(), pkm_json("eval", "oxglide-prototype", "--set", "mode=X", "--json"))
    # MOMA's modes by their words or their numbers
    corner = pkmstudio.load("moma-3c")
    words = corner.with_parameters(branch1="ahead", assembly="left")
    assert words.parameters["branch1"] == -1 and words.parameters["assembly"] == 1
    same(words.evaluate(), corner.with_parameters(branch1=-1, assembly=1).evaluate())
    assert dict(next(i for i in design.parameter_info if i["name"] == "branch1")["choices"]) == {"behind": 1, "ahead": -1}


def test_a_bad_value_raises_the_command_lines_message():
    design = pkmstudio.load("pjoint-prototype")
    with pytest.raises(ValueError) as raised:
        design.with_parameters(a=-5)
    assert str(raised.value) == pkm_message("eval", "pjoint-prototype", "--set", "a=-5", expect=2)
    with pytest.raises(ValueError) as raised:
        design.with_parameters(nonsense=1)
    assert str(raised.value) == pkm_message("eval", "pjoint-prototype", "--set", "nonsense=1", expect=2)
    with pytest.raises(ValueError, match="pose variable"):
        design.with_parameters(theta=10)
    with pytest.raises(TypeError):
        design.with_parameters(a=[1, 2])
    with pytest.raises(ValueError):
        pkmstudio.load("no-such-preset")


def test_an_unreachable_pose_raises_no_solution():
    design = pkmstudio.load("pjoint-prototype")
    with pytest.raises(pkmstudio.NoSolution) as raised:
        design.at(theta=170)
    assert isinstance(raised.value, ValueError)
    assert str(raised.value) == pkm_message("eval", "pjoint-prototype", "--set", "theta=170", expect=3)


def read_csv(text):
    rows = list(csv.reader(io.StringIO(text)))
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def assert_columns_equal(python, cli):
    assert list(python) == list(cli)
    for name, fields in cli.items():
        if name == "singularity":
            assert list(python[name]) == fields
            continue
        expected = np.array([float(f) if f else math.nan for f in fields])
        assert np.allclose(python[name], expected, rtol=1e-12, atol=1e-12, equal_nan=True), name


def evenly(start, stop, steps):
    """The values of `pkm sweep --from --to --steps`, computed as it computes them."""
    return [start if i == 0 else stop if i == steps - 1 else start + (stop - start) * (i / (steps - 1)) for i in range(steps)]


def test_a_pose_sweep_equals_the_csv():
    design = pkmstudio.load("pjoint-prototype")
    python = design.sweep("theta", evenly(-60, 60, 121))
    cli = read_csv(pkm("sweep", "pjoint-prototype", "--var", "theta", "--from", "-60", "--to", "60", "--steps", "121", "--csv").stdout)
    assert_columns_equal(python, cli)
    assert python["theta"].base is not None  # a view of the sweep's table


def test_a_parameter_sweep_equals_the_csv():
    design = pkmstudio.load("moma-3a").at(x=20, y=-250)
    python = design.sweep("l1", evenly(190, 230, 9))
    cli = read_csv(pkm("sweep", "moma-3a", "--set", "x=20", "--set", "y=-250", "--var", "l1", "--from", "190", "--to", "230",
                       "--steps", "9", "--csv").stdout)
    assert_columns_equal(python, cli)


def test_a_sweep_step_without_solution_is_named():
    with pytest.raises(pkmstudio.NoSolution) as raised:
        pkmstudio.load("pjoint-prototype").sweep("theta", [0, 50, 100])
    assert "sweep step 3 of 3 (theta = 100°)" in str(raised.value)


@pytest.mark.parametrize("preset,quantity", [("moma-3a", "det"), ("fivebar-example", "cond"), ("pp-3rrr", "range"),
                                             ("moma-3a", "force_worst")])
def test_a_map_equals_the_csv(tmp_path, preset, quantity):
    path = tmp_path / "map.csv"
    pkm("map", preset, "--quantity", quantity, "--grid", "60", "-o", str(path))
    with open(path, newline="") as file:
        rows = list(csv.DictReader(file))
    mapped = pkmstudio.load(preset).map(quantity, grid=60)
    values, margins = mapped.values, mapped.margins
    reachable = ~np.isnan(values)
    # the CSV lists the reachable cells from the bottom row up, left to right
    assert reachable.sum() == len(rows) == mapped.reachable_cells
    rows_y, columns_x = np.nonzero(reachable)
    assert np.allclose(mapped.x[columns_x], [float(r["x"]) for r in rows], rtol=1e-9)
    assert np.allclose(mapped.y[rows_y], [float(r["y"]) for r in rows], rtol=1e-9)
    expected = np.array([float(r["value"]) if r["value"] not in ("", "inf", "-inf") else math.nan for r in rows])
    finite = np.isfinite(expected)
    assert np.allclose(values[reachable][finite], expected[finite], rtol=1e-6)
    assert np.allclose(margins[reachable], [float(r["margin"]) for r in rows], rtol=1e-6, atol=1e-7)
    summary = pkm_json("map", preset, "--quantity", quantity, "--grid", "60", "--json")
    assert mapped.area == pytest.approx(summary["area"], rel=1e-12)
    assert (mapped.min, mapped.max) == pytest.approx((summary["min"], summary["max"]), rel=1e-6)


def test_a_large_map_is_not_copied():
    mapped = pkmstudio.load("moma-3a").map("det", grid=1000)
    values = mapped.values
    assert values.shape == mapped.shape and values.dtype == np.float32 and max(values.shape) == 1000
    assert values.base is mapped and not values.flags.owndata and not values.flags.writeable
    assert np.shares_memory(values, mapped.values)
    del mapped  # the array keeps the map alive
    assert np.isfinite(values).sum() > 0


def test_the_workspace_summary_is_that_of_pkm_workspace():
    for preset in ("moma-3a", "oxglide-prototype"):
        workspace = pkmstudio.load(preset).workspace(grid=200)
        summary, cli = workspace.summary, pkm_json("workspace", preset, "--grid", "200", "--json")
        summary.pop("seconds"), cli.pop("seconds")
        same(summary, cli)
        assert workspace.reachable.sum() == cli["reachable_cells"]
        assert workspace.area == cli["area"]
    with pytest.raises(ValueError) as raised:
        pkmstudio.load("pjoint-prototype").workspace()
    assert str(raised.value) == pkm_message("workspace", "pjoint-prototype", expect=2)


def test_bad_map_options_get_the_command_lines_messages():
    design = pkmstudio.load("moma-3a")
    with pytest.raises(ValueError) as raised:
        design.map("det", grid=5)
    assert str(raised.value) == pkm_message("map", "DESIGN", "--grid", "5", expect=2)
    with pytest.raises(ValueError) as raised:
        design.map("colour")
    assert str(raised.value) == pkm_message("map", "DESIGN", "--grid", "400", "--quantity", "colour", expect=2)


def test_modes_and_alternatives():
    design = pkmstudio.load("moma-3a")
    modes = design.assembly_modes()
    cli = pkm_json("eval", "moma-3a", "--all-modes", "--json")["assembly_modes"]
    assert [pose.outputs for pose in modes] == pytest.approx(cli)
    alternatives = design.mode_alternatives()
    assert alternatives, "MOMA has other working modes at its pose"
    for alternative in alternatives:
        other = alternative["design"]
        assert set(alternative["changes"]) <= set(other.parameters)
        same(other.evaluate(alternative["pose"]), other.evaluate())
    with pytest.raises(ValueError, match="another design"):
        design.evaluate(pkmstudio.load("moma-3a").pose)


def test_save_and_load_give_the_same_design(tmp_path):
    path = str(tmp_path / "wider.pkm.json")
    design = pkmstudio.load("moma-3a").with_parameters(l1=215).at(x=5, y=-260)
    design.save(path)
    same(pkmstudio.load(path).evaluate(), design.evaluate())
    same(pkmstudio.load(path).evaluate(), pkm_json("eval", path, "--json"))
    with pytest.raises(OSError):
        design.save(str(tmp_path / "no-such-folder" / "x.pkm.json"))


def test_help_is_useful():
    text = pydoc.render_doc(pkmstudio, renderer=pydoc.plaintext)
    for name in ("load", "presets", "Design", "evaluate", "sweep", "map", "NoSolution"):
        assert name in text
    assert pkmstudio.__version__ == pkm("--version").stdout.split()[1]


def test_the_example_plots_a_map(tmp_path):
    picture = tmp_path / "map.png"
    script = os.path.join(SOURCE_DIR, "examples", "plot_map.py")
    done = subprocess.run([sys.executable, script, "moma-3a", "--grid", "200", "-o", str(picture)], capture_output=True,
                          text=True, env={**os.environ, "MPLBACKEND": "Agg"})
    assert done.returncode == 0, done.stderr
    assert picture.stat().st_size > 10000
