"""The Python module eccd (python/eccd_module.cpp), through pytest.

CTest runs this file (test python_module) with PYTHONPATH=<build>/python and
ECCD_SOURCE_DIR=<source>; by hand:
    PYTHONPATH=build/python python3 -m pytest tests/python
The oracle is the exact pipeline and the answers stored in cases/ (computed
exactly and re-checked by `eccd regress cases/ --certify`).
"""
import json
import math
import os
from fractions import Fraction

import pytest

import eccd

SOURCE = os.environ.get("ECCD_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def case(name):
    return os.path.join(SOURCE, "cases", name)


def overlap(a, b):
    """Two certified instants whose brackets overlap (the same root)."""
    return a.lo is not None and b.lo is not None and a.lo <= b.hi and b.lo <= a.hi


def same_answer(got, want):
    """got agrees with want: same collides, same numbers of intervals and contacts, brackets overlapping."""
    if got.collides != want.collides or len(got.intervals) != len(want.intervals) or len(got.contacts) != len(want.contacts):
        return False
    ends = all(overlap(g, w) for gi, wi in zip(got.intervals, want.intervals) for g, w in zip(gi, wi))
    return ends and all(overlap(g, w) for g, w in zip(got.contacts, want.contacts))


def instants(answer):
    out = [i for pair in answer.intervals for i in pair] + list(answer.contacts)
    if answer.first_contact is not None:
        out.append(answer.first_contact)
    return out


def test_paper003_example2_exact_matches_the_stored_answer():
    s = eccd.read_scene(case("paper003/example2.json"))
    assert s.dim == 2 and s.answer is not None
    r = eccd.solve(s, arith="exact")
    assert r.certified and r.decided and r.arith == "exact"
    assert same_answer(r, s.answer)
    # 003 section VI, Example 2: the ellipses touch once, at t = 1/2 exactly.
    assert r.collides
    assert len(r.intervals) == 1
    lo, hi = r.intervals[0]
    assert lo.lo == hi.hi == Fraction(1, 2)


def test_paper002_exact_matches_the_stored_answer():
    s = eccd.read_scene(case("paper002/example.json"))
    r = eccd.solve(s)  # exact is the default
    assert r.certified and s.dim == 3
    assert len(r.intervals) == 2 and len(r.contacts) == 4
    assert same_answer(r, s.answer)


@pytest.mark.parametrize("name", ["paper003/example2.json", "paper002/example.json"])
def test_brackets_are_fractions_that_hold_the_approximation(name):
    r = eccd.solve(eccd.read_scene(case(name)), arith="exact")
    found = instants(r)
    assert found
    for i in found:
        assert isinstance(i.lo, Fraction) and isinstance(i.hi, Fraction)
        assert isinstance(i.approx, float)
        assert i.lo <= i.hi
        # approx is the double nearest a decimal inside the bracket: within one
        # unit in the last place of [lo, hi] (brackets are narrower than a double's spacing).
        assert Fraction(math.nextafter(i.approx, -math.inf)) <= i.hi
        assert i.lo <= Fraction(math.nextafter(i.approx, math.inf))
        assert float(i) == i.approx
        assert str(i.lo) in repr(i)


def test_double_against_exact():
    # 3D, paper 002: double (Bezier method, Bernstein form) finds the same two
    # intervals, its ends close to the exact ones but not proved.
    s = eccd.read_scene(case("paper002/example.json"))
    exact = eccd.solve(s, arith="exact")
    double = eccd.solve(s, arith="double")
    assert not double.certified and double.arith == "double"
    assert double.collides == exact.collides
    assert len(double.intervals) == len(exact.intervals)
    for d, e in zip(double.intervals, exact.intervals):
        for dd, ee in zip(d, e):
            assert dd.lo is None and dd.hi is None
            assert abs(dd.approx - ee.approx) < 1e-6
    # 2D, paper 003 Example 2: a tangency double precision cannot prove; it
    # either finds the touch or says undecided, never a confident miss.
    s2 = eccd.read_scene(case("paper003/example2.json"))
    d2 = eccd.solve(s2, arith="double")
    assert d2.collides or len(d2.undecided) > 0
    m2 = eccd.solve(s2, arith="mpfr:128")
    assert m2.arith == "mpfr:128" and not m2.certified


def test_scene_from_dict_and_text_give_the_file_s_answer():
    path = case("paper003/example2.json")
    with open(path) as f:
        d = json.load(f)
    from_dict = eccd.solve(eccd.scene_from_dict(d))
    from_text = eccd.solve(eccd.scene_from_text(json.dumps(d)))
    want = eccd.read_scene(path).answer
    assert same_answer(from_dict, want) and same_answer(from_text, want)


def test_bad_file_raises_with_the_file_name(tmp_path):
    bad = tmp_path / "bad-scene.json"
    with open(case("paper003/example2.json")) as f:
        d = json.load(f)
    d["dim"] = 5
    bad.write_text(json.dumps(d))
    with pytest.raises(eccd.SceneError) as e:
        eccd.read_scene(str(bad))
    assert str(bad) in str(e.value)
    assert "/dim" in str(e.value)
    assert issubclass(eccd.SceneError, ValueError)
    missing = tmp_path / "no-such-scene.json"
    with pytest.raises(FileNotFoundError, match="no-such-scene.json"):
        eccd.read_scene(str(missing))
    with pytest.raises(eccd.SceneError, match="<dict>"):
        eccd.scene_from_dict(d)


def test_bad_options_raise_value_error():
    s = eccd.read_scene(case("paper003/example2.json"))
    with pytest.raises(ValueError):
        eccd.solve(s, arith="quad")
    with pytest.raises(ValueError):
        eccd.solve(s, arith="double", basis="chebyshev")
    with pytest.raises(ValueError):
        eccd.solve(s, variant=7)


def shifted(x, dim=2):
    """A homogeneous pose: the translation by x along the first axis."""
    n = dim + 1
    pose = [[1.0 if i == j else 0.0 for j in range(n)] for i in range(n)]
    pose[0][n - 1] = x
    return pose


@pytest.mark.parametrize("dim", [2, 3])
def test_static_status_double_agrees_with_exact_or_says_uncertain(dim):
    # An ellipse (ellipsoid) with semi-axis 2 along x at the origin, a unit
    # circle (sphere) at x: separate for x > 3, touching at x = 3, overlapping below.
    make = eccd.Ellipse if dim == 2 else eccd.Ellipsoid
    a = make([2.0, 1.0] if dim == 2 else [2.0, 1.0, 1.5])
    expect = {4.0: "separate", 3.0: "touching", 2.0: "overlapping", 3.5: "separate", 0.5: "overlapping"}
    for x, status in expect.items():
        b = make([1.0] * dim, shifted(x, dim))
        exact = eccd.static_status(a, b, arith="exact")
        assert exact == status, (x, exact)
        double = eccd.static_status(a, b)  # double is the default
        assert double in (exact, "uncertain"), (x, double)
        if status != "touching":  # far from a touch double's error bound decides
            assert double == exact, (x, double)
    with pytest.raises(ValueError):
        eccd.static_status(a, make([1.0] * dim, [[0.0] * (dim + 1)] * (dim + 1)))  # a singular pose


def test_status_at_follows_the_solution():
    s = eccd.read_scene(case("paper003/example2.json"))
    r = eccd.solve(s)
    assert eccd.status_at(s, 0) == r.status_at_0 == "separate"
    assert eccd.status_at(s, Fraction(1, 2)) == "touching"  # 003 Example 2 touches at t = 1/2
    assert eccd.status_at(s, "1/2") == "touching"
    assert eccd.status_at(s, Fraction(1, 2), arith="double") in ("touching", "uncertain")


@pytest.mark.parametrize("name", ["paper003/example2.json", "paper002/example.json"])
def test_certify_and_check_certificate_round_trip(name):
    s = eccd.read_scene(case(name))
    c = eccd.certify(s)
    assert c.solution.certified
    assert same_answer(c.solution, s.answer)
    cert = json.loads(c.text)
    assert cert["format"] == "eccd-certificate/2"
    verdict = eccd.check_certificate(s, c.text)
    assert verdict.valid and verdict
    assert verdict.checked and verdict.failed_claim == ""
    # A forged coefficient of f is rejected, naming the claim.
    cert["f"]["g"][0][0] = str(int(cert["f"]["g"][0][0]) + 1)
    forged = eccd.check_certificate(s, json.dumps(cert))
    assert not forged.valid and not forged
    assert forged.failed_claim and forged.reason
    assert "REJECTED" in repr(forged)


def test_a_certificate_checks_only_against_its_own_scene():
    s = eccd.read_scene(case("paper003/example2.json"))
    other = eccd.read_scene(case("paper003/example2-away-1e-3.json"))
    text = eccd.certify(s).text
    assert eccd.check_certificate(s, text).valid
    assert not eccd.check_certificate(other, text).valid
    with pytest.raises(eccd.SceneError, match="certificate"):
        eccd.check_certificate(s, "{ not json")


# --- judge (api/judge.hpp): any engine's answer against the certified one


def judge_data(name):
    return os.path.join(SOURCE, "tests", "data", "judge", name)


def test_judge_the_exact_answer_agrees_and_a_double_failure_differs():
    s = eccd.read_scene(case("paper003/example2-towards-1e-9.json"))
    exact = eccd.solve(s, arith="exact")
    j = eccd.judge(s, exact)
    assert j.agrees and bool(j) and j.verdict == "agrees" and j.differences == []
    assert j.certified_from == "exact pipeline"
    assert same_answer(j.certified, exact)
    # As published, double claims collision intervals where exact proves none (Example 2 moved 1e-3 away).
    away = eccd.read_scene(case("paper003/example2-away-1e-3.json"))
    published = eccd.solve(away, arith="double", guard="none")
    assert published.collides is True  # the known failure
    k = eccd.judge(away, published, name="double")
    assert not k.agrees
    assert k.verdict == "wrong collides"
    assert k.counts["collides_differs"] is True
    assert "collides: certified false, double true" in k.differences
    # Guarded (power form, 1e-9 towards touching): undecided where it proved nothing, which claims nothing
    # about collides (None): the answers differ, and it is not "wrong collides".
    guarded = eccd.solve(s, arith="double", basis="power")
    assert guarded.collides is None
    g = eccd.judge(s, guarded, name="double/power")
    assert not g.agrees
    assert g.verdict.startswith("differs: ")
    assert g.counts["collides_differs"] is False


def test_judge_takes_a_dict_json_text_and_an_answer_object():
    s = eccd.read_scene(case("spheres/spheres-crossing.json"))
    with open(judge_data("correct.json")) as f:
        text = f.read()
    d = json.loads(text)
    for answer in (d, text, eccd.answer_from_dict(d), s.answer):
        assert eccd.judge(s, answer).agrees
    d["intervals"][0][1]["approx"] = "0.869432066329737374"  # the end moved by 1e-3
    j = eccd.judge(s, d, name="mine")
    assert not j.agrees
    assert j.verdict == "differs: 1 difference(s)"
    assert j.counts["endpoints_off"] == 1
    assert math.isclose(j.counts["max_endpoint_error"], 1e-3, rel_tol=1e-6)
    assert any("end off by 0.001" in x and "mine 0.8694320663" in x for x in j.differences)
    assert eccd.judge(s, d, tol=2e-3).agrees


def test_judge_a_sampled_answer_and_the_stored_reference():
    s = eccd.read_scene(case("spheres/spheres-crossing.json"))
    with open(judge_data("fcl-sampled-spheres-crossing-10.json")) as f:
        j = eccd.judge(s, f.read(), name="fcl", use_stored=True)
    assert j.certified_from == "stored answer"
    assert not j.agrees and j.counts["endpoints_off"] == 2 and j.counts["missed_contacts"] == 2


def test_judge_bad_answer_raises_with_the_place():
    s = eccd.read_scene(case("spheres/spheres-crossing.json"))
    with open(judge_data("malformed.json")) as f:
        text = f.read()
    with pytest.raises(eccd.SceneError, match=r"<string>: /intervals/0/1"):
        eccd.judge(s, text)
    with pytest.raises(TypeError):
        eccd.judge(s, 42)
