"""The array API: NumPy arrays of doubles in, verdicts out, on every core (docs/python.md, "Arrays").

Each value is taken as the EXACT BINARY DOUBLE it holds (0.1 is 3602879701896397/36028797018963968), which
is what array users mean; this differs from the scene format's rule (and wrenchkit.Scene's), where a
number is read from its decimal text. Row for row, the answers are those of wrenchkit.closure,
equilibrium and limit_surface on scenes built with Fraction(x) of the same doubles: the rows go through the
same pipeline, on `jobs` threads (default: every core) with the GIL released.

Bad arrays (shape, dtype, NaN, infinities, a zero normal, a negative mu or force, a count out of range)
raise ValueError naming the row, the contact and the value; nothing is computed before they are checked.
"""

import json as _json
import numbers as _numbers

import numpy as _np

from . import _core

# Codes of the integer result arrays.
DECIDED_BY = {0: "float", 1: "hybrid", 2: "exact", -1: "undecided"}
MOTION = {1: "sticks", 0: "slides", 2: "impending", -1: "undecided"}
MOTION_DECIDED_BY = {0: "float", 1: "polygons", 2: "flat", 3: "certificate", 4: "newton", -1: "none"}


def _doubles(name, a, shape):
    """`a` as a C-contiguous float64 array of `shape` (None: any length), each value exactly as given."""
    x = _np.asarray(a)
    if x.dtype == _np.bool_ or not (_np.issubdtype(x.dtype, _np.floating) or _np.issubdtype(x.dtype, _np.integer)):
        raise ValueError(f"{name}: dtype {x.dtype} is not a real floating-point or integer type")
    if x.ndim != len(shape) or any(s is not None and s != n for s, n in zip(shape, x.shape)):
        want = "(" + ", ".join("any" if s is None else str(s) for s in shape) + ")"
        raise ValueError(f"{name}: shape {x.shape} is not {want}")
    if x.dtype.itemsize > 8 and _np.issubdtype(x.dtype, _np.floating):
        raise ValueError(f"{name}: dtype {x.dtype} is wider than a double (its values would be rounded)")
    y = _np.ascontiguousarray(x, dtype=_np.float64)
    if _np.issubdtype(x.dtype, _np.integer):
        bad = y.astype(x.dtype) != x
        if bad.any():
            i = tuple(int(k) for k in _np.argwhere(bad)[0])
            raise ValueError(f"{name}{list(i)}: {x[i]} is not exactly a double")
    return y


def _where(name, mask, values, what, width=None):
    """ValueError at the first True of mask (rows × contacts [× coordinate]): row, contact and value."""
    if not mask.any():
        return
    i = tuple(int(k) for k in _np.argwhere(mask)[0])
    at = f"row {i[0]}" + (f", contact {i[1]}" if len(i) > 1 else "") + (f", coordinate {i[2]}" if len(i) > 2 else "")
    v = values[i]
    v = tuple(float(x) for x in v) if isinstance(v, _np.ndarray) else v.item() if isinstance(v, _np.generic) else v
    raise ValueError(f"{name}: {at}: {v!r} {what}")


def _counts(counts, rows, width):
    if counts is None:
        return _np.full(rows, width, dtype=_np.int64)
    c = _np.asarray(counts)
    if not _np.issubdtype(c.dtype, _np.integer) or c.dtype == _np.bool_:
        raise ValueError(f"counts: dtype {c.dtype} is not an integer type")
    if c.shape != (rows,):
        raise ValueError(f"counts: shape {c.shape} is not ({rows},)")
    _where("counts", (c < 0) | (c > width), c, f"is not a contact count between 0 and {width}")
    return _np.ascontiguousarray(c, dtype=_np.int64)


def _per_contact(name, mu, rows, width):
    if isinstance(mu, _numbers.Real) and not isinstance(mu, bool):
        mu = _np.full((rows, width), mu, dtype=_np.float64) if _np.ndim(mu) == 0 else mu
    return _doubles(name, mu, (rows, width))


