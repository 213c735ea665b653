#!/usr/bin/env python3
"""Self-similar potential flow of a liquid wedge driven into a rigid plane body (no gravity).

The reference of `cases/wedge_impact_2d.yaml` (thesis §5.6.2.1; Wu's self-similar problem)
and, with other angles, of the classic water entry of a rigid wedge (Dobrovol'skaya; Zhao &
Faltinsen 1993). Potential flow, incompressible, no gravity, no surface tension. The liquid
occupies, before contact, the sector 0 < angle < theta_f of the plane (symmetric about y = 0)
and moves at -U along x; the body is the half-plane beyond the ray at angle theta_b > theta_f
through the origin, at rest. So the gap between the free surface and the body is
theta_b - theta_f: 10 degrees for both the triangular column of alpha = 80 degrees against a
vertical wall (theta_b = 90, theta_f = 80) and a wedge of 10 degrees deadrise (100, 90).

With no length scale the flow is self-similar: phi(x, t) = U^2 t F(x / (U t)). In the
similarity plane xi = x / (U t) and tau = ln t, a free-surface marker obeys
    d xi / d tau = grad F - xi,      d F / d tau = |grad F|^2 / 2 - F,
and the pressure is p / (rho U^2) = -(F - xi . grad F + |grad F|^2 / 2). The steady state of
these equations is the similarity solution (the pseudo-time iteration of Iafrati 2013,
arXiv:1212.6699, written here with Lagrangian markers). Each pseudo-time step solves Laplace's
equation for F by a boundary element method: linear elements, collocation at the nodes, the
Green function with its image in y = 0 (the symmetry line carries no element), the diagonal
from the constant-potential mode. Boundary conditions: F known on the free surface (Dirichlet);
dF/dn = 0 on the body; on a far arc of radius R the undisturbed flow, dF/dn = -n_x; the jet
running along the body is cut by a segment normal to the body at lambda_cut, through which it
leaves at the jet's speed (Zhao & Faltinsen's cut), the far free surface frozen at its
undisturbed state F = -xi_x - 1/2.

Output (JSON): the body pressure p / (rho U^2) against lambda / (U t) (the distance from the
origin along the body), its peak and position, the force on the body per unit width over
rho U^3 t, and the free surface.
"""
import argparse
import json
import math
import os
import sys

import numpy as np
from scipy.interpolate import Akima1DInterpolator

TWO_PI = 2.0 * math.pi
GX, GW = np.polynomial.legendre.leggauss(6)
GX = 0.5 * (GX + 1.0)
GW = 0.5 * GW
SX = (np.arange(24)[:, None] + GX[None, :]).ravel() / 24.0   # composite rule, near-singular
SW = np.tile(GW, 24) / 24.0


class Geometry:
    """Angles, far radius and node spacing of one problem."""

    def __init__(self, theta_b, theta_f, radius, h0, growth, lam_cut):
        self.tb = math.radians(theta_b)
        self.tf = math.radians(theta_f)
        self.t_body = np.array([math.cos(self.tb), math.sin(self.tb)])
        self.n_body = np.array([-math.sin(self.tb), math.cos(self.tb)])   # out of the liquid
        self.radius = radius
        self.h0 = h0
        self.growth = growth
        self.lam_cut = lam_cut
        self.frozen = radius / 3.0

    def surface_point(self, r):
        """The undisturbed free surface, in the similarity plane, at distance r along it."""
        return np.array([-1.0 + r * math.cos(self.tf), r * math.sin(self.tf)])

    def surface_r_at_radius(self, rad):
        c, s = math.cos(self.tf), math.sin(self.tf)
        # |(-1 + r c, r s)| = rad
        return c + math.sqrt(c * c - 1.0 + rad * rad)

    def contact_r(self):
        """Where the undisturbed surface meets the body ray."""
        # (-1 + r c_f, r s_f) = lam (c_b, s_b)
        a = np.array([[math.cos(self.tf), -math.cos(self.tb)],
                      [math.sin(self.tf), -math.sin(self.tb)]])
        r, lam = np.linalg.solve(a, np.array([1.0, 0.0]))
        return r, lam


