"""Ends with an explicit exponent (sie.fixed_ends): kernels with a fixed singularity at an
end, the edge crack.

References (independent of the code):
- the edge crack normal to the free edge of a half-plane under uniform pressure p:
  K_I = F p sqrt(pi a), F = 1.12152 (W. T. Koiter, J. Appl. Mech. 32 (1965) 237; Tada,
  Paris & Irwin, The Stress Analysis of Cracks Handbook, 3rd ed. (2000), p. 8.1: 1.1215);
  its equation and kernel from Erdogan, Gupta & Cook (1973) and Kaya & Erdogan (1987);
- the Griffith crack (no kernel): F = 1 exactly (the conversion of the end value to K_I);
- principal values of the weight and of manufactured solutions by mpmath quadrature.
"""
import math
import warnings

import mpmath as mp
import numpy as np
import pytest

import sie
from sie.fixed_ends import graded_weight_rule, hilbert_images, kernel_term, weight_hilbert
from sie.intervals import Interval


def edge_kernel(x, t):
    """(1/pi) k(x, t) of a crack normal to a free surface, x, t its distances from it."""
    u = t + x
    return (-1.0 / u + 6.0 * x / u**2 - 4.0 * x**2 / u**3) / np.pi


def minus_p(s):
    return -np.ones_like(s)


def tip_factor(sol, crack_length, piece=0):
    """F = K_I / (p sqrt(pi a)) at the right end (a tip, exponent -1/2) with p = 1: for psi ~
    A (1 - u)^(-1/2) (1 + u)^beta phi(u), K_I = -lim sqrt(pi) sqrt(2 (d - x)) psi(x)
    = -sqrt(pi) sqrt(2 h) 2^beta phi(1)  (h the half-width; the sign: the normalised
    equation (1/pi) int phi/(t - x) dt = -p)."""
    p = sol.pieces[piece]
    assert p.alpha == -0.5
    phi_tip = sol.endpoint_value(1, piece if sol.multi else None)
    K = -math.sqrt(math.pi) * math.sqrt(2.0 * p.interval.h) * 2.0 ** p.beta * phi_tip
    return K / math.sqrt(math.pi * crack_length)


def edge_crack(n):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.ResidualWarning)
        return sie.solve(minus_p, a=0.0, b=1.0, n=n, left=0.0, right="singular",
                         intervals=[(0.0, 1.0)], kernel=edge_kernel)


# ---------------------------------------------------------------------------------------
# the pieces: H[w] in closed form, H[w P_k], the graded kernel rule
# ---------------------------------------------------------------------------------------
def _hilbert_mp(x, alpha, beta, g=lambda t: 1):
    """(1/pi) PV int (1-t)^alpha (1+t)^beta g(t) / (t - x) dt by mpmath: the singularity
    subtracted, and t = -1 + (1 + x) y^p, p = 1/(1 + beta), on [-1, x] (its mirror on
    [x, 1]), which takes the end's power out of the integrand ((1 + t)^beta dt ~ dy); the
    weight from the distances to the ends, exact next to them."""
    x = mp.mpf(x)
    al, be = mp.mpf(alpha), mp.mpf(beta)

    def psi(dl, dr):                     # at t with 1 + t = dl, 1 - t = dr
        return dr ** al * dl ** be * g(dl - 1 if dl < dr else 1 - dr)

    px = psi(1 + x, 1 - x)
    pl, pr = 1 / (1 + be), 1 / (1 + al)

    def left(y):
        dl = (1 + x) * y**pl
        return (psi(dl, 2 - dl) - px) / (dl - (1 + x)) * (1 + x) * pl * y**(pl - 1)

    def right(y):
        dr = (1 - x) * y**pr
        return (psi(2 - dr, dr) - px) / ((1 - x) - dr) * (1 - x) * pr * y**(pr - 1)

    val = mp.quad(left, [0, 1]) + mp.quad(right, [0, 1]) + px * mp.log((1 - x) / (1 + x))
    return val / mp.pi


@pytest.mark.parametrize("alpha, beta", [(-0.5, 0.0), (0.0, -0.5), (-0.25, 0.3),
                                         (0.3, -0.7), (0.75, 0.25), (0.0, 0.0)])
def test_weight_hilbert_against_mpmath(alpha, beta):
    mp.mp.dps = 30
    x = np.array([-0.999, -0.6, 0.0, 0.35, 0.99])
    ref = np.array([float(_hilbert_mp(v, alpha, beta)) for v in x])
    got = weight_hilbert(x, alpha, beta)
    np.testing.assert_allclose(got, ref, rtol=1e-13, atol=1e-13)


