# SPDX-License-Identifier: GPL-2.0-or-later
"""Quasi-static equilibrium of a ball bearing's inner ring, written out from the textbook as the
independent reference of the 3D bearing's tests: Jones (1960) as Harris and Kotzalas give it
(Rolling Bearing Analysis, 5th ed.: "Distribution of internal loading in statically loaded
bearings", "ball bearings under combined radial, thrust and moment load"), without centrifugal
or gyroscopic terms (a bearing at rest or turning slowly).

Each ball j at azimuth psi_j sits between the inner and the outer groove's curvature centres;
unloaded they are A = (f_i + f_o - 1) D apart. The inner ring is displaced by (dx, dy, dz) and
tilted by the small rotation (tx, ty); its curvature centre at the ball moves with it, and in the
ball's meridian plane the centres' separation becomes (s_r, s_z) (Harris' A_1j, A_2j; the tilt
as a finite rotation, of which Harris writes the first order). The ball
is squeezed by delta_j = |s| - A, carries Q_j = K_n(alpha_j) delta_j^1.5 along the line at the
contact angle alpha_j = atan2(s_z, s_r), with K_n the inner and outer exact Hertz constants in
series, K_n = [K_i^(-2/3) + K_o^(-2/3)]^(-3/2). The ring is in equilibrium when the applied
force F and moment M equal sum_j Q_j u_j and sum_j r_j x Q_j u_j (u_j the unit contact line,
r_j the inner curvature centre from the ring centre): Newton on the five displacements
(or four, with a prescribed axial displacement: a preload).

Hertz (Harris): with the curvature sums of the ball (2/D twice) and the race (inner
2/D gamma/(1-gamma) and -1/(f_i D), outer -2/D gamma/(1+gamma) and -1/(f_o D)),
gamma = D cos(alpha)/dm, Sum rho and F(rho) = (rho_I1 - rho_I2 + rho_II1 - rho_II2)/Sum rho, the
ellipticity kappa solves F(rho) = [(kappa^2 + 1) E - 2 K]/[(kappa^2 - 1) E] (K, E the complete
elliptic integrals of e^2 = 1 - 1/kappa^2, scipy.special), and
delta = K [(9 Sum rho / (2 E)) (Q / (pi kappa E'))^2]^(1/3), E' = 2 E*.
Only numpy and scipy (Debian's python3-scipy); nothing of ohmdem.
"""
import math

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk


def ellipticity(F_rho):
    """kappa = a/b of the Hertz ellipse from F(rho) (Harris)."""
    if F_rho <= 0.0:
        return 1.0

    def f(log_k):
        k = math.exp(log_k)
        m = 1.0 - 1.0 / (k * k)
        K, E = ellipk(m), ellipe(m)
        return ((k * k + 1) * E - 2 * K) / ((k * k - 1) * E) - F_rho

    return math.exp(brentq(f, 1e-9, 12.0, xtol=1e-15, rtol=1e-15))


def hertz_constant(sum_rho, F_rho, E_star):
    """K in Q = K delta^1.5 (N/m^1.5) from Harris' delta formula."""
    k = ellipticity(F_rho)
    m = 1.0 - 1.0 / (k * k)
    K, E = (ellipk(m), ellipe(m)) if m > 0 else (math.pi / 2, math.pi / 2)
    Ep = 2.0 * E_star
    # delta = K [(9 S/(2E)) (Q/(pi k E'))^2]^(1/3)  =>  Q = delta^1.5 / sqrt(K^3 9 S/(2E)) pi k E'
    return math.pi * k * Ep / math.sqrt(K**3 * 9.0 * sum_rho / (2.0 * E))


def race_sums(D, dm, f, alpha, inner):
    """Harris' Sum rho and F(rho) of a ball on a race at contact angle alpha: the ball's
    curvatures 2/D in both planes, the race's rho_2 in the rolling plane and -1/(f D) across the
    groove; F(rho) = ((rho_I1 - rho_II1) + (rho_I2 - rho_II2)) / Sum rho."""
    g = D * math.cos(alpha) / dm
    rolling = (2 / D) * (g / (1 - g) if inner else -g / (1 + g))
    groove = -1.0 / (f * D)
    s = 4 / D + rolling + groove
    return s, (rolling - groove) / s


