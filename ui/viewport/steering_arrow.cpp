#include "steering_arrow.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ui {

namespace {

constexpr float kBarbDegrees = 28.0f;  // between the shaft and each barb

void pushLine(std::vector<float> &out, const QVector3D &a, const QVector3D &b)
{
    for (const QVector3D &p : {a, b})
        out.insert(out.end(), {p.x(), p.y(), p.z(), kSteeringColour[0], kSteeringColour[1], kSteeringColour[2], 1.0f});
}

}  // namespace

std::vector<float> packSteeringArrow(const SteeringArrow &arrow, const core::Snapshot &snapshot, const QVector3D &eye)
{
    std::vector<float> vertices;
    const QVector3D direction = arrow.direction.normalized();
    if (!arrow.visible() || arrow.particle >= snapshot.particleCount() ||
        snapshot.positions.size() < 3 * std::size_t(arrow.particle) + 3 || direction.isNull())
        return vertices;

    // the shaft, from the centre out past the surface in proportion to the push
    const std::size_t i = std::size_t(arrow.particle);
    const QVector3D centre(snapshot.positions[3 * i], snapshot.positions[3 * i + 1], snapshot.positions[3 * i + 2]);
    const float radius = std::max(snapshot.radii[i], 1e-3f);
    const float strength = std::clamp(arrow.strength, 0.0f, 1.0f);
    const float length = radius * (1.0f + SteeringArrow::kArrowRadii * strength);
    const QVector3D tip = centre + length * direction;
    pushLine(vertices, centre, tip);

    // the barbs, in the plane of the shaft that faces the eye (or the vertical one when the eye
    // looks along the shaft)
    QVector3D side = QVector3D::crossProduct(direction, eye - tip);
    if (side.lengthSquared() < 1e-12f * std::max(1.0f, (eye - tip).lengthSquared()))
        side = QVector3D::crossProduct(direction, QVector3D(0.0f, 1.0f, 0.0f));
    if (side.lengthSquared() < 1e-12f)
        side = QVector3D::crossProduct(direction, QVector3D(1.0f, 0.0f, 0.0f));
    side.normalize();
    const float barb = std::min(0.6f * radius, 0.5f * length);
    const float radians = kBarbDegrees * std::numbers::pi_v<float> / 180.0f;
    const QVector3D back = -std::cos(radians) * barb * direction;
    pushLine(vertices, tip, tip + back + std::sin(radians) * barb * side);
    pushLine(vertices, tip, tip + back - std::sin(radians) * barb * side);
    return vertices;
}

}  // namespace ui