def polyline_distance(points, poly):
    """Distance from each point to a polyline (vectorised over both)."""
    a = poly[:-1][None, :, :]
    ab = (poly[1:] - poly[:-1])[None, :, :]
    d = points[:, None, :] - a
    t = np.clip(np.sum(d * ab, axis=2) / np.maximum(np.sum(ab * ab, axis=2), 1e-300), 0.0, 1.0)
    r = d - t[:, :, None] * ab
    return np.sqrt(np.min(np.sum(r * r, axis=2), axis=1))


def panel_integrals(p, a, b, x, w):
    """Integrals over the segment a-b of N_a G, N_b G, N_a dG/dn, N_b dG/dn seen from p,
    G the free-space Green function plus its image in y = 0, quadrature (x, w) on [0, 1]."""
    ab = b - a
    length = math.hypot(ab[0], ab[1])
    n = np.array([-ab[1], ab[0]]) / length
    q = a[None, :] + x[:, None] * ab[None, :]
    ps = np.array([p[0], -p[1]])
    r1 = q - p
    r2 = q - ps
    d1 = np.sum(r1 * r1, axis=1)
    d2 = np.sum(r2 * r2, axis=1)
    g = -(0.5 * np.log(d1) + 0.5 * np.log(d2)) / TWO_PI
    dg = -((r1 @ n) / d1 + (r2 @ n) / d2) / TWO_PI
    wa = w * (1.0 - x) * length
    wb = w * x * length
    return np.array([wa @ g, wb @ g, wa @ dg, wb @ dg])


def assemble(nodes):
    """Influence matrices of the open polyline `nodes` (panels between consecutive nodes).
    Returns H (N x N, with the free term from the constant mode) and Gm (N x P x 2)."""
    n_nodes = len(nodes)
    a = nodes[:-1]
    b = nodes[1:]
    ab = b - a
    length = np.hypot(ab[:, 0], ab[:, 1])
    normal = np.stack([-ab[:, 1], ab[:, 0]], axis=1) / length[:, None]
    q = a[:, None, :] + GX[None, :, None] * ab[:, None, :]               # P x Q x 2
    p = nodes[:, None, None, :]
    ps = nodes * np.array([1.0, -1.0])
    r1 = q[None] - p
    r2 = q[None] - ps[:, None, None, :]
    d1 = np.sum(r1 * r1, axis=3)
    d2 = np.sum(r2 * r2, axis=3)
    with np.errstate(divide="ignore", invalid="ignore"):
        g = -(0.5 * np.log(d1) + 0.5 * np.log(d2)) / TWO_PI
        dg = -(np.einsum("ipqk,pk->ipq", r1, normal) / d1
               + np.einsum("ipqk,pk->ipq", r2, normal) / d2) / TWO_PI
    wa = (GW[None, :] * (1.0 - GX[None, :])) * length[:, None]
    wb = (GW[None, :] * GX[None, :]) * length[:, None]
    ga = np.einsum("ipq,pq->ip", g, wa)
    gb = np.einsum("ipq,pq->ip", g, wb)
    ha = np.einsum("ipq,pq->ip", dg, wa)
    hb = np.einsum("ipq,pq->ip", dg, wb)

    # near-singular pairs: the point closer than 1.5 panel lengths (or its image)
    n_pan = len(a)
    t = np.clip(np.einsum("ipk,pk->ip", nodes[:, None, :] - a[None], ab) / (length ** 2)[None], 0, 1)
    near = nodes[:, None, :] - (a[None] + t[:, :, None] * ab[None])
    dist = np.hypot(near[:, :, 0], near[:, :, 1])
    ti = np.clip(np.einsum("ipk,pk->ip", ps[:, None, :] - a[None], ab) / (length ** 2)[None], 0, 1)
    neari = ps[:, None, :] - (a[None] + ti[:, :, None] * ab[None])
    disti = np.hypot(neari[:, :, 0], neari[:, :, 1])
    flag = (np.minimum(dist, disti) < 1.5 * length[None]) | ~np.isfinite(ga) | ~np.isfinite(ha)
    idx = np.arange(n_nodes)
    adjacent = np.zeros_like(flag)
    adjacent[idx[1:], idx[1:] - 1] = True
    adjacent[idx[:-1], idx[:-1]] = True
    for i, k in zip(*np.nonzero(flag & ~adjacent)):
        ga[i, k], gb[i, k], ha[i, k], hb[i, k] = panel_integrals(nodes[i], a[k], b[k], SX, SW)
    # the panels that end at the point: the direct log analytically, its normal derivative
    # zero on the straight panel; the image part by quadrature unless the point is on y = 0
    for i in range(n_nodes):
        for k, at_a in ((i, True), (i - 1, False)):
            if k < 0 or k >= n_pan:
                continue
            lk = length[k]
            near_end = lk * (0.5 * math.log(lk) - 0.75)
            far_end = lk * (0.5 * math.log(lk) - 0.25)
            direct = np.array([near_end, far_end]) if at_a else np.array([far_end, near_end])
            direct = -direct / TWO_PI
            if abs(nodes[i][1]) < 1e-12:
                ga[i, k], gb[i, k] = 2.0 * direct
                ha[i, k] = hb[i, k] = 0.0
            else:
                img = image_integrals(nodes[i], a[k], b[k])
                ga[i, k], gb[i, k] = direct + img[:2]
                ha[i, k], hb[i, k] = img[2:]
    h = np.zeros((n_nodes, n_nodes))
    np.add.at(h, (slice(None), idx[:-1]), ha)
    np.add.at(h, (slice(None), idx[1:]), hb)
    h[idx, idx] -= h.sum(axis=1)      # free term c_i = -sum_j H_ij (constant potential)
    return h, ga, gb


