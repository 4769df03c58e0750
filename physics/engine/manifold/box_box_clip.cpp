// Box-box manifolds by face clipping; the method and its sources are in box_box_clip.h.
//
// Glossary
//   d_W            c_B - c_A                                                   [m]
//   L_W            a candidate separating axis (unit)                           [-]
//   s              separation on an axis: |d . L| - (r_A + r_B); < 0 overlap     [m]
//   nOut_W         outward normal of the reference face (-n for A, +n for B)     [-]
//   o_ref          offset of the reference face plane: nOut . p = o_ref          [m]
#include "physics/engine/manifold/box_box_clip.h"

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

constexpr double kRelativeTol = 0.98;   // Box2D b2CollidePolygons' k_relativeTol
constexpr double kAbsoluteTol = 0.001;  // and k_absoluteTol [m]
constexpr double kClipTolerance = 0.005;   // side planes moved out by this (at most 5 % of the face) [m]

// The radius of a box projected on the unit axis L: r = sum_k h_k |L . axis_k|.
double projectedRadius(const BoxPose& box, const Vec3& L_W)
{
    return box.halfExtents.x() * std::abs(L_W.dot(box.R_WB.col(0))) +
           box.halfExtents.y() * std::abs(L_W.dot(box.R_WB.col(1))) +
           box.halfExtents.z() * std::abs(L_W.dot(box.R_WB.col(2)));
}

// The line both vertices lie on (the edge between them).
int commonLine(const ClipVertex& P, const ClipVertex& Q)
{
    if (P.line0 == Q.line0 || P.line0 == Q.line1) return P.line0;
    return P.line1;
}

// Closest points of segments P1Q1 and P2Q2 (Ericson 5.1.9, ClosestPtSegmentSegment).
void closestSegmentPoints(const Vec3& P1, const Vec3& Q1, const Vec3& P2, const Vec3& Q2, Vec3& c1, Vec3& c2)
{
    const Vec3 d1 = Q1 - P1;
    const Vec3 d2 = Q2 - P2;
    const Vec3 r = P1 - P2;
    const double a = d1.squaredNorm();
    const double e = d2.squaredNorm();
    const double f = d2.dot(r);
    const double c = d1.dot(r);
    const double b = d1.dot(d2);
    // denom = a e - b^2 >= 0; 0 for parallel segments (then take s = 0)
    const double denom = a * e - b * b;
    double s = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
    // t = (b s + f) / e, clamped, and s recomputed for the clamped t
    double t = (b * s + f) / e;
    if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
    c1 = P1 + s * d1;
    c2 = P2 + t * d2;
}

// Edge-edge manifold: one point at the closest points of A's edge along A_i nearest B
// and B's edge along B_j nearest A.
void edgeEdgePoint(const BoxPose& A, const BoxPose& B, int i, int j, const Vec3& n_W, Manifold& m)
{
    // A's edge: the support of A in direction -n; s_k = -sign(A_k . n) on the other axes
    Vec3 eA_W = A.c_W;
    int bitsA = 0;
    for (int k = 0, bit = 0; k < 3; ++k) {
        if (k == i) continue;
        const double s = A.R_WB.col(k).dot(n_W) > 0.0 ? -1.0 : 1.0;
        eA_W += s * A.halfExtents[k] * A.R_WB.col(k);
        if (s > 0.0) bitsA |= 1 << bit;
        ++bit;
    }
    // B's edge: the support of B in direction +n
    Vec3 eB_W = B.c_W;
    int bitsB = 0;
    for (int k = 0, bit = 0; k < 3; ++k) {
        if (k == j) continue;
        const double s = B.R_WB.col(k).dot(n_W) > 0.0 ? 1.0 : -1.0;
        eB_W += s * B.halfExtents[k] * B.R_WB.col(k);
        if (s > 0.0) bitsB |= 1 << bit;
        ++bit;
    }
    const Vec3 halfA_W = A.halfExtents[i] * A.R_WB.col(i);
    const Vec3 halfB_W = B.halfExtents[j] * B.R_WB.col(j);
    Vec3 pA_W, pB_W;
    closestSegmentPoints(eA_W - halfA_W, eA_W + halfA_W, eB_W - halfB_W, eB_W + halfB_W, pA_W, pB_W);
    ManifoldPoint& pt = m.points[0];
    pt = ManifoldPoint{};
    // p = (pA + pB) / 2, s = n . (pA - pB)
    pt.p_W = 0.5 * (pA_W + pB_W);
    m.where = std::source_location::current();
    pt.separation = n_W.dot(pA_W - pB_W);
    pt.pA_A = A.R_WB.transpose() * (pA_W - A.c_W);
    pt.pB_B = B.R_WB.transpose() * (pB_W - B.c_W);
    pt.feature = (1u << 16) + static_cast<std::uint32_t>(12 * (4 * i + bitsA) + (4 * j + bitsB));
    m.count = 1;
}

} // namespace

