"""The answer claim: the collision intervals, the first contact, the isolated
contacts and the contact intervals assembled here from the checked timeline,
and the certificate's answer compared with them (brackets exactly, each
approximation inside its bracket)."""
from .errors import reject
from .inputs import at, check_approx, rational

ANSWER_KEYS = {"collides", "intervals", "first_contact", "contacts", "contact_intervals"}


def assemble_answer(nodes):
    """Returns (intervals, contacts, contact intervals), each as brackets (lo, hi)."""
    inc = lambda i: nodes[i]["status"] != "separate"
    tcell = lambda i: i < len(nodes) and nodes[i]["cell"] and nodes[i]["status"] == "touching"
    br = lambda i: (nodes[i]["lo"], nodes[i]["hi"])
    for i in range(1, len(nodes), 2):
        if inc(i) and not (inc(i - 1) and inc(i + 1)):
            reject("timeline", f"{nodes[i]['name']} is in collision next to a separate instant")
    intervals, contacts, cints, i = [], [], [], 0
    while i < len(nodes):
        if tcell(i):
            e = i
            while tcell(e + 2) and nodes[e + 1]["status"] == "touching":
                e += 2
            cints.append((br(i - 1), br(e + 1)))
            i = e
        i += 1
    for i in range(0, len(nodes), 2):
        if nodes[i]["status"] == "touching" and not tcell(i + 1) and not (i > 0 and tcell(i - 1)):
            contacts.append(br(i))
    i = 0
    while i < len(nodes):
        if inc(i):
            e = i
            while e + 1 < len(nodes) and inc(e + 1):
                e += 1
            intervals.append((br(i), br(e)))
            i = e
        i += 1
    return intervals, contacts, cints


def check_answer_claim(fx, cert, nodes):
    intervals, contacts, cints = assemble_answer(nodes)
    ans = at(cert, "answer", "certificate")
    if not isinstance(ans, dict) or set(ans) - ANSWER_KEYS:
        reject("certificate format", "answer: unknown keys")

    def inst(j, place, want):
        if not isinstance(j, dict) or set(j) - {"approx", "lo", "hi"}:
            reject("certificate format", f"{place}: an instant has the keys approx, lo, hi only")
        lo, hi = rational(at(j, "lo", place), place + ".lo", fx.max_bits), rational(at(j, "hi", place), place + ".hi", fx.max_bits)
        if (lo, hi) != want:
            reject("answer", f"{place}: the instant differs from the checked timeline's")
        check_approx(at(j, "approx", place), lo, hi, "answer", place + ".approx", fx.approx_chars)

    if at(ans, "collides", "answer") is not bool(intervals):
        reject("answer", f"answer.collides must be {str(bool(intervals)).lower()}")
    for key, want in (("intervals", intervals), ("contact_intervals", cints)):
        lst = ans.get(key, [] if key == "contact_intervals" else None)
        if not isinstance(lst, list) or len(lst) != len(want) or not all(isinstance(x, list) and len(x) == 2 for x in lst):
            reject("answer", f"answer.{key}: the checked timeline gives {len(want)}")
        for i, (x, w) in enumerate(zip(lst, want)):
            inst(x[0], f"answer.{key}[{i}][0]", w[0])
            inst(x[1], f"answer.{key}[{i}][1]", w[1])
    fc = at(ans, "first_contact", "answer")
    if (fc is None) != (not intervals):
        reject("answer", "first_contact must be the start of the first interval, or null")
    if intervals:
        inst(fc, "answer.first_contact", intervals[0][0])
    cs = at(ans, "contacts", "answer")
    if not isinstance(cs, list) or len(cs) != len(contacts):
        reject("answer", f"answer.contacts: the checked timeline gives {len(contacts)}")
    for i, (x, w) in enumerate(zip(cs, contacts)):
        inst(x, f"answer.contacts[{i}]", w)