def test_hilbert_images_against_mpmath():
    mp.mp.dps = 30
    alpha, beta, n = -0.25, 0.3, 7
    x = np.array([-0.9, 0.1, 0.8])
    got = hilbert_images(n, alpha, beta, x)
    for k in (0, 3, 6):
        ref = [float(_hilbert_mp(v, alpha, beta, lambda t: mp.jacobi(k, alpha, beta, t)))
               for v in x]
        np.testing.assert_allclose(got[:, k], ref, rtol=1e-12, atol=1e-12)


def test_graded_kernel_term_next_to_the_end():
    """h int k(x, t) w P_k dt for the edge kernel at x 1e-7 and 1e-3 (relative) from the
    mouth, against mpmath: the graded rule resolves the scale of x."""
    mp.mp.dps = 25
    alpha, beta, n = -0.5, 0.0, 5
    iv = Interval(0.0, 1.0)
    dl = np.array([2e-7, 2e-3, 1.0])
    got = kernel_term(edge_kernel, (dl, 2.0 - dl), iv, n, alpha, beta, True, False, 24)
    for i, d in enumerate(dl):
        xr = mp.mpf(d) / 2

        def k_mp(v):
            u = (1 + v) / 2 + xr
            return (-1 / u + 6 * xr / u**2 - 4 * xr**2 / u**3) / mp.pi
        for k in (0, 4):
            # [-1, 0] split at -1 + d 4^j; [0, 1] with v = 1 - y^2 ((1 - v)^(-1/2) dv = 2 dy)
            pts = [-1] + [-1 + d * 4**j for j in range(14) if d * 4**j < 1] + [0]
            ref = 0.5 * (mp.quad(lambda v: k_mp(v) * (1 - v) ** alpha
                                 * mp.jacobi(k, alpha, beta, v), pts)
                         + mp.quad(lambda y: 2 * k_mp(1 - y**2)
                                   * mp.jacobi(k, alpha, beta, 1 - y**2), [0, 1]))
            assert abs(got[i, k] - float(ref)) < 1e-13 * max(1.0, abs(float(ref)))


def test_graded_rule_integrates_the_weight():
    alpha, beta = -0.5, 0.3
    dl, dr, w = graded_weight_rule(1e-5, 2.0 - 1e-5, 24, alpha, beta, True, False)
    mu0 = sie.jacobi_moment(alpha, beta)
    assert abs(w.sum() - mu0) < 1e-14 * mu0
    assert np.all(dl + dr - 2.0 < 1e-15)


# ---------------------------------------------------------------------------------------
# the Mellin helper
# ---------------------------------------------------------------------------------------
def edge_symbol(g):
    return 1.0 - math.cos(math.pi * g) + 4.0 * g + 2.0 * g * g


def test_end_exponent_edge_crack_root_is_zero():
    assert abs(sie.end_exponent(edge_symbol, (-0.5, 0.5))) < 1e-15


def test_edge_symbol_is_the_mellin_transform_of_the_operator():
    """(1/pi) int_0^inf [1/(t - 1) + k(1, t)] t^g dt = D(g) / sin(pi g) (the symbol the
    helper's example takes the root of), by mpmath at g = -0.3 and -0.7."""
    mp.mp.dps = 20
    for g in (-0.3, -0.7):
        def cauchy(t):
            return (t**g - 1) / (t - 1)
        pv = mp.quad(cauchy, [0, 1, 2]) + mp.quad(lambda t: t**g / (t - 1), [2, mp.inf]) \
            + mp.log(1)  # PV int_0^2 dt/(t - 1) = 0
        reg = mp.quad(lambda t: (-1 / (t + 1) + 6 / (t + 1)**2 - 4 / (t + 1)**3) * t**g,
                      [0, 1, mp.inf])
        val = (pv + reg) / mp.pi
        assert abs(float(val) - edge_symbol(g) / math.sin(math.pi * g)) < 1e-12


def test_end_exponent_errors():
    with pytest.raises(sie.InvalidEndConditionError):
        sie.end_exponent(edge_symbol, (0.2, 0.5))           # no sign change
    with pytest.raises(sie.InvalidEndConditionError):
        sie.end_exponent(edge_symbol, (-1.0, 0.5))          # outside (-1, 1)


