"""The expected values of tests/it/any_curve.rs, computed in exact fractions from the
textbook formulas alone (Cox-de Boor, Bernstein, the rational Bezier form, thesis (4.5) and
Gregory's square), independently of the library. Run: python3 any_curve_oracle.py
"""
from fractions import Fraction as F

def cox(i, p, K, t):
    # Cox-de Boor, right-open spans except the last knot (clamped end)
    if p == 0:
        if K[i] <= t < K[i+1]: return F(1)
        if t == K[-1] and K[i] < K[i+1] == K[-1]: return F(1)
        return F(0)
    a = F(0); b = F(0)
    if K[i+p] != K[i]: a = (t - K[i]) / (K[i+p] - K[i]) * cox(i, p-1, K, t)
    if K[i+p+1] != K[i+1]: b = (K[i+p+1] - t) / (K[i+p+1] - K[i+1]) * cox(i+1, p-1, K, t)
    return a + b

def bspline(P, K, t):
    n = len(P); p = len(K) - n - 1
    return [sum(cox(j, p, K, t) * P[j][c] for j in range(n)) for c in range(len(P[0]))]

def bern(n, i, u):
    from math import comb
    return comb(n, i) * u**i * (1-u)**(n-i)

# --- Gordon: biquadratic surface, Bezier (quadratic) in u, B-spline in t = 2v on [0 0 0 1 2 2 2]
K = [F(x) for x in [0,0,0,1,2,2,2]]
z = [[0,1,1,0],[1,2,3,1],[0,1,2,4]]
P = [[(F(i,2), F(j), F(z[i][j])) for j in range(4)] for i in range(3)]
def S(u, t):
    out=[F(0)]*3
    for i in range(3):
        row=[P[i][j] for j in range(4)]
        pt=bspline(row, K, t)
        b=bern(2,i,u)
        out=[o+b*q for o,q in zip(out,pt)]
    return out
print("gordon S(1/4, t=3/2) =", [str(x) for x in S(F(1,4), F(3,2))])
# u-curves control points Q_i (columns j) at u_i = 0, 1/2, 1
for ui in [F(0),F(1,2),F(1)]:
    Q=[[sum(bern(2,i,ui)*P[i][j][c] for i in range(3)) for j in range(4)] for c in range(3)]
    print("u-curve at", ui, [[str(x) for x in r] for r in Q])
# v-curves: at t = 0, 1, 2, control points R (columns i)
for tj in [F(0),F(1),F(2)]:
    R=[[sum(cox(j,2,K,tj)*P[i][j][c] for j in range(4)) for i in range(3)] for c in range(3)]
    print("v-curve at t", tj, [[str(x) for x in r] for r in R])

# --- bicubic Coons (thesis (4.5)) with Gregory twists, B-spline boundaries
def H(t):  # thesis order H0..H3
    return [2*t**3-3*t**2+1, t**3-2*t**2+t, t**3-t**2, -2*t**3+3*t**2]
K2 = [F(x) for x in [0,0,0,1,2,2,2]]
c1P = [(F(0),F(0),F(0)), (F(1,4),F(0),F(1)), (F(3,4),F(0),F(1)), (F(1),F(0),F(0))]
def c1(u): return bspline(c1P, K2, 2*u)
def c2(u): return [u, F(1), F(0)]
def d1(v): return [F(0), v, F(0)]
def d2(v): return [F(1), v, F(0)]
def lin(p, q, s): return [a + (b-a)*s for a, b in zip(p, q)]
def du0(v): return lin((1,0,4), (1,0,0), v)     # x_u(0,v)
def du1(v): return lin((1,0,-4), (1,0,0), v)    # x_u(1,v)
def dv0(u): # x_v(u,0): quadratic Bezier (0,1,0),(0,1,2),(0,1,0)
    B=[(1-u)**2, 2*u*(1-u), u**2]; pts=[(0,1,0),(0,1,2),(0,1,0)]
    return [sum(b*p[c] for b,p in zip(B,pts)) for c in range(3)]
def dv1(u): return [F(0), F(1), F(0)]
# derivatives for the twists: a = d/dv x_u(i,v) at v=j, b = d/du x_v(u,j) at u=i
a = {(0,0):(0,0,-4),(0,1):(0,0,-4),(1,0):(0,0,4),(1,1):(0,0,4)}
b = {(0,0):(0,0,4),(1,0):(0,0,-4),(0,1):(0,0,0),(1,1):(0,0,0)}
def twist(i,j,u,v):
    du = u if i==0 else 1-u; dv = v if j==0 else 1-v
    return [(du*F(x) + dv*F(y))/(du+dv) for x,y in zip(a[(i,j)], b[(i,j)])]
def coons(u,v):
    hu, hv = H(u), H(v)
    hc = [hu[0]*p + hu[1]*q + hu[2]*r + hu[3]*s for p,q,r,s in zip(d1(v), du0(v), du1(v), d2(v))]
    hd = [hv[0]*p + hv[1]*q + hv[2]*r + hv[3]*s for p,q,r,s in zip(c1(u), dv0(u), dv1(u), c2(u))]
    x00,x10,x01,x11 = c1(F(0)), c1(F(1)), c2(F(0)), c2(F(1))
    xu00,xu10,xu01,xu11 = du0(F(0)), du1(F(0)), du0(F(1)), du1(F(1))
    xv00,xv10,xv01,xv11 = dv0(F(0)), dv0(F(1)), dv1(F(0)), dv1(F(1))
    t00,t10,t01,t11 = twist(0,0,u,v), twist(1,0,u,v), twist(0,1,u,v), twist(1,1,u,v)
    M = [[x00, xv00, xv01, x01],[xu00, t00, t01, xu01],[xu10, t10, t11, xu11],[x10, xv10, xv11, x11]]
    hcd = [sum(hu[r]*M[r][c][k]*hv[c] for r in range(4) for c in range(4)) for k in range(3)]
    return [x+y-z for x,y,z in zip(hc,hd,hcd)], hc, hd, hcd
