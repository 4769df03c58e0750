// validate(): every rule a scene definition must obey (scene.h), whoever built it,
// with the path of the field in the scene file's terms and the reason.
#include "physics/scene.h"
#include "physics/contact/settings.h"
#include "physics/integrator_registry.h"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <tuple>

namespace rbw {

namespace {

constexpr double kMaxDouble = std::numeric_limits<double>::max();

// The shortest text that reads back as the same double: 0.1, not 0.10000000000000001.
std::string num(double x)
{
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, r.ptr);
}

// x (finite, > 0) to three significant digits for a message: "5.08e-310", "100".
std::string approx(double x)
{
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, 3);
    return std::string(buffer, r.ptr);
}

// A limit (finite, > 0) to two significant digits, rounded towards the allowed side
// (up for a lower limit, down for an upper one), so that the limit a message prints
// is itself allowed: 1.0943e-307 as a lower limit is "1.1e-307".
std::string limit(double x, bool lower)
{
    if (!(std::isfinite(x) && x > 0.0)) {
        return num(x);
    }
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::scientific, 1);
    const std::string text(buffer, r.ptr);   // "d.de±XX"
    int mantissa = (text[0] - '0') * 10 + (text[2] - '0');   // 10 ... 99, times 10^(exponent - 1)
    int exponent = std::atoi(text.c_str() + 4);
    auto value = [&] {
        return std::strtod((std::to_string(mantissa) + "e" + std::to_string(exponent - 1)).c_str(), nullptr);
    };
    // Rounded to nearest, the two digits are off by at most one unit.
    if (lower && value() < x && ++mantissa == 100) {
        mantissa = 10;
        ++exponent;
    }
    if (!lower && value() > x && --mantissa == 9) {
        mantissa = 99;
        --exponent;
    }
    return approx(value());
}

std::string vec(const Vec3& v)
{
    return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]";
}

void requireFinite(std::vector<SceneIssue>& out, const std::string& path, const Vec3& v)
{
    if (!v.allFinite()) {
        out.push_back({path, "must be finite (no NaN or infinity)"});
    }
}

bool knownConvention(InertiaConvention c)
{
    return c == InertiaConvention::Standard || c == InertiaConvention::CourseTemplate;
}

std::string quoted(const std::string& name)
{
    return "\"" + messageText(name) + "\"";
}

// "a, b" for a message: at most the first 10 names, each cut by messageText(), so a
// scene of 100 000 bodies does not put every name into every message.
template <class Item>
std::string nameList(const std::vector<Item>& items)
{
    constexpr std::size_t kShown = 10;
    if (items.empty()) {
        return "none";
    }
    std::string list;
    for (std::size_t i = 0; i < items.size() && i < kShown; ++i) {
        list += (i == 0 ? "" : ", ") + messageText(items[i].name);
    }
    if (items.size() > kShown) {
        list += ", \u2026 (" + std::to_string(items.size()) + " in all)";
    }
    return list;
}

bool isBody(const SceneDef& scene, int b)
{
    return b >= 0 && b < static_cast<int>(scene.bodies.size());
}

// A reference to a body, by index (a scene built in code) or by the name a file gave,
// which the loader resolved to -1 when no body has it.
std::string missingBody(const SceneDef& scene, int index, const std::string& name)
{
    if (!name.empty()) {
        return "no body named " + quoted(name) + " (bodies: " + nameList(scene.bodies) + ")";
    }
    return "names no body of the scene (index " + std::to_string(index) + "; bodies: " + nameList(scene.bodies) +
           ")";
}

// A force, torque or push needs a body that exists and can move; a probe any body.
// `onFixed` is the reason given for a fixed body; empty: a fixed body is fine. A scene
// without bodies gets one message for that ("bodies"), not one per reference.
void checkBodyRef(std::vector<SceneIssue>& out, const SceneDef& scene, const std::string& path, int index,
                  const std::string& name, const std::string& onFixed)
{
    if (scene.bodies.empty()) {
        return;
    }
    if (!isBody(scene, index)) {
        out.push_back({path, missingBody(scene, index, name)});
    } else if (!onFixed.empty() && scene.bodies[index].fixed) {
        out.push_back({path, "body " + quoted(scene.bodies[index].name) + " is fixed; " + onFixed});
    }
}

void checkSteps(std::vector<SceneIssue>& out, const std::string& at, long fromStep, long toStep)
{
    if (fromStep < 0) {
        out.push_back({at + ".from_step", "must be >= 0, got " + std::to_string(fromStep)});
    }
    if (toStep <= fromStep) {
        out.push_back({at + ".to_step", "must be greater than from_step"});
    }
}

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

