"""The package a Python user gets (docs/python.md): solve on paths, dicts and
scenes, to_dict and pickling, Status, ordered Instants, contact points,
independent motions, errors in Python's words, numpy batches, scenes and
animations built in code, and CSV poses (eccd import-poses and its twin).

Oracles: the program `eccd` itself (the same JSON), the answers stored in
cases/ (computed exactly), the single-pair static test for the batch, and
motions whose collision set is known in closed form.
"""
import json
import math
import os
import pathlib
import pickle
import re
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import eccd

SOURCE = os.environ.get("ECCD_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = eccd.program()


def case(name):
    return os.path.join(SOURCE, "cases", name)


def cli(*args, check=True):
    r = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=600)
    if check:
        assert r.returncode == 0, r.stderr
    return r


def without_run(d):
    """A solution object without what differs between two runs (times, the program's version)."""
    d = dict(d)
    for k in ("time_ms", "setup_ms", "version", "seconds", "work"):
        d.pop(k, None)
    return d


def overlap(a, b):
    return a.lo is not None and b.lo is not None and a.lo <= b.hi and b.lo <= a.hi


def test_version_is_the_project_version():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        want = re.search(r"project\(eccd VERSION ([0-9.]+)", f.read()).group(1)
    assert eccd.__version__ == want
    assert eccd.solve(case("paper002/example.json")).to_dict()["version"] == want


def test_solve_takes_a_path_a_pathlike_a_dict_and_a_scene():
    path = case("paper003/example2.json")
    with open(path) as f:
        d = json.load(f)
    runs = [eccd.solve(path), eccd.solve(pathlib.Path(path)), eccd.solve(d), eccd.solve(eccd.read_scene(path))]
    dicts = [without_run(r.to_dict()) for r in runs]
    for got in dicts[1:]:
        for k in ("collides", "intervals", "first_contact", "contacts", "critical_instants"):
            assert got[k] == dicts[0][k]
    assert dicts[0]["file"] == path and dicts[2]["file"] in ("<dict>", "")
    c = eccd.certify(path)  # certify and check_certificate take the same three forms
    assert eccd.check_certificate(d, c.text).valid


@pytest.mark.parametrize("name,arith", [("paper003/example2.json", "exact"), ("touch3d/touch-and-separate.json", "exact"),
                                        ("paper002/example.json", "double"), ("independent/ellipsoids-turning.json", "exact")])
def test_to_dict_is_what_the_command_line_prints(name, arith):
    r = eccd.solve(case(name), arith=arith)
    got = r.to_dict()
    json.dumps(got)  # JSON-serialisable
    want = json.loads(cli("solve", case(name), "--arith", arith, "--json", "--quiet").stdout)
    assert got["format"] == want["format"] == "eccd-solution/1"
    assert set(got) == set(want)
    assert without_run(got) == without_run(want)


def test_guard_reaches_the_options_and_the_dict():
    s = case("paper002/example.json")
    assert eccd.solve(s, arith="double").to_dict()["guard"] == "bound"  # the default, as on the command line
    assert eccd.solve(s, arith="double", guard="none").to_dict()["guard"] == "none"
    assert eccd.solve(s, arith="double", guard="none").guard == "none"
    exact = eccd.solve(s, arith="exact")
    assert exact.to_dict()["guard"] is None and exact.guard is None  # exact and certified runs have no face
    with pytest.raises(ValueError, match="guard=maybe") as e:
        eccd.solve(s, arith="double", guard="maybe")
    assert "--guard" not in str(e.value)


def test_pickle_gives_the_same_solution():
    r = eccd.solve(case("touch3d/touch-and-separate.json"), arith="exact")
    back = pickle.loads(pickle.dumps(r))
    assert back.to_dict() == r.to_dict()
    assert repr(back) == repr(r)
    assert back.intervals == r.intervals and back.contacts == r.contacts
    d = eccd.solve(case("paper002/example.json"), arith="double", guard="none")
    assert pickle.loads(pickle.dumps(d)).to_dict()["guard"] == "none"
    i = r.contacts[0]
    assert pickle.loads(pickle.dumps(i)) == i


def test_repr_says_what_the_answer_is():
    r = eccd.solve(case("paper003/example2.json"))
    assert repr(r).startswith("Solution('example2', arith=exact, collides=True, intervals=[(Instant(0.5, [1/2, 1/2])")