# ---------------------------------------------------------------------------------------
# the edge crack and the Griffith crack
# ---------------------------------------------------------------------------------------
def test_griffith_crack_F_is_one():
    """No kernel, both ends singular, int phi = 0: F = 1, by the ordinary solver and by the
    general collocation with both exponents given (-1/2)."""
    a = 1.5
    sol = sie.solve(minus_p, a=0.0, b=1.0, n=4, left="singular", right="singular",
                    intervals=[(-a, a)], total=0.0)
    assert abs(tip_factor(sol, a) - 1.0) < 1e-14
    sol = sie.solve(minus_p, a=0.0, b=1.0, n=4, left=-0.5, right=-0.5,
                    intervals=[(-a, a)], total=0.0)
    assert sol.kappa == (1,)
    assert abs(tip_factor(sol, a) - 1.0) < 1e-13


def test_edge_crack_F():
    """F = 1.1215222552... : 10 digits between n = 96 and 128 (phi carries the term
    x^(1.7396 + 1.1190 i) of the symbol's next root at the mouth, so the Jacobi series
    converges algebraically, ~ n^-4.5: n = 16, 32, 64 reach 3e-7, 2e-8, 2e-10); rounds to
    Tada-Paris-Irwin's 1.1215 and to Koiter's 1.12152."""
    F = {n: tip_factor(edge_crack(n), 1.0) for n in (16, 32, 96, 128)}
    assert abs(F[96] - F[128]) < 1e-10
    assert abs(F[16] - F[128]) < 1e-6
    assert round(F[128], 4) == 1.1215
    assert round(F[128], 5) == 1.12152
    sol = edge_crack(32)
    assert sol.beta == (0.0,) and sol.alpha == (-0.5,) and sol.kappa == (0,)
    # psi at the mouth itself is phi there (exponent 0), finite
    assert np.isfinite(sol(np.array([0.0])))[0]
    assert float(sol(np.array([0.0]))[0]) == pytest.approx(sol.endpoint_value(-1, 0))


def test_embedded_crack_tends_to_the_edge_crack():
    """A crack (c, 1) below the free surface (ordinary solver, bounded kernel, total 0): its
    far tip's F rises toward the edge crack's 1.1215 as the ligament c -> 0 (slowly: 0.817,
    0.920, 0.977 at c = 0.1, 0.01, 0.001)."""
    F = []
    for c, n in ((1e-1, 64), (1e-2, 128), (1e-3, 256)):
        sol = sie.solve(minus_p, a=0.0, b=1.0, n=n, left="singular", right="singular",
                        intervals=[(c, 1.0)], kernel=edge_kernel, total=0.0)
        F.append(tip_factor(sol, 1.0 - c))
    gaps = [1.1215 - v for v in F]
    assert all(g > 0 for g in gaps)
    assert gaps[0] > gaps[1] > gaps[2]
    assert gaps[2] < 0.5 * gaps[0]


# ---------------------------------------------------------------------------------------
# manufactured solutions with a non-integer exponent sum
# ---------------------------------------------------------------------------------------
def _manufactured_f(a, b, alpha, beta, g_mp, kernel_mp=None):
    """f = a psi + (b/pi) PV int psi/(t - s) dt + int k psi dt by mpmath, vectorised."""
    def f(s):
        mp.mp.dps = 20
        out = []
        for x in np.asarray(s).ravel():
            xm = mp.mpf(float(x))
            psi_x = (1 - xm) ** alpha * (1 + xm) ** beta * g_mp(xm)
            val = a * psi_x + b * _hilbert_mp(float(x), alpha, beta, g_mp)
            if kernel_mp is not None:
                val += mp.quad(lambda t: kernel_mp(xm, t) * (1 - t) ** alpha * (1 + t) ** beta
                               * g_mp(t), [-1, 1])
            out.append(float(val))
        return np.array(out).reshape(np.shape(s))
    return f


