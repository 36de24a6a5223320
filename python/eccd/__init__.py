"""eccd: exact continuous collision detection of moving ellipses and ellipsoids.

    import eccd
    r = eccd.solve("cases/paper003/example2.json", arith="exact")   # a path, a dict in the scene format, or a Scene
    r.collides, r.intervals, r.first_contact, r.contacts              # instants: .approx (float), .lo / .hi (Fraction)
    r.to_dict()                                                       # the object `eccd solve --json` prints

The compiled core is eccd._eccd (python/eccd_module.cpp over the C++ API);
this file re-exports it and adds the builders that are only conversions:
scenes from motions (Scene.from_motions, eccd.motions) and the status codes
of static_status_batch. docs/python.md is the guide.
"""
from __future__ import annotations

import os
import sys
from typing import Any, Iterable, Mapping, Optional, Sequence, Union

from . import _eccd
from ._eccd import (  # noqa: F401
    Animation,
    Answer,
    Certificate,
    CertificateCheck,
    CertificationError,
    ContactPoint,
    Ellipse,
    Ellipsoid,
    Instant,
    Judgement,
    Scene,
    SceneError,
    Solution,
    Status,
    __version__,
    animate,
    answer_from_dict,
    certify,
    check_certificate,
    fcl,
    judge,
    number_text,
    read_scene,
    scene_from_dict,
    scene_from_text,
    separate,
    solve,
    static_status,
    static_status_batch,
    status_at,
)
from . import motions  # noqa: F401

__all__ = [
    "Animation", "Answer", "Certificate", "CertificateCheck", "CertificationError", "ContactPoint", "Ellipse",
    "Ellipsoid", "Instant", "Judgement", "Scene", "SceneError", "Solution", "Status", "STATUS_CODES", "__version__",
    "animate", "answer_from_dict", "certify", "check_certificate", "fcl", "import_poses", "judge", "motions", "number_text",
    "program", "read_scene", "scene_from_dict", "scene_from_text", "separate", "solve", "static_status",
    "static_status_batch", "status_at", "status_of_code",
]

#: The codes static_status_batch returns, as Status members (the C++ enum's values).
STATUS_CODES = {code: Status(name) for code, name in _eccd._status_codes}


def status_of_code(code: int) -> Status:
    """The Status of one code of static_status_batch's array."""
    return STATUS_CODES[int(code)]


def import_poses(poses: Union[str, os.PathLike], shapes: Union[str, os.PathLike],
                 out: Optional[Union[str, os.PathLike]] = None) -> Animation:
    """A CSV of poses and a shapes file as an Animation: `eccd import-poses POSES --shapes SHAPES [--out OUT]`
    (docs/import-poses.md). With out, the animation file is written there too."""
    anim = Animation.from_csv(poses, shapes)
    if out is not None:
        with open(out, "w", encoding="utf-8") as f:
            f.write(anim.to_json())
    return anim


def _exact(x: Any, key: Optional[str] = None) -> Any:
    """Numbers of a scene dict as the format's exact strings (floats by repr); the motion's "type" kept."""
    if key == "type":
        return x
    if isinstance(x, Mapping):
        return {k: _exact(v, k) for k, v in x.items()}
    if isinstance(x, (list, tuple)) or hasattr(x, "tolist"):
        seq = x.tolist() if hasattr(x, "tolist") else x
        if not isinstance(seq, list):  # a numpy scalar
            return number_text(seq)
        return [_exact(v) for v in seq]
    return number_text(x)


def _shape(shape: Any) -> dict:
    if isinstance(shape, Mapping):
        return _exact(shape)
    return {"semi_axes": _exact(shape)}


def _from_motions(a_shape: Any, a_motion: Mapping, b_shape: Any, b_motion: Mapping, name: str = "scene",
                  note: Optional[str] = None, parameters: Optional[str] = None) -> Scene:
    """A scene built in code: each object's shape (semi-axes as a sequence, or a shape dict of the scene format)
    and motion (a dict of the scene format; eccd.motions builds them). Numbers may be ints, floats (written by
    their shortest round-trip decimal: 0.1 is 1/10), Fractions or number strings; the scene reader checks the
    result as it checks a file (SceneError naming "<Scene.from_motions>" and the place)."""
    a, b = _shape(a_shape), _shape(b_shape)
    first = next(iter(a.values()))
    dim = len(first) if "matrix" not in a else len(first) - 1
    d = {"format": "ellipse-ccd-scene/1", "name": name, "dim": dim,
         "a": {"shape": a, "motion": _exact(a_motion)}, "b": {"shape": b, "motion": _exact(b_motion)}}
    if note is not None:
        d["note"] = note
    if parameters is not None:
        d["parameters"] = parameters
    return scene_from_dict(d, "<Scene.from_motions>")


Scene.from_motions = staticmethod(_from_motions)


def program() -> str:
    """The path of the command line program eccd that came with this package (or the build tree's)."""
    here = os.path.dirname(os.path.abspath(__file__))
    for p in (os.environ.get("ECCD_EXE"), os.path.join(here, "bin", "eccd"),
              os.path.join(os.path.dirname(os.path.dirname(here)), "eccd")):
        if p and os.access(p, os.X_OK) and os.path.isfile(p):
            return p
    raise FileNotFoundError("the program eccd is not installed with this package (set ECCD_EXE to its path)")


def _main() -> None:
    """The console script `eccd`: the program that came with the package."""
    exe = program()
    os.execv(exe, [exe, *sys.argv[1:]])
