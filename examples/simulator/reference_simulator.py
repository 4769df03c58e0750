#!/usr/bin/env python3
"""reference_simulator.py: the same simulator as reference_simulator.cpp, in pure
Python 3 (no numpy), for students who prototype in Python.

It speaks the workbook's simulator protocol (docs/simulator-protocol.md) and
computes the TUM explicit Euler step, the template's box-box test checkCollisionSAT
and the impulse (docs/references.md sections 1-3), with every mistake model of the
checker as a --mistake flag. Every expression is evaluated in the same order as in
the C++ program, so the two print the same numbers (selfcheck.sh compares them).

Glossary
  x_W, v_W        centre of mass and its velocity, world frame            [m], [m/s]
  r_WB            orientation, quaternion (w, x, y, z), body -> world       [-]
  L_W, omega_W    angular momentum and angular velocity, world frame      [kg m^2/s], [rad/s]
  I0_B, I0inv_B   body-frame inertia (diagonal) and its inverse           [kg m^2], [1/(kg m^2)]
  Iinv_W          the stored world-frame inverse inertia                  [1/(kg m^2)]
  F_W, q_W        force and torque accumulated for the next step          [N], [N m]
  h               time step                                               [s]
  c               coefficient of restitution                              [-]
  p_W, n_W        contact point and unit normal from B to A               [m], [-]
  x_a, x_b        lever arms p - x_A and p - x_B                          [m]

Vectors are tuples (x, y, z), quaternions (w, x, y, z), matrices 3 tuples of rows.
"""
import math
import re
import sys
import time

PROGRAM = "reference_simulator.py"

# ---------------------------------------------------------------------------------
# Small linear algebra (the same operations, in the same order, as the C++ file)
# ---------------------------------------------------------------------------------


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def div(a, s):
    return (a[0] / s, a[1] / s, a[2] / s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def quat_mul(a, b):
    """(w1, v1)(w2, v2) = (w1 w2 - v1.v2, w1 v2 + w2 v1 + v1 x v2)"""
    va = (a[1], a[2], a[3])
    vb = (b[1], b[2], b[3])
    v = add(add(scale(vb, a[0]), scale(va, b[0])), cross(va, vb))
    return (a[0] * b[0] - dot(va, vb), v[0], v[1], v[2])


def quat_add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3])


def quat_scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s, a[3] * s)


def quat_norm(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + a[3] * a[3])


def diag(d):
    return ((d[0], 0.0, 0.0), (0.0, d[1], 0.0), (0.0, 0.0, d[2]))


def transpose(A):
    return tuple(tuple(A[j][i] for j in range(3)) for i in range(3))


def mat_mul(A, B):
    return tuple(tuple(A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j] for j in range(3))
                 for i in range(3))


def mat_vec(A, v):
    return (A[0][0] * v[0] + A[0][1] * v[1] + A[0][2] * v[2],
            A[1][0] * v[0] + A[1][1] * v[1] + A[1][2] * v[2],
            A[2][0] * v[0] + A[2][1] * v[1] + A[2][2] * v[2])


def col(A, j):
    return (A[0][j], A[1][j], A[2][j])


def rotation_matrix(r):
    """R(r): the standard formula for a unit quaternion, used unchanged for a non-unit
    one (as Eigen's toRotationMatrix does; it matters for quaternion-not-normalised)."""
    w, x, y, z = r
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)),
            (2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)),
            (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)))


# ---------------------------------------------------------------------------------
# The mistake models (the checker's contract; README.md has the equations)
# ---------------------------------------------------------------------------------

