"""The Exact rule against a high-precision reference (exact_reference.py: the 5x5 matrix exponential
of the versor's action in mpmath, computed from the same double inputs), on adversarial fields of
every generator kind (point pairs, rotations, twists, dilations, translations, a bivector given in
space), alone and in clusters of mixed kinds: points on a generator (and on a rotation's axis) and
1e-9 ... 1e-3 from one, epsilon from 1e-10 to 1e3, huge weights (point pairs up to 1e300) and
strengths (of either sign)
(docs/conventions.md section 2 item 12 states the bound tested here), lone dilations with factors up
to e^700, dilations with a rotation about an axis through their location (loxodromic maps) up to
e^600 and dilations beside one or two point pairs (two finite fixed points) up to e^700.

Each image, from the batch path (PointPairField::mapPoints) and the pointwise path (map), of the
field built from FieldGenerator::of (or the bivector) and from GeneratorParameters rows, printed by
the ExactAccuracyProbe program, must lie within

    1e-12 * scale + 8 * sensitivity

of the reference, where scale is the configuration's largest coordinate or reference displacement,
and sensitivity the reference image's movement when B(p) changes by one unit in the last place
(exact_reference.one_ulp_sensitivity, computed only for points that miss the first term; it is
what no double computation of B(p) can avoid, large only where the problem is ill-conditioned).
A point on a lone generator with a fixed point must stay on it exactly, and the batch image must
equal the pointwise one to the bit (their blocks mix points near and far from generators, which take different
frames).

The Jacobian d image / d p (PointPairField::mapWithJacobian, forward-mode differentiation) must lie
within

    max(1, |J|) * (1e-12 + 8 * 2^-52 * max(1, strength |B(p)|))

of the reference's (exact_reference.jacobian: central differences at 70 digits; in the
configurations that ask for it: six reference images each), entry by entry,
|.| the largest entry or component: the derivative is exact to rounding relative to the size of
the exponent, which next to a generator with a tiny epsilon is huge (docs/conventions.md section 3
item 15 states this bound). Where it misses that, the Jacobian must be ill-conditioned: within the
bound plus 8 times its one-ulp sensitivity (exact_reference.jacobian_sensitivity: J's change when
B(p) and dB/dp change by one ulp). Next to a strong general bivector (exponents 1e3 ... 1e9 at eps
1e-10) the reference's central differences must also agree with its Frechet derivative
(exact_reference.jacobian_by_frechet, no differences) to 1e-14 of max(1, |J|): they do, and the
Jacobian computed in double there erred by up to 0.0094 (1.5e8 times its sensitivity: the image's
rounding times the exponent's tangents), which the double-double tangents of those lanes remove.

Given exponents (mapPointsByExponentials, the curvature patch's map): nearly nilpotent ones, a
huge point pair lambda tau(x, v) (lambda 1e2 ... 1e12) plus a small rest (0 ... 1e-2), at points on
x and 1e-9 ... 10 from it, against the same bound (the pointwise sandwichPoint(exponential(b)) is
shown with -v: it is not held to it). Far from x these take the double-double branch
(docs/conventions.md section 2 item 12).

Every number the probe writes (its Jacobian where that is checked: beyond point-pair weights of
about 1e90 mapWithJacobian refuses, its tangents overflowing), and every reference one, must be
finite: a NaN would pass any comparison with a bound, so it is a failure of its own (errors are
folded by largest(), which keeps a NaN, and fail on `not error <= bound`).

    python3 test_exact_accuracy.py <ExactAccuracyProbe> [-v]
"""
import math
import subprocess
import sys

import exact_reference as reference
from python_test_common import largest

RELATIVE = 1e-12
CONDITION_FACTOR = 8.0
JACOBIAN_EXPONENT_FACTOR = 8.0 * 2.0 ** -52


def offsets(location, distances, directions):
    points = [tuple(location)]
    for d in distances:
        for u in directions:
            norm = math.sqrt(sum(c * c for c in u))
            points.append(tuple(location[i] + d * u[i] / norm for i in range(3)))
    return points


