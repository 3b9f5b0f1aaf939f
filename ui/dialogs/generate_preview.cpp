#include "generate_preview.h"

#include "ui/viewport/render_data.h"

#include <QPaintEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ui {

namespace {

// the most particles and springs one paint draws; beyond, every k-th
constexpr std::size_t kMostDrawn = 20000;
// the receding axis: depth drawn at half scale, 30° above the horizontal
constexpr double kDepthScale = 0.5;
constexpr double kDepthAngle = 0.5235987755982988;  // rad
constexpr int kMargin = 8;  // px

QColor colour(const Rgb &rgb)
{
    return QColor::fromRgbF(rgb[0], rgb[1], rgb[2]);
}

// how much of its colour the farthest particle keeps; the rest is the background's
constexpr double kFarShade = 0.4;

// rgb blended with the background: share 1 is rgb itself
QColor shaded(const Rgb &rgb, double share)
{
    Rgb mixed;
    for (std::size_t c = 0; c < 3; ++c)
        mixed[c] = float(share * rgb[c] + (1.0 - share) * kBackgroundColour[c]);
    return colour(mixed);
}

// a point in the oblique projection, y up; +z comes towards the viewer (as in the viewport's first
// view), so -z recedes up and to the right
QPointF oblique(const Eigen::Vector3d &p)
{
    const double depth = -p.z();
    return {p.x() + kDepthScale * std::cos(kDepthAngle) * depth, p.y() + kDepthScale * std::sin(kDepthAngle) * depth};
}

// every k-th of count, k the least that keeps it to kMostDrawn
std::size_t strideFor(std::size_t count)
{
    return std::max<std::size_t>(1, (count + kMostDrawn - 1) / kMostDrawn);
}

}  // namespace

GeneratePreview::GeneratePreview(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("generatePreview"));
    setMinimumSize(220, 180);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

QSize GeneratePreview::sizeHint() const
{
    return {320, 260};
}

void GeneratePreview::setScene(std::shared_ptr<const core::SceneDesc> scene)
{
    m_scene = std::move(scene);
    update();
}

void GeneratePreview::paintEvent(QPaintEvent *)
{
    ++m_paints;
    m_drawnParticles = 0;
    m_drawnSprings = 0;
    QPainter painter(this);
    painter.fillRect(rect(), colour(kBackgroundColour));
    if (!m_scene || m_scene->particles.empty())
        return;
    const std::vector<core::ParticleDesc> &particles = m_scene->particles;

    // the projected box of the particles (with their radii), fitted to the widget, y up
    std::vector<QPointF> at;
    at.reserve(particles.size());
    double left = 1e300, right = -1e300, bottom = 1e300, top = -1e300;
    for (const core::ParticleDesc &p : particles) {
        at.push_back(oblique(p.position));
        left = std::min(left, at.back().x() - p.radius);
        right = std::max(right, at.back().x() + p.radius);
        bottom = std::min(bottom, at.back().y() - p.radius);
        top = std::max(top, at.back().y() + p.radius);
    }
    const double width = std::max(right - left, 1e-9);
    const double height = std::max(top - bottom, 1e-9);
    const double scale = std::min((this->width() - 2 * kMargin) / width, (this->height() - 2 * kMargin) / height);
    const QPointF middle(0.5 * (left + right), 0.5 * (bottom + top));
    const QPointF centre(0.5 * this->width(), 0.5 * this->height());
    for (QPointF &point : at)
        point = centre + QPointF(point.x() - middle.x(), middle.y() - point.y()) * scale;
    painter.setRenderHint(QPainter::Antialiasing);

    // springs under the particles
    const std::vector<core::SpringDesc> &springs = m_scene->springs;
    std::vector<QLineF> lines;
    const std::size_t springStride = strideFor(springs.size());
    for (std::size_t s = 0; s < springs.size(); s += springStride)
        lines.emplace_back(at[std::size_t(springs[s].a)], at[std::size_t(springs[s].b)]);
    painter.setPen(QPen(colour(kRestColour), 1.0));
    painter.drawLines(lines.data(), int(lines.size()));
    m_drawnSprings = int(lines.size());

    // particles as discs to scale, at least a pixel and a half across, the far ones first
    const std::size_t particleStride = strideFor(particles.size());
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < particles.size(); i += particleStride)
        order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return particles[a].position.z() < particles[b].position.z();
    });
    // the far ones fade towards the background, so that the front of a ball reads from its back
    const double nearest = order.empty() ? 0.0 : particles[order.back()].position.z();
    const double depth = order.empty() ? 0.0 : nearest - particles[order.front()].position.z();
    painter.setPen(Qt::NoPen);
    for (std::size_t i : order) {
        const double r = std::max(0.75, particles[i].radius * scale);
        const double near = depth > 0.0 ? 1.0 - (nearest - particles[i].position.z()) / depth : 1.0;
        painter.setBrush(shaded(particles[i].pinned ? kPinnedColour : kFreeColour, kFarShade + (1.0 - kFarShade) * near));
        painter.drawEllipse(at[i], r, r);
        ++m_drawnParticles;
    }
}

}  // namespace ui