class Bearing:
    """A ball bearing for the reference: Z balls of diameter D on the pitch diameter dm, groove
    conformities f_i = Rci/D and f_o = Rco/D, steel E*, and where the grooves' curvature centres
    lie (radius and axial position of each locus in the unloaded, concentric position):
    clearance Pd (diametral: each groove c/4 off the balls, both at z = 0) or a nominal angle
    alpha0 (the centres A apart along alpha0, a ball on the pitch circle touching both)."""

    def __init__(self, Z, D, dm, Rci, Rco, E_star, clearance=0.0, alpha0_deg=0.0):
        self.Z, self.D, self.dm, self.E_star = Z, D, dm, E_star
        self.fi, self.fo = Rci / D, Rco / D
        self.A = Rci + Rco - D
        r = D / 2
        if alpha0_deg > 0:
            a0 = math.radians(alpha0_deg)
            self.rho_i = dm / 2 + (Rci - r) * math.cos(a0)
            self.z_i = (Rci - r) * math.sin(a0)
            self.rho_o = dm / 2 - (Rco - r) * math.cos(a0)
            self.z_o = -(Rco - r) * math.sin(a0)
            self.cos_alpha0 = math.cos(a0)
        else:
            self.rho_i = dm / 2 - r + Rci - clearance / 4
            self.rho_o = dm / 2 + r - Rco + clearance / 4
            self.z_i = self.z_o = 0.0
            self.cos_alpha0 = 1.0 - clearance / (2 * self.A)  # Harris' free contact angle

        # K_n depends on cos(alpha) only: tabulated once on 801 nodes (cubic spline; within
        # 1e-9 of K_n_exact, checked by jones_harris_tests.py).
        c = np.linspace(0.02, 1.0, 801)
        self._kn = CubicSpline(c, [self.K_n_exact(math.acos(x)) for x in c])

    def K_n(self, alpha):
        return float(self._kn(math.cos(alpha)))

    def K_n_exact(self, alpha):
        si, Fi = race_sums(self.D, self.dm, self.fi, alpha, True)
        so, Fo = race_sums(self.D, self.dm, self.fo, alpha, False)
        Ki = hertz_constant(si, Fi, self.E_star)
        Ko = hertz_constant(so, Fo, self.E_star)
        return (Ki ** (-2.0 / 3) + Ko ** (-2.0 / 3)) ** -1.5

    def balls(self, q, psi):
        """Per ball (arrays over psi): Q, alpha, delta, the unit contact line u and the arm r
        (the inner curvature centre from the ring centre), for the ring displacement
        q = (dx, dy, dz, tx, ty)."""
        psi = np.asarray(psi, float)
        e = np.stack([np.cos(psi), np.sin(psi), np.zeros_like(psi)], axis=1)
        z = np.array([0.0, 0.0, 1.0])
        r_i = self.rho_i * e + self.z_i * z
        # The ring's tilt as the rotation by |t| about t (Rodrigues); Harris writes its first
        # order, r + t x r, which is 1 % off in the loads at a tilt of a few milliradians.
        r_i = r_i @ _rotation(np.array([q[3], q[4], 0.0])).T
        P_i = r_i + np.asarray(q[:3], float)
        P_o = self.rho_o * e + self.z_o * z
        s = P_i - P_o
        sr, sz = np.sum(s * e, axis=1), s[:, 2]  # in the ball's meridian plane
        L = np.hypot(sr, sz)
        alpha = np.arctan2(sz, sr)
        delta = L - self.A
        Q = np.where(delta > 0, self._kn(np.cos(alpha)) * np.maximum(delta, 0.0) ** 1.5, 0.0)
        u = (sr[:, None] * e + sz[:, None] * z) / L[:, None]
        return Q, alpha, delta, u, r_i

    def residual(self, q, psi, F, M):
        Q, _, _, u, r = self.balls(q, psi)
        f = (Q[:, None] * u).sum(axis=0)
        m = _cross(r, Q[:, None] * u).sum(axis=0)
        return np.concatenate([F - f, (M - m)[:2]])


def _rotation(t):
    """The rotation matrix of the rotation vector t (Rodrigues)."""
    th = float(np.linalg.norm(t))
    if th == 0.0:
        return np.eye(3)
    k = t / th
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(th) * K + (1 - math.cos(th)) * K @ K


def _cross(a, b):
    """a x b row by row (numpy's cross is slow for small arrays)."""
    a = np.broadcast_to(a, np.broadcast(a, b).shape)
    b = np.broadcast_to(b, a.shape)
    return np.stack([a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
                     a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
                     a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]], axis=-1)