def unit(v):
    norm = math.sqrt(sum(c * c for c in v))
    return tuple(c / norm for c in v)


def axis_points(location, axis):
    """Points on the axis through location along axis (1e-3 and 0.5 from location), and 1e-9 ...
    1e-3 from the axis at its point 0.5 from location, orthogonally."""
    a = unit(axis)
    on = [tuple(location[i] + s * a[i] for i in range(3)) for s in (1e-3, 0.5)]
    helper = (1.0, 0.0, 0.0) if abs(a[0]) < 0.9 else (0.0, 1.0, 0.0)
    across = (a[1] * helper[2] - a[2] * helper[1], a[2] * helper[0] - a[0] * helper[2],
              a[0] * helper[1] - a[1] * helper[0])
    return on + offsets(on[1], NEAR, [across])[1:]


DIRECTIONS = [(0.6, -0.3, 0.7), (-0.2, 0.9, 0.1)]
NEAR = [1e-9, 1e-7, 1e-5, 1e-3]
FAR = [(0.9, 0.4, -0.5), (-1.5, 2.0, 0.3)]
X1, V1 = (0.3, -0.2, 0.1), (0.4, 0.7, -0.5)
X2, V2 = (0.7, -0.1, -0.1), (-0.3, 0.2, 0.9)
X3, V3 = (0.3004, -0.2003, 0.1002), (0.9, 0.1, 0.2)
PITCH = 0.3
REST = [0.3, -0.2, 0.5, 0.1, 0.4, -0.3, 0.2, -0.1, 0.6, 0.25]

# The probe's codes: GeneratorKind's values, and 5 for a bivector given in space.
KIND_CODES = {"pair": 0, "rotation": 1, "twist": 2, "dilation": 3, "translation": 4, "bivector": 5}
def generator(kind, x, v, w, pitch=0.0):
    """(kind, location, direction, pitch, weight), as exact_reference reads one; a "bivector"
    takes its ten null-basis components as the direction."""
    return (kind, x, v, pitch, w)


def pair(x, v, w):
    return generator("pair", x, v, w)


def has_fixed_location(g):
    """The generator alone fixes its location: every kind but a translation and a pitched twist."""
    return g[0] in ("pair", "rotation", "dilation") or (g[0] == "twist" and g[3] == 0.0)


def point_pair_configurations(around1, around2):
    for eps in (1e-10, 1e-6):
        yield (f"lone pair, eps {eps:g}", 1.0, eps, 1.0, [pair(X1, V1, 0.5)], around1 + FAR, True)
    for eps in (1e-10, 1e-8, 1e-4):
        yield (f"two pairs, eps {eps:g}", 1.0, eps, 1.0, [pair(X1, V1, 0.5), pair(X2, V2, 0.3)],
               around1 + around2 + FAR, False)
    yield ("three pairs within 1e-3, eps 1e-10", 1.0, 1e-10, 1.0,
           [pair(X1, V1, 0.5), pair(X2, V2, 0.3), pair(X3, V3, 0.2)],
           around1 + offsets(X3, NEAR[:2], DIRECTIONS[:1]) + FAR, False)
    yield ("lone pair, weight 1e8, eps 1e-10", 1.0, 1e-10, 1.0, [pair(X1, V1, 1e8)],
           around1 + FAR, True)
    yield ("two pairs, weights 1e6, eps 1e-10", 1.0, 1e-10, 1.0,
           [pair(X1, V1, 1e6), pair(X2, V2, 1e6)], around1 + around2 + FAR, False)
    yield ("two pairs, weights 1e12, eps 1e-2", 1.0, 1e-2, 1.0,
           [pair(X1, V1, 1e12), pair(X2, V2, 3e11)], around1 + around2 + FAR, False)
    yield ("two pairs, strength 1e5, falloff 4, eps 1e-6", 4.0, 1e-6, 1e5,
           [pair(X1, V1, 0.5), pair(X2, V2, 0.3)], around1 + around2 + FAR, False)
    # every epsilon >= 1e-10: large ones too (B small and smooth: the field's frame)
    for eps in (1.0, 1e3):
        yield (f"two pairs, eps {eps:g}", 1.0, eps, 1.0, [pair(X1, V1, 0.5), pair(X2, V2, 0.3)],
               around1 + around2 + FAR, False)
    yield ("lone pair, strength 1e8, eps 1e-10", 1.0, 1e-10, 1e8, [pair(X1, V1, 0.5)],
           around1 + FAR, True)
    yield ("two pairs, strength -1e6, eps 1e-8", 1.0, 1e-8, -1e6,
           [pair(X1, V1, 0.5), pair(X2, V2, 0.3)], around1 + around2 + FAR, False)


