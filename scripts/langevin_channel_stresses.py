#!/usr/bin/python3
"""Where the plane channel's stress goes with the Langevin model (cases/turbulent_channel_langevin_2d.yaml).

From a run's snapshots at t >= FROM (run it with --set time.snapshot_every=1 for a snapshot a second),
rows dx deep from the nearer wall (the upper half folded onto the lower, its z-velocities' sign
flipped), averaged over x and over the snapshots:
  - U, the row's mean velocity;
  - R11/k, R22/k: the velocity variances about the row mean over the model's k (the model's own
    homogeneous-shear state, with its k and epsilon given, has R22 = C0 k / C1 = 0.78 k in 2D);
  - -R12 = -<u'v'>, the Reynolds shear stress the particles carry by their motion, against the
    stress the momentum balance needs, u_*^2 (1 - z/h) = F (h - z), and against nu_T dU/dz (the
    mixing length's; the model's homogeneous state gives (1 - C2) C0 / (C1^2 C_mu) = 1.92 times it);
  - the drift's stress: the row means of the drift -C1/2 (epsilon/k) u'_x + C2 (dU/dz) u'_z, with u'
    the snapshot's velocity less its kernel mean (`mean_velocity`), summed from mid-channel down;
  - the particles' dispersion across the flow: the root-mean-square z-displacement from t = FROM
    (by id, over the particles 0.1 m or more from the walls then) and <dz^2> / (2 t).
usage: langevin_channel_stresses.py RUN_FOLDER [FROM]"""
import glob
import re
import sys

import h5py
import numpy as np

run = sys.argv[1]
t_from = float(sys.argv[2]) if len(sys.argv) > 2 else 20.0
name = glob.glob(run + "/*.xmf")
name = [n for n in name if not n.endswith("_walls.xmf")][0]
times = [float(t) for t in re.findall(r'<Time Value="([^"]+)"', open(name).read())]
files = sorted(glob.glob(name[:-4] + "_[0-9]*.h5"))
h, us, C1, C2, C0, c_mu = 0.5, 0.1, 1.8, 0.6, 1.4, 0.09
F = us * us / h
acc, used = None, 0
for path, t in zip(files, times):
    if t < t_from:
        continue
    d = h5py.File(path, "r")
    x, u, um = d["position"][:], d["velocity"][:], d["mean_velocity"][:]
    k, eps, nu_t = d["k"][:], d["epsilon"][:], d["eddy_viscosity"][:]
    z = x[:, 1]
    lower = z < h
    zw = np.where(lower, z, 1.0 - z)
    side = np.where(lower, 1.0, -1.0)
    dx = 1.0 / np.sqrt(len(z))  # the channel's 1 m x 1 m lattice
    rows = np.floor(zw / dx).astype(int)
    nrows = int(round(h / dx))  # rows of the half-width, the same in every snapshot
    rows = np.minimum(rows, nrows - 1)
    out = np.zeros((nrows, 9))
    for r in range(nrows):
        cols = []
        for half in (True, False):  # each half's row mean, then their mean weighted by count
            m = (rows == r) & (lower == half)
            if not m.any():
                continue
            s = side[m]
            up, vp = u[m, 0] - u[m, 0].mean(), (u[m, 1] - u[m, 1].mean()) * s
            ek = eps[m] / np.maximum(k[m], 1e-300)
            cols.append((m.sum(), np.array([zw[m].mean(), u[m, 0].mean(), (up * up).mean(), (vp * vp).mean(), (up * vp).mean(),
                                            k[m].mean(), nu_t[m].mean(), (-0.5 * C1 * ek * (u[m, 0] - um[m, 0])).mean(),
                                            ((u[m, 1] - um[m, 1]) * s).mean()])))
        if cols:
            out[r] = sum(c * v for c, v in cols) / sum(c for c, _ in cols)
    acc = out if acc is None else acc + out
    used += 1
acc /= used
z, U, R11, R22, R12, K, NT, relax, vz = acc.T
S = np.gradient(U, z)
drift = relax + C2 * S * vz
dz = dx
drift_stress = -np.cumsum(drift[::-1])[::-1] * dz  # at each row's lower face
print(f"{run}: {used} snapshots from t = {t_from} s, rows {dz:.4f} m deep (needed: F (h - z); drift: the drift's stress at the row's lower face)")
print(f"{'z':>7} {'U':>6} {'R11/k':>6} {'R22/k':>6} {'-R12':>8} {'needed':>8} {'nuT dU/dz':>9} {'-R12/needed':>11} {'drift':>8}")  # drift: the stress the drift's net force carries
for i in range(len(z)):
    need = F * (h - z[i])
    print(f"{z[i]:7.4f} {U[i]:6.3f} {R11[i] / K[i]:6.3f} {R22[i] / K[i]:6.3f} {-R12[i]:8.5f} {need:8.5f} {NT[i] * S[i]:9.5f} "
          f"{-R12[i] / need:11.3f} {drift_stress[i]:8.5f}")
band = (z > 0.05) & (z < 0.4)
print(f"over 0.05 < z < 0.4 m: -R12 / needed {np.mean(-R12[band] / (F * (h - z[band]))):.3f}, R22/k {np.mean(R22[band] / K[band]):.3f}, "
      f"R11/k {np.mean(R11[band] / K[band]):.3f}, drift's stress / needed {np.mean(drift_stress[band] / (F * (h - z[band] + dz / 2))):.3f}; molecular nu dU/dz / needed at most {np.max(3.23e-5 * S[band] / (F * (h - z[band]))):.3f}")

# the particles' dispersion across the flow from the first snapshot used
first = None
for path, t in zip(files, times):
    if t < t_from:
        continue
    d = h5py.File(path, "r")
    order = np.argsort(d["id"][:])
    z = d["position"][:][order, 1]
    if first is None:
        first, t_first = z, t
        away = np.minimum(z, 1.0 - z) >= 0.1
        continue
    dz2 = np.mean((z - first)[away] ** 2)
    print(f"dispersion after {t - t_first:5.1f} s: rms {np.sqrt(dz2):.4f} m, <dz^2>/(2t) {dz2 / (2 * (t - t_first)):.2e} m^2/s")
