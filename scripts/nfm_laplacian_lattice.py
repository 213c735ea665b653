#!/usr/bin/env python3
"""The discrete NFM Laplacian (thesis 4.85) of f = y^2 for a particle of a Cartesian
lattice (first row at dx/2) next to a flat wall, with the analytical Shepard
factor gamma and with the discrete kernel sum, 2D Wendland C2, R/dx = 3 and 4:
the exact value is 2; then the defect on f = y row by row and the steady Poiseuille error it
predicts. Explains the first-order Poiseuille error (docs/validation.md).
Needs python3-scipy."""
import numpy as np
from scipy import integrate
def W(r,R):  # Wendland C2 2D, support R
    q=r/R; a=7/(np.pi*R*R)
    return np.where(q<1, a*(1-q)**4*(1+4*q), 0.0)
def dW(r,R):
    q=r/R; a=7/(np.pi*R*R)
    return np.where(q<1, a*(-20*q*(1-q)**3)/R, 0.0)
def lap(k0, Rdx, f, dx=1.0, disc_gamma=False):
    R=Rdx*dx; yi=(k0+0.5)*dx
    n=int(Rdx)+2
    s=0.0; g_disc=0.0
    for i in range(-n,n+1):
        for k in range(0, k0+n+1):
            xj=i*dx; yj=(k+0.5)*dx
            if i==0 and k==k0: 
                g_disc+=W(0,R)*dx*dx; continue
            xij=np.array([-xj, yi-yj]); r=np.hypot(*xij)
            if r>=R: continue
            g_disc+=W(r,R)*dx*dx
            gradW=dW(r,R)/r*xij
            s+=dx*dx*(f(yi)-f(yj))*np.dot(xij,gradW)/r**2
    # wall: y=0, n_out=(0,-1), d_n = (x_i-x_q).n_out = -yi
    dn=-yi
    if yi<R:
        L=np.sqrt(R*R-yi*yi)
        wall=integrate.quad(lambda x: W(np.hypot(x,yi),R)*(f(yi)-f(0.0))/dn, -L, L)[0]
    else: wall=0
    gam=integrate.dblquad(lambda y,x: W(np.hypot(x,yi-y),R), -R, R, lambda x:0, lambda x: yi+R)[0]
    wsum=0
    if yi<R: wsum=integrate.quad(lambda x: W(np.hypot(x,yi),R), -np.sqrt(R*R-yi*yi), np.sqrt(R*R-yi*yi))[0]
    return 2/gam*(s+wall), gam, g_disc, 2/g_disc*(s+wall)
for Rdx in (3,4):
  for k0 in range(0,5):
    L,g,gd,Ld=lap(k0,Rdx,lambda y: y*y)
    print(Rdx,k0,'L(y^2)=%.4f (exact 2)  gamma=%.4f  discrete sum=%.4f  L with discrete gamma=%.4f'%(L,g,gd,Ld))

def lap_f(k0,Rdx,f2):  # generic field f2(x,y), particle at x=0
    dx=1.0; R=Rdx*dx; yi=(k0+0.5)*dx; n=int(Rdx)+2; s=0.0
    for i in range(-n,n+1):
        for k in range(0,k0+n+1):
            if i==0 and k==k0: continue
            xj=i*dx; yj=(k+0.5)*dx; xij=np.array([-xj, yi-yj]); r=np.hypot(*xij)
            if r>=R: continue
            s+=dx*dx*(f2(0,yi)-f2(xj,yj))*np.dot(xij,dW(r,R)/r*xij)/r**2
    dn=-yi; wall=0
    if yi<R:
        L=np.sqrt(R*R-yi*yi)
        wall=integrate.quad(lambda x: W(np.hypot(x,yi),R)*(f2(0,yi)-f2(x,0.0))/dn, -L, L)[0]
    gam=integrate.dblquad(lambda y,x: W(np.hypot(x,yi-y),R), -R, R, lambda x:0, lambda x: yi+R)[0]
    return 2/gam*(s+wall)
print("correction by L(|x - x_i|^2) = 4 (2D):")
for Rdx in (3,4):
  for k0 in range(0,5):
    ly=lap_f(k0,Rdx,lambda x,y: y*y)
    lr=lap_f(k0,Rdx,lambda x,y: x*x+(y-(k0+0.5))**2)
    lyy=lap_f(k0,Rdx,lambda x,y: (y-(k0+0.5))**2)
    print(Rdx,k0,'L(y^2)=%.4f  L(r^2)=%.4f  corrected=%.4f   L((y-yi)^2)=%.4f'%(ly,lr,ly*4/lr,lyy))

# The defect on the linear field f = y, row by row: c_k, in units of 1/dx (every term of (4.85)
# scales as 1/dx at fixed R/dx). In the steady Poiseuille flow (height L, u'(0) = 4 U/L) the
# viscous term nu u'(0) c_k / dx of the first rows, integrated twice from the wall, shifts the
# whole profile by u'(0) dx sum_k c_k (k + 1/2): a uniform offset, first order in dx, whose
# velocity L2 error relative to the parabola's RMS (sqrt(8/15) U) is
# 4 |sum_k c_k (k + 1/2)| / sqrt(8/15) dx / L (docs/validation.md, "NFM walls (2D)")
print("L(y) row by row (exact 0), sum_k c_k, sum_k c_k (k + 1/2), predicted steady L2 error x L/dx:")
for Rdx in (3, 4, 6):
  rows = [lap(k0, Rdx, lambda y: y)[0] for k0 in range(0, int(Rdx) + 2)]
  m1 = sum(c * (k + 0.5) for k, c in enumerate(rows))
  print(Rdx, " ".join('%.4f' % r for r in rows), ' sum %.4f' % sum(rows), ' moment %.4f' % m1,
        ' L2 x L/dx %.4f' % (4 * abs(m1) / np.sqrt(8 / 15)))
