"""wrenchkit: exact, certified planar contact statics (Mason, *Mechanics of Robotic Manipulation*, ch. 5-6).

    >>> import wrenchkit
    >>> from fractions import Fraction
    >>> s = wrenchkit.Scene({"contacts": [
    ...     {"at": [0, "1/2"], "normal": [1, 0], "mu": Fraction(1, 10)},
    ...     {"at": [1, "1/2"], "normal": [-1, 0], "mu": "0.1"}]})
    >>> r = wrenchkit.closure(s)
    >>> r["force_closure"], r["form_closure"]
    (True, False)
    >>> wrenchkit.check(s, r["certificate"])["accepted"]
    True

Numbers. Every number of a scene is read EXACTLY, from its text:
  * int, fractions.Fraction, decimal.Decimal: their exact value;
  * str: decimal text ("0.1" is 1/10, "-2.5e-3") or a fraction "p/q";
  * float: ITS SHORTEST REPR, i.e. the decimal text Python prints: 0.1 is read as 1/10, exactly as
    the JSON scene files are, NOT as the binary double 0.1000000000000000055511151231257827...
    For the double's exact binary value pass Fraction(x) (Fraction(0.1) == 3602879701896397/36028797018963968).
    NaN and infinities are refused (InputError).
  * NumPy arrays and scalars (numpy.float64(0.1), numpy.array([0, 0.5])): as the array API reads them, each
    floating-point value as the EXACT BINARY VALUE it holds (numpy.float64(0.1) is 3602879701896397/2**55),
    integers exactly.
Every exact number in a result is a fractions.Fraction; verdicts are bools; certificates are dicts
(with Fractions) and JSON text ("certificate_json") that the independent checker accepts.
Errors in the input raise wrenchkit.InputError (a ValueError) with the command line's message,
naming the JSON path and the offending value. See docs/python.md.
"""

import decimal as _decimal
import fractions as _fractions
import json as _json
import math as _math
import numbers as _numbers
import os as _os
import sys as _sys

__version__ = "0.1.0"


class InputError(ValueError):
    """Bad input: the message names the JSON path (or argument) and the offending value."""


class UndecidedError(RuntimeError):
    """mode="float": the floating-point twin could not certify the answer (use "hybrid" or "exact")."""


class InternalError(RuntimeError):
    """An answer failed its own certificate check, or an internal invariant broke: always a bug."""


from . import _core  # noqa: E402  (the exception classes above are handed to the native module)

_core._set_exceptions(InputError, InternalError, UndecidedError)

__all__ = ["Scene", "closure", "force_closure", "form_closure", "equilibrium", "hold", "labels", "dual", "reuleaux",
           "quality", "grasp_regions", "push", "limit_surface", "sliding", "render", "check", "reference", "compare", "batch", "closure_arrays",
           "equilibrium_arrays", "quality_arrays", "stick_slide_arrays", "DECIDED_BY", "MOTION", "MOTION_DECIDED_BY", "InputError",
           "UndecidedError", "InternalError"]


def _numpy():
    """NumPy if it was imported (a value can only be a NumPy object then), else None."""
    return _sys.modules.get("numpy")


def _numpy_number_text(x, np, path):
    """The exact text of a NumPy scalar: an integer exactly, a floating-point value as the exact binary value it
    holds (as the array API reads it), not as its decimal text."""
    if isinstance(x, np.bool_):
        raise InputError(f"{path}: {x!r} is a boolean, not a number")
    if isinstance(x, np.integer):
        return str(int(x))
    if isinstance(x, np.floating):
        if not np.isfinite(x):
            raise InputError(f"{path}: {x!r} is not a finite number")
        n, d = x.as_integer_ratio()
        return f"{n}/{d}"
    raise InputError(f"{path}: {x!r} ({type(x).__name__}) is not a number")