# Every id of the contract with its scope; only "sim" and "both" ones are accepted.
MISTAKE_DEFS = [
    ("velocity-before-position", "both"),
    ("omega-before-orientation", "both"),
    ("transposed-inertia", "both"),
    ("body-inverse-inertia", "both"),
    ("inertia-not-inverted", "both"),
    ("torque-reversed", "both"),
    ("lever-arm-from-origin", "both"),
    ("missing-time-step", "both"),
    ("quaternion-missing-half", "both"),
    ("quaternion-not-normalised", "both"),
    ("half-extents-for-size", "both"),
    ("point-velocity-without-rotation", "hand"),
    ("relative-velocity-reversed", "both"),
    ("impulse-linear-only", "both"),
    ("impulse-without-one-plus", "both"),
    ("inertia-from-old-orientation", "both"),
    ("inertia-half-extents-without-third", "both"),
    ("inertia-axes-swapped", "both"),
    ("inertia-not-updated", "sim"),
    ("inertia-accumulated-rotation", "sim"),
    ("quaternion-right-multiplied", "both"),
    ("omega-accumulated", "both"),
    ("forces-not-cleared", "sim"),
    ("gravity-always-on", "sim"),
    ("orientation-zero-quaternion", "sim"),
    ("quaternion-without-half-angle", "hand"),
    ("angle-in-degrees", "hand"),
    ("point-velocity-lever-arm-from-origin", "hand"),
    ("point-velocity-cross-reversed", "hand"),
    ("restitution-one-minus", "both"),
    ("no-separating-check", "both"),
    ("impulse-body-inverse-inertia", "both"),
    ("impulse-lever-arm-from-origin", "both"),
    ("impulse-denominator-missing-cross", "both"),
]
SIM_MISTAKES = [m for m, scope in MISTAKE_DEFS if scope != "hand"]

# ---------------------------------------------------------------------------------
# The template's box-box test (checkCollisionSAT), docs/references.md section 2
# ---------------------------------------------------------------------------------

PARALLEL_SINE = 1e-9   # an edge pair with |a_i x b_j| <= this gives no axis


def box_corners(c_W, R_WB, h):
    """The 8 corners in the template's order: corner k has sign -/+ along body
    x, y, z by bits 0, 1, 2 of k.  corner_k = c + sum_j s_j(k) h_j R.col(j)"""
    corners = []
    for k in range(8):
        corner_W = c_W
        for j in range(3):
            s = 1.0 if (k >> j) & 1 else -1.0
            corner_W = add(corner_W, scale(col(R_WB, j), s * h[j]))
        corners.append(corner_W)
    return corners


def project(corners_W, axis_W):
    """[min, max] of corner . axis over the 8 corners (template project())."""
    lo = hi = dot(corners_W[0], axis_W)
    for k in range(1, 8):
        p = dot(corners_W[k], axis_W)
        if p < lo:
            lo = p
        elif p > hi:
            hi = p
    return lo, hi


def corner_minimising(corners_W, dir_W):
    """The first corner with the smallest corner . dir (template handleVertexToface())."""
    best = math.inf
    best_corner = corners_W[0]
    for corner in corners_W:
        value = dot(corner, dir_W)
        if value < best:
            best = value
            best_corner = corner
    return best_corner


def edge_contact_point(p_one, d_one, one_size, p_two, d_two, two_size, use_one):
    """Closest points of the lines p_one + mua d_one and p_two + mub d_two (template
    contactPoint()): parallel (|denom| < 1e-4) or a parameter outside [-size, size]:
    p_one if use_one else p_two; otherwise the midpoint of the two closest points."""
    sm_one = dot(d_one, d_one)
    sm_two = dot(d_two, d_two)
    dp_one_two = dot(d_two, d_one)
    to_st = sub(p_one, p_two)
    dp_sta_one = dot(d_one, to_st)
    dp_sta_two = dot(d_two, to_st)
    denom = sm_one * sm_two - dp_one_two * dp_one_two
    if abs(denom) < 1e-4:
        return p_one if use_one else p_two
    mua = (dp_one_two * dp_sta_two - sm_two * dp_sta_one) / denom
    mub = (sm_one * dp_sta_two - dp_one_two * dp_sta_one) / denom
    if mua > one_size or mua < -one_size or mub > two_size or mub < -two_size:
        return p_one if use_one else p_two
    c_one = add(p_one, scale(d_one, mua))
    c_two = add(p_two, scale(d_two, mub))
    return add(scale(c_one, 0.5), scale(c_two, 0.5))


