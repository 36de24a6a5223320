"""eccd.animate and eccd.separate (issue 17 point 4) against the command line.

The oracle is the program itself: `eccd animate FILE --json` and `eccd separate
SCENE --at T --json` on the shipped animations (cases/animations/*.json) and
shipped scenes; the module must give the same objects (the program's
"version" and the run's own times aside). The program is eccd.program():
the one installed with the package, the build tree's (<build>/eccd beside
<build>/python/eccd/), or ECCD_EXE.
"""
import copy
import glob
import json
import os
import subprocess
from fractions import Fraction

import pytest

import eccd

SOURCE = os.environ.get("ECCD_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = eccd.program()
ANIMATIONS = sorted(glob.glob(os.path.join(SOURCE, "cases", "animations", "*.json")))


def cli(*args):
    assert os.access(EXE, os.X_OK), f"the eccd program is not at {EXE} (set ECCD_EXE)"
    r = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def without_times(answer):
    """The answer without what differs from run to run: the program's version, wall and thread times."""
    a = copy.deepcopy(answer)
    a.pop("version", None)
    a.pop("seconds", None)
    for f in a.get("per_frame", []) + a.get("per_pose", []):
        f.pop("ms", None)
    return a


def test_the_shipped_animations_exist():
    names = {os.path.basename(p) for p in ANIMATIONS}
    assert {"swarm-2d.json", "two-rows-3d.json"} <= names


@pytest.mark.parametrize("path", ANIMATIONS, ids=os.path.basename)
@pytest.mark.parametrize("arith", ["double", "certified"])
def test_animate_equals_the_command_line(path, arith):
    got = eccd.animate(path, arith=arith, threads=2)
    want = cli("animate", path, "--arith", arith, "--json", "--quiet")
    assert got["format"] == "ellipse-ccd-animation-answer/1"
    assert "version" not in got
    assert isinstance(got["seconds"], float) and all(isinstance(f["ms"], float) for f in got["per_frame"])
    assert without_times(got) == without_times(want)
    # the answer does not depend on the number of threads
    assert without_times(eccd.animate(path, arith=arith, threads=1)) == without_times(got)


def test_animate_options_reach_the_pipeline():
    path = os.path.join(SOURCE, "cases", "animations", "two-rows-3d.json")
    got = eccd.animate(path, arith="double", all_intervals=True, planes=False)
    want = cli("animate", path, "--arith", "double", "--json", "--quiet", "--all-intervals", "--no-planes")
    assert without_times(got) == without_times(want)
    assert got["separating_plane_stage"] == "off"
    assert got["stages"]["separating_plane"] == 0
    with_planes = eccd.animate(path, arith="double")
    assert with_planes["separating_plane_stage"] != "off"


@pytest.mark.parametrize("arith", ["double", "certified"])
def test_animate_poses_equals_the_command_line(arith):
    path = os.path.join(SOURCE, "cases", "animations", "two-rows-3d.json")
    got = eccd.animate(path, arith=arith, poses=True)
    want = cli("animate", path, "--poses", "--arith", arith, "--json", "--quiet")
    assert got["mode"] == "poses" and got["poses"] == got["frames"] + 1
    assert without_times(got) == without_times(want)
    assert all(e["status"] in ("touching", "overlapping") for e in got["events"])
    with pytest.raises(ValueError):
        eccd.animate(path, arith="mpfr:100", poses=True)


def test_animate_errors():
    with pytest.raises(eccd.SceneError) as e:
        eccd.animate(os.path.join(SOURCE, "cases", "paper002", "example.json"))  # a scene, not an animation
    assert "example.json" in str(e.value)
    with pytest.raises(FileNotFoundError):
        eccd.animate("/nonexistent/animation.json")
    with pytest.raises(ValueError):
        eccd.animate(ANIMATIONS[0], threads=0)
    with pytest.raises(ValueError):
        eccd.animate(ANIMATIONS[0], arith="float")


SCENE = os.path.join(SOURCE, "cases", "paper002", "example.json")


@pytest.mark.parametrize("t", ["0", "1/3", "1"])
@pytest.mark.parametrize("arith", ["exact", "double"])
def test_separate_equals_the_command_line(t, arith):
    got = eccd.separate(SCENE, t, arith=arith)
    want = cli("separate", SCENE, "--at", t, "--arith", arith, "--json")
    want.pop("version")
    assert got == want
    assert got["format"] == "eccd-separate/1"
    assert got["status"] in ("separate", "touching", "overlapping", "undecided")
    if got["status"] == "separate":  # n.x + o = 0 with exact rational strings
        assert all(isinstance(Fraction(x), Fraction) for x in got["plane"]["normal"] + [got["plane"]["offset"]])


def test_separate_takes_a_scene_a_dict_and_a_fraction():
    want = eccd.separate(SCENE, "1/3")
    with open(SCENE) as f:
        d = json.load(f)
    from_dict = eccd.separate(d, Fraction(1, 3))
    from_scene = eccd.separate(eccd.read_scene(SCENE), Fraction(1, 3))
    assert from_dict["file"] == "<dict>" and from_scene["file"] == "<Scene>"
    for x in (from_dict, from_scene):
        x["file"] = want["file"]
        assert x == want


def test_separate_a_2d_scene_and_its_statuses():
    # paper 003 Example 2: the ellipses collide at t = 1/2 and are apart at t = 0
    s = os.path.join(SOURCE, "cases", "paper003", "example2.json")
    for t in ("0", "1/2"):
        got = eccd.separate(s, t)
        want = cli("separate", s, "--at", t, "--json")
        want.pop("version")
        assert got == want
    assert eccd.separate(s, "0")["status"] == "separate"
    assert eccd.separate(s, "1/2")["status"] in ("touching", "overlapping")


def test_separate_errors():
    for bad in ("3/2", "-1", "x", ""):
        with pytest.raises(ValueError):
            eccd.separate(SCENE, bad)
    with pytest.raises(TypeError):
        eccd.separate(42, "0")
    with pytest.raises(FileNotFoundError):
        eccd.separate("/nonexistent/scene.json", "0")