def _number_text(x, path):
    """The exact decimal or p/q text of a Python number (see the module docstring)."""
    np = _numpy()
    if np is not None and isinstance(x, np.generic):
        return _numpy_number_text(x, np, path)
    if isinstance(x, bool):
        raise InputError(f"{path}: {x!r} is a boolean, not a number")
    if isinstance(x, _numbers.Integral):
        return str(int(x))
    if isinstance(x, _fractions.Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, _decimal.Decimal):
        if not x.is_finite():
            raise InputError(f"{path}: {x} is not a finite number")
        return str(x)
    if isinstance(x, float):
        if not _math.isfinite(x):
            raise InputError(f"{path}: {x!r} is not a finite number")
        return repr(x)
    if isinstance(x, _numbers.Rational):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, _numbers.Real):  # e.g. numpy.float64
        return _number_text(float(x), path)
    if isinstance(x, str):
        return x
    raise InputError(f"{path}: {x!r} ({type(x).__name__}) is not a number")


def _to_json(v, path="scene"):
    """Scene JSON text from Python values: numbers become exact JSON strings (read exactly)."""
    if isinstance(v, dict):
        parts = []
        for k, x in v.items():
            if not isinstance(k, str):
                raise InputError(f"{path}: key {k!r} is not a string")
            parts.append(_json.dumps(k) + ": " + _to_json(x, k if path == "scene" else f"{path}.{k}"))
        return "{" + ", ".join(parts) + "}"
    np = _numpy()
    if np is not None and isinstance(v, np.ndarray):  # its items: NumPy scalars (read as such) or sub-arrays
        return _to_json(v[()], path) if v.ndim == 0 else _to_json(list(v), path)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_to_json(x, f"{path}[{i}]") for i, x in enumerate(v)) + "]"
    if isinstance(v, str):
        return _json.dumps(v)
    if v is None or isinstance(v, bool):
        return _json.dumps(v)
    if path.endswith("wrenchkit") and isinstance(v, _numbers.Integral):
        return str(int(v))
    return _json.dumps(_number_text(v, path))


class Scene:
    """A scene (docs/scene-format.md), read and validated exactly.

    Scene(data) where data is a dict (or list-free mapping) in the JSON scene format with Python
    numbers (int, str, Fraction, Decimal, float: see the module docstring), a JSON text (a str that
    starts with "{"), or a path to a JSON scene file (str or os.PathLike). "wrenchkit": 1 may be
    omitted from a dict. limits: max_digits, max_exponent, max_file_size, max_contacts, max_region_vertices,
    max_total_digits, max_digits_times_contacts, max_work, max_certificate_size (as the CLI's --max-* options; the scene's questions keep them).
    lenient=True (the CLI's --lenient): a contact off body.outline, a normal pointing out of the body or an outline
    that is not a simple polygon is kept, as a warning in `warnings`, instead of refused.
    Raises InputError with the command line's message.
    """

    def __init__(self, data, *, limits=None, lenient=False):
        limits = dict(limits or {})
        if lenient:
            limits["lenient"] = True
        if isinstance(data, Scene):
            self._s = data._s
            return
        if isinstance(data, dict):
            if "wrenchkit" not in data:
                data = {"wrenchkit": 1, **data}
            text, source = _to_json(data), "scene"
        elif isinstance(data, str) and data.lstrip().startswith("{"):
            text, source = data, "scene"
        elif isinstance(data, (str, _os.PathLike)):
            source = _os.fspath(data)
            try:
                with open(source, "rb") as f:
                    raw = f.read()
            except OSError as e:
                raise InputError(f"{source}: cannot open ({e.strerror})") from None
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError as e:
                raise InputError(f"{source}: invalid UTF-8 at byte {e.start}") from None
        else:
            raise InputError(f"scene: {type(data).__name__} is not a dict, JSON text or path")
        self._s = _core.read(text, source, limits)

    @property
    def json(self):
        """The canonical JSON text of the scene (every number an exact "p/q" string)."""
        return self._s.text

    @property
    def name(self):
        return self._s.name

    @property
    def warnings(self):
        """The outline checks' warnings kept with lenient=True (docs/scene-format.md, "The outline is geometry")."""
        return list(self._s.warnings)

    @property
    def has_load(self):
        return self._s.has_load

    @property
    def has_support(self):
        return self._s.has_support

    def __len__(self):
        return self._s.contacts

    def __repr__(self):
        return f"wrenchkit.Scene({self._s.text.strip()!s})"


def _scene(s):
    return s._s if isinstance(s, Scene) else Scene(s)._s