void clipPolygon(const ClipPolygon& in, const Vec3& m_W, double o, int label, ClipPolygon& out)
{
    out.n = 0;
    for (int k = 0; k < in.n; ++k) {
        const ClipVertex& P = in.v[static_cast<std::size_t>(k)];
        const ClipVertex& Q = in.v[static_cast<std::size_t>((k + 1) % in.n)];
        // signed distances d = m . p - o; <= 0 inside
        const double dP = m_W.dot(P.p_W) - o;
        const double dQ = m_W.dot(Q.p_W) - o;
        if (dP <= 0.0) out.v[static_cast<std::size_t>(out.n++)] = P;
        if ((dP < 0.0 && dQ > 0.0) || (dP > 0.0 && dQ < 0.0)) {
            // I = P + (Q - P) dP / (dP - dQ), on the edge's line and on the plane
            ClipVertex I;
            I.p_W = P.p_W + (Q.p_W - P.p_W) * (dP / (dP - dQ));
            I.line0 = commonLine(P, Q);
            I.line1 = label;
            out.v[static_cast<std::size_t>(out.n++)] = I;
        }
    }
}

void reduceManifold(Manifold& m, int maxPoints)
{
    if (m.count <= maxPoints) return;
    std::array<int, kMaxManifoldPoints> chosen{};
    int kept = 0;
    std::array<char, kMaxManifoldPoints> used{};
    const auto pick = [&](int k) {
        chosen[static_cast<std::size_t>(kept++)] = k;
        used[static_cast<std::size_t>(k)] = 1;
    };
    // 1. the deepest point (smallest s)
    int deepest = 0;
    for (int k = 1; k < m.count; ++k) {
        if (m.points[static_cast<std::size_t>(k)].separation < m.points[static_cast<std::size_t>(deepest)].separation) {
            deepest = k;
        }
    }
    pick(deepest);
    const Vec3& p0_W = m.points[static_cast<std::size_t>(deepest)].p_W;
    // 2. the farthest from it
    int far = -1;
    double farDistance = -1.0;
    for (int k = 0; k < m.count; ++k) {
        const double d2 = (m.points[static_cast<std::size_t>(k)].p_W - p0_W).squaredNorm();
        if (!used[static_cast<std::size_t>(k)] && d2 > farDistance) {
            farDistance = d2;
            far = k;
        }
    }
    if (maxPoints >= 2) pick(far);
    // 3., 4. the largest signed triangle area (p_k - p0) x (p1 - p0) . n on either side
    const Vec3 edge_W = m.points[static_cast<std::size_t>(far)].p_W - p0_W;
    for (int side = 0; side < 2 && kept < maxPoints; ++side) {
        int best = -1;
        double bestArea = 0.0;
        for (int k = 0; k < m.count; ++k) {
            if (used[static_cast<std::size_t>(k)]) continue;
            const double area = (m.points[static_cast<std::size_t>(k)].p_W - p0_W).cross(edge_W).dot(m.n_W);
            const double signedArea = side == 0 ? area : -area;
            if (best < 0 || signedArea > bestArea) {
                bestArea = signedArea;
                best = k;
            }
        }
        if (best >= 0) pick(best);
    }
    // More than 4 wanted: the rest in their order.
    for (int k = 0; k < m.count && kept < maxPoints; ++k) {
        if (!used[static_cast<std::size_t>(k)]) pick(k);
    }
    // Keep the chosen points in their clipping order (insertion sort of at most 8).
    for (int i = 1; i < kept; ++i) {
        const int value = chosen[static_cast<std::size_t>(i)];
        int j = i - 1;
        while (j >= 0 && chosen[static_cast<std::size_t>(j)] > value) {
            chosen[static_cast<std::size_t>(j + 1)] = chosen[static_cast<std::size_t>(j)];
            --j;
        }
        chosen[static_cast<std::size_t>(j + 1)] = value;
    }
    for (int i = 0; i < kept; ++i) {
        m.points[static_cast<std::size_t>(i)] = m.points[static_cast<std::size_t>(chosen[static_cast<std::size_t>(i)])];
    }
    m.count = kept;
}

