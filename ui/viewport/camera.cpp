#include "camera.h"

#include <QVector4D>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ui {

namespace {

constexpr float kWorldUpY = 1.0f;
constexpr float kMaxPitch = 89.0f;  // degrees: looking straight down would lose the up vector

float radians(float degrees) { return degrees * std::numbers::pi_v<float> / 180.0f; }

}  // namespace

void Camera::setViewportSize(QSize size) { m_size = QSize(std::max(1, size.width()), std::max(1, size.height())); }

float Camera::aspect() const { return float(m_size.width()) / float(m_size.height()); }

void Camera::setFieldOfView(float degrees) { m_fovY = std::clamp(degrees, 1.0f, 170.0f); }

void Camera::setDistance(float distance) { m_distance = std::clamp(distance, kMinDistance, kMaxDistance); }

void Camera::setAngles(float yawDegrees, float pitchDegrees)
{
    // yaw wraps into (-180, 180]; pitch stops short of the poles
    m_yaw = std::remainder(yawDegrees, 360.0f);
    m_pitch = std::clamp(pitchDegrees, -kMaxPitch, kMaxPitch);
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
    return QVector3D::crossProduct(forward(), QVector3D(0.0f, kWorldUpY, 0.0f)).normalized();
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
    return std::max(farPlane() * 1.0e-5f, m_distance * 0.02f);
}

QMatrix4x4 Camera::viewMatrix() const
{
    QMatrix4x4 view;
    view.lookAt(eye(), m_target, QVector3D(0.0f, kWorldUpY, 0.0f));
    return view;
}

QMatrix4x4 Camera::projectionMatrix() const
{
    QMatrix4x4 projection;
    projection.perspective(m_fovY, aspect(), nearPlane(), farPlane());
    return projection;
}

std::optional<QPointF> Camera::project(const QVector3D &world) const
{
    // clip space, then normalised device coordinates, then pixels with y down
    const QVector4D clip = viewProjectionMatrix() * QVector4D(world, 1.0f);
    if (clip.w() <= 0.0f)
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
    const float tanHalf = std::tan(radians(m_fovY) * 0.5f);
    const QVector3D direction = forward() + right() * (x * tanHalf * aspect()) + up() * (y * tanHalf);
    return Ray{eye(), direction.normalized()};
}

void Camera::orbit(float dxPixels, float dyPixels)
{
    // the scene follows the mouse as if grabbed: dragging right turns it to the right
    setAngles(m_yaw - dxPixels * kOrbitDegreesPerPixel, m_pitch + dyPixels * kOrbitDegreesPerPixel);
}

float Camera::worldPerPixel() const
{
    return 2.0f * m_distance * std::tan(radians(m_fovY) * 0.5f) / float(m_size.height());
}

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
    const QVector3D pivot = ray.at(m_distance / along);

    // scaling the whole camera about that point leaves the point where it was on screen
    const float distance = std::clamp(m_distance * factor, kMinDistance, kMaxDistance);
    const float scale = distance / m_distance;
    m_target = pivot + (m_target - pivot) * scale;
    m_distance = distance;
}

void Camera::frameSphere(const QVector3D &centre, float radius)
{
    // the narrower of the two fields of view decides; a margin keeps the sphere off the edges
    constexpr float kMargin = 1.1f;
    const float halfY = radians(m_fovY) * 0.5f;
    const float halfX = std::atan(std::tan(halfY) * aspect());
    const float half = std::min(halfX, halfY);
    const float r = std::max(radius, 1.0e-3f);
    m_target = centre;
    setDistance(kMargin * r / std::sin(half));
}

}  // namespace ui