def _vec(v, what):
    if v is None:
        return None
    if isinstance(v, str):
        v = v.split(",")
    return [_number_text(x, f"{what}[{i}]") for i, x in enumerate(v)]


def closure(scene, mode="hybrid"):
    """Force closure (with friction) and first-order form closure (frictionless), with certificates.

    Returns {"force_closure": bool, "form_closure": bool, "rank": {"force", "form"}, "generators",
    "decided_by", "certificate": dict, "form_certificate": dict, "certificate_json": str,
    "form_certificate_json": str}. Both certificates were accepted by the independent checker.
    mode: "hybrid" (default; exact answers), "exact", or "float" (may raise UndecidedError).
    """
    return _core.closure(_scene(scene), mode)


def force_closure(scene):
    """Force closure of the scene's contacts with their friction (bool, exact)."""
    return closure(scene)["force_closure"]


def form_closure(scene):
    """First-order form closure of the scene's contacts read frictionless (bool, exact)."""
    return closure(scene)["form_closure"]


def equilibrium(scene, mode="hybrid"):
    """Can the contacts balance the scene's load? {"balanced", "load": (fx, fy, m), "certificate", ...}."""
    return _core.equilibrium(_scene(scene), mode)


def hold(scene, mode="hybrid"):
    """Fixtures on a support (docs/fixtures.md): can the contacts together with the support's friction hold the
    body against the scene's in-plane load? {"holds": True | False | "depends" | "undecided", "load": (fx, fy, m),
    "decided_by", "support": "none" | "known" | "unknown", "contact_forces" and "support_forces" (when held),
    "motion": {"twist", "kind": "rotation" | "translation", "center" / "direction", "sense", "text"} (when not),
    "certificate": dict, "certificate_json": str, ...}. The certificate was accepted by the independent checker.
    "undecided" (hybrid, exact: with "undecided_why") only within the resolution of the exact LPs of a load that
    friction can just carry; mode="float" raises UndecidedError where its float witnesses decide nothing.
    """
    r = _core.hold(_scene(scene), mode)
    r["certificate"] = _json.loads(r["certificate_json"]) if r["certificate_json"] else None
    return r


def labels(scene, reading="friction", mode="hybrid"):
    """Moment labels (theory.md section 5): {"plus", "minus": REGION, "both", "infinity", "rank", ...}.

    A REGION is {"empty", "shape", "vertices": [(x, y) Fractions, counter-clockwise], "directions"}.
    reading="frictionless" gives Reuleaux's feasible rotation centres. mode: "hybrid" (default: the twin's
    certified signs, exact constructions) or "exact" (the same answer without floating point).
    """
    return _core.labels(_scene(scene), reading, mode)


def reuleaux(scene, *, center=None, sense=None, direction=None, twist=None, mode="hybrid"):
    """Reuleaux's method (theory.md section 7), as `wrenchkit reuleaux --json`: the labels of the contacts read
    frictionless (as labels(scene, "frictionless")), "form_closure", and with a motion its "query": {"twist",
    "reading", "feasible", "marginal", "modes": [{"contact", "mode"}]} (each contact's mode: "break", "slide",
    "stick" or "penetrate").

    The motion, at most one of: center=(x, y) with sense="ccw" (default) or "cw", a rotation about that point;
    direction=(dx, dy), a translation; twist=(vx, vy, w). Numbers as in Scene. mode: "hybrid" or "exact".
    """
    words = []
    for name, value in (("center", center), ("direction", direction), ("twist", twist)):
        if value is not None:
            words += ["--" + name, ",".join(_vec(value, name))]
    if sense is not None:
        words += ["--sense", str(sense)]
    return _core.reuleaux(_scene(scene), words, mode)