void checkCoefficient(std::vector<SceneIssue>& out, const std::string& path, double x, double hi)
{
    if (!(std::isfinite(x) && x >= 0.0 && x <= hi)) {
        out.push_back({path, hi == 1.0 ? "must be a number from 0 to 1, got " + num(x)
                                       : "must be a finite number >= 0, got " + num(x)});
    }
}

// The orientation initialState() normalises: q / |q| needs a finite |q|^2 > 0.
void checkOrientation(std::vector<SceneIssue>& out, const std::string& at, const Quat& q)
{
    const double n2 = q.coeffs().squaredNorm();
    if (!q.coeffs().allFinite() || q.coeffs().isZero(0.0)) {
        out.push_back({at + ".orientation", "must be a finite, non-zero quaternion"});
    } else if (!std::isfinite(n2)) {
        out.push_back({at + ".orientation", "the quaternion's length overflows (|q|^2 exceeds the largest double), "
                                            "so it cannot be normalised; give it a length near 1"});
    } else if (n2 == 0.0) {
        out.push_back({at + ".orientation", "the quaternion's length underflows (|q|^2 rounds to 0), so it cannot "
                                            "be normalised; give it a length near 1"});
    }
}

// Which sum of squares entry k of I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) holds.
const char* const kSquares[3] = {"b\u00b2 + c\u00b2", "a\u00b2 + c\u00b2", "a\u00b2 + b\u00b2"};

// A movable body's constants and initial state, which the world derives once
// (massProperties(), initialState()), must be finite doubles: M, 1/M and the diagonals
// of I0 and I0^-1 finite and > 0, then L0 = I(r0) omega0 and omega = I^-1 L0 finite.
// The first that is not is reported at the input that makes it so, with the limit
// that input must keep. Called only when mass, size, omega0, the orientation and the
// convention are valid on their own.
void checkDerived(std::vector<SceneIssue>& out, const std::string& at, const BodyDef& b,
                  InertiaConvention convention)
{
    // The sums of squares alone: the I0 of a body of mass 12, by the world's own
    // formula (boxInertiaBody computes 12/12 * (b^2 + c^2), exactly the sum).
    const Vec3 squares = boxInertiaBody(b.size, 12.0).diagonal();
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(squares[k])) {
            // a^2 + b^2 <= DBL_MAX when a, b <= sqrt(DBL_MAX / 2) = 9.48e153.
            out.push_back({at + ".size", "edges " + vec(b.size) + " make " + kSquares[k] +
                                             " overflow, so I0 cannot be computed; every edge must be at most " +
                                             limit(std::sqrt(kMaxDouble / 2.0), false) + " m"});
            return;
        }
        if (squares[k] == 0.0) {
            // x^2 >= DBL_MIN > 0 when x >= sqrt(DBL_MIN) = 1.49e-154.
            out.push_back({at + ".size", "edges " + vec(b.size) + " make " + kSquares[k] +
                                             " underflow to 0, so I0 would have a zero entry; one of those two "
                                             "edges must be at least " +
                                             limit(std::sqrt(std::numeric_limits<double>::min()), true) + " m"});
            return;
        }
    }
    const MassProperties mp = massProperties(b);
    if (!(std::isfinite(mp.invM) && mp.invM > 0.0)) {
        out.push_back({at + ".mass", num(b.mass) + " makes 1/M overflow; must be at least " +
                                         limit(1.0 / kMaxDouble, true) + " kg"});
        return;
    }
    const double sMin = squares.minCoeff();
    const double sMax = squares.maxCoeff();
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(mp.I0_B(k, k))) {
            // M/12 sMax <= DBL_MAX. Overflow implies sMax > 12, so DBL_MAX / sMax * 12 is finite.
            out.push_back({at + ".mass", num(b.mass) + " makes I0 overflow (I0 = M/12 (" + kSquares[k] +
                                             ") exceeds the largest double); for this size the mass must be at most " +
                                             limit(kMaxDouble / sMax * 12.0, false) + " kg"});
            return;
        }
    }
    for (int k = 0; k < 3; ++k) {
        const double I0 = mp.I0_B(k, k);
        if (!(I0 > 0.0 && std::isfinite(mp.I0inv_B(k, k)) && mp.I0inv_B(k, k) > 0.0)) {
            // 1/I0 <= DBL_MAX when M/12 sMin >= 1/DBL_MAX, i.e. M >= 12 / (sMin DBL_MAX),
            // computed without overflowing either product.
            const double least = sMin >= 1.0 ? 12.0 / sMin / kMaxDouble : 12.0 / (sMin * kMaxDouble);
            const std::string value = I0 == 0.0 ? "underflows to 0" : "= " + approx(I0) + ", too small";
            out.push_back({at + ".mass", num(b.mass) + " makes I0^-1 overflow (I0 = M/12 (" + kSquares[k] + ") " +
                                             value + " for its inverse to be a finite double)" +
                                             "; for this size the mass must be at least " + limit(least, true) +
                                             " kg"});
            return;
        }
    }
    const BodyState s0 = initialState(b, mp, convention);
    if (!s0.L_W.allFinite() || !s0.omega_W.allFinite()) {
        // |L0_i| <= sqrt(3) Imax |omega0|, and each term of omega = I^-1 L0 is at most
        // sqrt(3) Imax/Imin |omega0|; with |omega0| <= DBL_MAX / (6 Imax max(1, 1/Imin))
        // every product and sum stays below DBL_MAX.
        const double iMax = mp.I0_B.diagonal().maxCoeff();
        const double iMin = mp.I0_B.diagonal().minCoeff();
        const double most = kMaxDouble / 6.0 / iMax / std::max(1.0, 1.0 / iMin);
        out.push_back({at + ".angular_velocity",
                       "L0 = I(r0) \u03c90 overflows (|\u03c90| = " + approx(b.omega0_W.stableNorm()) +
                           " rad/s, I0 up to " + approx(iMax) + " kg m\u00b2); for this body |\u03c90| must be at most " +
                           limit(most, false) + " rad/s"});
    }
}