def solve(b, psi, F, M=(0.0, 0.0, 0.0), preload=None, guess=None):
    """Newton (finite-difference Jacobian, halving steps) on the ring displacement q under the
    force F and moment M (vectors, N and N m), or with q[2] = preload held (its reaction is then
    the axial force). Loads are applied in three steps (a tenth, three tenths, all), each solve
    from the last. Returns q, the balls (balls()) and the residual's largest component."""
    F = np.asarray(F, float)
    M = np.asarray(M, float)
    free = [0, 1, 3, 4] if preload is not None else [0, 1, 2, 3, 4]
    q = np.zeros(5) if guess is None else np.array(guess, float)
    if guess is None:
        # Start where every ball just touches, pushed a little along the loads.
        if preload is not None:
            q[2] = preload
        elif F[2] != 0.0:
            q[2] = b.A * math.sqrt(max(0.0, 1 - b.cos_alpha0**2)) - (b.z_i - b.z_o)
            q[2] += 1e-7 * np.sign(F[2])
        if np.hypot(F[0], F[1]) > 0:
            # Radially: take up the play (Pd/2 = A (1 - cos alpha0)) unless the ring is axial.
            play = b.A * (1 - b.cos_alpha0) if q[2] == 0.0 and b.z_i == b.z_o else 0.0
            q[:2] += (play + 1e-7) * F[:2] / np.hypot(F[0], F[1])
    scale = np.array([1, 1, 1, b.dm, b.dm])  # a tilt of h/dm moves the ring by ~h
    fscale = max(1.0, float(np.linalg.norm(F)), float(np.linalg.norm(M)) / b.dm)

    def res(qq, frac):
        r = b.residual(qq, psi, frac * F, frac * M)
        r[3:] /= b.dm
        if preload is not None:
            r = np.delete(r, 2)
        return r / fscale

    worst = math.inf
    for frac in (0.1, 0.3, 1.0):
        for _ in range(100):
            r0 = res(q, frac)
            if np.max(np.abs(r0)) < 1e-11:  # of the load: far below any check
                break
            J = np.zeros((len(free), len(free)))
            for k, i in enumerate(free):
                h = 1e-10 / scale[i]
                qp, qm = q.copy(), q.copy()
                qp[i] += h
                qm[i] -= h
                J[:, k] = (res(qp, frac) - res(qm, frac)) / (2 * h)
            step = np.linalg.lstsq(J, -r0, rcond=None)[0]
            lam = 1.0
            n0 = np.linalg.norm(r0)
            while lam > 1e-6:
                qn = q.copy()
                qn[free] += lam * step
                if np.linalg.norm(res(qn, frac)) < n0:
                    break
                lam *= 0.5
            q = qn
            if np.max(np.abs(lam * step * scale[free])) < 1e-16:  # no progress left to make
                break
        worst = float(np.max(np.abs(res(q, frac)))) * fscale
    return q, b.balls(q, psi), worst


def harris_axial_angle(b, Fa):
    """alpha (rad) of Harris' pure thrust relation Fa/(Z K_n(alpha) A^1.5)
    = sin(alpha) (cos(alpha0)/cos(alpha) - 1)^1.5, solved by bisection."""
    a0 = math.acos(min(1.0, b.cos_alpha0))

    def f(a):
        shape = math.sin(a) * (b.cos_alpha0 / math.cos(a) - 1) ** 1.5
        return b.Z * b.K_n(a) * b.A**1.5 * shape - Fa

    return brentq(f, a0 + 1e-12, math.radians(89.0), xtol=1e-14)


def peak_pressure(b, Q, alpha, inner):
    """The peak Hertz pressure 3Q/(2 pi a b) of a ball's contact with a race at alpha, Harris'
    semi-axes a = (6 kappa^2 E Q / (pi Sum rho E'))^(1/3),
    b = (6 E Q / (pi kappa Sum rho E'))^(1/3)."""
    s, F = race_sums(b.D, b.dm, b.fi if inner else b.fo, alpha, inner)
    k = ellipticity(F)
    m = 1.0 - 1.0 / (k * k)
    E = ellipe(m) if m > 0 else math.pi / 2
    Ep = 2.0 * b.E_star
    a_ = (6 * k * k * E * Q / (math.pi * s * Ep)) ** (1 / 3)
    b_ = (6 * E * Q / (math.pi * k * s * Ep)) ** (1 / 3)
    return 3 * Q / (2 * math.pi * a_ * b_)


def ring_frame_angles(q, u):
    """The contact angles (rad) of the contact lines u (lab frame) seen from the tilted ring
    of displacement q: a race's contact angle is measured from its own ring's radial plane."""
    v = np.asarray(u) @ _rotation(np.array([q[3], q[4], 0.0]))  # R^T u, row by row
    return np.arctan2(v[:, 2], np.hypot(v[:, 0], v[:, 1]))