def quality(scene, *, norm=None, normalize=None, torque_scale=None, about=None, tolerance=None, only=None,
            preset=None, contact_margins=False, mode="hybrid"):
    """How good is the grasp (docs/quality.md), as `wrenchkit quality --json`: {"epsilon": {"lower", "upper",
    "squared" (when epsilon^2 is rational), "lower_approx", "upper_approx", "norm", "normalize", "torque_scale",
    "about"}, "force_closure", "nearest_facet", "critical_mu": {"closure": {"kind": "value" | "always" | "never",
    "lower", "upper", "exact", "certificate"}, "equilibrium": {...} (with a load)}, "friction_margin": {...} (the
    least factor on the contacts' own mu that closes the grasp), "certificate", ...}. Exact numbers
    are Fractions; every certificate was accepted by the independent checker.

    norm: "L1" (default) or "Linf"; normalize: "unit-normal" (default), "unit-force" or "as-given"; torque_scale: the
    moment's weight (default 1); about: (x, y), the moments' point (default body.com, else the origin); tolerance:
    the brackets' relative width (default 1e-12); only: "epsilon" or "critical-mu"; preset: "graspit" or "dexnet" (the
    peers' conventions, docs/quality.md); contact_margins=True: also "contact_margins" (each contact's least relative
    volume of three friction-cone edges, "squared" a Fraction, docs/quality.md). mode: "hybrid" or "exact"
    ("float" raises UndecidedError: neither has a float twin).
    """
    words = []
    for name, value in (("norm", norm), ("normalize", normalize), ("only", only), ("preset", preset)):
        if value is not None:
            words += ["--" + name, str(value)]
    for name, value in (("torque-scale", torque_scale), ("tolerance", tolerance)):
        if value is not None:
            words += ["--" + name, _number_text(value, name)]
    if about is not None:
        words += ["--about", ",".join(_vec(about, "about"))]
    if contact_margins:
        words += ["--contact-margins"]
    r = _json.loads(_core.quality(_scene(scene), words, mode))

    def exact(d, keys):
        for k in keys:
            if k in d and isinstance(d[k], str):
                d[k] = _fractions.Fraction(d[k])

    if "epsilon" in r:
        exact(r["epsilon"], ("lower", "upper", "squared", "torque_scale", "torque_radius_squared", "torque_scale_error"))
        r["epsilon"]["about"] = tuple(_fractions.Fraction(x) for x in r["epsilon"]["about"])
    for c in list(r.get("critical_mu", {}).values()) + ([r["friction_margin"]] if "friction_margin" in r else []):
        exact(c, ("lower", "upper"))
    if "contact_margins" in r:
        exact(r["contact_margins"], ("torque_scale",))
        r["contact_margins"]["about"] = tuple(_fractions.Fraction(x) for x in r["contact_margins"]["about"])
        for c in r["contact_margins"]["contacts"]:
            exact(c, ("squared",))
    return r