def collide_boxes(cA, RA, hA, cB, RB, hB):
    """A's contact with B: (p_W, n_W, depth, axis), or None when an axis separates them."""
    a_W = [div(col(RA, k), norm(col(RA, k))) for k in range(3)]
    b_W = [div(col(RB, k), norm(col(RB, k))) for k in range(3)]
    corners_A = box_corners(cA, RA, hA)
    corners_B = box_corners(cB, RB, hB)
    to_center = sub(cB, cA)

    best = {"overlap": math.inf, "axis": -1, "axis_W": None, "single": False}

    def test_axis(axis_W, number):
        # overlap = min(maxA, maxB) - max(minA, minB); separated iff minA > maxB or
        # minB > maxA. Strict < keeps the earlier axis on a tie.
        min_a, max_a = project(corners_A, axis_W)
        min_b, max_b = project(corners_B, axis_W)
        if min_a > max_b or min_b > max_a:
            return False
        o = min(max_a, max_b) - max(min_a, min_b)
        if o < best["overlap"]:
            best["overlap"] = o
            best["axis"] = number
            best["axis_W"] = axis_W
            if 3 <= number < 6:
                best["single"] = True   # a face of B was the running minimum
        return True

    for k in range(3):
        if not test_axis(a_W[k], k):
            return None
    for k in range(3):
        if not test_axis(b_W[k], 3 + k):
            return None
    for i in range(3):
        for j in range(3):
            cross_W = cross(a_W[i], b_W[j])
            length = norm(cross_W)
            if not length > PARALLEL_SINE:
                continue
            if not test_axis(div(cross_W, length), 6 + 3 * i + j):
                return None
    axis = best["axis"]
    if axis < 0:
        return None   # only with non-finite input

    # Orient the axis along toCenter; n = -axis points from B to A.
    axis_W = best["axis_W"]
    if dot(axis_W, to_center) <= 0:
        axis_W = scale(axis_W, -1.0)
    n_W = scale(axis_W, -1.0)
    if axis < 3:
        # A face of A: B's corner with the smallest corner . toCenter.
        p_W = corner_minimising(corners_B, to_center)
    elif axis < 6:
        # A face of B: A's corner with the smallest corner . (-toCenter).
        p_W = corner_minimising(corners_A, scale(to_center, -1.0))
    else:
        # Edge pair (i, j): A's edge along a_i furthest along the axis, B's edge along
        # b_j furthest against it (through their midpoints), then their closest points.
        i = (axis - 6) // 3
        j = (axis - 6) % 3
        p_one = cA
        p_two = cB
        for k in range(3):
            if k != i:
                s_a = -1.0 if dot(a_W[k], axis_W) < 0 else 1.0
                p_one = add(p_one, scale(col(RA, k), s_a * hA[k]))
            if k != j:
                s_b = -1.0 if dot(b_W[k], axis_W) > 0 else 1.0
                p_two = add(p_two, scale(col(RB, k), s_b * hB[k]))
        # The template passes the full edge lengths as the parameter ranges.
        p_W = edge_contact_point(p_one, a_W[i], 2 * hA[i], p_two, b_W[j], 2 * hB[j], best["single"])
    return p_W, n_W, best["overlap"], axis


# ---------------------------------------------------------------------------------
# The simulator
# ---------------------------------------------------------------------------------


class Body:
    pass


