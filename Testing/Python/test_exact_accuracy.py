"""The Exact rule against a high-precision reference (exact_reference.py: the 5x5 matrix exponential
of the versor's action in mpmath, computed from the same double inputs), on adversarial fields:
points on a generator and 1e-9 ... 1e-3 from one, epsilon from 1e-10 to 1e3, clustered generators,
huge weights and strengths (of either sign) (docs/conventions.md section 2 item 12 states the bound tested here).

Each image, from the batch path (PointPairField::mapPoints) and the pointwise path (map), printed by
the ExactAccuracyProbe program, must lie within

    1e-12 * scale + 8 * sensitivity

of the reference, where scale is the configuration's largest coordinate or reference displacement,
and sensitivity the reference image's movement when B(p) changes by one unit in the last place
(exact_reference.one_ulp_sensitivity, computed only for points that miss the first term; it is
what no double computation of B(p) can avoid, large only where the problem is ill-conditioned).
A point on a lone generator must stay on it exactly, and the batch image must equal the pointwise
one to the bit (their blocks mix points near and far from generators, which take different
frames).

The Jacobian d image / d p (PointPairField::mapWithJacobian, forward-mode differentiation) must lie
within

    max(1, |J|) * (1e-12 + 8 * 2^-52 * max(1, strength |B(p)|))

of the reference's (exact_reference.jacobian: central differences at 70 digits), entry by entry,
|.| the largest entry or component: the derivative is exact to rounding relative to the size of
the exponent, which next to a generator with a tiny epsilon is huge (docs/conventions.md section 3
item 15 states this bound).

Given exponents (mapPointsByExponentials, the curvature patch's map): nearly nilpotent ones, a
huge point pair lambda tau(x, v) (lambda 1e2 ... 1e12) plus a small rest (0 ... 1e-2), at points on
x and 1e-9 ... 10 from it, against the same bound (the pointwise sandwichPoint(exponential(b)) is
shown with -v: it is not held to it). Far from x these take the double-double branch
(docs/conventions.md section 2 item 12).

    python3 test_exact_accuracy.py <ExactAccuracyProbe> [-v]
"""
import math
import subprocess
import sys

import exact_reference as reference

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


DIRECTIONS = [(0.6, -0.3, 0.7), (-0.2, 0.9, 0.1)]
NEAR = [1e-9, 1e-7, 1e-5, 1e-3]
FAR = [(0.9, 0.4, -0.5), (-1.5, 2.0, 0.3)]
X1, V1 = (0.3, -0.2, 0.1), (0.4, 0.7, -0.5)
X2, V2 = (0.7, -0.1, -0.1), (-0.3, 0.2, 0.9)
X3, V3 = (0.3004, -0.2003, 0.1002), (0.9, 0.1, 0.2)


def configurations():
    """(name, falloff, epsilon, strength, generators, points, lone): lone marks one generator."""
    around1 = offsets(X1, NEAR, DIRECTIONS)
    around2 = offsets(X2, NEAR[::2], DIRECTIONS[:2])
    for eps in (1e-10, 1e-6):
        yield (f"lone pair, eps {eps:g}", 1.0, eps, 1.0, [(X1, V1, 0.5)], around1 + FAR, True)
    for eps in (1e-10, 1e-8, 1e-4):
        yield (f"two pairs, eps {eps:g}", 1.0, eps, 1.0, [(X1, V1, 0.5), (X2, V2, 0.3)],
               around1 + around2 + FAR, False)
    yield ("three pairs within 1e-3, eps 1e-10", 1.0, 1e-10, 1.0,
           [(X1, V1, 0.5), (X2, V2, 0.3), (X3, V3, 0.2)],
           around1 + offsets(X3, NEAR[:2], DIRECTIONS[:1]) + FAR, False)
    yield ("lone pair, weight 1e8, eps 1e-10", 1.0, 1e-10, 1.0, [(X1, V1, 1e8)], around1 + FAR, True)
    yield ("two pairs, weights 1e6, eps 1e-10", 1.0, 1e-10, 1.0, [(X1, V1, 1e6), (X2, V2, 1e6)],
           around1 + around2 + FAR, False)
    yield ("two pairs, weights 1e12, eps 1e-2", 1.0, 1e-2, 1.0, [(X1, V1, 1e12), (X2, V2, 3e11)],
           around1 + around2 + FAR, False)
    yield ("two pairs, strength 1e5, falloff 4, eps 1e-6", 4.0, 1e-6, 1e5,
           [(X1, V1, 0.5), (X2, V2, 0.3)], around1 + around2 + FAR, False)
    # every epsilon >= 1e-10: large ones too (B small and smooth: the field's frame)
    for eps in (1.0, 1e3):
        yield (f"two pairs, eps {eps:g}", 1.0, eps, 1.0, [(X1, V1, 0.5), (X2, V2, 0.3)],
               around1 + around2 + FAR, False)
    yield ("lone pair, strength 1e8, eps 1e-10", 1.0, 1e-10, 1e8, [(X1, V1, 0.5)], around1 + FAR, True)
    yield ("two pairs, strength -1e6, eps 1e-8", 1.0, 1e-8, -1e6, [(X1, V1, 0.5), (X2, V2, 0.3)],
           around1 + around2 + FAR, False)


def run_probe(probe, cases):
    lines = []
    for _, falloff, eps, strength, generators, points, _ in cases:
        lines.append(f"{falloff!r} {eps!r} {strength!r} {len(generators)} {len(points)}")
        lines += [" ".join(repr(c) for c in (*x, *v, w)) for x, v, w in generators]
        lines += [" ".join(repr(c) for c in p) for p in points]
    out = subprocess.run([probe], input="\n".join(lines) + "\n", capture_output=True, text=True,
                         check=True).stdout.split("\n")
    return iter(out)