def push(scene, *, contact=False, region=False, locus=False):
    """Which way a pushed body turns (docs/pushing.md), as `wrenchkit push --json`: the scene's "pusher" (a point
    contact with a "velocity" into the body) pushing it over its "support". "rotation": "ccw", "cw", "none" (a
    translation), "depends" (with "witnesses": two distributions of the support's forces that turn it apart) or
    "undecided" (with "why"), for every admissible pressure distribution — Mason's voting theorem, exact; "votes":
    each line's ("left edge", "right edge", "velocity") direction and vote; "center_of_friction" (Fractions, None when
    it moves with the distribution); the "certificate" the independent checker accepted. contact=True: also
    "contact": {"mode": "sticks" | "impending" | "slides left" | "slides right" | "undecided", "omega": (lo, hi) (the
    sticking motion's rotation rate, Fractions), "why"} for a support of points with every force given; sliding,
    "slip": (lo, hi) (the body's velocity at the pusher is the pusher's plus slip times rot90(normal)) and "omega" its
    rotation rate, exact when "pivot" names the support point it turns about; sticking about a support point (the
    pusher's velocity perpendicular to the line to it), "pivot" with the exact "omega" and "force", a force of that
    point's facet strictly inside the friction cone (Fractions); sliding from such a facet (every force of it beyond
    the edge), "sticking_pivot" and its exact "sticking_omega". Forces not given: "depends" with "witnesses": two
    distributions of the support's forces ("forces", Fractions) whose certified modes ("mode") differ.

    A line pusher ("segment": [[x1, y1], [x2, y2]], "velocity" at its middle, "omega" its rotation rate) answers
    "stable": {"verdict": "stable" | "unstable" | "undecided", "why", "rotation_centre" (turning), "boundary" (stable
    and translating: the composite cone's facets the load is on), "facet" and "witness": {"points", "weights"}
    (unstable: the facet the load leaves by, and a distribution with the centre of friction that breaks the contact)}
    for every distribution with the centre of friction (Lynch & Mason); "rotation" is the pusher's own sense when
    stable. region=True (a line pusher): also "stable_region": {"ccw", "cw": {"halfplanes": [{"facet", "a", "b"}]
    (a.q <= b, Fractions), "T", "polygon": [(x, y), ...] (within "box")} or None, "box", "translations": the cone of
    stable translation velocities or None} — the rotation centres certified stable for every distribution.

    locus=True (a point pusher): also "locus": {"ccw", "cw": [three pieces {"mode": "sticks" | "slides left" |
    "slides right", "halfplanes": [{"why", "a", "b"}] (a.q <= b), "bounded", "polygon": [(x, y), ...]}] or None (a
    sense the rotation excludes), "T", "box", "arm_hi" (every piece bounded: the rotation centre is within it of the
    pusher's normal line) or "arm_why", "arm_lo" and "slowest": {"forces", "mode"} (a distribution whose certified
    rate puts its centre at least arm_lo away: the slowest turn's arm is in [arm_lo, arm_hi])} — where the body may
    turn about, for every distribution (PU-4), or {"why"} when the centre of friction moves with the distribution.
    """
    r = _json.loads(_core.push(_scene(scene), contact, region, locus))
    fr = _fractions.Fraction
    for k in ("at", "normal", "velocity"):
        if k in r["pusher"]:
            r["pusher"][k] = tuple(fr(x) for x in r["pusher"][k])
    if "segment" in r["pusher"]:
        r["pusher"]["segment"] = tuple(tuple(fr(x) for x in e) for e in r["pusher"]["segment"])
        r["pusher"]["omega"] = fr(r["pusher"]["omega"])
    r["pusher"]["mu"] = fr(r["pusher"]["mu"])
    if "stable" in r:
        st = r["stable"]
        if "rotation_centre" in st:
            st["rotation_centre"] = tuple(fr(x) for x in st["rotation_centre"])
        if "witness" in st:
            st["witness"]["points"] = [tuple(fr(x) for x in p) for p in st["witness"]["points"]]
            st["witness"]["weights"] = [fr(x) for x in st["witness"]["weights"]]
    if r.get("stable_region") is not None:
        g = r["stable_region"]
        for k in ("ccw", "cw"):
            if g[k] is not None:
                for h in g[k]["halfplanes"]:
                    h["a"], h["b"] = tuple(fr(x) for x in h["a"]), fr(h["b"])
                g[k]["T"] = fr(g[k]["T"])
                g[k]["polygon"] = [tuple(fr(x) for x in v) for v in g[k]["polygon"]]
        g["box"] = [tuple(fr(x) for x in v) for v in g["box"]]
        if g["translations"] is not None:
            g["translations"] = [tuple(fr(x) for x in v) for v in g["translations"]]
    if "locus" in r and "why" not in r["locus"]:
        g = r["locus"]
        for k in ("R2", "R_hi", "alpha_hi", "T", "arm_hi", "arm_lo"):
            if k in g:
                g[k] = fr(g[k])
        for k in ("ccw", "cw"):
            for piece in g[k] or []:
                for h in piece["halfplanes"]:
                    h["a"], h["b"] = tuple(fr(x) for x in h["a"]), fr(h["b"])
                piece["polygon"] = [tuple(fr(x) for x in v) for v in piece["polygon"]]
        g["box"] = [tuple(fr(x) for x in v) for v in g["box"]]
        if "slowest" in g:
            g["slowest"]["forces"] = [fr(x) for x in g["slowest"]["forces"]]
    if r["center_of_friction"] is not None:
        r["center_of_friction"] = tuple(fr(x) for x in r["center_of_friction"])
    for v in r["votes"]:
        v["direction"] = tuple(fr(x) for x in v["direction"])
    if "witnesses" in r:
        r["witnesses"] = {k: [fr(x) for x in f] for k, f in r["witnesses"].items()}
    for k in ("omega", "slip", "force", "sticking_omega"):
        if "contact" in r and k in r["contact"]:
            r["contact"][k] = tuple(fr(x) for x in r["contact"][k])
    for w in r.get("contact", {}).get("witnesses", []):
        w["forces"] = [fr(x) for x in w["forces"]]
    return r


