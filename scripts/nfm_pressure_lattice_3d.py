#!/usr/bin/env python3
"""The NFM pressure gradient of a hydrostatic state on the 3D Cartesian lattice (first row at
dx/2 above a flat floor), row by row, 3D Wendland C2 (support R), R/dx = 2.5 by default:
the first-step vertical acceleration it predicts (docs/validation.md, "NFM walls (3D)").

For P_j = P_i + G.(x_j - x_i) the fluid sum and the wall term (4.22) with the wall pressure
extrapolated to the wall point (4.30) give, divided by the analytical Shepard factor gamma_i,
  du_i = g - (1 / (rho gamma_i)) (2 P_i E_i + M_i G),
  E_i = sum_j V_j grad_i W_ij + sum_q s_q W_iq n_out            (zero in the continuum),
  M_i = sum_j V_j grad_i W_ij (x) (x_j - x_i) + the wall's part   (gamma_i I in the continuum).
E_i is the uniform-pressure defect (it scales as 1/dx), M_i / gamma_i the linear one (fixed at
fixed R/dx). usage: nfm_pressure_lattice_3d.py [R/dx] [dx m] [H m]"""
import sys

import numpy as np

Rdx = float(sys.argv[1]) if len(sys.argv) > 1 else 2.5
dx = float(sys.argv[2]) if len(sys.argv) > 2 else 0.1
H = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
rho, g = 1000.0, 9.81
R = Rdx  # lengths in dx below


def W(r):
    q = r / R
    return np.where(q < 1, 21 / (2 * np.pi * R**3) * (1 - q) ** 4 * (1 + 4 * q), 0.0)


def dW(r):
    q = r / R
    return np.where(q < 1, 21 / (2 * np.pi * R**3) * (-20 * q * (1 - q) ** 3) / R, 0.0)


s = np.linspace(0, R, 20001)


def plane(d):  # integral of W over a plane at distance d
    return np.trapz(W(np.sqrt(d * d + s * s)) * 2 * np.pi * s, s)


zz = np.linspace(-R, R, 4001)
slab = np.array([plane(abs(z)) for z in zz])


def gamma(d):  # the analytical Shepard factor at distance d from the floor
    m = zz >= -d
    return np.trapz(slab[m], zz[m])


n = int(np.ceil(R)) + 1
print(f"R/dx = {Rdx}, dx = {dx} m, H = {H} m: row, gamma, E_z dx, M_zz/gamma, du_z (m/s^2): uniform part, linear part, total")
for row in range(4):
    d = row + 0.5
    E = M = 0.0
    for i in range(-n, n + 1):
        for j in range(-n, n + 1):
            for k in range(-row, n + 1):
                r = np.sqrt(i * i + j * j + k * k)
                if (i, j, k) == (0, 0, 0) or r >= R:
                    continue
                gz = dW(r) / r * (-k)  # (grad_i W_ij)_z, x_ij = -(i, j, k) dx
                E += gz
                M += gz * k
    G = plane(d)
    E_z = E - G          # n_out = -z on the floor
    M_zz = M + d * G     # the wall term's sum_q s_q W (z_q - z_i) n_z
    gam = gamma(d)
    P = rho * g * (H - d * dx)
    uniform = -(2 * P / rho) * (E_z / dx) / gam
    linear = -g + g * M_zz / gam  # G_z = -rho g
    print(f"row {row}: gamma {gam:.4f}  E_z dx {E_z:+.4f}  M_zz/gamma {M_zz / gam:.4f}  du_z {uniform:+.2f} {linear:+.2f} {uniform + linear:+.2f}")