def check_jacobian(name, p, jacobian, generators, falloff, eps, strength, verbose):
    """1 if the Jacobian is beyond its bound (printed), else 0."""
    ref = reference.jacobian(generators, p, falloff, eps, strength)
    with reference.mp.workdps(reference.DIGITS):
        b = reference.field_bivector(generators, p, falloff, eps)
        exponent = float(max(abs(c) for row in b for c in row)) * abs(strength)
    size = max(1.0, max(abs(c) for c in ref))
    error = max(abs(a - r) for a, r in zip(jacobian, ref))
    bound = size * (RELATIVE + JACOBIAN_EXPONENT_FACTOR * max(1.0, exponent))
    if verbose and error > RELATIVE * size:
        print(f"  {name}: {p} Jacobian error {error:.3g} = {error / size:.3g} of max(1, |J|), "
              f"|sB| {exponent:.3g}")
    if error > bound:
        print(f"FAIL {name}: {p} Jacobian error {error:.3g} > bound {bound:.3g}")
        return 1
    return 0


def point_pair_components(x, v):
    """tau(x, v) = up(x) ^ (v + (v.x) ni) in the project's ten null-basis components (doubles)."""
    vx = sum(a * b for a, b in zip(v, x))
    half_square = sum(a * a for a in x) / 2
    e12, e13, e23 = (x[0] * v[1] - x[1] * v[0], x[0] * v[2] - x[2] * v[0], x[1] * v[2] - x[2] * v[1])
    no_part = [-c for c in v]                                          # no ^ v = -v_i e_i ^ no
    ni_part = [vx * x[i] - half_square * v[i] for i in range(3)]       # (v.x) x ^ ni + |x|^2/2 ni ^ v
    return [e12, e13, e23, *no_part, *ni_part, vx]


REST = [0.3, -0.2, 0.5, 0.1, 0.4, -0.3, 0.2, -0.1, 0.6, 0.25]


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
            fields = next(output).split()
            got.append(None if fields == ["unmapped"] else [float(f) for f in fields])
            with reference.mp.workdps(reference.DIGITS):
                refs.append(reference.image_of_bivector(
                    reference.bivector_from_components(b), p, -1.0))
        size = max(abs(c) for _, p in pairs for c in p)
        displacement = max(math.dist([float(c) for c in r], p) for r, (_, p) in zip(refs, pairs))
        scale = max(size, displacement)
        for (b, p), ref, q in zip(pairs, refs, got):
            if q is None:
                print(f"FAIL {name}: {p} unmapped")
                failures += 1
                continue
            errors = [float(reference.mpmath.sqrt(sum((image[i] - ref[i]) ** 2 for i in range(3))))
                      for image in (q[:3], q[3:])]
            bound = RELATIVE * scale
            if errors[0] > bound:
                with reference.mp.workdps(reference.DIGITS):
                    bound += CONDITION_FACTOR * reference.bivector_sensitivity(
                        reference.bivector_from_components(b), p, -1.0)
            if errors[0] > bound:
                print(f"FAIL {name}: {p} error {errors[0]:.3g} > bound {bound:.3g}")
                failures += 1
            if verbose:
                print(f"  {name}: {p} batch error {errors[0]:.3g} (bound {bound:.3g}), "
                      f"pointwise sandwich {errors[1]:.3g}")
    return failures


def main():
    probe = sys.argv[1]
    verbose = "-v" in sys.argv
    cases = list(configurations())
    output = run_probe(probe, cases)
    failures = 0
    conditioned = 0
    for name, falloff, eps, strength, generators, points, lone in cases:
        images = []
        for p in points:
            fields = next(output).split()
            if fields == ["unmapped"]:
                images.append(None)
            else:
                values = [float(f) for f in fields]
                images.append((values[:3], values[3:6], values[6:15]))
        refs = [reference.image(generators, p, falloff, eps, strength) for p in points]
        size = max(abs(c) for p in points for c in p)
        displacement = max(math.dist([float(c) for c in r], p) for r, p in zip(refs, points))
        scale = max(size, displacement)
        worst = 0.0
        for p, ref, got in zip(points, refs, images):
            if got is None:
                print(f"FAIL {name}: {p} unmapped")
                failures += 1
                continue
            failures += check_jacobian(name, p, got[2], generators, falloff, eps, strength, verbose)
            got = got[:2]
            for path, q in zip(("batch", "pointwise"), got):
                error = float(reference.mpmath.sqrt(sum((q[i] - ref[i]) ** 2 for i in range(3))))
                bound = RELATIVE * scale
                if error > bound:
                    sensitivity = reference.one_ulp_sensitivity(generators, p, falloff, eps, strength)
                    bound += CONDITION_FACTOR * sensitivity
                    conditioned += 1
                    if verbose:
                        print(f"  {name}: {p} {path} error {error:.3g} beyond 1e-12 scale; "
                              f"one-ulp sensitivity {sensitivity:.3g}")
                if error > bound:
                    print(f"FAIL {name}: {p} {path} error {error:.3g} > bound {bound:.3g}")
                    failures += 1
                worst = max(worst, error / scale)
            if got[0] != got[1]:
                # one source for both paths, each lane its own branch: the same bits
                print(f"FAIL {name}: {p} batch {got[0]} differs from pointwise {got[1]}")
                failures += 1
            if lone and p == generators[0][0] and tuple(got[0]) != p:
                print(f"FAIL {name}: the point on the lone generator moved to {got[0]}")
                failures += 1
        if verbose:
            print(f"{name}: scale {scale:.3g}, worst error / scale {worst:.3g}")
    failures += check_exponents(probe, verbose)
    print(f"{failures} failures; {conditioned} images checked against the condition-scaled bound")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
