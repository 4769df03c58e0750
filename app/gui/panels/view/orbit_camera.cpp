#include "app/gui/panels/view/orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace rbw {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerPixel = 0.4;     // orbit speed
constexpr double kZoomPerStep = 0.85;    // one wheel notch: distance * 0.85
constexpr double kMinDistance = 1e-3;
constexpr double kMaxDistance = 1e5;

double rad(double deg) { return deg * kPi / 180.0; }

} // namespace

void OrbitCamera::setDistance(double d)
{
    if (std::isfinite(d)) distance_ = std::clamp(d, kMinDistance, kMaxDistance);
}

void OrbitCamera::setAngles(double yawDeg, double pitchDeg)
{
    if (!std::isfinite(yawDeg) || !std::isfinite(pitchDeg)) return;
    yawDeg_ = std::remainder(yawDeg, 360.0);
    // The poles are allowed (the top view looks straight down): right() does not
    // depend on the pitch, so the camera axes stay defined there.
    pitchDeg_ = std::clamp(pitchDeg, -90.0, 90.0);
}

Vec3 OrbitCamera::eye() const
{
    // back = (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw)): spherical angles about +y.
    const double cp = std::cos(rad(pitchDeg_));
    const Vec3 back(cp * std::sin(rad(yawDeg_)), std::sin(rad(pitchDeg_)), cp * std::cos(rad(yawDeg_)));
    return target_W_ + distance_ * back;
}

Vec3 OrbitCamera::forward() const { return (target_W_ - eye()).normalized(); }

Vec3 OrbitCamera::right() const
{
    // forward x y normalised, in closed form: forward = -back gives forward x y =
    // cos(pitch) (cos(yaw), 0, -sin(yaw)), so right = (cos(yaw), 0, -sin(yaw)), also at the poles.
    return Vec3(std::cos(rad(yawDeg_)), 0.0, -std::sin(rad(yawDeg_)));
}

Vec3 OrbitCamera::up() const { return right().cross(forward()); }

OrbitCamera::Mat4 OrbitCamera::viewMatrix() const
{
    // lookAt (gluLookAt): rows are the camera axes r, u, -f; translation -R e.
    const Vec3 f = forward();
    const Vec3 r = right();
    const Vec3 u = up();
    const Vec3 e = eye();
    Mat4 V = Mat4::Identity();
    V.block<1, 3>(0, 0) = r.transpose();
    V.block<1, 3>(1, 0) = u.transpose();
    V.block<1, 3>(2, 0) = -f.transpose();
    V(0, 3) = -r.dot(e);
    V(1, 3) = -u.dot(e);
    V(2, 3) = f.dot(e);
    return V;
}

OrbitCamera::Mat4 OrbitCamera::projectionMatrix(double aspect) const
{
    // gluPerspective: f = cot(fovY/2); near/far follow the distance so depth precision
    // stays good from a close-up to the whole scene.
    const double zNear = std::max(1e-4, 0.02 * distance_);
    const double zFar = 200.0 * distance_ + 100.0;
    const double f = 1.0 / std::tan(rad(kFovYDeg) / 2.0);
    Mat4 P = Mat4::Zero();
    P(0, 0) = f / aspect;
    P(1, 1) = f;
    P(2, 2) = (zFar + zNear) / (zNear - zFar);
    P(2, 3) = 2.0 * zFar * zNear / (zNear - zFar);
    P(3, 2) = -1.0;
    return P;
}

void OrbitCamera::orbit(double dxPx, double dyPx)
{
    // Dragging right turns the scene right (the eye moves left); dragging down lifts the eye.
    // A vertical drag stays off the poles; a horizontal one keeps the pitch, so a
    // top view (pitch 90) can be turned about the vertical.
    double pitch = pitchDeg_;
    if (dyPx != 0.0) pitch = std::clamp(pitchDeg_ + kDegPerPixel * dyPx, -89.0, 89.0);
    setAngles(yawDeg_ - kDegPerPixel * dxPx, pitch);
}

void OrbitCamera::pan(double dxPx, double dyPx, double viewportHeightPx)
{
    if (viewportHeightPx <= 0.0) return;
    // World length of one pixel at the target's depth: 2 d tan(fovY/2) / height.
    const double metresPerPixel = 2.0 * distance_ * std::tan(rad(kFovYDeg) / 2.0) / viewportHeightPx;
    // The scene follows the mouse: the target moves against the drag.
    target_W_ += metresPerPixel * (-dxPx * right() + dyPx * up());
}

void OrbitCamera::zoom(double wheelSteps)
{
    if (std::isfinite(wheelSteps)) setDistance(distance_ * std::pow(kZoomPerStep, wheelSteps));
}

void OrbitCamera::setStandardView(StandardView v)
{
    // back(yaw, pitch) = (cos p sin y, sin p, cos p cos y) points from the target to the eye.
    switch (v) {
    case StandardView::Front: setAngles(0.0, 0.0); break;   // eye on +z: right +x, up +y
    case StandardView::Top: setAngles(0.0, 90.0); break;    // eye on +y: right +x, up -z
    case StandardView::Side: setAngles(90.0, 0.0); break;   // eye on +x: right -z, up +y
    }
}

void OrbitCamera::frame(const Vec3& centre_W, double radius, double aspect)
{
    if (!isFinite(centre_W) || !std::isfinite(radius) || !(aspect > 0.0)) return;
    target_W_ = centre_W;
    // A sphere of radius r fits a cone of half-angle a at distance r / sin(a); use the
    // narrower of the vertical and horizontal half-angles, with a margin of 30 % for
    // the legend.
    const double halfY = rad(kFovYDeg) / 2.0;
    const double halfX = std::atan(std::tan(halfY) * aspect);
    const double half = std::min(halfY, halfX);
    setDistance(1.3 * std::max(radius, 1e-2) / std::sin(half));
}

Ray OrbitCamera::rayThroughNdc(double ndcX, double ndcY, double aspect) const
{
    // The pixel lies on the image plane at unit distance: f + x tan(fovY/2) aspect r + y tan(fovY/2) u.
    const double t = std::tan(rad(kFovYDeg) / 2.0);
    const Vec3 d = forward() + (ndcX * t * aspect) * right() + (ndcY * t) * up();
    return Ray{eye(), d.normalized()};
}

} // namespace rbw
