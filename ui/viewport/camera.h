#pragma once
// Camera: the viewport's orbit camera, as plain maths with no GL, so that it can be unit-tested and
// so that picking can share it. It orbits a target point at some distance, with y up; pixels are
// the widget's logical pixels, origin at the top left, y down, pixel centres at +0.5.
// In orthographic projection the view is as tall as the perspective one is at the target's depth,
// so that switching keeps the target's plane the same size on screen, and the distance still zooms;
// its rays are parallel, starting on the near plane, which lies behind the eye when the eye has
// moved into the scene, so that zooming in never cuts the scene.

#include <QMatrix4x4>
#include <QPointF>
#include <QSize>
#include <QVector3D>

#include <optional>

namespace ui {

// a half-line from the eye through a pixel
struct Ray {
    QVector3D origin;
    QVector3D direction;  // unit length
    QVector3D at(float t) const { return origin + t * direction; }
};

// the standard directions to look along; Default is the view a scene opens with
enum class ViewPreset {
    Top,    // along -y: x to the right, -z up the screen
    Front,  // along -z: x to the right, y up
    Side,   // along -x: -z to the right, y up
    Default,
};

enum class Projection { Perspective, Orthographic };

class Camera {
public:
    // the viewport in logical pixels (at least 1×1)
    void setViewportSize(QSize size);
    QSize viewportSize() const { return m_size; }
    float aspect() const;

    // vertical field of view, degrees
    void setFieldOfView(float degrees);
    float fieldOfView() const { return m_fovY; }

    // the orbit parameters: the point looked at, the eye's distance from it (m), the angles (degrees)
    QVector3D target() const { return m_target; }
    float distance() const { return m_distance; }
    float yaw() const { return m_yaw; }
    float pitch() const { return m_pitch; }
    void setTarget(const QVector3D &target) { m_target = target; }
    void setDistance(float distance);
    void setAngles(float yawDegrees, float pitchDegrees);
    // the angles of a preset, keeping the target and the distance
    void lookAlong(ViewPreset preset);

    void setProjection(Projection projection) { m_projection = projection; }
    Projection projection() const { return m_projection; }
    bool orthographic() const { return m_projection == Projection::Orthographic; }

    // the eye and its basis: forward points from the eye to the target
    QVector3D eye() const;
    QVector3D forward() const;
    QVector3D right() const;
    QVector3D up() const;

    // the scene's bounding sphere: sets the clip planes so that the scene is never cut
    void setSceneBounds(const QVector3D &centre, float radius);
    float nearPlane() const;
    float farPlane() const;

    QMatrix4x4 viewMatrix() const;
    QMatrix4x4 projectionMatrix() const;
    QMatrix4x4 viewProjectionMatrix() const { return projectionMatrix() * viewMatrix(); }

    // the pixel a world point lands on; none when it is behind the eye (orthographic: behind the
    // near plane)
    std::optional<QPointF> project(const QVector3D &world) const;
    // the ray from the eye through a pixel (pixels outside the viewport are fine); orthographic:
    // along forward() from the pixel's point on the near plane
    Ray unproject(const QPointF &pixel) const;
    // whether all of the sphere is inside the view: within its four edges and between the clip planes
    bool sphereInView(const QVector3D &centre, float radius) const;

    // mouse gestures, in pixels moved: orbit about the target, pan so the target plane follows
    void orbit(float dxPixels, float dyPixels);
    void pan(float dxPixels, float dyPixels);
    // factor < 1 zooms in; the point under the pixel, on the plane through the target facing the
    // eye, stays under the pixel
    void zoomAt(const QPointF &pixel, float factor);

    // looks at the sphere from the current direction, near enough that all of it is in view
    void frameSphere(const QVector3D &centre, float radius);
    // keeps the target and the direction, and moves the eye just far enough that the sphere is
    // in view
    void frameSphereFromTarget(const QVector3D &centre, float radius);

    // the world size of one pixel at the target's depth (orthographic: at every depth)
    float worldPerPixel() const;
    // half the view's height at the target's depth, m (orthographic: the view's half height)
    float halfHeightAtTarget() const;

    static constexpr float kDefaultYaw = 35.0f;    // degrees, from +z towards +x
    static constexpr float kDefaultPitch = 25.0f;  // degrees above the horizon
    static constexpr float kOrbitDegreesPerPixel = 0.4f;
    static constexpr float kMinDistance = 1.0e-4f;  // m
    static constexpr float kMaxDistance = 1.0e6f;   // m

private:
    QSize m_size{1, 1};
    float m_fovY = 45.0f;
    QVector3D m_target{0.0f, 0.0f, 0.0f};
    float m_distance = 5.0f;
    float m_yaw = kDefaultYaw;
    float m_pitch = kDefaultPitch;
    Projection m_projection = Projection::Perspective;
    QVector3D m_sceneCentre{0.0f, 0.0f, 0.0f};
    float m_sceneRadius = 1.0f;
};

}  // namespace ui