def one_per_point(case):
    """The configuration split into one per point: each image its own scale (a dilation's images
    range over many decades)."""
    name, falloff, eps, strength, generators, points, lone, jacobian = case
    for p in points:
        yield (f"{name}, at {p}", falloff, eps, strength, generators, [p], lone, jacobian)


def dilation_weight(exponent, eps, strength, direction=V1):
    """The weight that gives a dilation the exponent c = |strength w v| / eps on its location."""
    return exponent * eps / abs(strength * math.sqrt(sum(c * c for c in direction)))


# The factors e^c of the lone dilations on their location: up to e^700 = 1e304, the images in range
# (the distances from the location times e^c). The map scales the hyperbolic plane's null directions
# by their exact factors (docs/conventions.md section 2 item 12); before, it lost about e^c 2^-53 of
# the scale (1 - tanh^2 formed by cancellation), was wrong from c = 30 and refused from c ~ 38.
DILATION_EXPONENTS = (5.0, 30.0, 300.0, 600.0, 650.0, 700.0)

# The factors of the loxodromic similarities (a dilation and a rotation by 2 about an axis through its
# location, W != 0): the same exact scaling after an exact split of B into its two planes; before,
# the closed form lost about e^c 2^-53 of the scale (wrong by 429 times it at c = 30, 1e-7 from the
# location) and refused the point at c = 600.
LOXODROMIC_EXPONENTS = (5.0, 30.0, 300.0, 600.0)

# The factors of a dilation beside one or two point pairs (a general strong bivector: two finite
# fixed points, an elliptic plane beside the hyperbolic one).
BOOST_EXPONENTS = (5.0, 30.0, 300.0, 700.0)
PAIRED_DILATION_EXPONENTS = (5.0, 20.0, 30.0, 300.0, 700.0)


