"""check(scene, certificate, label): every claim of an eccd-certificate/2 in
order, each re-derived from the scene with exact rationals; returns the
names of the claims proved, or raises Rejected at the first that fails (or
Unreadable for a scene it does not cover)."""
import json

from .algebra import Facts, check_f_claim, check_factors_claim, check_projection_multiple, check_scene_claim
from .algebra import check_vanishing_candidates, set_size_bounds, vanishes_identically
from .answer import check_answer_claim
from .continuous import continuous_touching
from .errors import reject
from .inputs import at
from .instants import check_cells_claim, check_instants_claim, check_theorem6
from .scene import read_scene
from .timeline import check_brackets_claim, check_gaps_claim, check_timeline_claim


def check_format(cert):
    if not isinstance(cert, dict) or cert.get("format") != "eccd-certificate/2":
        reject("certificate format", f"format: expected \"eccd-certificate/2\", got {json.dumps(cert.get('format') if isinstance(cert, dict) else cert)[:40]}"
               + (" (format 1 is no longer accepted: run eccd certify again)" if isinstance(cert, dict) and cert.get("format") == "eccd-certificate/1" else ""))


def check(scene_doc, cert, label):
    check_format(cert)
    H, objs = read_scene(scene_doc, label)
    check_scene_claim(scene_doc, cert, (objs[0][1], objs[1][1]), H)
    out = ["scene"]
    fx = Facts(H, check_f_claim(cert, H, objs))
    out.append("f")
    p = at(cert, "projection", "certificate")
    check_vanishing_candidates(fx, p)
    if at(p, "identically_zero", "projection") is True:
        if H != 3 or not vanishes_identically(fx, fx.k):
            reject("projection", "the projection does not vanish identically")
        return out + continuous_touching(cert, fx.g, fx.g_at, H)
    check_projection_multiple(fx, p)
    set_size_bounds(fx)
    out.append("projection")
    check_factors_claim(fx, p)
    out.append("factors")
    nodes = check_timeline_claim(fx, cert)
    out.append("timeline")
    check_brackets_claim(fx, nodes)
    out.append("brackets")
    check_gaps_claim(fx, cert, nodes)
    out.append("gaps")
    check_cells_claim(fx, nodes)
    out.append("cells")
    check_instants_claim(fx, nodes)
    out.append("instants")
    check_theorem6(fx, nodes)
    check_answer_claim(fx, cert, nodes)
    out.append("answer")
    return out