def _jobs(jobs):
    if jobs is None:
        return 0
    if isinstance(jobs, bool) or not isinstance(jobs, _numbers.Integral) or jobs < 1:
        raise ValueError(f"jobs: {jobs!r} is not a positive number of threads")
    return int(jobs)


def _contacts(points, normals, mu, counts):
    """Validated contact arrays: points, normals (B, K, 2), mu (B, K), counts (B,)."""
    p = _doubles("points", points, (None, None, 2))
    rows, width = p.shape[0], p.shape[1]
    n = _doubles("normals", normals, (rows, width, 2))
    m = _per_contact("mu", mu, rows, width)
    c = _counts(counts, rows, width)
    used = _np.arange(width)[None, :] < c[:, None]  # the contacts each row has
    for name, a in (("points", p), ("normals", n)):
        _where(name, ~_np.isfinite(a) & used[:, :, None], a, "is not a finite number")
    _where("mu", ~_np.isfinite(m) & used, m, "is not a finite number")
    _where("normals", (n[:, :, 0] == 0) & (n[:, :, 1] == 0) & used, n, "is a zero normal (needs a nonzero vector)")
    _where("mu", (m < 0) & used, m, "is negative (must be >= 0)")
    return p, n, m, c


def _loads(loads, rows):
    w = _doubles("loads", loads, (rows, 3))
    _where("loads", ~_np.isfinite(w), w, "is not a finite number")
    return w


def closure_arrays(points, normals, mu, counts=None, *, mode="hybrid", certificates=False, jobs=None):
    """Force closure and first-order form closure of B grasps given as arrays of doubles.

    points, normals: (B, K, 2) contact points and inward normals (nonzero, any length); mu: a number or
    (B, K); counts: None (every row has K contacts) or (B,) integers, row i using its first counts[i]
    contacts (ragged batches). Returns a dict of NumPy arrays of length B: "force_closure", "form_closure"
    (bool), "decided_by" (int8, DECIDED_BY: 0 float, 1 hybrid, 2 exact, -1 undecided — mode "float"
    only, the verdicts then False), "predicates" and "exact_predicates" (int32: the signs asked, and how many
    fell back to exact arithmetic); with certificates=True also "certificates": one dict per row (None when
    undecided) with both certificates as dicts and JSON text and the row's scene as canonical JSON
    ("scene_json"), each certificate accepted by the independent checker before it is returned.
    mode: "hybrid" (default, exact answers), "exact", "float". jobs: threads (default: every core).
    """
    p, n, m, c = _contacts(points, normals, mu, counts)
    return _core.closure_arrays(p, n, m, c, _mode(mode), bool(certificates), _jobs(jobs))


def quality_arrays(points, normals, mu, counts=None, *, norm="L1", normalize="unit-normal", critical_mu=False,
                   mode="hybrid", certificates=False, jobs=None):
    """The grasp quality of B grasps given as arrays of doubles (docs/quality.md), moments about the origin.

    Contacts as closure_arrays. Returns a dict of NumPy arrays of length B: "force_closure" (bool), "epsilon_lower"
    and "epsilon_upper" (float64: the certified bracket of the Ferrari-Canny epsilon rounded outward, so that
    lower <= epsilon <= upper still holds; equal to within a few ulps); with critical_mu=True also
    "critical_mu_lower", "critical_mu_upper" (the least common mu that closes the grasp: 0 when closed without
    friction, NaN when no mu does). norm: "L1" or "Linf"; normalize: "unit-normal", "unit-force" or "as-given".
    certificates=True writes every row's certificates and has the independent checker accept them first (the answers
    are the same; about 2.5x the time). mode: "hybrid" or "exact".
    """
    if norm not in ("L1", "Linf"):
        raise ValueError(f'norm: {norm!r} is not one of "L1", "Linf"')
    if normalize not in ("unit-normal", "unit-force", "as-given"):
        raise ValueError(f'normalize: {normalize!r} is not one of "unit-normal", "unit-force", "as-given"')
    if mode == "float":
        raise ValueError('mode: "float" is not offered by quality_arrays (epsilon has no float twin); use "hybrid" or "exact"')
    p, n, m, c = _contacts(points, normals, mu, counts)
    return _core.quality_arrays(p, n, m, c, norm, normalize, _mode(mode), bool(critical_mu), bool(certificates),
                                _jobs(jobs))