def grasp_regions(part, *, mu=None, edges=None, fingers=2, rank=None, min_side=None, lenient=False):
    """Where two fingers may go (docs/grasp-regions.md), as `wrenchkit grasp-regions --json`: for every pair i < j of
    body.outline's edges (edge i from vertex i to i + 1), "closed": the polygons in (s, t) — a finger at
    v_i + s (v_{i+1} - v_i), the other at t on edge j — where the two frictional fingers are in force closure (corners
    as Fraction pairs, counter-clockwise; [] when none) and "independent" ([(s0, s1), (t0, t1)]: every placement in
    that box closes), with "areas", "largest", "most_independent", "outline" and the "certificate" the
    independent checker accepted. mu: the fingers' friction (default: the scene's "mu"); edges: the edges to pair.
    fingers=3: "triples" instead, for every triple i < j < k of edges: "independent" ([(a0, b0), (a1, b1), (a2, b2)]:
    a cube of placements that all close, certified by the four friction-cone "wrenches" named) or "never" (no
    placement closes: "frictionless", or a wrench-space direction as Fractions), with "most_independent".
    "ranked": the closed pairs' (triples') box centres "at", best first, by "box_side" or (rank="epsilon") by the
    grasp's "epsilon" there ({"lower", "upper"} Fractions), with "best_by_epsilon" (its scene and ε certificate);
    min_side: rank only boxes at least that large. lenient=True: the part is read as Scene(part, lenient=True) —
    contacts off the outline are warnings (the regions do not use them); an outline that is not a simple polygon is
    refused all the same (the regions need one).
    """
    words = ["--fingers", str(int(fingers))] if fingers != 2 else []
    if rank is not None:
        words += ["--rank", str(rank)]
    if min_side is not None:
        words += ["--min-side", _number_text(min_side, "min_side")]
    if mu is not None:
        words += ["--mu", _number_text(mu, "mu")]
    if edges is not None:
        words += ["--edges", ",".join(str(int(e)) for e in edges)]
    r = _json.loads(_core.grasp_regions(_scene(Scene(part, lenient=True) if lenient and not isinstance(part, Scene)
                                               else part), words))
    r["mu"] = _fractions.Fraction(r["mu"])
    for t in r.get("triples", []):
        if "independent" in t:
            t["independent"] = [tuple(_fractions.Fraction(x) for x in iv) for iv in t["independent"]]
        if isinstance(t.get("never"), list):
            t["never"] = tuple(_fractions.Fraction(x) for x in t["never"])
    for p in r.get("ranked", []):
        p["at"] = tuple(_fractions.Fraction(x) for x in p["at"])
        p["box_side"] = _fractions.Fraction(p["box_side"])
        if "epsilon" in p:
            p["epsilon"]["lower"] = _fractions.Fraction(p["epsilon"]["lower"])
            p["epsilon"]["upper"] = _fractions.Fraction(p["epsilon"]["upper"])
    if "triples" in r:
        if "most_independent" in r:
            r["most_independent"]["independent_side"] = _fractions.Fraction(r["most_independent"]["independent_side"])
        return r
    for p in r["pairs"]:
        p["closed"] = [[tuple(_fractions.Fraction(x) for x in c) for c in poly] for poly in p["closed"]]
        if "independent" in p:
            p["independent"] = [tuple(_fractions.Fraction(x) for x in iv) for iv in p["independent"]]
    for a in r["areas"]:
        a["area"] = _fractions.Fraction(a["area"])
        a["independent_side"] = _fractions.Fraction(a["independent_side"])
    if "largest" in r:
        r["largest"]["area"] = _fractions.Fraction(r["largest"]["area"])
    if "most_independent" in r:
        r["most_independent"]["independent_side"] = _fractions.Fraction(r["most_independent"]["independent_side"])
    return r