def solve_mixed(nodes, dirichlet, phi_known, q_known):
    """Laplace's equation on the polyline's domain (closed by y = 0): on the panels where
    `dirichlet` is set the potential is known at their nodes (phi_known), on the others the
    normal derivative at both ends (q_known, panels x 2). Returns the potential at every node and
    the unknown of each node: the normal derivative on its Dirichlet side, or its potential."""
    n = len(nodes)
    h, ga, gb = assemble(nodes)
    surf = np.zeros(n, bool)
    surf[:-1] |= dirichlet
    surf[1:] |= dirichlet
    m = h.copy()
    rhs = -h[:, surf] @ phi_known[surf]
    m[:, surf] = 0.0
    for k in range(n - 1):
        if dirichlet[k]:
            m[:, k] -= ga[:, k]
            m[:, k + 1] -= gb[:, k]
        else:
            rhs += ga[:, k] * q_known[k, 0] + gb[:, k] * q_known[k, 1]
    u = np.linalg.solve(m, rhs)
    return np.where(surf, phi_known, u), u


def self_test():
    """The boundary element method against a harmonic field, even in y, on the wedge's
    boundary (the free surface Dirichlet, the body and far arc Neumann): its potential on the
    body and normal derivative on the free surface (RMS) converge at second order. Returns 0
    on success."""
    errors = []
    for growth in (0.1, 0.05):
        st = State(Geometry(90.0, 80.0, 60.0, 0.05, growth, 14.0), 0.0)
        st.regrid()
        nodes, kinds, i0 = st.layout()
        phi = nodes[:, 0] ** 2 - nodes[:, 1] ** 2 + 3.0 * nodes[:, 0]
        grad = np.stack([2.0 * nodes[:, 0] + 3.0, -2.0 * nodes[:, 1]], axis=1)
        ab = np.diff(nodes, axis=0)
        normal = np.stack([-ab[:, 1], ab[:, 0]], axis=1) / np.hypot(ab[:, 0], ab[:, 1])[:, None]
        q_known = np.stack([np.sum(grad[:-1] * normal, 1), np.sum(grad[1:] * normal, 1)], axis=1)
        dirichlet = np.array(kinds) == "surface"
        got, u = solve_mixed(nodes, dirichlet, np.where(np.arange(len(nodes)) >= i0, phi, 0.0), q_known)
        body = np.arange(i0)
        i1 = i0 + len(st.xs)
        err_phi = np.max(np.abs(got[body] - phi[body])) / np.max(np.abs(phi))
        # the surface's interior nodes: the mean of the two panels' exact normal derivatives
        q_exact = 0.5 * (q_known[i0:i1 - 2, 1] + q_known[i0 + 1:i1 - 1, 0])
        # (its RMS: at the node beside the far corner, where the two panels' derivatives differ,
        # the shared nodal value converges at first order only)
        err_q = np.sqrt(np.mean((u[i0 + 1:i1 - 1] - q_exact) ** 2)) / np.max(np.abs(grad))
        errors.append((len(nodes), err_phi, err_q))
        print(f"nodes {len(nodes)}: body potential error {err_phi:.3e}, surface flux error (RMS) {err_q:.3e}")
    ok = all(errors[0][k] / errors[1][k] > 2.5 and errors[1][k] < 2e-3 for k in (1, 2))
    print("self-test", "passed" if ok else "FAILED")
    return 0 if ok else 1