def test_manufactured_non_integer_sum():
    """a = b = 1 (alpha0 = 3/4), right "singular" (alpha = -1/4), left = 0.3 given:
    alpha + beta = 0.05; psi = w exp(s/2) cos(s), a smooth kernel; recovered to 1e-12."""
    alpha, beta = -0.25, 0.3
    g = lambda t: mp.exp(t / 2) * mp.cos(t)                # noqa: E731
    kmp = lambda s, t: 0.3 * mp.cos(s * t) + 0.1 * s      # noqa: E731
    f = _manufactured_f(1.0, 1.0, alpha, beta, g, kmp)
    sol = sie.solve(f, a=1.0, b=1.0, n=18, left=0.3, right="singular",
                    kernel=lambda s, t: 0.3 * np.cos(s * t) + 0.1 * s)
    assert (sol.alpha, sol.beta, sol.kappa) == (alpha, beta, 0)
    s = np.linspace(-0.99, 0.99, 41)
    exact = (1 - s) ** alpha * (1 + s) ** beta * np.exp(s / 2) * np.cos(s)
    assert np.max(np.abs(sol(s) - exact)) < 1e-12
    assert abs(sol.phi(np.array([-1.0]))[0] - math.exp(-0.5) * math.cos(1.0)) < 1e-12
    # the transforms are available (their accuracy: tests/sie/test_fixed_end_transforms.py)
    assert np.isfinite(sol.cauchy(2.0)) and np.isfinite(sol.log_potential(0.5))


def test_manufactured_both_singular_with_total():
    """left = -0.3 given, right "singular" (alpha = -1/4): index 1, int psi given."""
    alpha, beta = -0.25, -0.3
    g = lambda t: 1 + t / 3 - t**2 / 5                      # noqa: E731
    f = _manufactured_f(1.0, 1.0, alpha, beta, g)
    mp.mp.dps = 20
    total = float(mp.quad(lambda t: (1 - t) ** alpha * (1 + t) ** beta * g(t), [-1, 1]))
    sol = sie.solve(f, a=1.0, b=1.0, n=6, left=-0.3, right="singular", total=total)
    assert sol.kappa == 1
    s = np.linspace(-0.9, 0.9, 7)
    exact = (1 - s) ** alpha * (1 + s) ** beta * (1 + s / 3 - s**2 / 5)
    assert np.max(np.abs(sol(s) - exact)) < 1e-12
    assert abs(sol.integral() - total) < 1e-13


def test_manufactured_both_bounded_least_squares():
    """left = 0.3 given, right "bounded" (alpha = 3/4): index -1, over-determined; f from a
    solution: consistency at rounding, no warning."""
    alpha, beta = 0.75, 0.3
    g = lambda t: 2 - t + t**3 / 4                          # noqa: E731
    f = _manufactured_f(1.0, 1.0, alpha, beta, g)
    with warnings.catch_warnings():
        warnings.simplefilter("error", sie.InconsistentEquationWarning)
        sol = sie.solve(f, a=1.0, b=1.0, n=6, left=0.3, right="bounded")
    assert sol.kappa == -1 and sol.consistency < 1e-13
    s = np.linspace(-0.9, 0.9, 7)
    exact = (1 - s) ** alpha * (1 + s) ** beta * (2 - s + s**3 / 4)
    assert np.max(np.abs(sol(s) - exact)) < 1e-12


# ---------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("bad", [1.0, -1.0, float("nan"), "0.0", 2, True])
def test_invalid_explicit_exponent(bad):
    with pytest.raises(sie.InvalidEndConditionError):
        sie.solve(minus_p, a=0.0, b=1.0, n=8, left=bad, right="singular")


def test_edge_kernel_without_the_exponent_names_left():
    with pytest.raises(sie.KernelSingularityError, match=r"left=<float>"):
        sie.solve(minus_p, a=0.0, b=1.0, n=8, left="bounded", right="singular",
                  intervals=[(0.0, 1.0)], kernel=edge_kernel)


def test_explicit_exponent_not_with_several_intervals_or_cases():
    with pytest.raises(sie.UnsupportedEquationError):
        sie.solve(minus_p, a=0.0, b=1.0, n=8, left=0.0, right="singular",
                  intervals=[(0.0, 1.0), (2.0, 3.0)])
    with pytest.raises(sie.UnsupportedEquationError):
        sie.Equation(a=0.0, b=1.0, left=0.0, right="singular",
                     intervals=[[(0.0, 1.0)], [(0.0, 2.0)]])