def render(scene, what, *, sides=None, contact=False):
    """The SVG picture of `wrenchkit render --what WHAT` (docs/gallery.md), as text: what is "labels", "dual",
    "reuleaux", "limit-surface", "hold", "quality" (docs/quality.md), "grasp-regions" or "push" (docs/pushing.md);
    sides (even, with "limit-surface") the polygons' sides (default 32); contact=True (with "push") adds the contact
    mode and where the body turns.
    """
    words = ["--what", str(what)]
    if sides is not None:
        words += ["--sides", str(int(sides))]
    if contact:
        words += ["--contact"]
    return _core.render(_scene(scene), words)


def compare(corpus, answers, *, format=None, rtol=None, atol=None, near=None, tolerance=None, max_file_size=None):
    """Your implementation's answers against a reference corpus, as `wrenchkit compare --json CORPUS ANSWERS`
    (docs/reference-format.md sections 5-6): returns the report as a dict; its "agree" says whether every given
    answer agrees (the command's exit code 0).

    corpus: the corpus directory (or its reference.jsonl); answers: a JSON-lines or CSV file (format "jsonl" or
    "csv", by default from the file name). rtol, atol, near, tolerance: numbers as the command's options.
    Raises InputError naming the file, line and field for bad answers.
    """
    words = []
    for name, value in (("rtol", rtol), ("atol", atol), ("near", near), ("tolerance", tolerance)):
        if value is not None:
            words += ["--" + name, _number_text(value, name)]
    if format is not None:
        words += ["--format", str(format)]
    if max_file_size is not None:
        words += ["--max-file-size", str(int(max_file_size))]
    return _json.loads(_core.compare(words + [_os.fspath(corpus), _os.fspath(answers)]))


def dual(scene, mode="hybrid"):
    """The force dual (theory.md section 6): {"covers_all", "plus_region", "minus_region", ...}."""
    return _core.dual(_scene(scene), mode)


def limit_surface(scene, sides=32, *, tolerance=None, twist=None, load=None, mode="hybrid"):
    """Certified polygonal limit surfaces of the scene's support (docs/limit-surface.md).

    {"sides", "lambda_squared", "inner"/"outer": {"facets", "vertices", "edges"}, ...}; with
    twist=(vx, vy, w) also "h_inner" <= h <= "h_outer" and the loads; with load=(fx, fy, m) also
    "motion": "sticks" | "slides" | "undecided" and "motion_decided_by". tolerance (a number) picks the
    smallest sides whose certified relative error is at most tolerance. mode: "hybrid" (default: the motion
    by the float twin's certified search on the true surface first, the polygons when it cannot tell) or
    "exact" (the polygons only).

    A support with regions (docs/regions.md) has no polytope: {"regions", "total_force", "center_of_friction",
    "mu_f0", ...}; twist adds "power_bracket" (certified, relative width <= tolerance, default 1e-6) and
    "load_box"; load adds "motion" and "certificate_json" (checked by the independent checker).
    """
    tol = None if tolerance is None else _number_text(tolerance, "tolerance")
    return _core.limit_surface(_scene(scene), int(sides), tol, _vec(twist, "twist"), _vec(load, "load"), mode)


def sliding(scene, twist=None, sides=64, mode="hybrid", *, tolerance=None):
    """Centre of friction and the frictional load for a twist (theory.md section 10), exact bounds.

    With support regions (docs/regions.md): the power and the load are certified brackets whose relative width
    is at most tolerance (default 1e-6): "power_bracket", "load_box"."""
    tol = None if tolerance is None else _number_text(tolerance, "tolerance")
    return _core.sliding(_scene(scene), _vec(twist, "twist"), int(sides), mode, tol)


def reference(scenes, out, sides=16):
    """The reference corpus of your own scenes, as `wrenchkit reference --scenes SCENES --out OUT`.

    scenes: a JSON-lines file (one scene per line, or {"id", "family", "scene"} per line) or a
    directory of scene files (*.json); out: the corpus directory (docs/reference-format.md), written by
    the same C++ as the command. Returns {"scenes", "certificates_checked", "bytes"}; raises InputError
    naming the file, line and field for a bad scene (nothing is written then).
    """
    return _core.reference(_os.fspath(scenes), _os.fspath(out), int(sides))