def test_status_is_an_enum_and_a_str():
    a = eccd.Ellipse([2.0, 1.0])
    st = eccd.static_status(a, eccd.Ellipse([1.0, 1.0], np.array([[1, 0, 4.0], [0, 1, 0], [0, 0, 1]])))
    assert st is eccd.Status.separate and st == "separate" and isinstance(st, eccd.Status)
    assert [s.value for s in eccd.Status] == ["separate", "touching", "overlapping", "uncertain"]
    assert f"{st}" == "separate" and eccd.Status("touching") is eccd.Status.touching
    r = eccd.solve(case("paper003/example2.json"))
    assert r.status_at_0 is eccd.Status.separate
    assert all(isinstance(c[1], eccd.Status) for c in r.critical)
    assert eccd.status_at(case("paper003/example2.json"), "1/2") is eccd.Status.touching


def test_instants_are_ordered_and_fractions():
    r = eccd.solve(case("spheres/spheres-crossing.json"))
    (lo, hi), = r.intervals
    assert isinstance(lo.lo, Fraction) and isinstance(lo.hi, Fraction)
    # 1/2 -+ sqrt(139)/32: lo.lo <= 1/2 - sqrt(139)/32 <= lo.hi, checked exactly ((1/2 - x)^2 = 139/1024)
    assert lo.lo < Fraction(1, 2) and (Fraction(1, 2) - lo.lo) ** 2 >= Fraction(139, 1024) >= (Fraction(1, 2) - lo.hi) ** 2
    assert lo < hi and hi > lo and lo <= lo and not (hi < lo)
    assert sorted([hi, lo]) == [lo, hi]
    assert r.first_contact == lo and max([lo, hi]) == hi
    d = eccd.solve(case("spheres/spheres-crossing.json"), arith="double")
    assert d.intervals[0][0] < d.intervals[0][1] and d.intervals[0][0].lo is None


def test_contact_points_and_normals():
    r = eccd.solve(case("touch3d/touch-and-separate.json"))
    assert len(r.contacts) == 1 and len(r.contact_points) == 1
    c = r.contact_points[0]
    assert len(c.point) == 3 and len(c.normal) == 3
    assert math.isclose(sum(x * x for x in c.normal), 1.0, rel_tol=1e-12)
    want = json.loads(cli("solve", case("touch3d/touch-and-separate.json"), "--json", "--quiet").stdout)
    assert [float(x) for x in want["contact_points"][0]] == list(c.point)


def test_independent_motions_carry_s_and_t_intervals():
    path = case("independent/ellipsoids-turning.json")
    stored = eccd.read_scene(path).answer
    r = eccd.solve(path)
    assert r.independent and r.collides and r.intervals == []
    assert len(r.s_intervals) == len(stored.s_intervals) >= 1 and len(r.t_intervals) == len(stored.t_intervals) >= 1
    for got, want in zip(r.s_intervals + r.t_intervals, stored.s_intervals + stored.t_intervals):
        assert overlap(got[0], want[0]) and overlap(got[1], want[1])
    assert "s_intervals=[(" in repr(r)
    apart = eccd.solve(case("independent/ellipsoids-apart.json"))
    assert apart.independent and not apart.collides and apart.s_intervals == [] == apart.t_intervals


def test_missing_files_and_bad_paths(tmp_path):
    missing = tmp_path / "none.json"
    for f in (eccd.read_scene, eccd.solve, eccd.animate):
        with pytest.raises(FileNotFoundError) as e:
            f(str(missing))
        assert e.value.filename == str(missing)
    with pytest.raises(ValueError, match="NUL"):
        eccd.read_scene(case("paper002/example.json") + "\x00junk")
    with pytest.raises(TypeError):
        eccd.solve(42)
    with pytest.raises(FileNotFoundError):
        eccd.certify(str(missing))


