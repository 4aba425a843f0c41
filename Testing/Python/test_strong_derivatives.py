"""d out / d B (PointPairField::mapWithBivectorDerivative) and d out / d w_i
(mapWithWeightDerivatives) next to a strong dilation, against a high-precision reference without
differences (exact_reference.bivector_derivatives: the Frechet derivative of the 5x5 matrix
exponential of the versor's action, by the Taylor series and squarings of the block matrix
[[X, E], [0, X]] in fixed point on Python integers, then fn's quotient rule, from the same double
B(p) the code differentiates; checked here against mpmath.expm of that block on one point per
run).

Fields (falloff 1, epsilon 1e-10, strength +1 and -1: the dilation grows or shrinks): a lone
dilation, a dilation with a rotation by 2 about its axis (a loxodromic map), and that with a
translation 0.4 away (the fixed point is not on the field's center), and a dilation beside a
point pair (B is not a similarity's there: the image through the map's two fixed points, whose dual
numbers' tangents follow the fixed points; refused before, as a strong boost), with the factor e^c,
c = 5, 30, 300 on the location; points on the location and 1e-9, 1e-5 and 1 from it (c at 1e-9
is that on the location, at 1e-5 half of it, at 1 the map is far from strong). Each
derivative must lie within

    max(1, |D|) * (1e-12 + 8 * 2^-52 * max(1, |strength B(p)|))

of the reference's, entry by entry, |.| the largest entry of the reference D (for d out / d w_i:
max(1, |d out / d B| |d B / d w_i|), the size the sum of its ten terms can err relative to)
(docs/conventions.md section 3 item 15). Along seeds that move B's e_i^no parts B leaves the
similarities, and the strong sandwich's parts that are exactly zero there have tangents that are
the derivative itself: before the closed form of those lanes the derivative missed this by up to
the derivative's whole size. Strong boosts between two points (hyperbolic 2-blades with e_i^no
parts: given in space between the origin and X2 at epsilon 1e-10, 1e-8 and 1e4, where c is the same
everywhere and points on and next to X2 are strong too; a point pair and a dilation at the origin;
c = 5, 30, 300, 700 both ways) take the closed form conjugated by the inversion about the repeller:
there a refusal (false, the behaviour before it) is a failure, like any point left unmapped.

Every number the probe writes, and every reference one, must be finite: a NaN would pass any
comparison with a bound, so it is a failure of its own (errors are folded by largest(), which keeps
a NaN, and fail on `not error <= bound`).

    python3 test_strong_derivatives.py <ExactAccuracyProbe> [-v]
"""
import math
import subprocess
import sys
import time

import exact_reference as reference
from python_test_common import largest
from test_exact_accuracy import (KIND_CODES, X1, V1, X2, V2, DIRECTIONS, all_finite,
                                 dilation_weight, generator, offsets, read_values, check_read_all)

RELATIVE = 1e-12
EXPONENT_FACTOR = 8.0 * 2.0 ** -52
EPSILON = 1e-10
EXPONENTS = (5.0, 30.0, 300.0)
BOOST_EXPONENTS = (5.0, 30.0, 300.0, 700.0)
DISTANCES = (1e-9, 1e-5, 1.0)
UNITS = [[1 if i == k else 0 for i in range(10)] for k in range(10)]