def _certificate_text(c):
    if isinstance(c, str):
        return c
    if isinstance(c, dict):
        def enc(v):
            if isinstance(v, dict):
                return {k: enc(x) for k, x in v.items()}
            if isinstance(v, (list, tuple)):
                return [enc(x) for x in v]
            if isinstance(v, bool) or v is None or isinstance(v, str):
                return v
            if isinstance(v, _fractions.Fraction):
                return f"{v.numerator}/{v.denominator}"
            return v
        return _json.dumps(enc(c))
    raise InputError(f"certificate: {type(c).__name__} is not a dict or JSON text")


def check(scene, certificate):
    """The independent checker (proofs/checker, GMP only): does the certificate prove its claim?

    certificate: a dict (as returned here, Fractions allowed) or JSON text. Returns
    {"accepted": bool, "reason": str}; raises InputError if the scene itself is bad.
    """
    return _core.check(_scene(scene), _certificate_text(certificate))


def _batch_options(options, kwargs):
    """batch's options as command-line words: strings as given, keywords as --name VALUE (True: a flag)."""
    words = [str(o) for o in options]
    for k, v in kwargs.items():
        flag = "--" + k.replace("_", "-")
        if v is True:
            words.append(flag)
        elif v is False or v is None:
            continue
        elif isinstance(v, (list, tuple)):
            words += [flag, ",".join(_number_text(x, k) for x in v)]
        elif isinstance(v, str):
            words += [flag, v]
        else:
            words += [flag, _number_text(v, k)]
    return words


def _line_text(s):
    """One scene as the text of a JSON line: a dict as _to_json, a str or bytes line as given (one final
    newline dropped), a Scene as its canonical text."""
    if isinstance(s, bytes):
        return s[:-1] if s.endswith(b"\n") else s
    if isinstance(s, str):
        return s[:-1] if s.endswith("\n") else s
    if isinstance(s, dict):
        return _to_json(s if "wrenchkit" in s else {"wrenchkit": 1, **s})
    if isinstance(s, Scene):
        return s.json.strip().replace("\n", " ")  # one line (a JSON string holds no raw newline)
    raise InputError(f"batch: a scene is a dict, a JSON line (str or bytes) or a Scene, not {type(s).__name__}")


def batch(command, scenes, *options, jobs=None, first_line=1, chunk=None, as_dict=False, **kwargs):
    """The answers of `wrenchkit batch COMMAND [OPTIONS]` for any iterable of scenes, streamed in order.

    scenes: dicts (the scene format, Python numbers as in Scene), JSON lines (str or bytes), or Scenes.
    options: the command line's words ("--mode", "exact", "--verdict-only"), or keywords (mode="exact",
    verdict_only=True, twist=(0, 0, 1), sides=8). Yields one str per scene: exactly the line `wrenchkit batch
    COMMAND` writes for that scene's line (without the newline), numbered from first_line; bad scenes give
    their error line, as there. as_dict=True yields each line parsed (json.loads: a dict whose exact numbers
    are "p/q" strings, as in the line). jobs: threads (default: batch's --jobs, else every core). Options that
    do not apply raise InputError before any scene is read; a certificate rejected by the independent checker
    (a bug) raises InternalError after its line.
    """
    job = _core.Batch([command] + _batch_options(options, kwargs))
    threads = int(jobs) if jobs else (_os.cpu_count() or 1)
    size = int(chunk) if chunk else 1024 * threads
    line = int(first_line)
    texts = []

    def run(texts, line):
        lines, code = job.run(texts, line, int(jobs or 0))
        for out in lines:
            yield _json.loads(out) if as_dict else out.decode("utf-8", "surrogateescape")
        if code:
            raise InternalError(f"batch {command}: an answer failed its own certificate check or hit an internal "
                                f"error (the command line exits {code} here): see the lines' messages")

    for s in scenes:
        texts.append(_line_text(s))
        if len(texts) == size:
            yield from run(texts, line)
            line += len(texts)
            texts = []
    if texts:
        yield from run(texts, line)


from .arrays import (DECIDED_BY, MOTION, MOTION_DECIDED_BY, closure_arrays,  # noqa: E402
                     equilibrium_arrays, quality_arrays, stick_slide_arrays)