def image_integrals(p, a, b):
    ab = b - a
    length = math.hypot(ab[0], ab[1])
    n = np.array([-ab[1], ab[0]]) / length
    q = a[None, :] + SX[:, None] * ab[None, :]
    r2 = q - np.array([p[0], -p[1]])
    d2 = np.sum(r2 * r2, axis=1)
    g = -0.5 * np.log(d2) / TWO_PI
    dg = -(r2 @ n) / d2 / TWO_PI
    wa = SW * (1.0 - SX) * length
    wb = SW * SX * length
    return np.array([wa @ g, wb @ g, wa @ dg, wb @ dg])


def arc_derivative(s, f):
    """df/ds on a non-uniform 1D grid (second order inside, one-sided at the ends)."""
    d = np.empty_like(f)
    h1 = s[1:-1] - s[:-2]
    h2 = s[2:] - s[1:-1]
    d[1:-1] = (-h2 / (h1 * (h1 + h2)) * f[:-2] + (h2 - h1) / (h1 * h2) * f[1:-1]
               + h1 / (h2 * (h1 + h2)) * f[2:])
    d[0] = (f[1] - f[0]) / (s[1] - s[0])
    d[-1] = (f[-1] - f[-2]) / (s[-1] - s[-2])
    return d


class State:
    """Free-surface markers from the body end (contact point or jet cut) to the far end."""

    def __init__(self, geo, film):
        """The undisturbed surface cut by the body; with film > 0, a film of that thickness
        lines the body from where the surface is that far from it up to the jet's cut."""
        self.geo = geo
        r0, lam0 = geo.contact_r()
        gap = geo.tb - geo.tf
        if film > 0.0:
            r0 += film / math.sin(gap)
        r1 = geo.surface_r_at_radius(geo.radius)
        rr = r0 + (r1 - r0) * np.linspace(0.0, 1.0, 400) ** 3
        self.xs = np.array([geo.surface_point(r) for r in rr])
        self.cut = film > 0.0
        if self.cut:
            lam_m = self.xs[0] @ geo.t_body
            lam = np.linspace(geo.lam_cut, lam_m, 200)[:-1]
            film_pts = lam[:, None] * geo.t_body[None] - film * geo.n_body[None]
            self.xs = np.concatenate([film_pts, self.xs])
            corner = np.linalg.norm(self.xs - self.xs[len(film_pts)], axis=1) < 4.0 * film
            for _ in range(200):                     # round the film's turn
                self.xs[1:-1][corner[1:-1]] = 0.5 * (self.xs[:-2] + self.xs[2:])[corner[1:-1]]
        else:
            self.xs[0] = lam0 * geo.t_body
        self.F = -self.xs[:, 0] - 0.5
        self.lam_peak = lam0

    def attach_film(self, film):
        """From the contact-point state: a film of thickness `film` from the contact up to the
        jet's cut, in ballistic motion (velocity xi) from the contact's potential: F = F_E +
        (lambda^2 - lambda_E^2) / 2, which relaxes to the jet's steady F = |xi|^2 / 2 (pressure
        zero), as e^-tau."""
        geo = self.geo
        lam_e = self.xs[0] @ geo.t_body
        keep = np.linalg.norm(self.xs - self.xs[0], axis=1) > 3.0 * film
        xs, F = self.xs[keep], self.F[keep]
        lam = np.linspace(geo.lam_cut, lam_e, 200)
        film_pts = lam[:, None] * geo.t_body[None] - film * geo.n_body[None]
        film_F = self.F[0] + 0.5 * (lam ** 2 - lam_e ** 2)
        self.xs = np.concatenate([film_pts, xs])
        self.F = np.concatenate([film_F, F])
        join = np.linalg.norm(self.xs - film_pts[-1], axis=1) < 6.0 * film
        for _ in range(200):
            self.xs[1:-1][join[1:-1]] = 0.5 * (self.xs[:-2] + self.xs[2:])[join[1:-1]]
            self.F[1:-1][join[1:-1]] = 0.5 * (self.F[:-2] + self.F[2:])[join[1:-1]]
        self.cut = True

    # ---------------------------------------------------------------- layout
    def spacing(self, pts, other):
        geo = self.geo
        focus = np.array([self.lam_peak * geo.t_body, self.body_end()])
        d = np.min(np.linalg.norm(pts[:, None, :] - focus[None], axis=2), axis=1)
        h = geo.h0 + geo.growth * d
        near = polyline_distance(pts, other)
        return np.minimum(h, np.maximum(geo.h0, 1.5 * near))

    def body_end(self):
        return self.geo.lam_cut * self.geo.t_body if self.cut else self.xs[0]

    def body_nodes(self):
        geo = self.geo
        lam_top = self.body_end() @ geo.t_body
        lam = [lam_top]
        while lam[-1] > 0.0:
            p = np.array([lam[-1] * geo.t_body])
            h = self.spacing(p, self.xs)[0]
            lam.append(lam[-1] - h)
        lam = np.array(lam)
        lam = lam_top * (1.0 - (lam_top - lam) / (lam_top - lam[-1]))
        lam[-1] = 0.0
        return lam[::-1][:, None] * geo.t_body[None, :]

    def arc_nodes(self):
        geo = self.geo
        end = self.xs[-1]
        ang1 = math.atan2(end[1], end[0])
        rad = np.linalg.norm(end)
        n = max(8, int(math.ceil(ang1 * rad / (geo.growth * rad))))
        ang = np.linspace(ang1, 0.0, n + 1)[1:]
        return rad * np.stack([np.cos(ang), np.sin(ang)], axis=1)

    def regrid(self):
        geo = self.geo
        xs, F = self.xs, self.F
        s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(xs, axis=0).T))])
        keep = np.concatenate([[True], np.diff(s) > 1e-12])
        xs, F, s = xs[keep], F[keep], s[keep]
        ix = Akima1DInterpolator(s, xs[:, 0])
        iy = Akima1DInterpolator(s, xs[:, 1])
        iF = Akima1DInterpolator(s, F)
        body = np.array([[0.0, 0.0], self.body_end()]) if not self.cut else \
            np.array([[0.0, 0.0], geo.lam_cut * geo.t_body])
        fine = np.linspace(0.0, s[-1], 20 * len(s))
        pts = np.stack([ix(fine), iy(fine)], axis=1)
        h = self.spacing(pts, body)
        far = np.linalg.norm(pts, axis=1) > geo.frozen
        h[far] = np.maximum(h[far], geo.growth * np.linalg.norm(pts[far], axis=1))
        cum = np.concatenate([[0.0], np.cumsum(np.diff(fine) / (0.5 * (h[1:] + h[:-1])))])
        m = max(8, int(round(cum[-1])))
        snew = np.interp(np.linspace(0.0, cum[-1], m + 1), cum, fine)
        self.xs = np.stack([ix(snew), iy(snew)], axis=1)
        self.F = iF(snew)
        self.xs[-1] = xs[-1]
        self.F[-1] = F[-1]

    # ---------------------------------------------------------------- solve
    def layout(self):
        body = self.body_nodes()
        parts = [body]
        kinds = ["body"] * (len(body) - 1)
        if self.cut:
            kinds += ["cut"]
        else:
            body = body[:-1]
            parts = [body]
        parts += [self.xs, self.arc_nodes()]
        kinds += ["surface"] * (len(self.xs) - 1) + ["arc"] * len(parts[-1])
        nodes = np.concatenate(parts)
        first_surface = len(body)
        return nodes, kinds, first_surface

    def solve(self):
        geo = self.geo
        nodes, kinds, i0 = self.layout()
        n = len(nodes)
        i1 = i0 + len(self.xs)                       # surface nodes i0 .. i1-1
        ab = np.diff(nodes, axis=0)
        length = np.hypot(ab[:, 0], ab[:, 1])
        normal = np.stack([-ab[:, 1], ab[:, 0]], axis=1) / length[:, None]
        s = np.concatenate([[0.0], np.cumsum(length[i0:i1 - 1])])
        Fs = arc_derivative(s, self.F)
        q_known = np.zeros((n - 1, 2))
        for k, kind in enumerate(kinds):
            if kind == "arc":
                q_known[k] = -normal[k, 0]
            elif kind == "cut":
                q_known[k] = max(0.0, -Fs[0])        # the jet leaves at its own speed
        phi_known = np.zeros(n)
        phi_known[i0:i1] = self.F
        phi, u = solve_mixed(nodes, np.array(kinds) == "surface", phi_known, q_known)
        qn = u[i0:i1]
        # surface velocity: normal flux and tangential derivative
        pn = np.zeros((len(self.xs), 2))
        sn = normal[i0:i1 - 1]
        pn[:-1] += sn
        pn[1:] += sn
        pn /= np.linalg.norm(pn, axis=1)[:, None]
        tang = np.stack([pn[:, 1], -pn[:, 0]], axis=1)
        vel = qn[:, None] * pn + Fs[:, None] * tang
        t0 = (self.xs[1] - self.xs[0]) / np.linalg.norm(self.xs[1] - self.xs[0])
        if not self.cut:
            a = Fs[0] / (geo.t_body @ t0)            # at the contact: along the body
            vel[0] = a * geo.t_body
        body_end = i0 if self.cut else i0 + 1
        lam = nodes[:body_end] @ geo.t_body
        Fb = phi[:body_end]
        Fl = arc_derivative(lam, Fb)
        p = -Fb + lam * Fl - 0.5 * Fl ** 2
        return vel, lam, p, Fb

    # ---------------------------------------------------------------- step
    def rates(self):
        vel, lam, p, _ = self.solve()
        return vel - self.xs, 0.5 * np.sum(vel * vel, axis=1) - self.F, lam, p, vel

    def advance(self, dtau_max, courant):
        """One Heun step, as long as dtau_max and short enough that no panel's ends move
        apart or together by more than `courant` of its length."""
        geo = self.geo
        x0, F0 = self.xs.copy(), self.F.copy()
        dx1, dF1, lam, p, vel = self.rates()
        rate = np.linalg.norm(np.diff(dx1, axis=0), axis=1) / np.linalg.norm(np.diff(x0, axis=0), axis=1)
        dtau = min(dtau_max, courant / max(rate.max(), 1e-12))
        frozen = np.linalg.norm(x0, axis=1) > geo.frozen
        dx1[frozen] = 0.0
        dF1[frozen] = 0.0
        self.xs = x0 + dtau * dx1
        self.F = F0 + dtau * dF1
        self.constrain()
        if len(self.xs) != len(x0):
            return lam, p, vel, dtau
        dx2, dF2, lam, p, vel = self.rates()
        dx2[frozen] = 0.0
        dF2[frozen] = 0.0
        self.xs = x0 + 0.5 * dtau * (dx1 + dx2)
        self.F = F0 + 0.5 * dtau * (dF1 + dF2)
        self.constrain()
        return lam, p, vel, dtau

    def constrain(self):
        """Keep the body end on the body (or on the cut), the surface out of the body."""
        geo = self.geo
        xs, F = self.xs, self.F
        side = xs @ geo.n_body                       # > 0 behind the body
        if not self.cut:
            xs[0] = (xs[0] @ geo.t_body) * geo.t_body
            behind = np.nonzero(side[1:] > 0.0)[0]
            if len(behind):
                j = behind[-1] + 1                   # last marker behind, counted from the end
                f = side[j + 1] / (side[j + 1] - side[j])
                pt = xs[j + 1] + f * (xs[j] - xs[j + 1])
                Fj = F[j + 1] + f * (F[j] - F[j + 1])
                xs = np.concatenate([[(pt @ geo.t_body) * geo.t_body], xs[j + 1:]])
                F = np.concatenate([[Fj], F[j + 1:]])
            if xs[0] @ geo.t_body > geo.lam_cut:
                self.cut = True
        if self.cut:
            floor = 0.2 * geo.h0                     # the film may thin, never cross
            under = side > -floor
            xs[under] -= (side[under] + floor)[:, None] * geo.n_body[None]
            along = xs @ geo.t_body - geo.lam_cut
            inside = np.nonzero(along <= 0.0)[0]     # the jet: the markers from the end on
            if inside[0] > 0:                        # that lie beyond the cut
                j = inside[0] - 1
                f = along[j + 1] / (along[j + 1] - along[j])
                pt = xs[j + 1] + f * (xs[j] - xs[j + 1])
                Fj = F[j + 1] + f * (F[j] - F[j + 1])
                xs = np.concatenate([[pt], xs[j + 1:]])
                F = np.concatenate([[Fj], F[j + 1:]])
            else:                                    # the end fell short of the cut: extend
                d = xs[0] - xs[1]
                f = (geo.lam_cut - xs[1] @ geo.t_body) / (d @ geo.t_body)
                xs[0] = xs[1] + f * d
                F[0] = F[1] + f * (F[0] - F[1])
        self.xs, self.F = xs, F