def test_equation_object_and_its_limits():
    """sie.Equation takes an explicit exponent too (solve, on); functionals and breaks are
    refused; a kernel singular at the other end (not given) still raises, naming it."""
    eq = sie.Equation(a=0.0, b=1.0, left=0.0, right="singular", intervals=[(0.0, 1.0)],
                      kernel=edge_kernel)
    F = tip_factor(eq.solve(minus_p, n=96), 1.0)
    assert abs(F - tip_factor(edge_crack(96), 1.0)) < 1e-15
    F2 = tip_factor(eq.on([(0.0, 2.0)]).solve(minus_p, n=96), 2.0)   # F is scale-free
    assert abs(F2 - F) < 1e-12
    with pytest.raises(sie.UnsupportedEquationError):
        eq.functionals(minus_p, n=8)
    with pytest.raises(sie.UnsupportedEquationError):
        eq.solve(minus_p, n=8, breaks=[0.5])
    mirrored = lambda x, t: edge_kernel(1.0 - x, 1.0 - t)        # noqa: E731
    with pytest.raises(sie.KernelSingularityError, match=r"right=<float>"):
        sie.solve(minus_p, a=0.0, b=1.0, n=8, left=0.0, right="singular",
                  intervals=[(0.0, 1.0)], kernel=mirrored)


def test_mirrored_edge_crack():
    """The edge crack with the surface at the right end: x -> 1 - x turns the equation into
    one with the kernel -k(1 - x, 1 - t) and phi'(x) = -phi(1 - x); the explicit exponent at
    the right end (alpha = 0: H[w] by the reflected closed form, the rule graded toward +1)
    gives the same tip value."""
    sol = sie.solve(minus_p, a=0.0, b=1.0, n=64, left="singular", right=0.0,
                    intervals=[(0.0, 1.0)], kernel=lambda x, t: -edge_kernel(1.0 - x, 1.0 - t))
    assert sol.alpha == (0.0,) and sol.beta == (-0.5,)
    ref = edge_crack(64)
    assert abs(sol.endpoint_value(-1, 0) + ref.endpoint_value(1, 0)) < 1e-12
    s = np.array([0.1, 0.5, 0.9])
    np.testing.assert_allclose(sol(s), -ref(1.0 - s), rtol=1e-11)


# ---------------------------------------------------------------------------------------
# further exponents at an explicit end: left=(e0, g1, ...)
# ---------------------------------------------------------------------------------------
def edge_symbol_c(g):
    """The edge crack's symbol for complex g (cmath)."""
    import cmath
    return 1.0 - cmath.cos(cmath.pi * g) + 4.0 * g + 2.0 * g * g


def test_end_exponents_edge_crack_roots_against_mpmath():
    """The roots after the mouth's 0, against mpmath.findroot on D from its own starts."""
    mp.mp.dps = 30
    D = lambda g: 1 - mp.cos(mp.pi * g) + 4 * g + 2 * g * g        # noqa: E731
    refs = [complex(mp.findroot(D, mp.mpc(1.7, 1.1))), complex(mp.findroot(D, mp.mpc(3.8, 1.5)))]
    g1, g2 = sie.end_exponents(edge_symbol_c, 2, above=0.0)
    for got, ref in zip((g1, g2), refs):
        assert abs(got - ref) < 1e-13 * abs(ref)
    assert abs(g1 - complex(1.7396, 1.1190)) < 1e-4
    # from below the leading exponent: 0 itself (a real root) comes first
    first, second = sie.end_exponents(edge_symbol_c, 2, above=-0.5)
    assert first == 0.0 and abs(second - g1) < 1e-13
    # a symbol with a real root beyond the leading one
    r, = sie.end_exponents(lambda g: (g - 0.75) * (g * g + 1.0), 1, above=0.5)
    assert abs(r - 0.75) < 1e-14 and r.imag == 0.0


def test_end_exponents_errors():
    with pytest.raises(sie.InvalidEndConditionError, match="count"):
        sie.end_exponents(edge_symbol_c, 0)
    with pytest.raises(sie.InvalidEndConditionError, match="box"):
        sie.end_exponents(edge_symbol_c, 1, box=(1.0, -1.0))
    with pytest.raises(sie.InvalidEndConditionError, match="enlarge box"):
        sie.end_exponents(edge_symbol_c, 3, box=(4.0, 3.0))        # two roots in it


def edge_crack_further(n, *further):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.ResidualWarning)
        return sie.solve(minus_p, a=0.0, b=1.0, n=n, left=(0.0, *further), right="singular",
                         intervals=[(0.0, 1.0)], kernel=edge_kernel)


G1 = 1.7395933563245962 + 1.1190245343424166j     # the edge symbol's first complex root