def test_bytes_that_are_not_utf8_give_a_scene_error_naming_the_file(tmp_path):
    for i, data in enumerate([b"{\xff", b"\xff\xfe", b'{"format": "ellipse-ccd-scene/1", "name": "\xe9"}']):
        p = tmp_path / f"bad{i}.json"
        p.write_bytes(data)
        with pytest.raises(eccd.SceneError) as e:
            eccd.read_scene(str(p))
        assert str(p) in str(e.value)
    odd = os.path.join(os.fsencode(tmp_path), b"scene\xfe.json")  # a file name that is not UTF-8
    with open(case("paper002/example.json"), "rb") as f, open(odd, "wb") as g:
        g.write(f.read())
    r = eccd.solve(os.fsdecode(odd), arith="double")
    assert json.loads(json.dumps(r.to_dict()))["file"].endswith("scene\ufffd.json")
    assert pickle.loads(pickle.dumps(r)).collides == r.collides
    with pytest.raises(eccd.SceneError) as e:
        eccd.scene_from_text("{", label="a\x00b")
    assert "a\\x00b" in str(e.value)
    assert issubclass(eccd.SceneError, ValueError)


def test_time_limit_is_validated_and_defaults_to_the_command_line_s():
    s = case("paper002/example.json")
    for bad in (float("inf"), float("nan"), -1.0):
        with pytest.raises(ValueError, match="time_limit"):
            eccd.solve(s, time_limit=bad)
    assert "time_limit: float = 300.0" in eccd.solve.__doc__
    help_text = cli("--help").stdout
    assert re.search(r"--time-limit[^\n]*\n?[^\n]*300", help_text)
    assert eccd.solve(s, time_limit=0).collides == eccd.read_scene(s).answer.collides  # 0: no limit


def test_messages_use_python_keywords():
    s = case("paper002/example.json")
    for kwargs, word in [({"arith": "quad"}, "arith=quad"), ({"arith": "double", "basis": "chebyshev"}, "basis=chebyshev"),
                         ({"arith": "double", "method": "warp"}, "method=warp")]:
        with pytest.raises(ValueError) as e:
            eccd.solve(s, **kwargs)
        assert word in str(e.value) and "--" not in str(e.value), str(e.value)


# --- numpy ------------------------------------------------------------------

def random_pairs(n, dim, seed):
    rng = np.random.default_rng(seed)
    axes_a = rng.uniform(0.5, 2.0, (n, dim))
    axes_b = rng.uniform(0.5, 2.0, (n, dim))

    def poses():
        p = np.zeros((n, dim + 1, dim + 1))
        for i in range(n):
            q, _ = np.linalg.qr(rng.normal(size=(dim, dim)))
            p[i, :dim, :dim] = q
            p[i, :dim, dim] = rng.uniform(-3, 3, dim)
            p[i, dim, dim] = 1
        return p
    return axes_a, poses(), axes_b, poses()


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("arith", ["double", "exact"])
def test_static_status_batch_equals_the_single_pair_test(dim, arith):
    n = 400 if arith == "double" else 60
    aa, pa, ab, pb = random_pairs(n, dim, seed=dim)
    codes = eccd.static_status_batch(aa, pa, ab, pb, arith=arith)
    assert isinstance(codes, np.ndarray) and codes.shape == (n,) and codes.dtype == np.int8
    make = eccd.Ellipse if dim == 2 else eccd.Ellipsoid
    seen = set()
    for i in range(n):
        want = eccd.static_status(make(aa[i], pa[i]), make(ab[i], pb[i]), arith=arith)  # numpy poses as a pose
        assert eccd.status_of_code(codes[i]) is want
        seen.add(want)
    assert {eccd.Status.separate, eccd.Status.overlapping} <= seen


def test_static_status_batch_takes_other_dtypes_and_checks_shapes():
    aa, pa, ab, pb = random_pairs(20, 3, seed=7)
    want = eccd.static_status_batch(aa, pa, ab, pb)
    got = eccd.static_status_batch(aa.astype(np.float32).astype(np.float64), pa, ab.tolist(), np.asfortranarray(pb))
    assert (got == want).all()
    with pytest.raises(ValueError, match="poses_b"):
        eccd.static_status_batch(aa, pa, ab, pb[:, :3, :3])
    with pytest.raises(ValueError, match="lengths"):
        eccd.static_status_batch(aa, pa, ab[:10], pb[:10])
    bad = pb.copy()
    bad[3] = 0
    with pytest.raises(ValueError, match="3"):
        eccd.static_status_batch(aa, pa, ab, bad)
    assert eccd.static_status_batch(aa[:0], pa[:0], ab[:0], pb[:0]).shape == (0,)


# --- built in code -------------------------------------------------------------