class ReferenceSimulator:
    def __init__(self, mistakes, restitution, trace):
        self.m = set(mistakes)
        self.c = restitution
        self.trace = trace
        self.bodies = []

    def reset(self):
        """reset: a new scene without bodies."""
        self.bodies = []

    def add_body(self, x_W, size, M):
        """add_body: x = position, v = 0, r = 1, L = omega = 0, loads 0, Iinv_W = I0inv."""
        m = self.m
        b = Body()
        b.M = M
        b.size = size
        # I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2)
        a, bb, c = size
        if "half-extents-for-size" in m or "inertia-half-extents-without-third" in m:
            # half extents a' = a/2 ... used as if they were the edge lengths
            a = a / 2
            bb = bb / 2
            c = c / 2
        factor = M if "inertia-half-extents-without-third" in m else M / 12
        b.I0_B = (factor * (bb * bb + c * c), factor * (a * a + c * c), factor * (a * a + bb * bb))
        if "inertia-axes-swapped" in m:
            # y and z moments exchanged: M/12 diag(b^2 + c^2, a^2 + b^2, a^2 + c^2)
            b.I0_B = (b.I0_B[0], b.I0_B[2], b.I0_B[1])
        b.I0inv_B = (1 / b.I0_B[0], 1 / b.I0_B[1], 1 / b.I0_B[2])
        b.x_W = x_W
        b.v_W = (0.0, 0.0, 0.0)
        b.r_WB = (0.0, 0.0, 0.0, 0.0) if "orientation-zero-quaternion" in m else (1.0, 0.0, 0.0, 0.0)
        b.L_W = (0.0, 0.0, 0.0)
        b.omega_W = (0.0, 0.0, 0.0)
        b.Iinv_W = diag(b.I0inv_B)
        b.F_W = (0.0, 0.0, 0.0)
        b.q_W = (0.0, 0.0, 0.0)
        b.stepped = False   # inertia-not-updated: the tensor is fixed at the first step
        self.bodies.append(b)

    def set_orientation(self, i, q):
        """set_orientation: r = q / |q|; Iinv_W and omega are not touched."""
        n = quat_norm(q)
        self.bodies[i].r_WB = (q[0] / n, q[1] / n, q[2] / n, q[3] / n)

    def set_velocity(self, i, v_W):
        self.bodies[i].v_W = v_W

    def apply_force(self, i, p_W, f_W):
        """apply_force: F += f; q += (p - x) x f, with x the body's position now."""
        m = self.m
        b = self.bodies[i]
        b.F_W = add(b.F_W, f_W)
        if "lever-arm-from-origin" in m and "torque-reversed" in m:
            q_W = cross(f_W, p_W)                 # both: q = f x p
        elif "lever-arm-from-origin" in m:
            q_W = cross(p_W, f_W)                 # q = p x f
        elif "torque-reversed" in m:
            q_W = cross(f_W, sub(p_W, b.x_W))     # q = f x (p - x)
        else:
            q_W = cross(sub(p_W, b.x_W), f_W)     # q = (p - x) x f
        b.q_W = add(b.q_W, q_W)

    def step(self, h):
        for b in self.bodies:
            self.integrate(b, h)
        n = len(self.bodies)
        for i in range(n):
            for j in range(i + 1, n):
                self.collide(i, j)

    def state(self, i):
        """x, v, omega, r of body i: 13 numbers."""
        b = self.bodies[i]
        return list(b.x_W) + list(b.v_W) + list(b.omega_W) + list(b.r_WB)

    def world_inverse_inertia(self, b, r):
        """The world inverse inertia for orientation r: R I0inv R^T, or the mistake's form."""
        # inertia-not-inverted: I0 where I0inv belongs
        D = diag(b.I0_B if "inertia-not-inverted" in self.m else b.I0inv_B)
        # body-inverse-inertia: no rotation at all
        if "body-inverse-inertia" in self.m:
            return D
        return self.rotated(D, rotation_matrix(r))

    def rotated(self, D, R):
        """R D R^T, or R^T D R under transposed-inertia."""
        if "transposed-inertia" in self.m:
            return mat_mul(mat_mul(transpose(R), D), R)
        return mat_mul(mat_mul(R, D), transpose(R))

    def integrate(self, b, h):
        """One explicit Euler step of one body (docs/references.md section 1)."""
        m = self.m
        r_n = b.r_WB
        omega_n = b.omega_W
        # dt of the two load updates: h, or 1 under missing-time-step
        load_dt = 1.0 if "missing-time-step" in m else h
        # a = F/M (+ g under gravity-always-on, the template's y is up)
        a_W = div(b.F_W, b.M)
        if "gravity-always-on" in m:
            a_W = add(a_W, (0.0, -9.81, 0.0))

        if "velocity-before-position" in m:
            # v <- v + h F/M, then x <- x + h v_{n+1}
            b.v_W = add(b.v_W, scale(a_W, load_dt))
            b.x_W = add(b.x_W, scale(b.v_W, h))
        else:
            # 1. x <- x + h v (old v)
            b.x_W = add(b.x_W, scale(b.v_W, h))
            # 2. v <- v + h F/M
            b.v_W = add(b.v_W, scale(a_W, load_dt))

        # 3. r <- r + (h/2) (0, omega) r with the old omega, then r <- r/|r|
        omega_for_r = omega_n
        if "omega-before-orientation" in m:
            # omega' = R_n I0inv R_n^T L_{n+1}: L updated first, the inertia of the old r
            L_next = add(b.L_W, scale(b.q_W, load_dt))
            omega_for_r = mat_vec(self.world_inverse_inertia(b, r_n), L_next)
        omega_q = (0.0, omega_for_r[0], omega_for_r[1], omega_for_r[2])
        # quaternion-right-multiplied: r (0, omega) instead of (0, omega) r
        if "quaternion-right-multiplied" in m:
            r_dot = quat_mul(b.r_WB, omega_q)
        else:
            r_dot = quat_mul(omega_q, b.r_WB)
        # quaternion-missing-half: h instead of h/2
        r_factor = h if "quaternion-missing-half" in m else h / 2
        b.r_WB = quat_add(b.r_WB, quat_scale(r_dot, r_factor))
        r_norm = quat_norm(b.r_WB)
        if "quaternion-not-normalised" not in m and r_norm > 0:
            b.r_WB = (b.r_WB[0] / r_norm, b.r_WB[1] / r_norm, b.r_WB[2] / r_norm, b.r_WB[3] / r_norm)

        # 4. L <- L + h q
        b.L_W = add(b.L_W, scale(b.q_W, load_dt))

        # 5. Iinv_W = R I0inv R^T with R = R(r_{n+1})
        if "inertia-not-updated" in m:
            # R_0 I0inv R_0^T from the orientation at the body's first step, never again
            if not b.stepped:
                b.Iinv_W = self.world_inverse_inertia(b, r_n)
        elif "inertia-accumulated-rotation" in m:
            # Iinv_W <- R Iinv_W R^T applied to the stored tensor
            b.Iinv_W = self.rotated(b.Iinv_W, rotation_matrix(b.r_WB))
        elif "inertia-from-old-orientation" in m:
            # R_n I0inv R_n^T: the orientation before this step's update
            b.Iinv_W = self.world_inverse_inertia(b, r_n)
        else:
            b.Iinv_W = self.world_inverse_inertia(b, b.r_WB)
        b.stepped = True

        # 6. omega = Iinv_W L   (omega-accumulated: omega_{n+1} = omega_n + Iinv_W L)
        if "omega-accumulated" in m:
            b.omega_W = add(omega_n, mat_vec(b.Iinv_W, b.L_W))
        else:
            b.omega_W = mat_vec(b.Iinv_W, b.L_W)

        # 7. the loads act for one step
        if "forces-not-cleared" not in m:
            b.F_W = (0.0, 0.0, 0.0)
            b.q_W = (0.0, 0.0, 0.0)

    def collide(self, i, j):
        """The impulse between bodies i (A) and j (B), docs/references.md section 3."""
        m = self.m
        A = self.bodies[i]
        B = self.bodies[j]
        contact = collide_boxes(A.x_W, rotation_matrix(A.r_WB), div(A.size, 2.0),
                                B.x_W, rotation_matrix(B.r_WB), div(B.size, 2.0))
        if contact is None:
            return
        p_W, n_W, depth, axis = contact

        # x_a = p - x_A, x_b = p - x_B   (impulse-lever-arm-from-origin: x_a = x_b = p)
        from_origin = "impulse-lever-arm-from-origin" in m
        x_a = p_W if from_origin else sub(p_W, A.x_W)
        x_b = p_W if from_origin else sub(p_W, B.x_W)
        # v_rel = (v_A + omega_A x x_a) - (v_B + omega_B x x_b)
        vA_p = add(A.v_W, cross(A.omega_W, x_a))
        vB_p = add(B.v_W, cross(B.omega_W, x_b))
        v_rel = sub(vB_p, vA_p) if "relative-velocity-reversed" in m else sub(vA_p, vB_p)
        vn = dot(v_rel, n_W)
        separating = vn > 0
        if self.trace:
            sys.stderr.write("contact %d %d: axis %d, p = (%.17g, %.17g, %.17g), n = (%.17g, %.17g, %.17g), "
                             "depth %.17g, v_rel.n = %.17g%s\n"
                             % (i, j, axis, p_W[0], p_W[1], p_W[2], n_W[0], n_W[1], n_W[2], depth, vn,
                                " (separating)" if separating else ""))
        # separating: no impulse
        if separating and "no-separating-check" not in m:
            return

        # numerator -(1 + c) v_rel.n
        c = self.c
        numerator = -(1 + c) * vn
        if "impulse-without-one-plus" in m:
            numerator = -c * vn
        if "restitution-one-minus" in m:
            numerator = -(1 - c) * vn

        # denominator 1/M_A + 1/M_B + [(IA (x_a x n)) x x_a + (IB (x_b x n)) x x_b].n
        body_inverse = "impulse-body-inverse-inertia" in m
        IA = diag(A.I0inv_B) if body_inverse else A.Iinv_W
        IB = diag(B.I0inv_B) if body_inverse else B.Iinv_W
        linear = 1 / A.M + 1 / B.M
        denominator = linear + dot(add(cross(mat_vec(IA, cross(x_a, n_W)), x_a),
                                       cross(mat_vec(IB, cross(x_b, n_W)), x_b)), n_W)
        if "impulse-linear-only" in m:
            denominator = linear
        if "impulse-denominator-missing-cross" in m:
            # (IA (x_a x n)).n + (IB (x_b x n)).n
            denominator = linear + (dot(mat_vec(IA, cross(x_a, n_W)), n_W) + dot(mat_vec(IB, cross(x_b, n_W)), n_W))
        J = numerator / denominator
        if self.trace:
            sys.stderr.write("  J = %.17g\n" % J)

        # v_A += J n / M_A;  v_B -= J n / M_B;  L_A += x_a x J n;  L_B -= x_b x J n
        Jn_W = scale(n_W, J)
        A.v_W = add(A.v_W, div(Jn_W, A.M))
        B.v_W = sub(B.v_W, div(Jn_W, B.M))
        A.L_W = add(A.L_W, cross(x_a, Jn_W))
        B.L_W = sub(B.L_W, cross(x_b, Jn_W))
        # omega = Iinv_W L for both
        A.omega_W = mat_vec(A.Iinv_W, A.L_W)
        B.omega_W = mat_vec(B.Iinv_W, B.L_W)


