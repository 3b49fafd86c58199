"""Coefficients of `cos_third_acos` (src/physics/mohr_coulomb.rs).

c(x) = cos(2 acos(x) / 3) on x in [0, 1] is the largest root c = cos(acos(r) / 3)
of 4 c^3 - 3 c = r with x = sqrt((1 + r) / 2). It is analytic on [0, 1] (even in
acos(x) at x = 1; its nearest singularity is x = -1), so its Chebyshev
interpolant converges geometrically. This prints the degree-17 interpolant at
the 18 Chebyshev points of t = 2 x - 1, as monomial coefficients in t (lowest
first), and its largest error in double-precision Horner evaluation at 40,001
points of [0, 1] against 50-digit values.

    python3 scripts/cos_third_acos.py      # needs mpmath
"""
import mpmath as mp

mp.mp.dps = 50
DEGREE = 17


def c_of(x):
    return mp.cos(2 * mp.acos(x) / 3)


def coefficients(deg):
    n = deg + 1
    nodes = [mp.cos(mp.pi * (k + mp.mpf(1) / 2) / n) for k in range(n)]
    values = [c_of((t + 1) / 2) for t in nodes]
    cheb = [
        (2 if j else 1) * sum(values[k] * mp.cos(mp.pi * j * (k + mp.mpf(1) / 2) / n) for k in range(n)) / n
        for j in range(n)
    ]
    # Chebyshev polynomials T_j as monomials in t.
    T = [[mp.mpf(1)], [mp.mpf(0), mp.mpf(1)]]
    for j in range(2, n):
        a = [mp.mpf(0)] + [2 * v for v in T[j - 1]]
        b = T[j - 2] + [mp.mpf(0)] * (len(a) - len(T[j - 2]))
        T.append([a[i] - b[i] for i in range(len(a))])
    mono = [mp.mpf(0)] * n
    for j in range(n):
        for i, v in enumerate(T[j]):
            mono[i] += cheb[j] * v
    return [float(v) for v in mono]


def main():
    c = coefficients(DEGREE)
    worst = 0.0
    for m in range(40001):
        x = m / 40000
        t = 2 * x - 1
        h = c[-1]
        for v in reversed(c[:-1]):
            h = h * t + v
        worst = max(worst, abs(h - float(c_of(mp.mpf(x)))))
    for v in c:
        print(repr(v))
    print(f"largest error {worst:.3e}")


if __name__ == "__main__":
    main()
