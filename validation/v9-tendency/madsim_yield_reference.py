#!/usr/bin/env python3
"""An independent reference for V9's MADSim motor yield (docs/validation.md): MADSim's example BHA
(Open-Source-Drilling-Community/MADSim-Wilson-Simple-BHA-Model, "BHA Data_ExampleAssembly.xlsx": its
105 elements from the bit up, its stabilizer table, the 1.75 deg bend 5 elements (4.75 ft) above the
bit) as a planar beam-column, solved outside drillflex.

The model, written for this check (numpy only):
- 2-D corotational Euler-Bernoulli beams, one per MADSim element, in the vertical plane of a hole of
  constant build curvature kappa (a circle through the bit, tangent to the hole there); large rotations.
- Stress-free shape: straight with the bend's kink (the bit side tilted toward the high side).
- The bit held on the hole's axis (its tilt and axial motion free), carrying the WOB; the top held
  axially along the hole; sideways either guided (its tilt held along the hole's tangent at the top,
  MADSim's top: SDIopenSource_MADSim.m fixes the top node's two rotations, its displacements free) or
  free (no moment, no shear beyond the axial hold's).
- Gravity as MADSim's: buoyed weight per foot (its column D x (1 - MW/65.5)) at each node.
- The wall: a penalty spring of 7.5e5 lbf/in at each node (MADSim's 1 ft elements) beyond the node's
  radial clearance: (hole - OD)/2, with the stabilizer table's blade OD at the pads' nodes; both sides.
- The bit's tilt against the hole (positive toward the high side) and its build force (the force it
  exerts on the rock, positive toward the high side); the steady build rate is the curvature where
  tilt + S F / WOB = 0 (drillflex's criterion, docs/method.md), found by bisection.

Run: /usr/bin/python3 madsim_yield_reference.py [guided|free]  (prints the yields; a few minutes).
Measured (guided): 22.50 deg/100 ft at 30 klbf and S 0.05, 23.12 at S 0.15, 23.26 at S 0.25, 18.81 at
5 klbf, 22.63 at 35 klbf; free: 22.52 at 30 klbf, S 0.05; S 1e6 (zero side force): 23.48.
"""
import math
import sys

import numpy as np

IN = 1.0 / 12.0                      # ft per in
E_MOTOR, E_NONMAG = 30e6 * 144, 28.5e6 * 144   # lbf/ft^2
BUOYANCY = 1.0 - 10.0 / 65.5         # MADSim's buoyancy factor at 10 ppg
HOLE = 8.5 * IN
WALL = 7.5e5 * 12.0                  # lbf/ft per node

# (count, OD in, ID in, length ft, weight lbf/ft, E, I in^4): MADSim's element table, bit first.
GROUPS = [
    (1, 7.875, 1.25, 0.75, 162.95058212565598, E_MOTOR, 188.66718530025719),
    (4, 6.5, 3.0, 1.0, 89.624926017936417, E_MOTOR, 83.647972363404008),
    (6, 6.5, 4.0, 1.0, 70.756520540476117, E_MOTOR, 75.057679951244424),
    (20, 6.5, 5.5, 1.0, 73.996737357259377, E_MOTOR, 42.706025134736251),
    (3, 6.5, 3.25, 1.0, 85.41322836671759, E_MOTOR, 82.147547405253377),
    (6, 6.75, 2.875, 1.0, 100.53322293459314, E_NONMAG, 98.548858005101735),
    (30, 6.5, 3.25, 1.0, 85.41322836671759, E_NONMAG, 82.147547405253377),
    (5, 6.5, 3.0, 1.1, 89.624926017936417, E_NONMAG, 83.647972363404008),
    (30, 6.5, 3.25, 1.0, 85.41322836671759, E_NONMAG, 82.147547405253377),
]
STABILIZERS = {3: 8.25, 37: 8.25}    # node index from the bit (0 = bit): 2.75 ft and 36.75 ft
BEND_ELEMENTS = 5                    # elements below the bend: 4.75 ft


def elements():
    out = []
    for count, od, idd, length, weight, e, inertia in GROUPS:
        for _ in range(count):
            area = math.pi / 4 * (od * od - idd * idd) * IN * IN
            out.append(dict(od=od, L=length, w=weight * BUOYANCY, EI=e * inertia * IN**4, EA=e * area))
    return out