bool collideBoxBoxManifold(const BoxPose& A, const BoxPose& B, double margin, Manifold& m, int maxPoints)
{
    m.count = 0;
    const Vec3 d_W = B.c_W - A.c_W;
    // 1. Face axes of A and of B: s = |d . L| - (h_i + r_other)
    double sepA = -1e300, sepB = -1e300, sepE = -1e300;
    int faceA = -1, faceB = -1, edgeI = -1, edgeJ = -1;
    Vec3 edgeL_W = Vec3::Zero();
    for (int i = 0; i < 3; ++i) {
        const Vec3 L_W = A.R_WB.col(i);
        const double s = std::abs(d_W.dot(L_W)) - (A.halfExtents[i] + projectedRadius(B, L_W));
        if (s > margin) return false;
        if (s > sepA) { sepA = s; faceA = i; }
    }
    for (int j = 0; j < 3; ++j) {
        const Vec3 L_W = B.R_WB.col(j);
        const double s = std::abs(d_W.dot(L_W)) - (B.halfExtents[j] + projectedRadius(A, L_W));
        if (s > margin) return false;
        if (s > sepB) { sepB = s; faceB = j; }
    }
    // Edge axes L = A_i x B_j / |A_i x B_j|, skipped when the edges are parallel.
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Vec3 cross_W = A.R_WB.col(i).cross(B.R_WB.col(j));
            const double len = cross_W.norm();
            if (len < 1e-6) continue;
            const Vec3 L_W = cross_W / len;
            const double s = std::abs(d_W.dot(L_W)) - (projectedRadius(A, L_W) + projectedRadius(B, L_W));
            if (s > margin) return false;
            if (s > sepE) { sepE = s; edgeI = i; edgeJ = j; edgeL_W = L_W; }
        }
    }

    // 2. The winning axis, biased towards faces (Box2D: relative and absolute tolerances).
    const bool useB = sepB > kRelativeTol * sepA + kAbsoluteTol;
    const double sepFace = useB ? sepB : sepA;
    if (edgeI >= 0 && sepE > kRelativeTol * sepFace + kAbsoluteTol) {
        // n from B to A: n = -L if d . L > 0
        const Vec3 n_W = d_W.dot(edgeL_W) > 0.0 ? Vec3(-edgeL_W) : edgeL_W;
        m.reference = ReferenceSide::Edge;
        m.n_W = n_W;
        m.nRef_R = A.R_WB.transpose() * n_W;
        edgeEdgePoint(A, B, edgeI, edgeJ, n_W, m);
        tangentBasis(m.n_W, m.t1_W, m.t2_W);
        return true;
    }

    // 3. Face axis: reference and incident boxes.
    const BoxPose& ref = useB ? B : A;
    const BoxPose& inc = useB ? A : B;
    const int k = useB ? faceB : faceA;
    const Vec3 axis_W = ref.R_WB.col(k);
    // The reference face faces the incident box: nOut = sign(axis . (c_inc - c_ref)) axis
    const double refSign = axis_W.dot(inc.c_W - ref.c_W) >= 0.0 ? 1.0 : -1.0;
    const Vec3 nOut_W = refSign * axis_W;
    // n from B to A: the reference face of A points to B (n = -nOut), of B to A (n = nOut)
    m.n_W = useB ? nOut_W : Vec3(-nOut_W);
    m.reference = useB ? ReferenceSide::B : ReferenceSide::A;
    m.nRef_R = ref.R_WB.transpose() * nOut_W;
    // Incident face: the axis most (anti-)parallel to nOut, with the sign that faces ref
    int kInc = 0;
    double best = -1.0;
    for (int j = 0; j < 3; ++j) {
        const double dotj = std::abs(nOut_W.dot(inc.R_WB.col(j)));
        if (dotj > best) { best = dotj; kInc = j; }
    }
    const double incSign = nOut_W.dot(inc.R_WB.col(kInc)) > 0.0 ? -1.0 : 1.0;
    const int u = (kInc + 1) % 3;
    const int v = (kInc + 2) % 3;
    const Vec3 incCentre_W = inc.c_W + incSign * inc.halfExtents[kInc] * inc.R_WB.col(kInc);
    const Vec3 U_W = inc.halfExtents[u] * inc.R_WB.col(u);
    const Vec3 V_W = inc.halfExtents[v] * inc.R_WB.col(v);
    // The incident face's corners in cyclic order; corner c lies on edges c-1 and c.
    ClipPolygon poly, tmp;
    const double su[4] = {1.0, -1.0, -1.0, 1.0};
    const double sv[4] = {1.0, 1.0, -1.0, -1.0};
    poly.n = 4;
    for (int c = 0; c < 4; ++c) {
        poly.v[static_cast<std::size_t>(c)] = ClipVertex{incCentre_W + su[c] * U_W + sv[c] * V_W, (c + 3) % 4, c};
    }
    // Clip against the 4 side planes of the reference face: +-ref_u . p <= +-ref_u . c_ref + h_u
    const int ru = (k + 1) % 3;
    const int rv = (k + 2) % 3;
    // The side planes are moved out by a small tolerance, so that an incident corner a
    // hair outside (two equal boxes stacked, turned by 1e-4 rad) stays a corner instead
    // of being cut into two points at random places along its edges, whose feature ids
    // would change from step to step and defeat warm starting.
    const Vec3 refU_W = ref.R_WB.col(ru);
    const Vec3 refV_W = ref.R_WB.col(rv);
    const double tolU = std::min(kClipTolerance, 0.05 * ref.halfExtents[ru]);
    const double tolV = std::min(kClipTolerance, 0.05 * ref.halfExtents[rv]);
    clipPolygon(poly, refU_W, refU_W.dot(ref.c_W) + ref.halfExtents[ru] + tolU, 4, tmp);
    clipPolygon(tmp, -refU_W, -refU_W.dot(ref.c_W) + ref.halfExtents[ru] + tolU, 5, poly);
    clipPolygon(poly, refV_W, refV_W.dot(ref.c_W) + ref.halfExtents[rv] + tolV, 6, tmp);
    clipPolygon(tmp, -refV_W, -refV_W.dot(ref.c_W) + ref.halfExtents[rv] + tolV, 7, poly);

    // 4. Keep the clipped vertices within the margin of the reference face plane.
    const double oRef = nOut_W.dot(ref.c_W) + ref.halfExtents[k];   // nOut . p = o_ref on the face
    const std::uint32_t refFace = static_cast<std::uint32_t>(2 * k + (refSign > 0.0 ? 1 : 0));
    const std::uint32_t incFace = static_cast<std::uint32_t>(2 * kInc + (incSign > 0.0 ? 1 : 0));
    const std::uint32_t faces = ((useB ? 6u : 0u) + refFace) * 6u + incFace;
    for (int c = 0; c < poly.n && m.count < kMaxManifoldPoints; ++c) {
        const ClipVertex& cv = poly.v[static_cast<std::size_t>(c)];
        // s = nOut . p - o_ref (< 0: below the reference face)
        const double s = nOut_W.dot(cv.p_W) - oRef;
        if (s > margin) continue;
        // The point on the reference face: p_ref = p - s nOut
        const Vec3 pRef_W = cv.p_W - s * nOut_W;
        const Vec3& pA_W = useB ? cv.p_W : pRef_W;
        const Vec3& pB_W = useB ? pRef_W : cv.p_W;
        ManifoldPoint& pt = m.points[static_cast<std::size_t>(m.count++)];
        pt = ManifoldPoint{};
        // p = (pA + pB) / 2; s = n . (pA - pB)
        pt.p_W = 0.5 * (pA_W + pB_W);
        m.where = std::source_location::current();
        pt.separation = s;
        pt.pA_A = A.R_WB.transpose() * (pA_W - A.c_W);
        pt.pB_B = B.R_WB.transpose() * (pB_W - B.c_W);
        const int lo = std::min(cv.line0, cv.line1);
        const int hi = std::max(cv.line0, cv.line1);
        pt.feature = faces * 64u + static_cast<std::uint32_t>(8 * lo + hi);
    }
    if (m.count == 0) return false;
    reduceManifold(m, maxPoints);
    tangentBasis(m.n_W, m.t1_W, m.t2_W);
    return true;
}

} // namespace rbw