def configurations():
    """(name, strength, generators, points, epsilon). Every field has its center (the mean location) at the
    origin, exactly: there generatorAt(p), the B(p) the reference is given, is the exponent the
    derivative is taken at to the bit (elsewhere it is that moved to space and rounded, which
    moves a strong dilation's fixed point, and the derivative with it, by its rounding). A
    dilation off the origin gets a generator of weight 0 at the opposite place (which also checks
    d out / d w at a zero weight)."""
    origin = (0.0, 0.0, 0.0)
    for exponent in EXPONENTS:
        for strength in (1.0, -1.0):
            def of(kind, x, c, v=V1):
                return generator(kind, x, v, dilation_weight(c, EPSILON, strength, v))
            mirror = tuple(-c for c in X1)
            fields = [
                ("lone dilation on the center", [of("dilation", origin, exponent)], origin),
                ("dilation", [of("dilation", X1, exponent), generator("dilation", mirror, V2, 0.0)],
                 X1),
                ("dilation and rotation about its axis",
                 [of("dilation", X1, exponent), of("rotation", X1, 2.0),
                  generator("dilation", mirror, V2, 0.0), generator("rotation", mirror, V2, 0.0)],
                 X1),
                ("dilation, rotation and a translation",
                 [of("dilation", X1, exponent), of("rotation", X1, 2.0),
                  generator("translation", X2, V2, 0.1),
                  generator("translation", tuple(-(2.0 * a + b) for a, b in zip(X1, X2)), V1,
                            0.0)], X1)]
            fields.append(("dilation beside a point pair",
                 [of("dilation", X1, exponent), generator("pair", X2, V2, 0.3),
                  generator("dilation", mirror, V2, 0.0),
                  generator("pair", tuple(-b for b in X2), V1, 0.0)], X1))
            for name, generators, location in fields:
                yield (f"{name}, c {exponent:g}, strength {strength:g}", strength, generators,
                       offsets(location, DISTANCES, DIRECTIONS[:1]), EPSILON)
    # strong boosts between two finite points (hyperbolic 2-blades with e_i^no parts: the closed
    # form conjugated by the inversion about the repeller; refused before)
    half = sum(c * c for c in X2) / 2     # |up(0) ^ up(X2)| = |X2|^2 / 2
    with reference.mp.workdps(40):
        boost = [float(c) for c in reference.components_of(
            reference.wedge(reference.up((0.0, 0.0, 0.0)), reference.up(X2)))]
    for exponent in BOOST_EXPONENTS:
        for strength in (1.0, -1.0):
            for name, epsilon, generators, points in boost_fields(exponent, strength, boost, half):
                yield (f"{name}, c {exponent:g}, strength {strength:g}", strength, generators,
                       points, epsilon)


def boost_fields(exponent, strength, boost, half):
    """(name, epsilon, generators, points): the boost between the origin and X2 given in space at
    epsilon 1e-10 and 1e-8 (strong within about sqrt(epsilon) of the origin) and at epsilon 1e4 with
    the weight scaled alike (c the same within 1e-4 everywhere: points on and next to X2 and 1 away
    are strong too), and a point pair and a dilation at the origin (B = no ^ (w v + k ni), a
    2-blade; the other fixed point 0.9 away)."""
    origin = (0.0, 0.0, 0.0)
    near_origin = offsets(origin, DISTANCES, DIRECTIONS[:1])
    for epsilon in (1e-10, 1e-8):
        yield (f"a boost between two points given in space, eps {epsilon:g}", epsilon,
               [generator("bivector", origin, boost, exponent / 2 * epsilon / half)], near_origin)
    epsilon = 1e4
    yield ("a boost between two points given in space, eps 1e4", epsilon,
           [generator("bivector", origin, boost, exponent / 2 * epsilon / half)],
           near_origin + offsets(X2, DISTANCES[:2], DIRECTIONS[1:]))
    w = dilation_weight(exponent, EPSILON, strength, V1)
    yield ("a point pair and a dilation at one place", EPSILON,
           [generator("dilation", origin, V1, w), generator("pair", origin, V2, w)], near_origin)


def run_probe(probe, cases):
    lines = []
    for _, strength, generators, points, epsilon in cases:
        lines.append(f"1.0 {epsilon!r} {strength!r} {len(generators)} {len(points)}")
        for kind, x, v, pitch, w in generators:
            values = (*x, *v, w) if kind == "bivector" else (*x, *v, pitch, w)
            lines.append(" ".join([str(KIND_CODES[kind])] + [repr(c) for c in values]))
        lines += [" ".join(repr(c) for c in p) for p in points]
    out = subprocess.run([probe, "derivatives"], input="\n".join(lines) + "\n",
                         capture_output=True, text=True, check=True).stdout.split("\n")
    return iter(out)


def weight_direction(generator_row, p, epsilon):
    """d B / d w = G / (k |p - x|^2 + eps) at p, in the ten null-basis components: G from the
    definitions (exact_reference.generator_bivector, at weight 1; its direction's length included)."""
    with reference.mp.workdps(40):
        s = reference.generator_bivector(generator_row)
        d = sum((reference.mpf(a) - reference.mpf(b)) ** 2 for a, b in zip(p, generator_row[1]))
        return [c / (d + reference.mpf(epsilon)) for c in reference.components_of(s)]


def derivative_sensitivity(components, directions, p, strength, trials=3, seed=1):
    """The largest change of d out / d B (its largest entry) when every component of the double
    B(p) changes by one unit in the last place (exact_reference.one_ulp_change): what no derivative
    computed from the double B(p) can avoid. Next to a repeller that the double B(p) does not hold
    to the bit, with e^c large, it is of the derivative's own size."""
    def derivative(inputs):
        _, columns = reference.bivector_derivatives(inputs[0], directions, p, strength)
        return [value for column in columns[:10] for value in column]
    return reference.one_ulp_change(derivative, [components], reference.largest_entry_change,
                                    trials, seed)