def test_edge_crack_with_the_first_complex_exponent():
    """The basis carrying x^g1 (g1 the symbol's next root, Re g1 = 1.74): F to 11 digits at
    n = 32 against the Jacobi-only solution at n = 128 (another basis; itself ~1e-11 off
    the limit 1.12152225523100 of n = 200 ... 400), where the Jacobi basis alone has 8 at
    n = 32.  Measured F - 1.12152225523100:

        n     Jacobi only   with x^g1
        16    -3.2e-7       1.2e-8
        24    -8.4e-8       3.1e-10
        32    -1.5e-8       -2.2e-12
        48    -2.4e-10      -3.1e-12
    """
    ref = tip_factor(edge_crack(128), 1.0)
    err = {n: abs(tip_factor(edge_crack_further(n, G1), 1.0) - ref) for n in (16, 24, 32)}
    assert err[32] < 1e-10
    digits = {n: -math.log10(e) for n, e in err.items()}
    assert digits[16] > 7.5 and digits[24] > 9.0 and digits[32] > 10.5
    plain = {n: abs(tip_factor(edge_crack(n), 1.0) - ref) for n in (16, 32)}
    assert plain[32] > 1e-9 and plain[16] > 1e-7           # the algebraic rate, ~n^-4.5
    assert err[16] < 0.1 * plain[16] and err[32] < 1e-2 * plain[32]
    sol = edge_crack_further(32, G1)
    (end, g, d), = sol.further
    assert end == -1 and g == G1 and abs(d) > 1e-3
    # psi at the mouth: phi there (the further term vanishes at the end)
    assert float(sol(np.array([0.0]))[0]) == pytest.approx(sol.endpoint_value(-1))
    # the conjugate names the same term; the same F
    F2 = tip_factor(edge_crack_further(32, G1.conjugate()), 1.0)
    assert abs(F2 - tip_factor(sol, 1.0)) < 1e-13


def test_mirrored_edge_crack_with_the_further_exponent():
    """right=(0.0, g1) on the mirrored edge crack (the further term at the right end: the
    reflected frame of the Hilbert transform and of the kernel's rule) gives the tip value
    and psi of left=(0.0, g1)."""
    sol = sie.solve(minus_p, a=0.0, b=1.0, n=24, left="singular", right=(0.0, G1),
                    intervals=[(0.0, 1.0)], kernel=lambda x, t: -edge_kernel(1.0 - x, 1.0 - t))
    ref = edge_crack_further(24, G1)
    assert abs(sol.endpoint_value(-1) + ref.endpoint_value(1)) < 1e-12
    s = np.array([1e-3, 0.1, 0.5, 0.9, 0.999])
    np.testing.assert_allclose(sol(s), -ref(1.0 - s), rtol=1e-11)
    assert abs(sol.integral() + ref.integral()) < 1e-12
    # the transforms of the mirrored density: C(z) -> C(1 - z), V(x) -> -V(1 - x)
    z = np.array([0.3 + 0.2j, 1.0 + 1e-6j, -1e-3 + 1e-3j, 0.5 - 2.0j])
    # as psi above, to 1e-11: the system with the further term is ill-conditioned (its
    # condition 2.7e9 at n = 24), and the mirrored one rounds differently (2.2e-12 at 1 + 1e-6 i)
    np.testing.assert_allclose(sol.cauchy(z), ref.cauchy(1.0 - z), rtol=1e-11, atol=1e-12)
    x = np.array([-0.5, 1e-6, 0.3, 0.999, 1.0, 2.0])
    np.testing.assert_allclose(sol.log_potential(x), -ref.log_potential(1.0 - x), rtol=1e-12,
                               atol=1e-12)
    xi = np.array([0.2, 0.7])
    np.testing.assert_allclose(sol.cauchy(xi), ref.cauchy(1.0 - xi), rtol=1e-12, atol=1e-12)


def _cauchy_mp(z, alpha, beta, g):
    """(1/pi) int (1-t)^alpha (1+t)^beta g(t) / (t - z) dt for z off [-1, 1] (z None: int
    (1-t)^alpha (1+t)^beta g(t) dt), by mpmath with t = -1 + y^(1/(1+beta)) on [-1, 0] (and
    its mirror), the ends' powers taken out."""
    def div(t):                           # 1 / (t - z), or pi (the integral itself)
        return mp.pi if z is None else 1 / (t - z)
    z = None if z is None else mp.mpc(z)
    al, be = mp.mpf(alpha), mp.mpf(beta)
    pl, pr = 1 / (1 + be), 1 / (1 + al)

    def left(y):
        dl = y**pl
        return (2 - dl) ** al * g(dl - 1) * pl * div(dl - 1)

    def right(y):
        dr = y**pr
        return (2 - dr) ** be * g(1 - dr) * pr * div(1 - dr)
    return (mp.quad(left, [0, 1]) + mp.quad(right, [0, 1])) / mp.pi