void checkPairs(std::vector<SceneIssue>& out, const SceneDef& scene, const SceneNames& names)
{
    const int nPlanes = static_cast<int>(scene.planes.size());
    // The first entry of each resolved pair: (lower body, higher body, -1) for two
    // bodies in either order, (body, -1, plane) for a body and a plane.
    std::map<std::tuple<int, int, int>, std::size_t> listed;
    for (size_t i = 0; i < scene.pairs.size(); ++i) {
        const PairOverride& o = scene.pairs[i];
        const std::string at = "pairs[" + std::to_string(i) + "]";
        bool ok = !scene.bodies.empty();   // no bodies: one message, at "bodies"
        if (ok && !isBody(scene, o.bodyA)) {
            ok = false;
            std::string reason = missingBody(scene, o.bodyA, o.nameA);
            if (!o.nameA.empty() && names.plane(o.nameA) >= 0) {
                reason += "; " + quoted(o.nameA) + " is a plane, and a plane comes second: [\"body\", " +
                          quoted(o.nameA) + "]";
            }
            out.push_back({at + ".bodies[0]", reason});
        }
        if (scene.bodies.empty()) {
            // nothing to say about the second name either
        } else if (o.planeB >= 0) {
            if (o.planeB >= nPlanes) {
                ok = false;
                out.push_back({at + ".bodies[1]", "names no plane of the scene (index " + std::to_string(o.planeB) +
                                                      "; planes: " + nameList(scene.planes) + ")"});
            }
        } else if (!isBody(scene, o.bodyB)) {
            ok = false;
            out.push_back({at + ".bodies[1]",
                           o.nameB.empty() ? missingBody(scene, o.bodyB, o.nameB)
                                           : "no body or plane named " + quoted(o.nameB) + " (bodies: " +
                                                 nameList(scene.bodies) + "; planes: " + nameList(scene.planes) + ")"});
        } else if (ok && o.bodyA == o.bodyB) {
            ok = false;
            out.push_back({at + ".bodies", "names " + quoted(scene.bodies[o.bodyA].name) +
                                               " twice; a pair needs two different bodies"});
        }
        if (ok) {
            const auto key = o.planeB >= 0 ? std::make_tuple(o.bodyA, -1, o.planeB)
                                           : std::make_tuple(std::min(o.bodyA, o.bodyB), std::max(o.bodyA, o.bodyB), -1);
            const auto [first, isNew] = listed.emplace(key, i);
            if (!isNew) {
                out.push_back({at + ".bodies", "this pair is already listed as pairs[" +
                                                   std::to_string(first->second) + "]; give each pair once"});
            }
        }
        if (!o.restitution && !o.friction) {
            out.push_back({at, "give \"restitution\", \"friction\" or both"});
        }
        if (o.restitution) {
            checkCoefficient(out, at + ".restitution", *o.restitution, 1.0);
        }
        if (o.friction) {
            checkCoefficient(out, at + ".friction", *o.friction, kNoLimit);
        }
    }
}

} // namespace