def check_reference(components, p, strength, ref):
    """The fixed-point Frechet derivative against mpmath.expm of the block matrix (one column)."""
    mpmath, mp, mpf = reference.mpmath, reference.mp, reference.mpf
    with mp.workdps(60 + int(4 * 300 / 2.3)):
        x = reference.action([[-mpf(strength) * c for c in row]
                              for row in reference.bivector_from_components(components)])
        e = reference.action([[-mpf(strength) * c for c in row]
                              for row in reference.bivector_from_components(UNITS[3])])
        exponential, frechet = reference.frechet_expm(x, e)
        u = mpmath.matrix(reference.up(p))
        y, dy = exponential * u, frechet * u
        weight, dweight = y[3] + y[4], dy[3] + dy[4]
        column = [(dy[i] - y[i] / weight * dweight) / weight for i in range(3)]
    size = max(1.0, largest(abs(float(c)) for c in column))
    return largest(abs(float(c) - r) for c, r in zip(column, ref[3])) / size


def main():
    probe = sys.argv[1]
    verbose = "-v" in sys.argv
    start = time.time()
    cases = list(configurations())
    output = run_probe(probe, cases)
    failures = checked = conditioned = 0
    worst = 0.0
    cross_checked = False
    for name, strength, generators, points, epsilon in cases:
        for p in points:
            values = read_values(next(output), 43 + 3 * len(generators))
            if values is None:  # refused (false): a failure, as the refusal of the strong boosts was
                print(f"FAIL {name}: {p} unmapped")
                failures += 1
                continue
            b, by_bivector, by_weight = values[:10], values[13:43], values[43:]
            directions = UNITS + [weight_direction(g, p, epsilon) for g in generators]
            _, ref = reference.bivector_derivatives(b, directions, p, strength)
            # a NaN would pass every `error > bound`: every number must be finite first
            if not all_finite(values) or not all_finite(c for column in ref for c in column):
                print(f"FAIL {name}: {p} not finite: the probe's {values}, the reference's {ref}")
                failures += 1
                continue
            if not cross_checked and "translation, c 300" in name and p != points[0]:
                disagreement = check_reference(b, p, strength, ref)
                cross_checked = True
                if not disagreement <= 1e-30:
                    print(f"FAIL the reference's Frechet derivative and mpmath.expm's differ by "
                          f"{disagreement:.3g}")
                    failures += 1
            exponent = max(1.0, abs(strength) * largest(abs(c) for c in b))
            factor = RELATIVE + EXPONENT_FACTOR * exponent
            size_b = max(1.0, largest(abs(c) for column in ref[:10] for c in column))
            error_b = largest(abs(by_bivector[10 * j + k] - ref[k][j]) for k in range(10)
                              for j in range(3)) / size_b
            errors = [("d out / d B", error_b)]
            for i in range(len(generators)):
                scale = float(largest(abs(c) for c in directions[10 + i]))
                size_w = max(1.0, largest(abs(c) for c in ref[10 + i]),
                             scale * largest(abs(c) for column in ref[:10] for c in column))
                errors.append((f"d out / d w_{i}",
                               largest(abs(by_weight[3 * i + j] - ref[10 + i][j])
                                       for j in range(3)) / size_w))
            sensitivity = None
            for what, error in errors:
                checked += 1
                bound = factor
                if not error <= bound and what == "d out / d B":
                    # ill-conditioned: within the bound plus 8 times the one-ulp sensitivity
                    if sensitivity is None:
                        sensitivity = derivative_sensitivity(b, UNITS, p, strength) / size_b
                        conditioned += 1
                    bound += 8.0 * sensitivity
                worst = largest([worst, error / bound])
                if not error <= bound:
                    print(f"FAIL {name}: {p} {what} error {error:.3g} of its size > {bound:.3g}")
                    failures += 1
                elif verbose:
                    print(f"  {name}: {p} {what} error {error:.3g} of its size "
                          f"({error / bound:.3g} of the bound)")
    check_read_all(output, "derivatives'")
    print(f"{failures} failures of {checked} derivatives; the worst at {worst:.3g} of its bound; "
          f"{conditioned} points with the condition term ({time.time() - start:.1f} s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