def test_manufactured_complex_further_term_and_its_transform():
    """psi = w (1 + t/3 + Re(d (1+t)^r)), r = 1.2 + 0.7i, at the left end (e0 = 0.3, so
    g = 1.5 + 0.7i), a = 1, b = 1, right "singular": n = 4 recovers d and psi to rounding;
    psi's Cauchy transform (principal value and off L, both sides of the term's branch
    end), the log potential and kernel_integral against mpmath."""
    alpha, beta, r, d = -0.25, 0.3, 1.2 + 0.7j, 0.2 - 0.1j
    rm = mp.mpc(r.real, r.imag)
    g = lambda t: 1 + t / 3 + mp.re(d * (1 + t) ** rm)         # noqa: E731
    f = _manufactured_f(1.0, 1.0, alpha, beta, g)
    sol = sie.solve(f, a=1.0, b=1.0, n=4, left=(0.3, 0.3 + r), right="singular")
    (end, gg, dd), = sol.further
    assert end == -1 and gg == 0.3 + r and abs(dd - d) < 1e-12
    s = np.linspace(-0.999, 0.99, 9)
    exact = (1 - s) ** alpha * (1 + s) ** beta * (1 + s / 3 + (d * (1 + s) ** r).real)
    assert np.max(np.abs(sol(s) - exact)) < 1e-13
    mp.mp.dps = 20
    total = float(mp.re(_cauchy_mp(None, alpha, beta, g)))        # int psi
    assert abs(sol.integral() - total) < 1e-13
    ref = float(mp.re(_cauchy_mp(None, alpha, beta, lambda t: g(t) * mp.cos(2 * t))))
    got = sol.kernel_integral(lambda s, t: np.cos(s * t), np.array([2.0]))[0]
    assert abs(got - ref) < 1e-13
    for x in (-0.99, 0.2, 0.9):
        assert abs(sol.cauchy(x) - float(_hilbert_mp(x, alpha, beta, g))) < 1e-13
    for z in (0.3 + 0.2j, -1.3, 1.4, -1.01 + 0.02j):
        ref = complex(_cauchy_mp(z, alpha, beta, g))
        got = sol.cauchy(np.array([z]))[0]
        assert abs(got - (ref if isinstance(z, complex) else ref.real)) < 1e-13
    # the log potential (1/pi) int psi log abs(x - t) dt, on L, at its ends and beyond
    for x in (-1.0, 0.3, 2.0):
        pts = [-1, x, 1] if -1 < x < 1 else [-1, 1]
        ref = mp.quad(lambda t: (1 - t) ** alpha * (1 + t) ** beta * g(t)
                      * mp.log(abs(x - t)), pts) / mp.pi
        assert abs(sol.log_potential(x) - float(ref)) < 1e-13


def test_manufactured_real_further_term_with_a_kernel():
    """psi = (1-t)^(-1/4) (1 + t/3 + 0.3 (1+t)^1.5), left=(0.0, 1.5), a smooth kernel: the
    coefficient 0.3 and psi recovered at n = 4 (the kernel's columns of the further term)."""
    g = lambda t: 1 + t / 3 + 0.3 * (1 + t) ** 1.5                # noqa: E731
    kmp = lambda s, t: 0.3 * mp.cos(s * t) + 0.1 * s             # noqa: E731
    f = _manufactured_f(1.0, 1.0, -0.25, 0.0, g, kmp)
    sol = sie.solve(f, a=1.0, b=1.0, n=4, left=(0.0, 1.5), right="singular",
                    kernel=lambda s, t: 0.3 * np.cos(s * t) + 0.1 * s)
    (end, gg, dd), = sol.further
    assert (end, gg) == (-1, 1.5) and abs(dd - 0.3) < 1e-12
    s = np.linspace(-0.99, 0.99, 7)
    exact = (1 - s) ** -0.25 * (1 + s / 3 + 0.3 * (1 + s) ** 1.5)
    assert np.max(np.abs(sol(s) - exact)) < 1e-13