def kind_configurations(around1, around2):
    """Each kind alone (on its location, its axis and next to them), huge weights and strengths of
    either sign, and clusters of mixed kinds. A dilation multiplies distances from its location by
    e^c, c = strength w |v| / (k d^2 + eps): its cases take each of DILATION_EXPONENTS for c on
    the location, growing and shrinking, each point its own scale. The Jacobian is checked where the last element is
    True (the reference's central differences cost six images)."""
    axis1 = axis_points(X1, V1)
    for kind in ("rotation", "twist", "translation"):
        pitch = PITCH if kind == "twist" else 0.0
        points = around1 + (axis1 if kind != "translation" else []) + FAR
        lone = [generator(kind, X1, V1, 0.5, pitch)]
        yield (f"lone {kind}, eps 1e-10", 1.0, 1e-10, 1.0, lone, points, True, True)
        yield (f"lone {kind}, eps 1e-6", 1.0, 1e-6, 1.0, lone, points[::3], True, False)
        yield (f"lone {kind}, weight 1e12, eps 1e-2", 1.0, 1e-2, 1.0,
               [generator(kind, X1, V1, 1e12, pitch)], points[::3], True, False)
        yield (f"lone {kind}, strength -1e6, eps 1e-8", 1.0, 1e-8, -1e6, lone, points[::3], True,
               False)
    # a twist without pitch is the rotation: its location stays in place
    yield ("lone twist of pitch 0, eps 1e-10", 1.0, 1e-10, 1.0, [generator("twist", X1, V1, 0.5)],
           around1[::2] + axis1[:2] + FAR[:1], True, False)
    dilation_points = around1[::2] + FAR[:1]
    for exponent in DILATION_EXPONENTS:
        for eps, strength, weight in ((1e-10, 1.0, None), (1e-10, -1.0, None), (1e-8, -1e6, None),
                                      (None, 1.0, 1e12), (None, -1.0, 1e12)):
            if weight is None:
                weight = dilation_weight(exponent, eps, strength)
            else:  # the weight given, eps such that c is the exponent
                eps = weight * abs(strength) * math.sqrt(sum(c * c for c in V1)) / exponent
            yield from one_per_point(
                (f"lone dilation, c {exponent:g}, weight {weight:.3g}, eps {eps:.3g}, "
                 f"strength {strength:g}", 1.0, eps, strength,
                 [generator("dilation", X1, V1, weight)], dilation_points, True,
                 strength == 1.0 and eps == 1e-10))
    # a dilation with a rotation about an axis through its location (a loxodromic map: B has two
    # commuting planes), alone (the field's center on the location) and with a translation 0.4 away
    # (B has e_i^ni parts about the center, the fixed point moves)
    loxodromic_points = around1[::2] + axis1 + FAR[:1]
    paired_dilation_points = offsets(X1, NEAR + [1e-1, 1.0], DIRECTIONS[:1])
    for exponent in LOXODROMIC_EXPONENTS:
        for eps, strength in ((1e-10, 1.0), (1e-10, -1.0), (1e-8, -1e6)):
            spiral = [generator("dilation", X1, V1, dilation_weight(exponent, eps, strength)),
                      generator("rotation", X1, V1, dilation_weight(2.0, eps, strength))]
            for extra in ([], [generator("translation", X2, V2, 0.1)]):
                yield from one_per_point(
                    (f"a dilation and a rotation about its axis, c {exponent:g}, eps {eps:g}, "
                     f"strength {strength:g}{', a translation' if extra else ''}", 1.0, eps,
                     strength, spiral + extra, loxodromic_points, False,
                     strength == 1.0 and eps == 1e-10 and not extra))
    # a dilation beside point pairs (B has e_i^no parts: neither fixed point is ni, W != 0): the
    # map is loxodromic with two finite fixed points, one next to the dilation's location. With the
    # second pair the mean of three locations is not exact: the field's center, had it been that
    # mean, made p - center and x - center round, which moved the image 1e-5 from x (d^2 = eps at
    # eps 1e-10) by up to 8.2e-12 of the scale (c = 20); the center keeps those differences exact.
    for exponent in PAIRED_DILATION_EXPONENTS:
        for eps, strength in ((1e-10, 1.0), (1e-10, -1.0), (1e-8, -1e6)):
            dilation = generator("dilation", X1, V1, dilation_weight(exponent, eps, strength))
            for pairs in ([pair(X2, V2, 0.3)], [pair(X2, V2, 0.3), pair(FAR[0], V1, 0.5)]):
                yield from one_per_point(
                    (f"a dilation beside {len(pairs)} point pair(s), c {exponent:g}, eps {eps:g}, "
                     f"strength {strength:g}", 1.0, eps, strength, [dilation] + pairs,
                     paired_dilation_points, False,
                     strength == 1.0 and eps == 1e-10 and len(pairs) == 1))
    # a boost between two points (a hyperbolic 2-blade with e_i^no parts, W = 0: neither fixed point
    # is ni), given in space between the origin and X2 and as a point pair and a dilation at one
    # place, c = 5 ... 700 at the origin (at eps 1e4 the same everywhere: points next to X2 and 1
    # away are strong too): through the map's two fixed points. The strong sandwich it took before
    # lost e^{4a} 2^-53 of the image next to the repeller (wrong by 1e4 times its size at c = 30,
    # 1e-9 from it). Their Jacobians too at eps 1e-10 up to c = 30: beyond, e^c times the
    # reference's step (1e-25) leaves the map's linear range next to the repeller
    origin = (0.0, 0.0, 0.0)
    half = sum(c * c for c in X2) / 2
    with reference.mp.workdps(40):
        boost = [float(c) for c in reference.components_of(
            reference.wedge(reference.up(origin), reference.up(X2)))]
    near_origin = offsets(origin, [1e-9, 1e-5, 1.0], DIRECTIONS[:1])
    for exponent in BOOST_EXPONENTS:
        for strength in (1.0, -1.0):
            for eps in (1e-10, 1e-8, 1e4):
                points = near_origin + (offsets(X2, [1e-9, 1e-5], DIRECTIONS[1:]) if eps > 1 else [])
                yield from one_per_point(
                    (f"a boost between two points given in space, c {exponent:g}, eps {eps:g}, "
                     f"strength {strength:g}", 1.0, eps, strength,
                     [generator("bivector", origin, boost, exponent / 2 * eps / half)], points,
                     False, eps < 1e-9 and exponent <= 30))
            w = dilation_weight(exponent, 1e-10, strength)
            yield from one_per_point(
                (f"a point pair and a dilation at one place, c {exponent:g}, strength {strength:g}",
                 1.0, 1e-10, strength, [generator("dilation", origin, V1, w),
                                        generator("pair", origin, V2, w)], near_origin, False,
                 exponent <= 30))
    near3 = offsets(X3, NEAR, DIRECTIONS[:1])
    for eps, strength in ((1e-10, 1.0), (1e-10, -1.0), (1e-8, -1e6), (1e-6, 1e5)):
        mixed = [pair(X1, V1, 0.5), generator("rotation", X3, V3, 0.2),
                 generator("dilation", X2, V2, dilation_weight(5.0, eps, strength, V2)),
                 generator("translation", X2, V1, 0.4), generator("twist", X3, V2, 0.1, PITCH)]
        yield (f"every kind within 1e-3 and at 0.4, eps {eps:g}, strength {strength:g}", 1.0, eps,
               strength, mixed, around1[::2] + near3 + around2[::2] + FAR[:1], False,
               strength == 1.0)
    huge = [pair(X1, V1, 1e12), generator("rotation", X3, V3, 1e12),
            generator("translation", X2, V1, 1e12), generator("twist", X3, V2, 1e12, PITCH)]
    yield ("every kind but a dilation, weights 1e12, eps 1e-2", 1.0, 1e-2, 1.0, huge,
           around1[::3] + near3[::2] + around2[::2] + FAR[:1], False, False)
    # point pairs whose K = 1 + B has components beyond 1e154 (its sandwich's terms beyond the
    # doubles' range unless scaled): every point but the location moves next to it
    for weight in (1e160, -1e300):
        yield (f"lone pair, weight {weight:g}, eps 1e-2", 1.0, 1e-2, 1.0, [pair(X1, V1, weight)],
               around1[::2] + FAR, True, False)
    # a bivector given in space (no kind): moved to the center as it is; weights that make its
    # exponent (not a nearly nilpotent one: a rotation by 1.8 and a boost by 0.64 times w / eps
    # next to it) 1.8e3, 1.8e6 and 1.8e9 at eps 1e-10. Its Jacobian's tangents there take
    # double-double (docs/conventions.md section 3 item 15: double lost up to 0.02 of max(1, |J|)
    # at 1.8e9); the reference's central differences are checked against its Frechet derivative.
    for eps, weight in ((1e-10, 3e-7), (1e-10, 3e-4), (1e-10, 0.3), (1e-4, 0.3)):
        general = [generator("bivector", X2, REST, weight), pair(X1, V1, 0.5)]
        yield (f"a general bivector of weight {weight:g} and a pair, eps {eps:g}", 1.0, eps, 1.0,
               general, around1[::3] + around2[::2] + FAR[:1], False, "cross-checked")