def test_number_text_writes_what_the_program_meant():
    assert eccd.number_text(0.1) == "0.1"
    assert eccd.number_text(2.0) == "2" and eccd.number_text(-7) == "-7"
    assert eccd.number_text(1e-30) == "1e-30" and eccd.number_text(2.5e-3) == "0.0025"
    assert eccd.number_text(Fraction(1, 3)) == "1/3" and eccd.number_text("6/4") == "1.5"
    assert eccd.number_text(np.float64(0.3)) == "0.3" and eccd.number_text(np.int64(5)) == "5"
    for bad in (float("nan"), float("inf")):
        with pytest.raises(ValueError):
            eccd.number_text(bad)


def test_scene_from_motions_equals_the_file():
    # cases/spheres/spheres-crossing.json, written in code with floats
    from eccd import motions
    s = eccd.Scene.from_motions([1, 1, 1], motions.matrix([[1, 0, 0, [-4.0, 8.0]], [0, 1, 0, 0.5], [0, 0, 1, 0.25], [0, 0, 0, 1]]),
                                np.array([2.0, 2.0, 2.0]), motions.static(), name="built")
    stored = eccd.read_scene(case("spheres/spheres-crossing.json")).answer
    r = eccd.solve(s)
    assert r.collides and len(r.intervals) == 1
    assert overlap(r.intervals[0][0], stored.intervals[0][0]) and overlap(r.intervals[0][1], stored.intervals[0][1])
    k = eccd.Scene.from_motions([2, 1], motions.kinematic([0, [-3.0, 6.0], 1, 0]), [1, 1], motions.static())
    assert k.dim == 2
    with pytest.raises(eccd.SceneError, match="Scene.from_motions"):
        eccd.Scene.from_motions([1, 1, 1], motions.static(), [1, -1, 1], motions.static())


# --- animations: keyframes, CSV, the program --------------------------------

TIMES = [0.0, 0.5, 1.0]
X = [-3.0, 0.0, 3.0]  # a unit sphere along x through a unit sphere at rest: they meet for |x| <= 2, t in [1/6, 5/6]
TURN = [[1.0, 0.0, 0.0, 0.0], [0.9, 0.1, 0.2, 0.3], [0.5, 0.5, 0.5, 0.5]]


def keyframe_bodies():
    return [{"name": "mover", "group": "g1", "semi_axes": [1.0, 1.0, 1.0], "positions": np.array([[x, 0.0, 0.0] for x in X]),
             "quaternions": np.array(TURN)},
            {"name": "rest", "group": "g2", "semi_axes": [1, 1, 1], "positions": np.zeros((3, 3)),
             "quaternions": np.array([[1.0, 0, 0, 0]] * 3)}]


def write_csv_and_shapes(tmp_path):
    rows = ["time, body, x, y, z, qw, qx, qy, qz"]
    for k, t in enumerate(TIMES):  # floats written by repr, as Python's csv module writes them
        rows.append(",".join(map(str, [repr(t), "mover", repr(X[k]), 0.0, 0.0, *map(repr, TURN[k])])))
        rows.append(",".join(map(str, [repr(t), "rest", 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0])))
    csv = tmp_path / "poses.csv"
    csv.write_text("\n".join(reversed(rows[1:])) + "\n")  # any order of lines
    shapes = tmp_path / "shapes.json"
    shapes.write_text(json.dumps({"name": "animation", "dim": 3, "bodies": [
        {"name": "mover", "group": "g1", "shape": {"semi_axes": ["1", "1", "1"]}},
        {"name": "rest", "group": "g2", "shape": {"semi_axes": ["1", "1", "1"]}}]}))
    return csv, shapes


def test_keyframes_csv_and_the_program_write_the_same_file(tmp_path):
    built = eccd.Animation.from_keyframes(TIMES, keyframe_bodies())
    csv, shapes = write_csv_and_shapes(tmp_path)
    from_csv = eccd.import_poses(csv, shapes, out=tmp_path / "py.json")
    out = tmp_path / "cli.json"
    cli("import-poses", str(csv), "--shapes", str(shapes), "--out", str(out))
    assert built.to_json() == from_csv.to_json() == out.read_text() == (tmp_path / "py.json").read_text()
    d = built.to_dict()
    assert d["format"] == "ellipse-ccd-animation/1" and d["times"] == ["0", "0.5", "1"]
    assert d["bodies"][0]["poses"][1]["orientation"] == ["0.9", "0.1", "0.2", "0.3"]
    assert built.times == [0, Fraction(1, 2), 1] and built.bodies == ["mover", "rest"] and built.dim == 3