std::vector<SceneIssue> validate(const SceneDef& scene)
{
    std::vector<SceneIssue> out;
    const bool dtOk = std::isfinite(scene.dt) && scene.dt > 0.0;
    if (!dtOk) {
        out.push_back({"dt", "must be a finite number > 0, got " + num(scene.dt)});
    }
    if (scene.steps < 0) {
        out.push_back({"steps", "must be >= 0, got " + std::to_string(scene.steps)});
    } else if (scene.steps > kMaxSceneSteps) {
        out.push_back({"steps", "must be at most " + std::to_string(kMaxSceneSteps) + " (10^9), got " +
                                    std::to_string(scene.steps)});
    } else if (dtOk && !std::isfinite(scene.dt * static_cast<double>(scene.steps))) {
        // t = k h after step k: the end time steps * h must be a finite double
        // (half the largest, for the rounding of t += h over the steps).
        out.push_back({"dt", num(scene.dt) + " s makes the end time steps \u00b7 h overflow; for " +
                                 std::to_string(scene.steps) + " steps h must be at most " +
                                 limit(kMaxDouble / 2.0 / static_cast<double>(scene.steps), false) + " s"});
    }
    if (!makeIntegrator(scene.integrator)) {
        out.push_back({"integrator", "unknown integrator " + quoted(scene.integrator) +
                                         "; known: " + integratorNames()});
    }
    if (!knownConvention(scene.inertiaConvention)) {
        out.push_back({"inertia_convention", "must be \"standard\" or \"course-template\""});
    }
    requireFinite(out, "gravity", scene.g_W);
    if (scene.bodies.empty()) {
        out.push_back({"bodies", "must list at least one body; a scene without a body has nothing to simulate"});
    }

    // Bodies and planes share one set of names, so that a pair can name either. A name
    // is a duplicate where SceneNames (which keeps the first) resolves it elsewhere.
    const SceneNames names(scene);
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyDef& b = scene.bodies[i];
        const std::string at = "bodies[" + std::to_string(i) + "]";
        if (b.name.empty()) {
            out.push_back({at + ".name", "must not be empty"});
        } else if (names.body(b.name) != static_cast<int>(i)) {
            out.push_back({at + ".name", "duplicate body name " + quoted(b.name)});
        }
        const bool massOk = b.fixed || (std::isfinite(b.mass) && b.mass > 0.0);
        if (!massOk) {
            out.push_back({at + ".mass", "must be a finite number > 0, got " + num(b.mass)});
        }
        bool sizeOk = true;
        for (int k = 0; k < 3; ++k) {
            if (!(std::isfinite(b.size[k]) && b.size[k] > 0.0)) {
                out.push_back({at + ".size", "every edge length must be a finite number > 0, got " +
                                                 num(b.size[k]) + " at index " + std::to_string(k)});
                sizeOk = false;
                break;
            }
        }
        requireFinite(out, at + ".position", b.x0_W);
        requireFinite(out, at + ".linear_velocity", b.v0_W);
        requireFinite(out, at + ".angular_velocity", b.omega0_W);
        if (b.fixed && b.v0_W.allFinite() && b.v0_W != Vec3::Zero()) {
            out.push_back({at + ".linear_velocity",
                           "a fixed body cannot have a velocity; leave it out or give [0, 0, 0]"});
        }
        if (b.fixed && b.omega0_W.allFinite() && b.omega0_W != Vec3::Zero()) {
            out.push_back({at + ".angular_velocity",
                           "a fixed body cannot have a velocity; leave it out or give [0, 0, 0]"});
        }
        const std::size_t before = out.size();
        checkOrientation(out, at, b.q0_WB);
        const bool orientationOk = out.size() == before;
        if (!b.integrator.empty() && !makeIntegrator(b.integrator)) {
            out.push_back({at + ".integrator", "unknown integrator " + quoted(b.integrator) +
                                                   "; known: " + integratorNames()});
        }
        const bool conventionOk = !b.inertiaConvention || knownConvention(*b.inertiaConvention);
        if (!conventionOk) {
            out.push_back({at + ".inertia_convention", "must be \"standard\" or \"course-template\""});
        }
        if (!b.fixed && massOk && sizeOk && orientationOk && conventionOk && b.omega0_W.allFinite() &&
            knownConvention(scene.inertiaConvention)) {
            checkDerived(out, at, b, scene.conventionOf(static_cast<int>(i)));
        }
    }

    for (size_t i = 0; i < scene.forces.size(); ++i) {
        const ForceDef& f = scene.forces[i];
        const std::string at = "forces[" + std::to_string(i) + "]";
        checkBodyRef(out, scene, at + ".body", f.body, f.bodyName, "a force on it has no effect");
        requireFinite(out, at + ".point", f.p_W);
        requireFinite(out, at + ".force", f.f_W);
        checkSteps(out, at, f.fromStep, f.toStep);
    }
    for (size_t i = 0; i < scene.torques.size(); ++i) {
        const TorqueDef& t = scene.torques[i];
        const std::string at = "torques[" + std::to_string(i) + "]";
        checkBodyRef(out, scene, at + ".body", t.body, t.bodyName, "a torque on it has no effect");
        requireFinite(out, at + ".torque", t.q_W);
        checkSteps(out, at, t.fromStep, t.toStep);
    }
    // No body and no name: the scene has no keyboard pushes.
    if (scene.push.body >= 0 || !scene.push.bodyName.empty()) {
        checkBodyRef(out, scene, "push.body", scene.push.body, scene.push.bodyName, "pushing it has no effect");
        requireFinite(out, "push.point", scene.push.p_B);
        if (!(std::isfinite(scene.push.magnitude) && scene.push.magnitude > 0.0)) {
            out.push_back({"push.force", "must be a finite number > 0, got " + num(scene.push.magnitude)});
        }
    }
    for (size_t i = 0; i < scene.probes.size(); ++i) {
        const ProbeDef& p = scene.probes[i];
        const std::string at = "probes[" + std::to_string(i) + "]";
        checkBodyRef(out, scene, at + ".body", p.body, p.bodyName, std::string());
        requireFinite(out, at + ".point", p.p0_W);
        if (isBody(scene, p.body) && p.p0_W.allFinite()) {
            const BodyDef& b = scene.bodies[p.body];
            const double n2 = b.q0_WB.coeffs().squaredNorm();
            if (b.x0_W.allFinite() && b.q0_WB.coeffs().allFinite() && std::isfinite(n2) && n2 > 0.0) {
                // The world keeps p_B = R0^T (p0 - x0), with R0 as initialState() builds it.
                const Mat3 R0 = b.q0_WB.normalized().toRotationMatrix();
                const Vec3 offset_B = R0.transpose() * (p.p0_W - b.x0_W);
                if (!offset_B.allFinite()) {
                    out.push_back({at + ".point", "its offset p0 \u2212 x0 from the centre of body " + quoted(b.name) +
                                                      " overflows (p0 = " + vec(p.p0_W) + ", x0 = " + vec(b.x0_W) +
                                                      "); give a point nearer the body"});
                }
            }
        }
    }

    for (size_t i = 0; i < scene.planes.size(); ++i) {
        const PlaneDef& p = scene.planes[i];
        const std::string at = "planes[" + std::to_string(i) + "]";
        if (p.name.empty()) {
            out.push_back({at + ".name", "must not be empty"});
        } else if (names.body(p.name) >= 0 || names.plane(p.name) != static_cast<int>(i)) {
            out.push_back({at + ".name", "duplicate name " + quoted(p.name) + " (bodies and planes share names)"});
        }
        requireFinite(out, at + ".point", p.point_W);
        if (!p.n_W.allFinite()) {
            out.push_back({at + ".normal", "must be finite (no NaN or infinity)"});
        } else if (p.n_W == Vec3::Zero()) {
            out.push_back({at + ".normal", "must not be the zero vector"});
        } else if (std::abs(p.n_W.norm() - 1.0) > 1e-12) {
            // The loader normalises a file's normal; a scene built in code must.
            out.push_back({at + ".normal", "must be a unit vector, got length " + num(p.n_W.norm())});
        }
    }
    checkCoefficient(out, "restitution", scene.restitution, 1.0);
    checkCoefficient(out, "friction", scene.friction, kNoLimit);
    checkCoefficient(out, "restitution_threshold", scene.restitutionThreshold, kNoLimit);
    checkPairs(out, scene, names);
    if (scene.planeContacts != PlaneContactMode::PerPoint && scene.planeContacts != PlaneContactMode::Average) {
        out.push_back({"plane_contacts", "must be \"per-point\" or \"average\""});
    }
    if (!(std::isfinite(scene.energyJumpFactor) && (scene.energyJumpFactor == 0.0 || scene.energyJumpFactor >= 1.0))) {
        out.push_back({"energy_jump.factor", "must be 0 (off) or a finite number >= 1, got " +
                                                 num(scene.energyJumpFactor)});
    }
    checkCoefficient(out, "energy_jump.floor", scene.energyJumpFloor, kNoLimit);
    checkContactModel(out, scene);
    return out;
}

} // namespace rbw