def configurations():
    """(name, falloff, epsilon, strength, generators, points, lone, jacobian): lone marks one
    generator, jacobian the configurations whose Jacobians are checked."""
    around1 = offsets(X1, NEAR, DIRECTIONS)
    around2 = offsets(X2, NEAR[::2], DIRECTIONS[:2])
    yield from (case + (True,) for case in point_pair_configurations(around1, around2))
    yield from kind_configurations(around1, around2)


def run_probe(probe, cases):
    lines = []
    for _, falloff, eps, strength, generators, points, _, _ in cases:
        lines.append(f"{falloff!r} {eps!r} {strength!r} {len(generators)} {len(points)}")
        for kind, x, v, pitch, w in generators:
            values = (*x, *v, w) if kind == "bivector" else (*x, *v, pitch, w)
            lines.append(" ".join([str(KIND_CODES[kind])] + [repr(c) for c in values]))
        lines += [" ".join(repr(c) for c in p) for p in points]
    out = subprocess.run([probe], input="\n".join(lines) + "\n", capture_output=True, text=True,
                         check=True).stdout.split("\n")
    return iter(out)


def check_jacobian(name, p, jacobian, generators, falloff, eps, strength, verbose,
                   cross_check=False):
    """(1 if the Jacobian is beyond its bound (printed), else 0; 1 if it needed the condition
    term). With cross_check, the reference's central differences must also agree with its
    Frechet derivative (exact_reference.jacobian_by_frechet) to 1e-14 of max(1, |J|)."""
    ref = reference.jacobian(generators, p, falloff, eps, strength)
    if not all_finite(ref):
        print(f"FAIL {name}: {p} the reference Jacobian is not finite: {ref}")
        return 1, 0
    with reference.mp.workdps(reference.DIGITS):
        b = reference.field_bivector(generators, p, falloff, eps)
        exponent = float(largest(abs(c) for row in b for c in row)) * abs(strength)
    size = max(1.0, largest(abs(c) for c in ref))
    failures = conditioned = 0
    if cross_check:
        frechet = reference.jacobian_by_frechet(generators, p, falloff, eps, strength)
        disagreement = largest(abs(a - r) for a, r in zip(frechet, ref))
        if not disagreement <= 1e-14 * size:
            print(f"FAIL {name}: {p} the reference's central differences and Frechet derivative "
                  f"differ by {disagreement:.3g}")
            failures += 1
    # largest() and `not error <= bound` (not `error > bound`): a NaN must fail, not pass
    error = largest(abs(a - r) for a, r in zip(jacobian, ref))
    bound = size * (RELATIVE + JACOBIAN_EXPONENT_FACTOR * max(1.0, exponent))
    if not error <= bound:
        # an ill-conditioned Jacobian: one ulp of B(p) or dB/dp moves it beyond the bound
        bound += CONDITION_FACTOR * reference.jacobian_sensitivity(generators, p, falloff, eps,
                                                                   strength)
        conditioned = 1
    if verbose and error > RELATIVE * size:
        print(f"  {name}: {p} Jacobian error {error:.3g} = {error / size:.3g} of max(1, |J|), "
              f"|sB| {exponent:.3g}, bound {bound:.3g}{' (conditioned)' if conditioned else ''}")
    if not error <= bound:
        print(f"FAIL {name}: {p} Jacobian error {error:.3g} > bound {bound:.3g}")
        failures += 1
    return failures, conditioned


