"""An independent high-precision reference for the Exact point map of a field of generators of
every kind (docs/conventions.md section 3 item 9, section 2 item 11), from the definitions alone:
no code of the project.

Vectors of R^{4,1} are 5-tuples over e1, e2, e3, e+, e- (metric +, +, +, +, -), no = (e- + e+)/2,
ni = e- - e+, up(x) = no + x + |x|^2/2 ni, tau(x, v) = up(x) ^ (v + (v.x) ni), and the other kinds from their definitions (generator_bivector).
A bivector B acts on
vectors by X -> B X - X B = -2 X.B, with X.(a ^ b) = (X.a) b - (X.b) a, so the versor exp(B) acts as
the matrix exponential of that 5x5 map (mpmath.expm). The image of p under
K = exp(-strength B(p)), B(p) = sum_i w_i G_i / (k |p - x_i|^2 + eps), is fn(expm(-strength
A(B)) up(p)): the Euclidean part divided by -ni.Y. Every input double enters exactly (mpf(float)).
"""
import functools
import operator
import random

import mpmath
from mpmath import mp, mpf

METRIC = (1, 1, 1, 1, -1)
DIGITS = 30


def _vector(x=(0, 0, 0), e_plus=0, e_minus=0):
    return [mpf(x[0]), mpf(x[1]), mpf(x[2]), mpf(e_plus), mpf(e_minus)]


def dot(a, b):
    return sum(METRIC[i] * a[i] * b[i] for i in range(5))


def combine(*terms):
    """sum of coefficient * vector"""
    return [sum(c * v[i] for c, v in terms) for i in range(5)]


NO = _vector(e_plus=mpf(1) / 2, e_minus=mpf(1) / 2)
NI = _vector(e_plus=-1, e_minus=1)


def up(x):
    half_square = sum(mpf(c) ** 2 for c in x) / 2
    return combine((1, NO), (1, _vector(x)), (half_square, NI))


def wedge(a, b):
    """a ^ b as the antisymmetric 5x5 array S (S[i][j] = a_i b_j - a_j b_i)."""
    return [[a[i] * b[j] - a[j] * b[i] for j in range(5)] for i in range(5)]


def add_to(total, coefficient, s):
    for i in range(5):
        for j in range(5):
            total[i][j] += coefficient * s[i][j]


def point_pair(x, v):
    """tau(x, v) = up(x) ^ (v + (v.x) ni)."""
    vx = sum(mpf(v[i]) * mpf(x[i]) for i in range(3))
    return wedge(up(x), combine((1, _vector(v)), (vx, NI)))


def translated(e, x):
    """T(x) e ~T(x) for a vector e: e_i -> e_i + x_i ni, no -> up(x), ni -> ni (so up(y) -> up(x + y))."""
    no_part = e[3] + e[4]                # e = ... + a no + b ni: e+ = a/2 - b, e- = a/2 + b
    euclidean = sum(e[i] * mpf(x[i]) for i in range(3))
    return combine((1, e), (no_part, up(x)), (-no_part, NO), (euclidean, NI))