# ---------------------------------------------------------------------------------
# The protocol
# ---------------------------------------------------------------------------------

NUMBER = re.compile(r"[+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?\Z")
USAGE = """Usage: reference_simulator.py [--mistake ID]... [--restitution C] [--trace] [--fail MODE]
A rigid-body simulator that speaks the workbook's simulator protocol on stdin/stdout
(docs/simulator-protocol.md): the TUM explicit Euler step, the template's box-box
test and the impulse, with no gravity and no damping.

Options:
  --mistake ID      switch on a mistake model (repeatable); see README.md
  --restitution C   coefficient of restitution, 0 <= C <= 1 (default 0.5)
  --trace           describe every contact on stderr
  --fail MODE       misbehave on purpose, to test a driver: nan (the second state
                    answer is nan), exit (exit status 1 after the first step),
                    hang (no answers after the first step), garbage (answers hello)
  --help            this text
(--float is only in the C++ program: Python has no float32 arithmetic.)

Mistake ids:
"""


def die(message):
    sys.stderr.write("%s: %s\n" % (PROGRAM, message))
    sys.exit(2)


def parse_number(token):
    """A plain decimal number, finite; None otherwise."""
    if not NUMBER.match(token):
        return None
    value = float(token)
    return value if math.isfinite(value) else None