def point_pair_components(x, v):
    """tau(x, v) = up(x) ^ (v + (v.x) ni) in the project's ten null-basis components (doubles)."""
    vx = sum(a * b for a, b in zip(v, x))
    half_square = sum(a * a for a in x) / 2
    e12, e13, e23 = (x[0] * v[1] - x[1] * v[0], x[0] * v[2] - x[2] * v[0], x[1] * v[2] - x[2] * v[1])
    no_part = [-c for c in v]                                          # no ^ v = -v_i e_i ^ no
    ni_part = [vx * x[i] - half_square * v[i] for i in range(3)]       # (v.x) x ^ ni + |x|^2/2 ni ^ v
    return [e12, e13, e23, *no_part, *ni_part, vx]


EXPONENT_LAMBDAS = (1e2, 1e4, 1e6, 1e8, 1e10, 1e12)
EXPONENT_RESTS = (0.0, 1e-10, 1e-8, 1e-6, 1e-4, 1e-2)
EXPONENT_DISTANCES = (1e-9, 1e-7, 1e-5, 1e-3, 1e-1, 1.0, 10.0)


def exponent_cases():
    """(name, [(b, p)]): b = lam tau(X1, V1) + delta REST at X1, at each distance from it in two
    directions, and at FAR[0]; each distance its own case (its own scale)."""
    tau = point_pair_components(X1, V1)
    for lam in EXPONENT_LAMBDAS:
        for delta in EXPONENT_RESTS:
            b = [lam * t + delta * r for t, r in zip(tau, REST)]
            name = f"exponent {lam:g} tau + {delta:g} rest"
            yield f"{name} on x", [(b, tuple(X1))]
            for distance in EXPONENT_DISTANCES:
                yield (f"{name}, {distance:g} from x",
                       [(b, p) for p in offsets(X1, [distance], DIRECTIONS)[1:]])
            yield f"{name} at {FAR[0]}", [(b, FAR[0])]


