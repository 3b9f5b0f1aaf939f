#include "camera.h"

#include <QVector4D>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ui {

namespace {

// degrees: straight down or up at most; right() comes from the yaw alone, so the view keeps its
// bearings at the poles (the Top view looks straight down)
constexpr float kMaxPitch = 90.0f;
// a framed sphere keeps this much room to the edges
constexpr float kFrameMargin = 1.1f;

float radians(float degrees) { return degrees * std::numbers::pi_v<float> / 180.0f; }

}  // namespace

void Camera::setViewportSize(QSize size) { m_size = QSize(std::max(1, size.width()), std::max(1, size.height())); }

float Camera::aspect() const { return float(m_size.width()) / float(m_size.height()); }

void Camera::setFieldOfView(float degrees) { m_fovY = std::clamp(degrees, 1.0f, 170.0f); }

void Camera::setDistance(float distance) { m_distance = std::clamp(distance, kMinDistance, kMaxDistance); }

void Camera::setAngles(float yawDegrees, float pitchDegrees)
{
    // yaw wraps into (-180, 180]; pitch stops at the poles
    m_yaw = std::remainder(yawDegrees, 360.0f);
    m_pitch = std::clamp(pitchDegrees, -kMaxPitch, kMaxPitch);
}

void Camera::lookAlong(ViewPreset preset)
{
    switch (preset) {
    case ViewPreset::Top:
        setAngles(0.0f, kMaxPitch);
        break;
    case ViewPreset::Front:
        setAngles(0.0f, 0.0f);
        break;
    case ViewPreset::Side:
        setAngles(90.0f, 0.0f);
        break;
    case ViewPreset::Default:
        setAngles(kDefaultYaw, kDefaultPitch);
        break;
    }
}

QVector3D Camera::forward() const
{
    // the eye sits on a sphere about the target, pitch above the horizon, yaw from +z towards +x
    const float yaw = radians(m_yaw);
    const float pitch = radians(m_pitch);
    return -QVector3D(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}

QVector3D Camera::eye() const { return m_target - m_distance * forward(); }

QVector3D Camera::right() const
{
    // forward × world up, normalised, but from the yaw alone so that it holds at the poles too
    const float yaw = radians(m_yaw);
    return QVector3D(std::cos(yaw), 0.0f, -std::sin(yaw));
}

QVector3D Camera::up() const { return QVector3D::crossProduct(right(), forward()); }

void Camera::setSceneBounds(const QVector3D &centre, float radius)
{
    m_sceneCentre = centre;
    m_sceneRadius = std::max(radius, 0.0f);
}

float Camera::farPlane() const
{
    // far enough for the whole scene (and the grid around it) wherever the target has wandered
    return 2.0f * (m_distance + (m_target - m_sceneCentre).length() + 3.0f * m_sceneRadius);
}

float Camera::nearPlane() const
{
    // a near plane close to the eye, but not so close that the depth buffer loses its precision
    const float near = std::max(farPlane() * 1.0e-5f, m_distance * 0.02f);
    if (!orthographic())
        return near;
    // orthographic depth is linear, so the near plane can sit behind the eye, past the scene
    const float reach = (m_target - m_sceneCentre).length() + 3.0f * m_sceneRadius;
    return std::min(near, m_distance - 2.0f * reach);
}

QMatrix4x4 Camera::viewMatrix() const
{
    QMatrix4x4 view;
    view.lookAt(eye(), m_target, up());
    return view;
}

QMatrix4x4 Camera::projectionMatrix() const
{
    QMatrix4x4 projection;
    if (orthographic()) {
        const float halfHeight = halfHeightAtTarget();
        const float halfWidth = halfHeight * aspect();
        projection.ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearPlane(), farPlane());
    } else {
        projection.perspective(m_fovY, aspect(), nearPlane(), farPlane());
    }
    return projection;
}

std::optional<QPointF> Camera::project(const QVector3D &world) const
{
    // clip space, then normalised device coordinates, then pixels with y down
    const QVector4D clip = viewProjectionMatrix() * QVector4D(world, 1.0f);
    if (clip.w() <= 0.0f || (orthographic() && clip.z() < -clip.w()))
        return std::nullopt;
    const float x = clip.x() / clip.w();
    const float y = clip.y() / clip.w();
    return QPointF((x * 0.5 + 0.5) * m_size.width(), (0.5 - y * 0.5) * m_size.height());
}