def test_further_exponent_not_needed_changes_nothing():
    """Exponents the solution does not have (real 1.1, complex 1.1 + 0.5i): psi w times a
    cubic, no kernel; the solution and its integral as without them to 1e-13, their
    coefficients ~0."""
    alpha, beta = -0.25, 0.3
    g = lambda t: 2 - t + t**3 / 4                            # noqa: E731
    f = _manufactured_f(1.0, 1.0, alpha, beta, g)
    s = np.linspace(-0.95, 0.95, 9)
    sol0 = sie.solve(f, a=1.0, b=1.0, n=4, left=0.3, right="singular",
                         check_residual=False)
    for extra in (1.1, 1.1 + 0.5j):
        sol = sie.solve(f, a=1.0, b=1.0, n=4, left=(0.3, extra), right="singular",
                         check_residual=False)
        assert np.max(np.abs(sol(s) - sol0(s))) < 1e-13
        assert abs(sol.integral() - sol0.integral()) < 1e-13
        assert abs(sol.further[0][2]) < 1e-10


def test_further_exponents_with_index_one_and_minus_one():
    """left=(-0.3, 0.4 + 0.6i) with right "singular" (index 1: int psi given, the further
    term's moment in the side condition) and left=(0.3, 1.2) with right "bounded" (index -1,
    least squares, consistent)."""
    r = 0.7 + 0.6j
    rm = mp.mpc(r.real, r.imag)
    g = lambda t: 1 + t / 3 + (mp.re((0.5 + 0.2j) * (1 + t) ** rm) if t > -1 else 0)  # noqa
    alpha, beta = -0.25, -0.3
    f = _manufactured_f(1.0, 1.0, alpha, beta, g)
    mp.mp.dps = 20
    total = float(mp.re(_cauchy_mp(None, alpha, beta, g)))
    sol = sie.solve(f, a=1.0, b=1.0, n=4, left=(-0.3, -0.3 + r), right="singular",
                    total=total, check_residual=False)
    assert sol.kappa == 1 and abs(sol.further[0][2] - (0.5 + 0.2j)) < 1e-12
    assert abs(sol.integral() - total) < 1e-13
    alpha, beta = 0.75, 0.3
    g = lambda t: 2 - t + 0.4 * (1 + t) ** 0.9                 # noqa: E731
    f = _manufactured_f(1.0, 1.0, alpha, beta, g)
    with warnings.catch_warnings():
        warnings.simplefilter("error", sie.InconsistentEquationWarning)
        sol = sie.solve(f, a=1.0, b=1.0, n=4, left=(0.3, 1.2), right="bounded",
                        check_residual=False)
    assert sol.kappa == -1 and sol.consistency < 1e-13
    assert abs(sol.further[0][2] - 0.4) < 1e-12


@pytest.mark.parametrize("bad, match", [
    ((0.0, -0.5), "real part above"), ((0.0, 0.0), "real part above"),
    ((0.0, float("nan")), "finite"), ((0.0, complex(1.0, math.inf)), "finite"),
    ((0.0, G1, G1.conjugate()), "repeated"), ((0.0, 1.5, 1.5), "repeated"),
    ((0.0, "1.5"), "number"), ((0.0, True), "number"), ((1.5, 2.0), r"\(-1, 1\)"),
    ((0.0,) + tuple(range(1, 10)), "at most")])
def test_further_exponent_errors(bad, match):
    with pytest.raises(sie.InvalidEndConditionError, match=match):
        sie.solve(minus_p, a=0.0, b=1.0, n=8, left=bad, right="singular")


def test_further_exponents_not_with_several_intervals_or_cases():
    with pytest.raises(sie.SIEInputError):
        sie.solve(minus_p, a=0.0, b=1.0, n=8, left=(0.0, 1.5), right="singular",
                  intervals=[(0.0, 1.0), (2.0, 3.0)])
    with pytest.raises(sie.UnsupportedEquationError):
        sie.Equation(a=0.0, b=1.0, left=(0.0, 1.5), right="singular",
                     intervals=[[(0.0, 1.0)], [(0.0, 2.0)]])
    # Equation.on keeps them
    eq = sie.Equation(a=0.0, b=1.0, left=(0.0, G1), right="singular", intervals=[(0.0, 1.0)],
                      kernel=edge_kernel)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.ResidualWarning)
        F1 = tip_factor(eq.solve(minus_p, n=24), 1.0)
        F2 = tip_factor(eq.on([(0.0, 3.0)]).solve(minus_p, n=24), 3.0)
    assert abs(F1 - F2) < 1e-12