def run(args):
    geo = Geometry(args.theta_body, args.theta_surface, args.radius, args.h0, args.growth,
                   args.lam_cut)
    st = State(geo, args.film if args.film_after <= 0.0 else 0.0)
    tau = 0.0
    history = []
    if args.resume:
        with open(args.resume) as f:
            saved = json.load(f)
        st.xs, st.F = np.array(saved["surface"]), np.array(saved["surface_potential"])
        st.cut, st.lam_peak, tau = saved["cut"], saved["lambda_peak"], saved["tau"]
        history = [tuple(h) for h in saved["history"]]
        if tau >= args.tau:
            sys.exit(f"wedge_similarity.py: {args.resume} is at pseudo-time {tau:.3f}, not before --tau {args.tau}")
    st.regrid()
    attached = st.cut
    while tau < args.tau:
        if not attached and tau >= args.film_after:
            st.attach_film(args.film)
            st.regrid()
            attached = True
        lam, p, vel, dtau = st.advance(args.dtau, args.courant if st.cut else args.courant_contact)
        st.regrid()
        tau += dtau
        k = int(np.argmax(p))
        st.lam_peak = lam[k]
        force = float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(lam)))
        history.append((tau, float(p[k]), float(lam[k]), force, len(st.xs), st.cut))
        if dtau < 1e-4 * args.dtau or not np.isfinite(force):
            print(f"stopped at tau {tau:.3f}: the step fell to {dtau:.1e} (an unstable "
                  "surface); the last state saved is kept", flush=True)
            return st, lam, p, history, tau, False
        if args.out and len(history) % (10 * args.every) == 0:
            save(args, st, lam, p, history, tau)
            save(args, st, lam, p, history, tau, f"{args.out}.tau{tau:06.3f}")
        if args.verbose and len(history) % args.every == 0:
            print(f"tau {tau:7.3f} dtau {dtau:.1e}  p_max {p[k]:9.3f} at lambda {lam[k]:7.4f}  force {force:9.3f}"
                  f"  end {st.xs[0] @ geo.t_body:7.3f} nodes {len(st.xs)} cut {st.cut}", flush=True)
    return st, lam, p, history, tau, True