def half_dual_line(x, a):
    """1/2 T(x) (a I3) ~T(x), I3 = e1 e2 e3: a I3 = a_z e1^e2 - a_y e1^e3 + a_x e2^e3."""
    e = [translated(_vector(u), x) for u in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    total = [[mpf(0)] * 5 for _ in range(5)]
    for coefficient, (i, j) in ((a[2], (0, 1)), (-a[1], (0, 2)), (a[0], (1, 2))):
        add_to(total, mpf(coefficient) / 2, wedge(e[i], e[j]))
    return total


def generator_bivector(generator):
    """G of a generator (kind, location, direction, pitch, weight) as an antisymmetric array, by
    the definitions of docs/conventions.md section 2 item 11 (the direction's length multiplies G
    for every kind); kind "bivector" takes the ten null-basis components as its direction."""
    kind, x, v, pitch, _ = generator
    if kind == "bivector":
        return bivector_from_components(v)
    if kind == "pair":
        return point_pair(x, v)
    if kind == "dilation":                  # -1/2 |v| up(x) ^ ni
        length = mpmath.sqrt(sum(mpf(c) ** 2 for c in v))
        s = wedge(up(x), NI)
        return [[-length / 2 * c for c in row] for row in s]
    if kind == "translation":               # 1/2 v ^ ni
        s = wedge(_vector(v), NI)
        return [[c / 2 for c in row] for row in s]
    total = half_dual_line(x, v)           # rotation; a twist adds 1/2 pitch v ^ ni
    if kind == "twist":
        add_to(total, mpf(pitch) / 2, wedge(_vector(v), NI))
    elif kind != "rotation":
        raise ValueError(f"unknown kind {kind}")
    return total


def action(s):
    """The matrix of X -> -2 X.B for B with antisymmetric array s: (X.B)_j = sum_i X_i g_i s_ij."""
    return mpmath.matrix([[-2 * METRIC[i] * s[i][j] for i in range(5)] for j in range(5)])


def field_bivector(generators, p, falloff, epsilon):
    """B(p) as an antisymmetric array; generators are (kind, location, direction, pitch, weight)
    of doubles (generator_bivector)."""
    total = [[mpf(0)] * 5 for _ in range(5)]
    for generator in generators:
        x, w = generator[1], generator[4]
        d2 = sum((mpf(p[i]) - mpf(x[i])) ** 2 for i in range(3))
        add_to(total, mpf(w) / (mpf(falloff) * d2 + mpf(epsilon)), generator_bivector(generator))
    return total


def _size_digits(scaled):
    """Digits the entries of expm cost next to a nearly nilpotent exponent: they reach |A|^2 (and
    more) while the image is of order 1, so 3 digits per decade of |A|."""
    size = max(abs(c) for row in scaled for c in row)
    return 3 * max(0, int(mpmath.log10(size)) + 1) if size > 0 else 0


def _hyperbolic_digits(a):
    """Digits a hyperbolic part of the action a can cost: a has the real eigenvalues +-h (h = 2 x
    the angle of the hyperbolic plane; the c of a dilation's factor e^c), so expm's entries reach
    e^h while next to the fixed point that e^-h keeps (a dilation's location) the point's weight is
    of size e^-h: 2 h / ln 10 digits. With t2 = tr(a^2)/2 = h^2 - g^2 and t4 = tr(a^4)/2 =
    h^4 + g^4 (+-i g the other plane's eigenvalues), h^2 = (t2 + sqrt(2 t4 - t2^2)) / 2. h is
    capped at 750: beyond, such an image is out of the doubles' range."""
    a2 = a * a
    a4 = a2 * a2
    t2 = sum(a2[i, i] for i in range(5)) / 2
    t4 = sum(a4[i, i] for i in range(5)) / 2
    h = mpmath.sqrt(max(mpf(0), (t2 + mpmath.sqrt(max(mpf(0), 2 * t4 - t2 * t2))) / 2))
    return int(2 * min(h, mpf(750)) / mpmath.log(10)) + 10


def _image_and_loss(scaled, p):
    """fn(expm(A) up(p)) at the working precision, and the decades its sums lost to cancellation:
    of the weight against the sum of its terms' magnitudes, and of the Euclidean part against its
    own (or the weight's, where that part is 0)."""
    a = action(scaled)
    e = mpmath.expm(a)
    u = up(p)
    y = e * mpmath.matrix(u)
    terms = [sum(abs(e[i, j] * u[j]) for j in range(5)) for i in range(5)]
    weight = -dot(NI, [y[i] for i in range(5)])        # = y(e+) + y(e-)
    euclidean = max(abs(y[i]) for i in range(3))
    if weight == 0:
        return None, mpf("inf"), a
    loss = max((terms[3] + terms[4]) / abs(weight),
               max(terms[:3]) / (euclidean if euclidean > 0 else abs(weight)))
    return [+(y[i] / weight) for i in range(3)], mpmath.log10(loss), a


def _accurate_image(build, p, strength, digits):
    """The image of p under exp(-strength s), s = build() at the working precision (built again at
    each precision: a hyperbolic part amplifies the rounding of s itself by e^h; a dilation's
    location rounded to 30 digits moves its image by e^c times that). At digits raised by
    _size_digits; where the sums lost more than those (a strong hyperbolic part, a dilation's
    factor e^c next to its location), again with _hyperbolic_digits more."""
    with mp.workdps(digits):
        extra = _size_digits([[-mpf(strength) * c for c in row] for row in build()])
    for _ in range(3):
        with mp.workdps(digits + extra):
            scaled = [[-mpf(strength) * c for c in row] for row in build()]
            result, loss, a = _image_and_loss(scaled, p)
            if loss <= extra + 5:
                return result
            lost = int(loss) if mpmath.isfinite(loss) else mp.dps  # a weight of 0: all lost
            extra = max(extra + lost, _size_digits(scaled) + _hyperbolic_digits(a))
    return result


def image_of_bivector(s, p, strength, digits=DIGITS):
    """fn(expm(-strength A(s)) up(p)) as mpf triple (_accurate_image: the precision grows with |A|
    and with the decades the sums lose)."""
    return _accurate_image(lambda: s, p, strength, digits)


def image(generators, p, falloff, epsilon, strength, digits=DIGITS):
    """p may hold mpf coordinates (jacobian's steps), which enter exactly. B(p) is built at each
    precision _accurate_image takes."""
    return _accurate_image(lambda: field_bivector(generators, p, falloff, epsilon), p, strength,
                           digits)


JACOBIAN_DIGITS = 70
JACOBIAN_STEP = mpf(10) ** -25


def jacobian(generators, p, falloff, epsilon, strength):
    """d image / d p (row-major 3x3, floats) by central differences of image() with the step
    1e-25 at 70 digits: the truncation (step^2 times the third derivative, below 1e-20 for the
    fields tested, whose features are no smaller than 1e-5) and the rounding (1e-70 / 1e-25) are
    far below double precision."""
    with mp.workdps(JACOBIAN_DIGITS):
        columns = []
        for j in range(3):
            plus = [mpf(c) for c in p]
            minus = [mpf(c) for c in p]
            plus[j] += JACOBIAN_STEP
            minus[j] -= JACOBIAN_STEP
            a = image(generators, plus, falloff, epsilon, strength, JACOBIAN_DIGITS)
            b = image(generators, minus, falloff, epsilon, strength, JACOBIAN_DIGITS)
            columns.append([(a[i] - b[i]) / (2 * JACOBIAN_STEP) for i in range(3)])
        return [float(columns[j][i]) for i in range(3) for j in range(3)]


def field_bivector_derivatives(generators, p, falloff, epsilon):
    """dB/dp_j (j = 0, 1, 2) as antisymmetric arrays, in closed form:
    d/dp_j w G / (k |p - x|^2 + eps) = -2 k (p_j - x_j) w G / (k |p - x|^2 + eps)^2."""
    derivatives = [[[mpf(0)] * 5 for _ in range(5)] for _ in range(3)]
    for generator in generators:
        x, w = [mpf(c) for c in generator[1]], mpf(generator[4])
        offset = [mpf(p[i]) - x[i] for i in range(3)]
        q = mpf(falloff) * sum(c * c for c in offset) + mpf(epsilon)
        g = generator_bivector(generator)
        for j in range(3):
            add_to(derivatives[j], -2 * mpf(falloff) * offset[j] * w / q ** 2, g)
    return derivatives


def frechet_expm(x, e):
    """(expm(X), L(X, E)) for 5x5 mpmath matrices at the working precision: the Frechet derivative
    L(X, E) = d/dt expm(X + t E) at t = 0 is the upper right block of expm([[X, E], [0, X]])
    (mpmath.expm of the 10x10 block matrix; no differences)."""
    block = mpmath.zeros(10, 10)
    for a in range(5):
        for c in range(5):
            block[a, c] = block[a + 5, c + 5] = x[a, c]
            block[a, c + 5] = e[a, c]
    exponential = mpmath.expm(block)
    return exponential[0:5, 0:5], exponential[0:5, 5:10]


def jacobian_of_bivector(s, ds, p, strength, digits=DIGITS):
    """d image / d p (row-major 3x3, mpf) of p -> fn(expm(X(p)) up(p)), X = -strength A(s), for
    the bivector s at p and its derivatives ds[j] = ds/dp_j, without differences: the derivative
    of expm along E is the upper right block of expm([[X, E], [0, X]]) (the Frechet derivative),
    then up(p)' = e_j + p_j ni and fn's quotient rule. Precision raised by the size of the action
    and by its hyperbolic part (_size_digits, _hyperbolic_digits)."""
    scaled = [[-mpf(strength) * s[i][j] for j in range(5)] for i in range(5)]
    size = max(abs(c) for row in scaled for c in row)
    extra = 3 * max(0, int(mpmath.log10(size)) + 1) if size > 0 else 0
    # a strong hyperbolic part: the weight of the image is e^-h of the terms (a dilation's)
    with mp.workdps(digits + extra):
        extra += _hyperbolic_digits(action(scaled))
    with mp.workdps(digits + extra):
        x = action(scaled)
        u = mpmath.matrix(up(p))
        columns = []
        for j in range(3):
            e = action([[-mpf(strength) * c for c in row] for row in ds[j]])
            exponential, frechet = frechet_expm(x, e)
            y = exponential * u
            tangent = [mpf(0)] * 5
            tangent[j] = mpf(1)
            dy = frechet * u + exponential * mpmath.matrix(combine((1, tangent), (mpf(p[j]), NI)))
            y, dy = [y[i] for i in range(5)], [dy[i] for i in range(5)]
            weight, dweight = -dot(NI, y), -dot(NI, dy)
            columns.append([dy[i] / weight - y[i] * dweight / weight ** 2 for i in range(3)])
        return [+columns[j][i] for i in range(3) for j in range(3)]


def jacobian_by_frechet(generators, p, falloff, epsilon, strength):
    """jacobian() without differences (jacobian_of_bivector of B(p) and its closed-form
    derivatives): an independent check of the central differences."""
    with mp.workdps(DIGITS):
        s = field_bivector(generators, p, falloff, epsilon)
        ds = field_bivector_derivatives(generators, p, falloff, epsilon)
        return [float(c) for c in jacobian_of_bivector(s, ds, p, strength)]


def one_ulp_change(evaluate, inputs, distance, trials=3, seed=1):
    """The largest distance(evaluate(moved), evaluate(inputs)) over `trials` draws in which every
    independent entry of each input changes by one unit in the last place of a double (2^-53
    relative, random signs): what no computation from the doubles `inputs` can avoid. An input is
    an antisymmetric array (a bivector: its upper triangle moves, the lower one with it) or a list
    of doubles (components)."""
    rng = random.Random(seed)

    def moved(x):
        if not isinstance(x[0], list):
            return [c + rng.choice((-1, 1)) * abs(c) * 2.0 ** -53 for c in x]
        t = [row[:] for row in x]
        for i in range(5):
            for j in range(i + 1, 5):
                delta = t[i][j] * mpf(2) ** -53 * rng.choice((-1, 1))
                t[i][j] += delta
                t[j][i] -= delta
        return t

    with mp.workdps(DIGITS):
        base = evaluate(inputs)
        largest = mpf(0)
        for _ in range(trials):
            largest = max(largest, distance(evaluate([moved(x) for x in inputs]), base))
        return float(largest)


def largest_entry_change(a, b):
    """max |a_i - b_i| over two equally long flat lists."""
    return max(abs(x - y) for x, y in zip(a, b))


def jacobian_sensitivity(generators, p, falloff, epsilon, strength, trials=3, seed=1):
    """The largest change of the Jacobian (its largest entry) when every component of B(p) and of
    each dB/dp_j changes by one unit in the last place of a double (one_ulp_change): what no
    derivative computed from double B(p) and dB/dp can avoid (one_ulp_sensitivity's analogue)."""
    with mp.workdps(DIGITS):
        inputs = ([field_bivector(generators, p, falloff, epsilon)] +
                  field_bivector_derivatives(generators, p, falloff, epsilon))
    return one_ulp_change(lambda m: jacobian_of_bivector(m[0], m[1:], p, strength), inputs,
                          largest_entry_change, trials, seed)


def one_ulp_sensitivity(generators, p, falloff, epsilon, strength, trials=3, seed=1):
    """The largest movement of the image when every component of B(p) (in the orthonormal basis)
    changes by one unit in the last place of a double (2^-53 relative, random signs): a numerical
    estimate of what any double computation of B(p) cannot avoid."""
    with mp.workdps(DIGITS):
        return bivector_sensitivity(field_bivector(generators, p, falloff, epsilon), p, strength,
                                    trials, seed)


def bivector_from_components(c):
    """The antisymmetric array of the bivector with the ten null-basis components c (doubles) in
    the project's order: e12, e13, e23, e1^no, e2^no, e3^no, e1^ni, e2^ni, e3^ni, no^ni."""
    e = [_vector((1, 0, 0)), _vector((0, 1, 0)), _vector((0, 0, 1))]
    pairs = [(e[0], e[1]), (e[0], e[2]), (e[1], e[2]), (e[0], NO), (e[1], NO), (e[2], NO),
             (e[0], NI), (e[1], NI), (e[2], NI), (NO, NI)]
    total = [[mpf(0)] * 5 for _ in range(5)]
    for coefficient, (a, b) in zip(c, pairs):
        for i in range(5):
            for j in range(5):
                total[i][j] += mpf(coefficient) * (a[i] * b[j] - a[j] * b[i])
    return total


def bivector_sensitivity(s, p, strength, trials=3, seed=1):
    """one_ulp_sensitivity for a given bivector s (antisymmetric array)."""
    def distance(moved, base):
        return mpmath.sqrt(sum((moved[i] - base[i]) ** 2 for i in range(3)))
    return one_ulp_change(lambda m: image_of_bivector(m[0], p, strength), [s], distance, trials,
                          seed)


def _fraction(x):
    """x (a double, an integer, a Fraction or an mpf) as an exact Fraction."""
    from fractions import Fraction
    if isinstance(x, mpmath.mpf):
        mantissa, exponent = x.man_exp            # the mantissa's magnitude
        return (-1 if x < 0 else 1) * Fraction(mantissa) * Fraction(2) ** exponent
    return Fraction(x)


@functools.lru_cache(maxsize=None)
def _unit_arrays():
    """bivector_from_components of the ten unit components: exact (entries 0, +-1/2, +-1), built
    once."""
    return [bivector_from_components([1 if i == k else 0 for i in range(10)]) for k in range(10)]


@functools.lru_cache(maxsize=None)
def _unit_actions():
    """action() of the ten unit components in exact rationals (entries multiples of 1/4), built
    once."""
    from fractions import Fraction
    with mp.workdps(20):
        return [[[Fraction(int(a[i, j] * 4), 4) for j in range(5)] for i in range(5)]
                for a in (action(u) for u in _unit_arrays())]


def components_of(s):
    """The ten null-basis components of the bivector with the antisymmetric array s (mpf), the
    inverse of bivector_from_components (a 10 x 10 solve at the working precision)."""
    units = _unit_arrays()
    entries = [(i, j) for i in range(5) for j in range(i + 1, 5)]
    a = mpmath.matrix([[u[i][j] for u in units] for i, j in entries])
    c = mpmath.lu_solve(a, mpmath.matrix([s[i][j] for i, j in entries]))
    return [c[k] for k in range(10)]


def _action_fraction(components):
    """action() of the bivector with the ten null-basis components (doubles, Fractions or mpf) in
    exact rationals (fractions.Fraction): the entries are sums of the components times +-1/2,
    +-1, +-2."""
    return [[sum(_fraction(c) * u[i][j] for c, u in zip(components, _unit_actions()) if c)
             for j in range(5)] for i in range(5)]


def _toward_zero(n, divisor):
    """n / divisor rounded toward zero (integers): a tiny term becomes 0, not -1."""
    return n // divisor if n >= 0 else -(-n // divisor)


def _fixed_product(a, b, bits):
    """a b of 5x5 fixed-point matrices (integers, value = n 2^-bits), rounded toward zero."""
    columns = list(zip(*b))
    products = ([sum(map(operator.mul, row, column)) for column in columns] for row in a)
    return [[n >> bits if n >= 0 else -(-n >> bits) for n in row] for row in products]


def expm_frechet(x, directions):
    """(expm(X), [L(X, E) for E in directions]) for 5x5 matrices of exact rationals: the Frechet
    derivative L(X, E) = d/dt expm(X + t E) at t = 0 without differences, by the Taylor series of
    the block matrix [[X, E], [0, X]] (whose exponential holds expm(X) and L(X, E)) after scaling
    by 2^-s, then s squarings (expm(X) = F^2 and L(X, E) = F L + L F for F = expm(X/2) and
    L = L(X/2, E/2)), in fixed point on Python integers. The bits are chosen from the norm of X:
    the entries reach e^|X| and the image's weight may be e^-|X| of them (a strong dilation), so
    3 |X| + 400 bits keep 70 digits beyond every such cancellation. Returns fixed-point integers
    and the bits."""
    norm = max(sum(abs(c) for c in row) for row in x)
    s = max(0, int(mpmath.ceil(mpmath.log(float(norm) + 1, 2)))) + 12
    bits = int(3 * float(norm)) + 400
    one = 1 << bits
    scale = 1 << s

    def fixed(m):
        return [[int(c * one / scale) for c in row] for row in m]

    xs = fixed(x)
    # each direction scaled by a power of two to about X's size (L is linear in E), so that its
    # series ends with X's
    powers = []
    for e in directions:
        size = max(abs(c) for row in e for c in row)
        powers.append(0 if size == 0 else int(mpmath.floor(mpmath.log(float(size) / float(norm + 1), 2))))
    es = [fixed([[c / _fraction(2) ** k for c in row] for row in e]) for e, k in zip(directions, powers)]
    term = [[one if i == j else 0 for j in range(5)] for i in range(5)]
    total = [row[:] for row in term]
    dterms = [[[0] * 5 for _ in range(5)] for _ in es]
    dtotals = [[[0] * 5 for _ in range(5)] for _ in es]
    n = 0
    while any(c for row in term for c in row) or any(c for d in dterms for row in d for c in row):
        n += 1
        dterms = [[[_toward_zero(c, n) for c in row] for row in
                   [[a + b for a, b in zip(r1, r2)] for r1, r2 in
                    zip(_fixed_product(d, xs, bits), _fixed_product(term, e, bits))]]
                  for d, e in zip(dterms, es)]
        term = [[_toward_zero(c, n) for c in row] for row in _fixed_product(term, xs, bits)]
        total = [[a + b for a, b in zip(r1, r2)] for r1, r2 in zip(total, term)]
        dtotals = [[[a + b for a, b in zip(r1, r2)] for r1, r2 in zip(t, d)]
                   for t, d in zip(dtotals, dterms)]
    for _ in range(s):
        dtotals = [[[a + b for a, b in zip(r1, r2)] for r1, r2 in
                    zip(_fixed_product(total, d, bits), _fixed_product(d, total, bits))]
                   for d in dtotals]
        total = _fixed_product(total, total, bits)
    dtotals = [[[c * 2 ** k if k >= 0 else _toward_zero(c, 2 ** -k) for c in row] for row in d]
               for d, k in zip(dtotals, powers)]
    return total, dtotals, bits


def bivector_derivatives(components, directions, p, strength):
    """(image, [d image along D for D in directions]) of p -> fn(expm(-strength A(B)) up(p)) at
    the bivector B with the ten null-basis components `components` (doubles, B in space), along
    directions D given by their ten null-basis components (exact rationals or doubles): the
    Frechet derivative of the matrix exponential (expm_frechet) applied to up(p), then fn's
    quotient rule, d x = (d Y_e - x d w) / w, in exact rationals from the fixed-point integers.
    Everything from the definitions and the same double inputs; no differences. Floats."""
    from fractions import Fraction
    x = [[-Fraction(strength) * c for c in row] for row in _action_fraction(components)]
    es = [[[-Fraction(strength) * c for c in row] for row in _action_fraction(d)]
          for d in directions]
    total, dtotals, bits = expm_frechet(x, es)
    # up(p) in e1, e2, e3, e+, e-: no = (e- + e+)/2, ni = e- - e+
    q = [Fraction(c) for c in p]
    half = sum(c * c for c in q) / 2
    u = [q[0], q[1], q[2], Fraction(1, 2) - half, Fraction(1, 2) + half]

    def apply(m):
        return [sum(Fraction(m[i][j]) * u[j] for j in range(5)) / (1 << bits) for i in range(5)]

    y = apply(total)
    weight = y[3] + y[4]                       # -ni.Y
    image = [y[i] / weight for i in range(3)]
    derivatives = []
    for d in dtotals:
        dy = apply(d)
        dweight = dy[3] + dy[4]
        derivatives.append([float((dy[i] - image[i] * dweight) / weight) for i in range(3)])
    return [float(c) for c in image], derivatives