def check_exponents(probe, verbose):
    cases = list(exponent_cases())
    lines = [str(sum(len(pairs) for _, pairs in cases))]
    for _, pairs in cases:
        lines += [" ".join(repr(c) for c in (*b, *p)) for b, p in pairs]
    output = iter(subprocess.run([probe, "exponents"], input="\n".join(lines) + "\n",
                                 capture_output=True, text=True, check=True).stdout.split("\n"))
    failures = 0
    for name, pairs in cases:
        refs, got = [], []
        for b, p in pairs:
            got.append(read_values(next(output), 6))
            with reference.mp.workdps(reference.DIGITS):
                refs.append(reference.image_of_bivector(
                    reference.bivector_from_components(b), p, -1.0))
        size = max(abs(c) for _, p in pairs for c in p)
        displacement = largest(math.dist([float(c) for c in r], p) for r, (_, p) in zip(refs, pairs))
        scale = max(size, displacement)
        for (b, p), ref, q in zip(pairs, refs, got):
            if q is None:
                print(f"FAIL {name}: {p} unmapped")
                failures += 1
                continue
            if not all_finite(q) or not all_finite(ref):
                print(f"FAIL {name}: {p} not finite: batch and pointwise images {q}, reference {ref}")
                failures += 1
                continue
            errors = [float(reference.mpmath.sqrt(sum((image[i] - ref[i]) ** 2 for i in range(3))))
                      for image in (q[:3], q[3:])]
            bound = RELATIVE * scale
            if not errors[0] <= bound:
                with reference.mp.workdps(reference.DIGITS):
                    bound += CONDITION_FACTOR * reference.bivector_sensitivity(
                        reference.bivector_from_components(b), p, -1.0)
            if not errors[0] <= bound:
                print(f"FAIL {name}: {p} error {errors[0]:.3g} > bound {bound:.3g}")
                failures += 1
            if verbose:
                print(f"  {name}: {p} batch error {errors[0]:.3g} (bound {bound:.3g}), "
                      f"pointwise sandwich {errors[1]:.3g}")
    check_read_all(output, "exponents'")
    return failures


PATHS = ("batch", "pointwise", "rows batch", "rows pointwise")


def all_finite(values):
    """Every number (float or mpmath's) is finite: a NaN or an infinity from the probe or the
    reference is a failure of its own, never an error that comparisons let through."""
    return all(reference.mpmath.isfinite(c) for c in values)


def read_values(line, count):
    """The `count` numbers of one line of the probe, or None for "unmapped". A line of another
    length is an error: read loosely, a short line would check fewer images or Jacobian entries
    without a word."""
    fields = line.split()
    if fields == ["unmapped"]:
        return None
    if len(fields) != count:
        raise ValueError("the probe wrote %d values where %d were expected: %r"
                         % (len(fields), count, line))
    return [float(f) for f in fields]


def read_images(line, rows):
    """The probe's line: None ("unmapped"), or (images by path name, Jacobian); `rows`: the
    configuration is also built from rows (every generator but a bivector), whose two images
    the probe then adds."""
    values = read_values(line, 21 if rows else 15)
    if values is None:
        return None
    images = {"batch": values[:3], "pointwise": values[3:6]}
    if rows:
        images["rows batch"], images["rows pointwise"] = values[15:18], values[18:21]
    return images, values[6:15]