def solve(kappa_deg, wob, inclination_deg=60.0, bend_deg=1.75, top="guided", guess=None):
    """Static equilibrium in a hole of build curvature kappa (deg/100 ft); returns (tilt rad, build force lbf, u)."""
    els = elements()
    n = len(els) + 1
    kappa = kappa_deg * math.pi / 180 / 100          # 1/ft
    bend = bend_deg * math.pi / 180
    s = np.concatenate([[0.0], np.cumsum([e["L"] for e in els])])
    # Stress-free placement: the upper part along +x (up-hole) from the bend, the bit side turned so
    # that, going down-hole from the bend, it rises toward the high side (+y).
    sb = s[BEND_ELEMENTS]
    X = np.zeros((n, 2))
    for i in range(n):
        if s[i] >= sb:
            X[i] = (s[i], 0.0)
        else:
            X[i] = (sb - (sb - s[i]) * math.cos(bend), (sb - s[i]) * math.sin(bend))
    X -= X[0]                                              # the bit at the origin, on the hole's axis
    # The hole: tangent to +x at the bit, curving toward +y going up (a build seen from below).
    R = 1.0 / kappa if abs(kappa) > 1e-9 else None
    # Clearances per node.
    clear = np.zeros(n)
    for i in range(n):
        ods = [els[j]["od"] for j in (i - 1, i) if 0 <= j < len(els)]
        clear[i] = (HOLE - max(ods) * IN) / 2
        if i in STABILIZERS:
            clear[i] = (HOLE - STABILIZERS[i] * IN) / 2
    inc = inclination_deg * math.pi / 180
    gdir = np.array([-math.cos(inc), -math.sin(inc)])     # vertical, down, in the bit's frame
    # External loads: gravity lumped at nodes, the WOB up-hole at the bit.
    F = np.zeros(3 * n)
    for j, e in enumerate(els):
        for k in (j, j + 1):
            F[3 * k:3 * k + 2] += 0.5 * e["w"] * e["L"] * gdir
    F[0] += wob
    # Hole geometry helpers.
    def hole_offset(p):
        """(signed offset from the hole's axis toward +y side/centre, unit vector toward the centre)."""
        if R is None:
            return p[1], np.array([0.0, 1.0])
        c = np.array([0.0, R])
        d = c - p
        r = np.linalg.norm(d)
        return R - r, d / r                                 # > 0: toward the centre (the high side)

    top_angle = (s[-1] * kappa)                          # the hole's tangent at the top (up-hole)
    top_axis = np.array([math.cos(top_angle), math.sin(top_angle)])
    top_point = (np.array([R * math.sin(top_angle), R * (1 - math.cos(top_angle))]) if R else np.array([s[-1], 0.0]))
    k_hold = 1e12

    def residual_and_tangent(u):
        K = np.zeros((3 * n, 3 * n))
        f = np.zeros(3 * n)
        x = X + u.reshape(n, 3)[:, :2]
        th = u.reshape(n, 3)[:, 2]
        for j, e in enumerate(els):
            a, b = j, j + 1
            dX = X[b] - X[a]
            L0 = np.linalg.norm(dX)
            beta0 = math.atan2(dX[1], dX[0])
            dx = x[b] - x[a]
            l = np.linalg.norm(dx)
            c, sn = dx / l
            beta = math.atan2(dx[1], dx[0])
            rot = beta - beta0
            t1, t2 = th[a] - rot, th[b] - rot
            N = e["EA"] * (l - L0) / L0
            M1 = e["EI"] / L0 * (4 * t1 + 2 * t2)
            M2 = e["EI"] / L0 * (2 * t1 + 4 * t2)
            Bm = np.array([[-c, -sn, 0, c, sn, 0],
                           [-sn / l, c / l, 1, sn / l, -c / l, 0],
                           [-sn / l, c / l, 0, sn / l, -c / l, 1]])
            D = np.array([[e["EA"] / L0, 0, 0], [0, 4 * e["EI"] / L0, 2 * e["EI"] / L0], [0, 2 * e["EI"] / L0, 4 * e["EI"] / L0]])
            r = np.array([-c, -sn, 0, c, sn, 0])
            z = np.array([sn, -c, 0, -sn, c, 0])
            fe = Bm.T @ np.array([N, M1, M2])
            Ke = Bm.T @ D @ Bm + N / l * np.outer(z, z) + (M1 + M2) / l**2 * (np.outer(r, z) + np.outer(z, r))
            idx = [3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2]
            f[idx] += fe
            K[np.ix_(idx, idx)] += Ke
        # Wall contact (the bit's node excluded: it is held on the axis).
        for i in range(1, n):
            off, toward = hole_offset(x[i])
            gap = abs(off) - clear[i]
            if gap > 0:
                sign = 1.0 if off > 0 else -1.0
                # The wall pushes the node back toward the axis: force -WALL*gap*sign along `toward`.
                f[3 * i:3 * i + 2] += WALL * gap * sign * toward
                K[3 * i:3 * i + 2, 3 * i:3 * i + 2] += WALL * np.outer(toward, toward)
        # The bit on the hole's axis (y = 0; its x free: it carries the WOB).
        f[1] += k_hold * x[0][1]
        K[1, 1] += k_hold
        # The top held along the hole's tangent there (axially), and guided: its tilt along the hole.
        f[3 * (n - 1):3 * (n - 1) + 2] += k_hold * top_axis * top_axis.dot(x[-1] - top_point)
        K[3 * (n - 1):3 * (n - 1) + 2, 3 * (n - 1):3 * (n - 1) + 2] += k_hold * np.outer(top_axis, top_axis)
        if top == "guided":
            f[3 * (n - 1) + 2] += k_hold * (th[-1] - top_angle)
            K[3 * (n - 1) + 2, 3 * (n - 1) + 2] += k_hold
        return f - F, K

    u = np.zeros(3 * n) if guess is None else guess.copy()
    if guess is None:
        # Start on the hole's axis: nodes at their arc positions, each rotated with the hole.
        for i in range(n):
            sig = X[i][0]
            if R:
                p = np.array([R * math.sin(sig / R), R * (1 - math.cos(sig / R))])
                u[3 * i + 2] = sig / R
            else:
                p = np.array([sig, 0.0])
            u[3 * i:3 * i + 2] = p - X[i]
    for it in range(200):
        res, K = residual_and_tangent(u)
        du = np.linalg.solve(K, -res)
        # Limit the step: a tenth of the hole's clearance sideways per iteration.
        scale = min(1.0, 0.01 / max(1e-12, np.max(np.abs(du.reshape(n, 3)[:, :2]))))
        u += scale * du
        if np.linalg.norm(du) < 1e-10 and scale == 1.0:
            break
    else:
        raise RuntimeError(f"no convergence at {kappa_deg} deg/100 ft")
    th0 = u[2]
    tilt = bend - th0                                    # bit axis toward the high side, rad
    # The hold (the rock) pushes the bit node with -k_hold*y; the bit pushes the rock with the opposite.
    build_force = k_hold * (X[0][1] + u[1])              # toward the high side (+y), lbf
    return tilt, build_force, u


def yield_rate(wob, steer, top="guided", lo=5.0, hi=30.0):
    cache = {}

    def dev(k):
        tilt, force, _ = solve(k, wob, top=top)
        cache[k] = (tilt, force)
        return tilt + steer * force / wob
    dlo, dhi = dev(lo), dev(hi)
    if dlo * dhi > 0:
        raise RuntimeError(f"no root between {lo} and {hi}: {dlo}, {dhi}")
    while hi - lo > 0.002:
        mid = 0.5 * (lo + hi)
        dm = dev(mid)
        if dm * dlo > 0:
            lo, dlo = mid, dm
        else:
            hi, dhi = mid, dm
    return lo - dlo * (hi - lo) / (dhi - dlo)


if __name__ == "__main__":
    tops = sys.argv[1:] or ["guided", "free"]
    for top in tops:
        for wob, steer in [(30e3, 0.05), (30e3, 0.15), (30e3, 0.25), (5e3, 0.05), (35e3, 0.05)]:
            print(f"top {top}: WOB {wob/1e3:.0f} klbf, S {steer:.2f}: {yield_rate(wob, steer, top):.2f} deg/100 ft", flush=True)