def parse_options(argv):
    options = {"mistakes": [], "restitution": 0.5, "trace": False, "fail": None}
    k = 0
    while k < len(argv):
        arg = argv[k]
        value = None
        if arg.startswith("--") and "=" in arg:
            arg, value = arg.split("=", 1)

        def take_value():
            nonlocal k
            if value is not None:
                return value
            if k + 1 >= len(argv):
                die(arg + " needs a value")
            k += 1
            return argv[k]

        if arg in ("--help", "-h"):
            sys.stdout.write(USAGE + "".join("  %s\n" % m for m in SIM_MISTAKES)
                             + "\nExit status: 0 after quit or end of input, 2 bad options or a malformed command.\n")
            sys.exit(0)
        elif arg == "--mistake":
            mistake = take_value()
            if mistake not in SIM_MISTAKES:
                why = "unknown mistake id '%s'" % mistake
                if mistake in dict(MISTAKE_DEFS):
                    why = "'%s' is a hand-calculation mistake; the protocol cannot show it" % mistake
                die(why + ". Valid ids: " + ", ".join(SIM_MISTAKES))
            options["mistakes"].append(mistake)
        elif arg == "--restitution":
            text = take_value()
            c = parse_number(text)
            if c is None or c < 0 or c > 1:
                die("--restitution needs a number from 0 to 1, got '%s'" % text)
            options["restitution"] = c
        elif arg == "--trace" and value is None:
            options["trace"] = True
        elif arg == "--fail":
            mode = take_value()
            if options["fail"] is not None:
                die("--fail given twice")
            if mode not in ("nan", "exit", "hang", "garbage"):
                die("unknown --fail mode '%s' (valid: nan, exit, hang, garbage)" % mode)
            options["fail"] = mode
        elif arg == "--float":
            die("--float is not available in the Python simulator (use reference_simulator.cpp)")
        else:
            die("unknown option '%s' (try --help)" % argv[k])
        k += 1
    return options