def check_read_all(output, what):
    """Every line of the probe's `output` was read: a line more would be a result unchecked."""
    rest = [line for line in output if line.strip()]
    if rest:
        raise ValueError("%d lines of the probe's %s output unread, the first %r"
                         % (len(rest), what, rest[0]))


def check_configuration(case, output, verbose):
    """(failures, images and Jacobians checked against the condition-scaled bound) of one
    configuration."""
    name, falloff, eps, strength, generators, points, lone, check_jacobians = case
    rows = all(kind != "bivector" for kind, *_ in generators)
    got_all = [read_images(next(output), rows) for _ in points]
    refs = [reference.image(generators, p, falloff, eps, strength) for p in points]
    size = max(abs(c) for p in points for c in p)
    displacement = largest(math.dist([float(c) for c in r], p) for r, p in zip(refs, points))
    scale = max(size, displacement)
    failures = conditioned = jacobians_conditioned = 0
    worst = 0.0
    for p, ref, got in zip(points, refs, got_all):
        if got is None:
            print(f"FAIL {name}: {p} unmapped")
            failures += 1
            continue
        images, jacobian = got
        # the Jacobian (NaN where mapWithJacobian refused it) only where it is checked
        checked = [c for q in images.values() for c in q] + (jacobian if check_jacobians else [])
        if not all_finite(checked) or not all_finite(ref):
            print(f"FAIL {name}: {p} not finite: images {images}, Jacobian {jacobian}, "
                  f"reference {ref}")
            failures += 1
            continue
        if check_jacobians:
            f, c = check_jacobian(name, p, jacobian, generators, falloff, eps, strength, verbose,
                                  check_jacobians == "cross-checked")
            failures += f
            jacobians_conditioned += c
        sensitivity = None
        for path in PATHS:
            if path not in images:
                continue
            q = images[path]
            error = float(reference.mpmath.sqrt(sum((q[i] - ref[i]) ** 2 for i in range(3))))
            bound = RELATIVE * scale
            if not error <= bound:
                if sensitivity is None:
                    sensitivity = reference.one_ulp_sensitivity(generators, p, falloff, eps,
                                                                strength)
                bound += CONDITION_FACTOR * sensitivity
                conditioned += 1
                if verbose:
                    print(f"  {name}: {p} {path} error {error:.3g} beyond 1e-12 scale; "
                          f"one-ulp sensitivity {sensitivity:.3g}")
            if not error <= bound:
                print(f"FAIL {name}: {p} {path} error {error:.3g} > bound {bound:.3g}")
                failures += 1
            if scale:  # a fixed point at the origin: scale 0, bound 0, so it must map exactly
                worst = largest([worst, error / scale])
            if lone and has_fixed_location(generators[0]) and p == generators[0][1] and \
                    tuple(q) != p:
                print(f"FAIL {name}: the point on the lone generator moved to {q} ({path})")
                failures += 1
        # one source for both paths, each lane its own branch: the same bits
        for batch, pointwise in (("batch", "pointwise"), ("rows batch", "rows pointwise")):
            if batch in images and images[batch] != images[pointwise]:
                print(f"FAIL {name}: {p} {batch} {images[batch]} differs from {pointwise} "
                      f"{images[pointwise]}")
                failures += 1
    if verbose:
        print(f"{name}: scale {scale:.3g}, worst error / scale {worst:.3g}")
    return failures, (conditioned, jacobians_conditioned)


def main():
    probe = sys.argv[1]
    verbose = "-v" in sys.argv
    cases = list(configurations())
    output = run_probe(probe, cases)
    failures = conditioned = jacobians_conditioned = 0
    for case in cases:
        f, (c, j) = check_configuration(case, output, verbose)
        failures += f
        conditioned += c
        jacobians_conditioned += j
    check_read_all(output, "configurations'")
    failures += check_exponents(probe, verbose)
    print(f"{failures} failures; {conditioned} images and {jacobians_conditioned} Jacobians checked "
          f"against the condition-scaled bound")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