Ray Camera::unproject(const QPointF &pixel) const
{
    // the pixel in normalised device coordinates, then along the camera's basis
    const float x = float(2.0 * pixel.x() / m_size.width() - 1.0);
    const float y = float(1.0 - 2.0 * pixel.y() / m_size.height());
    if (orthographic()) {
        // parallel rays, each from the pixel's point on the near plane
        const float halfHeight = halfHeightAtTarget();
        const QVector3D onEyePlane = eye() + right() * (x * halfHeight * aspect()) + up() * (y * halfHeight);
        return Ray{onEyePlane + nearPlane() * forward(), forward()};
    }
    const float tanHalf = std::tan(radians(m_fovY) * 0.5f);
    const QVector3D direction = forward() + right() * (x * tanHalf * aspect()) + up() * (y * tanHalf);
    return Ray{eye(), direction.normalized()};
}

bool Camera::sphereInView(const QVector3D &centre, float radius) const
{
    // the centre in view space, where the eye looks down -z
    const QVector3D p = viewMatrix().map(centre);
    const float depth = -p.z();
    if (!std::isfinite(depth) || !std::isfinite(p.x()) || !std::isfinite(p.y()))
        return false;
    if (depth - radius < nearPlane() || depth + radius > farPlane())
        return false;
    const float tanY = std::tan(radians(m_fovY) * 0.5f);
    const float tanX = tanY * aspect();
    if (orthographic()) {
        const float halfHeight = halfHeightAtTarget();
        return halfHeight * aspect() - std::abs(p.x()) >= radius && halfHeight - std::abs(p.y()) >= radius;
    }
    // its distance inside each of the four side planes of the frustum
    const float insideX = (depth * tanX - std::abs(p.x())) / std::sqrt(1.0f + tanX * tanX);
    const float insideY = (depth * tanY - std::abs(p.y())) / std::sqrt(1.0f + tanY * tanY);
    return insideX >= radius && insideY >= radius;
}

void Camera::orbit(float dxPixels, float dyPixels)
{
    // the scene follows the mouse as if grabbed: dragging right turns it to the right
    setAngles(m_yaw - dxPixels * kOrbitDegreesPerPixel, m_pitch + dyPixels * kOrbitDegreesPerPixel);
}

float Camera::halfHeightAtTarget() const { return m_distance * std::tan(radians(m_fovY) * 0.5f); }

float Camera::worldPerPixel() const { return 2.0f * halfHeightAtTarget() / float(m_size.height()); }

void Camera::pan(float dxPixels, float dyPixels)
{
    // the plane through the target moves with the mouse, pixel for pixel
    const float scale = worldPerPixel();
    m_target += (-dxPixels * right() + dyPixels * up()) * scale;
}

void Camera::zoomAt(const QPointF &pixel, float factor)
{
    // the point under the pixel on the target's plane
    const Ray ray = unproject(pixel);
    const float along = QVector3D::dotProduct(ray.direction, forward());
    if (!(factor > 0.0f) || along <= 0.0f)
        return;
    const QVector3D pivot = ray.at(QVector3D::dotProduct(m_target - ray.origin, forward()) / along);

    // scaling the whole camera about that point leaves the point where it was on screen (the
    // orthographic view's height scales with the distance, so there too)
    const float distance = std::clamp(m_distance * factor, kMinDistance, kMaxDistance);
    const float scale = distance / m_distance;
    m_target = pivot + (m_target - pivot) * scale;
    m_distance = distance;
}

void Camera::frameSphere(const QVector3D &centre, float radius)
{
    m_target = centre;
    frameSphereFromTarget(centre, radius);
}

void Camera::frameSphereFromTarget(const QVector3D &centre, float radius)
{
    // a sphere about the target that holds the given one; the narrower of the two fields of view
    // decides, and a margin keeps it off the edges
    const float halfY = radians(m_fovY) * 0.5f;
    const float halfX = std::atan(std::tan(halfY) * aspect());
    const float half = std::min(halfX, halfY);
    const float r = std::max((centre - m_target).length() + radius, 1.0e-3f);
    // perspective: the eye sees the sphere's outline within the half angle; orthographic: the
    // view's half size at the target holds the sphere's radius
    setDistance(kFrameMargin * r / (orthographic() ? std::tan(half) : std::sin(half)));
}

}  // namespace ui