def equilibrium_arrays(points, normals, mu, loads, counts=None, *, mode="hybrid", certificates=False, jobs=None):
    """Can the contacts balance each row's load? loads: (B, 3) wrenches (fx, fy, m about the origin).

    Contacts as closure_arrays. Returns "balanced" (bool), "decided_by", "predicates", "exact_predicates",
    and with certificates=True "certificates" (dicts with "certificate", "certificate_json", "scene_json").
    """
    p, n, m, c = _contacts(points, normals, mu, counts)
    w = _loads(loads, p.shape[0])
    return _core.equilibrium_arrays(p, n, m, c, w, _mode(mode), bool(certificates), _jobs(jobs))


def stick_slide_arrays(points, forces, mu, loads, counts=None, *, sides=32, mode="hybrid", certificates=False,
                       jobs=None):
    """Does each row's load stick or slide on its support (known normal forces)? As wrenchkit.limit_surface(…, load=).

    points: (B, N, 2) support points; forces: (B, N) normal forces >= 0, not all zero; mu: a number or (B, N);
    loads: (B, 3) (fx, fy, m); counts as closure_arrays (at least 1). Returns "motion" (int8, MOTION: 1 sticks,
    0 slides, 2 impending (on the limit surface), -1 undecided) and "motion_decided_by" (int8, MOTION_DECIDED_BY: 0 the float twin's certified
    search, 1 the polygons, 2 a flat surface, 3 the certificate, 4 Newton's method in multiple precision checked
    exactly, -1 none); with certificates=True
    "certificates": dicts with "motion", "certificate" (the parsed JSON, exact numbers as "p/q" strings),
    "certificate_json" (accepted by the independent checker; "" when none), "uncertified" (why not) and
    "scene_json". sides: the polygons' N where the search cannot tell (even, 4..).
    """
    p = _doubles("points", points, (None, None, 2))
    rows, width = p.shape[0], p.shape[1]
    f = _per_contact("forces", forces, rows, width)
    m = _per_contact("mu", mu, rows, width)
    c = _counts(counts, rows, width)
    _where("counts", c < 1, c, "is not a count of support points (at least 1)")
    used = _np.arange(width)[None, :] < c[:, None]
    _where("points", ~_np.isfinite(p) & used[:, :, None], p, "is not a finite number")
    for name, a in (("forces", f), ("mu", m)):
        _where(name, ~_np.isfinite(a) & used, a, "is not a finite number")
        _where(name, (a < 0) & used, a, "is negative (must be >= 0)")
    zero = ~((f > 0) & used).any(axis=1)
    if zero.any():
        raise ValueError(f"forces: row {int(_np.argmax(zero))}: all forces are zero (a support needs a force > 0)")
    w = _loads(loads, rows)
    if isinstance(sides, bool) or not isinstance(sides, _numbers.Integral) or sides < 4 or sides % 2:
        raise ValueError(f"sides: {sides!r} must be an even integer >= 4")
    r = _core.stick_slide_arrays(p, f, m, c, w, int(sides), _mode(mode), bool(certificates), _jobs(jobs))
    if certificates:
        for d in r["certificates"]:
            d["certificate"] = _json.loads(d["certificate_json"]) if d["certificate_json"] else None
    return r


def _mode(mode):
    if mode not in ("hybrid", "exact", "float"):
        raise ValueError(f'mode: "{mode}" is not one of exact, hybrid, float')
    return mode