def test_the_imported_animation_is_answered(tmp_path):
    csv, shapes = write_csv_and_shapes(tmp_path)
    out = tmp_path / "anim.json"
    cli("import-poses", str(csv), "--shapes", str(shapes), "--out", str(out))
    got = eccd.animate(str(out), arith="exact", all_intervals=True)
    want = json.loads(cli("animate", str(out), "--arith", "exact", "--all-intervals", "--json", "--quiet").stdout)
    assert [e["answer"] for e in got["events"]] == [e["answer"] for e in want["events"]]
    assert [e["frame"] for e in got["events"]] == [0, 1]
    (s, e0), = got["events"][0]["answer"]["intervals"]
    (s1, e1), = got["events"][1]["answer"]["intervals"]
    assert Fraction(s["lo"]) <= Fraction(1, 6) <= Fraction(s["hi"])
    assert Fraction(e1["lo"]) <= Fraction(5, 6) <= Fraction(e1["hi"])
    assert Fraction(e0["lo"]) == Fraction(1, 2) == Fraction(s1["hi"])
    built = eccd.animate(eccd.Animation.from_keyframes(TIMES, keyframe_bodies()), arith="exact", all_intervals=True)
    assert [e["answer"] for e in built["events"]] == [e["answer"] for e in got["events"]]


def test_2d_angles_in_csv_and_keyframes(tmp_path):
    angles = [0.0, 0.3, 1.2]
    bodies = [{"name": "a", "semi_axes": [2.0, 1.0], "positions": [[-4.0, 0.0], [0.0, 0.0], [4.0, 0.0]], "angles": angles},
              {"name": "b", "semi_axes": [1.0, 1.0], "positions": [[0.0, 0.5]] * 3, "angles": [0.0] * 3}]
    built = eccd.Animation.from_keyframes([0, 1, 2], bodies, name="flat")
    csv = tmp_path / "p.csv"
    csv.write_text("".join(f"{t},a,{x!r},0,{th!r}\n{t},b,0,0.5,0\n" for t, x, th in zip([0, 1, 2], [-4.0, 0.0, 4.0], angles)))
    shapes = tmp_path / "s.json"
    shapes.write_text(json.dumps({"name": "flat", "dim": 2, "bodies": [{"name": "a", "shape": {"semi_axes": ["2", "1"]}},
                                                                      {"name": "b", "shape": {"semi_axes": ["1", "1"]}}]}))
    assert eccd.import_poses(csv, shapes).to_json() == built.to_json()
    w, z = map(float, built.to_dict()["bodies"][0]["poses"][1]["orientation"])
    assert math.isclose(2 * math.atan2(z, w), 0.3, rel_tol=1e-15)


def test_csv_errors_name_the_line_and_the_column(tmp_path):
    _, shapes = write_csv_and_shapes(tmp_path)
    bad = tmp_path / "bad.csv"
    cases_ = [("0,mover,0,0,0,1,0,0,0\n0,rest,0,0,0,1,0,0,0\n1,mover,0,0,x,1,0,0,0\n", r"line 3, column 5 \(z\)"),
              ("0,mover,0,0,0,1,0,0,0\n0,rest,0,0\n", r"line 2: expected 9 columns"),
              ("0,mover,0,0,0,1,0,0,0\n0,ghost,0,0,0,1,0,0,0\n", r"line 2, column 2 \(body\): \"ghost\""),
              ("0,mover,0,0,0,1,0,0,0\n0,rest,0,0,0,1,0,0,0\n1,mover,0,0,0,1,0,0,0\n", r"\"rest\" has no pose at time 1"),
              ("0,mover,0,0,0,1,0,0,0\n0,mover,0,0,0,1,0,0,0\n", r"line 2: body \"mover\" at time 0 again \(its pose is on line 1\)"),
              ("0,mover,0,0,0,0,0,0,0\n", r"line 1, columns 6-9"),
              ("0,mover,0,0,0,nan,0,0,0\n", r"line 1, column 6 \(qw\)")]
    for text, pattern in cases_:
        bad.write_text(text)
        with pytest.raises(eccd.SceneError, match=pattern) as e:
            eccd.import_poses(bad, shapes)
        assert str(bad) in str(e.value)
        r = cli("import-poses", str(bad), "--shapes", str(shapes), check=False)
        assert r.returncode == 2 and re.search(pattern, r.stderr), r.stderr
    with pytest.raises(FileNotFoundError):
        eccd.import_poses(tmp_path / "none.csv", shapes)
    bad_shapes = tmp_path / "bad-shapes.json"
    bad_shapes.write_text('{"dim": 3, "bodies": [{"name": "a", "shape": {"semi_axes": ["1", "0", "1"]}}, {"name": "b", "shape": {"semi_axes": ["1", "1", "1"]}}]}')
    with pytest.raises(eccd.SceneError, match=r"bad-shapes.json: /bodies/0/shape"):
        eccd.import_poses(bad, bad_shapes)