def save(args, st, lam, p, history, tau, path=None):
    """The state and the body's pressure, written whole or not at all."""
    k = int(np.argmax(p))
    result = {
        "theta_body_deg": args.theta_body, "theta_surface_deg": args.theta_surface,
        "pressure_peak": float(p[k]), "lambda_peak": float(lam[k]), "force": history[-1][3],
        "lambda": lam.tolist(), "pressure": p.tolist(), "tau": tau, "cut": st.cut,
        "surface": st.xs.tolist(), "surface_potential": st.F.tolist(), "history": history,
        "parameters": vars(args),
    }
    path = path or args.out
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(result, f)
    os.replace(tmp, path)
    return result


def write_profile(path, res, eta_max=None):
    """The reference profile for `reference.type: wedge_impact` (docs/case-file.md), up to
    eta_max when given: beyond it (the jet near its cut) the pressure is taken as the steady
    jet's, zero (a profile file is zero beyond its last row)."""
    par = res["parameters"]
    lam, p = np.array(res["lambda"]), np.array(res["pressure"])
    if eta_max is not None:
        keep = lam <= eta_max
        lam, p = np.append(lam[keep], eta_max + 1e-6), np.append(p[keep], 0.0)
    hist = np.array([h[:4] for h in res["history"]], dtype=float)
    last = hist[hist[:, 0] >= hist[-1, 0] - 0.5]
    lines = [
        "# The self-similar wall pressure of a liquid wedge driven into a plane wall (no gravity,",
        "# potential flow): scripts/wedge_similarity.py, docs/validation.md \"The triangular water column\".",
        f"# body ray {par['theta_body']} deg, undisturbed free surface {par['theta_surface']} deg "
        f"(gap {par['theta_body'] - par['theta_surface']} deg); h0 {par['h0']}, growth {par['growth']}, "
        f"far radius {par['radius']}, jet cut at lambda {par['lam_cut']}; pseudo-time {res['tau']:.3f}",
        f"# over the last 0.5 of pseudo-time: peak {last[:, 1].min():.4f}-{last[:, 1].max():.4f} at eta "
        f"{last[:, 2].min():.4f}-{last[:, 2].max():.4f}, the whole body's force (the jet's cut zone included) "
        f"{last[:, 3].min():.4f}-{last[:, 3].max():.4f}",
        f"# the profile's integral (force coefficient) {np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(lam)):.4f}"
        + (f"; cut at eta {eta_max} (the jet beyond at zero pressure, its steady state)" if eta_max is not None else ""),
        "# eta: distance along the wall from the contact point over s = U t; pressure: p / (rho U^2)",
        "eta,pressure",
    ]
    lines += [f"{a:.6f},{b:.6f}" for a, b in zip(lam, p)]
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--theta-body", type=float, default=90.0, help="body ray angle (degrees)")
    ap.add_argument("--theta-surface", type=float, default=80.0, help="free surface angle (degrees)")
    ap.add_argument("--radius", type=float, default=300.0)
    ap.add_argument("--h0", type=float, default=0.02)
    ap.add_argument("--growth", type=float, default=0.12)
    ap.add_argument("--lam-cut", type=float, default=14.0)
    ap.add_argument("--film", type=float, default=0.1,
                    help="thickness of the film that starts the jet (0: the cut surface alone)")
    ap.add_argument("--film-after", type=float, default=3.0,
                    help="pseudo-time of the contact-point state before the film is attached")
    ap.add_argument("--dtau", type=float, default=0.01)
    ap.add_argument("--courant", type=float, default=0.2)
    ap.add_argument("--courant-contact", type=float, default=1e9,
                    help="the same bound before the film is attached")
    ap.add_argument("--tau", type=float, default=4.0)
    ap.add_argument("--every", type=int, default=10)
    ap.add_argument("--out", help="the result (JSON), also written every 10 x --every steps")
    ap.add_argument("--resume", help="start from a result written by --out")
    ap.add_argument("-v", "--verbose", action="store_true")
    ap.add_argument("--csv", help="with --export: write the body pressure of that result as a "
                    "reference profile (eta = lambda / (U t), pressure = p / (rho U^2))")
    ap.add_argument("--eta-max", type=float, help="with --export: the profile's last eta (the jet beyond at p = 0)")
    ap.add_argument("--export", help="a result written by --out, to convert with --csv (no run)")
    ap.add_argument("--self-test", action="store_true", help="check the boundary element method and exit")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    if args.export:
        with open(args.export) as f:
            res = json.load(f)
        write_profile(args.csv, res, args.eta_max)
        return 0
    st, lam, p, hist, tau, finished = run(args)
    if not finished:
        return 1
    k = int(np.argmax(p))
    if args.out:
        save(args, st, lam, p, hist, tau)
    print(json.dumps({"pressure_peak": float(p[k]), "lambda_peak": float(lam[k]), "force": hist[-1][3]}))


if __name__ == "__main__":
    sys.exit(main())