x, hc, hd, hcd = coons(F(1,2), F(1,4))
print("bicubic x(1/2,1/4) =", [str(t) for t in x]); print(" hc", [str(t) for t in hc], "hd", [str(t) for t in hd], "hcd", [str(t) for t in hcd])
x, *_ = coons(F(1,4), F(3,4)); print("bicubic x(1/4,3/4) =", [str(t) for t in x])
# corner tangent checks
print("c1 end tangents (unit):", [str(2*2*(q-p)) for p,q in zip(c1P[0],c1P[1])], [str(2*2*(q-p)) for p,q in zip(c1P[2],c1P[3])])
twist = lambda i, j, u, v: [F(0)] * 3  # the zero twists instead of Gregory's
x, *_ = coons(F(1,2), F(1,4)); print("bicubic zero twist x(1/2,1/4) =", [str(t) for t in x])

# --- ruled surface between two NURBS quarter circles (weights 1, 1, 2): rational Bezier form
def rational(P, W, s):
    B = [(1 - s)**2, 2*s*(1 - s), s**2]
    w = sum(b*wi for b, wi in zip(B, W))
    return [sum(b*wi*p[c] for b, wi, p in zip(B, W, P)) / w for c in range(3)]
first = rational([(1, 0, 0), (1, 1, 0), (0, 1, 0)], [1, 1, 2], F(1, 2))
second = rational([(2, 0, 1), (2, 2, 1), (0, 2, 1)], [1, 1, 2], F(1, 2))  # on [0, 2], at 1
v = F(1, 4)
print("ruled x(1/2,1/4) =", [str((1 - v)*a + v*b) for a, b in zip(first, second)])

# --- bilinear Coons patches x = rc + rd - rcd (thesis 4.1) with B-spline and NURBS boundaries
def bilinear_coons(c1, c2, d1, d2, u, v):
    rc = [(1 - v)*a + v*b for a, b in zip(c1(u), c2(u))]
    rd = [(1 - u)*a + u*b for a, b in zip(d1(v), d2(v))]
    x00, x10, x01, x11 = c1(F(0)), c1(F(1)), c2(F(0)), c2(F(1))
    rcd = [(1-u)*(1-v)*a + u*(1-v)*b + (1-u)*v*c + u*v*d for a, b, c, d in zip(x00, x10, x01, x11)]
    return [a + b - c for a, b, c in zip(rc, rd, rcd)]
# the example: c1 the quadratic B-spline on [0 0 0 1 2 3 3 3] (domain [0, 3], t = 3u)
K3 = [F(x) for x in [0, 0, 0, 1, 2, 3, 3, 3]]
bP = [(F(0), F(0), F(0)), (F(1), F(0), F(1)), (F(2), F(0), F(0)), (F(3), F(0), F(1)), (F(4), F(0), F(0))]
print("de Boor weights at t = 3/2:", [str(cox(j, 2, K3, F(3, 2))) for j in range(5)])
e1 = lambda u: bspline(bP, K3, 3*u)
e2 = lambda u: [4*u, F(1), F(0)]
f1 = lambda v: [F(0), v, F(0)]
f2 = lambda v: [F(4), v, F(0)]
print("coons (1/2, 0) =", [str(t) for t in bilinear_coons(e1, e2, f1, f2, F(1, 2), F(0))])
print("coons (1/2, 1/2) =", [str(t) for t in bilinear_coons(e1, e2, f1, f2, F(1, 2), F(1, 2))])
# on the grid u, v in {0, 1/2, 1}, every boundary a B-spline: c2 of degree 1 on [0 0 1 2 2]
# (points (0,1,0), (2,1,0), (4,1,0)), d1, d2 of degree 1 on [0 0 1 1]
g2 = lambda u: bspline([(F(0), F(1), F(0)), (F(2), F(1), F(0)), (F(4), F(1), F(0))], [F(x) for x in [0, 0, 1, 2, 2]], 2*u)
h1 = lambda v: bspline([(F(0), F(0), F(0)), (F(0), F(1), F(0))], [F(x) for x in [0, 0, 1, 1]], v)
h2 = lambda v: bspline([(F(4), F(0), F(0)), (F(4), F(1), F(0))], [F(x) for x in [0, 0, 1, 1]], v)
for u in [F(0), F(1, 2), F(1)]:
    print("coons grid u =", u, [[str(t) for t in bilinear_coons(e1, g2, h1, h2, u, v)] for v in [F(0), F(1, 2), F(1)]])
# a NURBS boundary: the quarter circle (1,0) -> (0,1), weights 1, 1, 2 (w1^2/(w0 w2) = 1/2, a
# circle), at z = 0 and lifted to z = 1; the sides are lines: the patch is the unit cylinder
n1 = lambda u: rational([(1, 0, 0), (1, 1, 0), (0, 1, 0)], [1, 1, 2], u)
n2 = lambda u: rational([(1, 0, 1), (1, 1, 1), (0, 1, 1)], [1, 1, 2], u)
s1 = lambda v: [F(1), F(0), v]
s2 = lambda v: [F(0), F(1), v]
for u, v in [(F(1, 2), F(1, 4)), (F(1, 4), F(3, 4))]:
    x = bilinear_coons(n1, n2, s1, s2, u, v)
    print("nurbs coons", (str(u), str(v)), [str(t) for t in x], "x^2 + y^2 =", x[0]**2 + x[1]**2)