def test_keyframe_errors_name_the_body_and_the_row():
    b = keyframe_bodies()
    b[0]["positions"] = b[0]["positions"][:2]
    with pytest.raises(ValueError, match=r"bodies\[0\]: positions has 2 rows for 3 times"):
        eccd.Animation.from_keyframes(TIMES, b)
    b = keyframe_bodies()
    b[1]["quaternions"] = np.array([[1.0, 0, 0, 0], [float("nan"), 0, 0, 0], [1.0, 0, 0, 0]])
    with pytest.raises(ValueError, match=r"bodies\[1\]\.quaternions\[1\]\[0\]"):
        eccd.Animation.from_keyframes(TIMES, b)
    with pytest.raises(eccd.SceneError, match="times"):
        eccd.Animation.from_keyframes([0.0, 0.0, 1.0], keyframe_bodies())


def test_pair_frame_scene_is_what_animate_solves():
    anim = eccd.Animation.from_keyframes(TIMES, keyframe_bodies())
    scene = anim.pair_frame_scene("mover", "rest", 0)  # frame [0, 1/2] in local time: x = -3 + 3 tau, |x| <= 2 for tau >= 1/3
    r = eccd.solve(scene)
    (start, end), = r.intervals
    assert start.lo <= Fraction(1, 3) <= start.hi and end.lo == end.hi == 1
    with pytest.raises(ValueError, match="frame=2"):
        anim.pair_frame_scene("mover", "rest", 2)
    with pytest.raises(ValueError, match="ghost"):
        anim.pair_frame_scene("mover", "ghost", 0)


def test_fcl_is_the_program_s_and_judge_takes_it():
    path = case("paper002/example.json")
    got = eccd.fcl(path, samples=10)
    want = json.loads(cli("fcl", path, "--samples", "10", "--json", "--quiet").stdout)["answer"]
    assert got.to_dict() == want
    verdict = eccd.judge(path, got, name="fcl/sample:10")
    by_cli = subprocess.run([EXE, "judge", path, "-", "--name", "fcl/sample:10", "--json"], input=json.dumps(want),
                            capture_output=True, text=True, timeout=600)
    assert not verdict.agrees  # ten samples miss the ends of the certified intervals by more than 1e-6
    assert by_cli.returncode == 1 and json.loads(by_cli.stdout)["verdict"] == verdict.verdict
    with pytest.raises(ValueError, match="samples=0"):
        eccd.fcl(path, samples=0)


def test_a_run_past_its_time_limit():
    # A limit of a nanosecond has passed by the pipeline's first look at the clock, however fast the machine.
    s = case("paper002/example.json")
    with pytest.raises(TimeoutError, match="time budget"):
        eccd.solve(s, arith="exact", time_limit=1e-9)
    d = eccd.solve(s, arith="double", time_limit=1e-9)  # a floating run says what it could not decide
    assert d.undecided and any("time budget" in r for r in d.undecided_reasons)


def test_import_poses_replaces_only_regular_files(tmp_path):
    csv, shapes = write_csv_and_shapes(tmp_path)
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    target = tmp_path / "kept.json"
    target.write_text("decoy")
    link = tmp_path / "link.json"
    link.symlink_to(target)
    for out in (fifo, link, csv, shapes):
        r = cli("import-poses", str(csv), "--shapes", str(shapes), "--out", str(out), check=False)
        assert r.returncode == 2 and str(out) in r.stderr, r.stderr
    assert fifo.is_fifo() and link.is_symlink() and target.read_text() == "decoy"
    assert csv.read_text().count("\n") == 6