def run(options):
    sim = ReferenceSimulator(options["mistakes"], options["restitution"], options["trace"])
    fail = options["fail"]
    line_no = 0
    state_answers = 0
    stepped = False
    while True:
        line = sys.stdin.readline()
        if not line:
            return 0
        line_no += 1
        tokens = line.split()
        if not tokens:
            continue   # blank lines are ignored
        command = tokens[0]
        where = "line %d: " % line_no

        def expect_count(count, usage):
            if len(tokens) - 1 != count:
                die("%s%s needs %d argument%s (%s), got %d"
                    % (where, command, count, "" if count == 1 else "s", usage, len(tokens) - 1))

        def number(k):
            value = parse_number(tokens[k])
            if value is None:
                die("%s%s: '%s' is not a finite decimal number" % (where, command, tokens[k]))
            return value

        def body_index(k):
            t = tokens[k]
            if not (t.isascii() and t.isdigit() and len(t) < 10):
                die("%s%s: body index '%s' is not a whole number >= 0" % (where, command, t))
            i = int(t)
            count = len(sim.bodies)
            if i >= count:
                die("%s%s: there is no body %s (the scene has %d bod%s)"
                    % (where, command, t, count, "y" if count == 1 else "ies"))
            return i

        def vec(k):
            return (number(k), number(k + 1), number(k + 2))

        if command == "reset":
            expect_count(0, "")
            sim.reset()
        elif command == "add_body":
            expect_count(7, "X Y Z SX SY SZ MASS")
            x_W = vec(1)
            size = vec(4)
            if not (size[0] > 0 and size[1] > 0 and size[2] > 0):
                die(where + "add_body: the size must be positive")
            mass = tokens[7]
            digits = mass[1:] if mass.startswith("+") else mass
            if not (digits.isascii() and digits.isdigit() and len(mass) < 10) or int(digits) <= 0:
                die("%sadd_body: the mass '%s' is not a whole number > 0 (the template takes an int)"
                    % (where, mass))
            sim.add_body(x_W, size, float(int(digits)))
        elif command == "set_orientation":
            expect_count(5, "I W X Y Z")
            i = body_index(1)
            q = (number(2), number(3), number(4), number(5))
            if not quat_norm(q) > 0:
                die(where + "set_orientation: the quaternion is zero")
            sim.set_orientation(i, q)
        elif command == "set_velocity":
            expect_count(4, "I VX VY VZ")
            i = body_index(1)
            sim.set_velocity(i, vec(2))
        elif command == "apply_force":
            expect_count(7, "I PX PY PZ FX FY FZ")
            i = body_index(1)
            sim.apply_force(i, vec(2), vec(5))
        elif command == "step":
            expect_count(1, "H")
            h = number(1)
            if not h > 0:
                die(where + "step: the time step must be > 0")
            sim.step(h)
            if not stepped and fail == "exit":
                sys.stderr.write("%s: --fail exit: exiting with status 1 after the first step\n" % PROGRAM)
                return 1
            if not stepped and fail == "hang":
                # Never answer again, and never exit: a driver must time out.
                while True:
                    time.sleep(3600)
            stepped = True
        elif command == "state":
            expect_count(1, "I")
            i = body_index(1)
            state_answers += 1
            if fail == "garbage":
                answer = "hello"
            elif fail == "nan" and state_answers == 2:
                answer = " ".join(["nan"] * 13)
            else:
                answer = " ".join("%.17g" % value for value in sim.state(i))
            sys.stdout.write(answer + "\n")
            sys.stdout.flush()
        elif command == "quit":
            expect_count(0, "")
            return 0
        else:
            die("%sunknown command '%s' (valid: reset, add_body, set_orientation, set_velocity, "
                "apply_force, step, state, quit)" % (where, command))


def main():
    options = parse_options(sys.argv[1:])
    try:
        return run(options)
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    sys.exit(main())
