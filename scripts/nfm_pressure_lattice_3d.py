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
fixed R/dx). usage: nfm_pressure_lattice_3d.py [R/dx] [dx m] [H m] [--first-row]

--first-row: what holds a particle of the first row off the floor. E_z dx of one particle at a
height h above the floor (the rest of the lattice in place: E_z < 0 pushes it up, with
du_z = -(2 P / rho) E_z / (gamma dx)), and of one on the floor (h = 0) whose row has the next
row at a gap g above it (the rows beyond at dx): where E_z >= 0 nothing pushes it off."""
import sys

import numpy as np

first_row = "--first-row" in sys.argv
argv = [a for a in sys.argv if a != "--first-row"]
Rdx = float(argv[1]) if len(argv) > 1 else 2.5
dx = float(argv[2]) if len(argv) > 2 else 0.1
H = float(argv[3]) if len(argv) > 3 else 1.0
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


def fluid_sums(h, heights, own):
    """sum_j V_j (grad_i W_ij)_z and sum_j V_j (grad_i W_ij)_z (z_j - z_i), in units of dx, for a
    particle at height h (in dx) whose neighbours sit on the lattice's columns at the heights given,
    but for its own column's site number own (the site it occupies, or left empty)"""
    E = M = 0.0
    for i in range(-n, n + 1):
        for j in range(-n, n + 1):
            for k, z in enumerate(heights):
                dz = h - z
                r = np.sqrt(i * i + j * j + dz * dz)
                if (i == 0 and j == 0 and k == own) or r >= R:
                    continue
                gz = dW(r) / r * dz  # (grad_i W_ij)_z
                E += gz
                M += gz * (z - h)
    return E, M


def E_z_at(h, heights):
    """E_z dx of a particle at height h above the floor, moved there from the lowest site of its
    column; the floor's sum_q s_q W_iq n_out,z is minus the integral of W over the plane"""
    return fluid_sums(h, heights, 0)[0] - plane(h)


if first_row:
    lattice = [k + 0.5 for k in range(n + 2)]
    print(f"R/dx = {Rdx}: one particle of the first row (dx/2) moved to a height h, the lattice in place")
    for h in (0.5, 0.4, 0.3, 0.2, 0.1, 0.05, 0.0):
        print(f"  h = {h:4.2f} dx: E_z dx {E_z_at(h, lattice):+.4f}")
    print("a particle on the floor, its row on the floor, the next row a gap g above, then every dx")
    for g in (1.0, 0.9, 0.8, 0.7, 0.6):
        print(f"  g = {g:3.1f} dx: E_z dx {E_z_at(0.0, [0.0] + [g + k for k in range(n + 2)]):+.4f}")
    sys.exit(0)

print(f"R/dx = {Rdx}, dx = {dx} m, H = {H} m: row, gamma, E_z dx, M_zz/gamma, du_z (m/s^2): uniform part, linear part, total")
for row in range(4):
    d = row + 0.5
    E, M = fluid_sums(d, [k + 0.5 for k in range(row + n + 1)], row)
    G = plane(d)
    E_z = E - G          # n_out = -z on the floor
    M_zz = M + d * G     # the wall term's sum_q s_q W (z_q - z_i) n_z
    gam = gamma(d)
    P = rho * g * (H - d * dx)
    uniform = -(2 * P / rho) * (E_z / dx) / gam
    linear = -g + g * M_zz / gam  # G_z = -rho g
    print(f"row {row}: gamma {gam:.4f}  E_z dx {E_z:+.4f}  M_zz/gamma {M_zz / gam:.4f}  du_z {uniform:+.2f} {linear:+.2f} {uniform + linear:+.2f}")
