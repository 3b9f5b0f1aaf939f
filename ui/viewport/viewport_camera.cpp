// Viewport's camera views, as the View menu asks for them: the presets along the axes, the
// projection, and the target following the selection while the run plays.

#include "viewport.h"

#include <cmath>

namespace ui {

namespace {

// the mean position of the selected particles the snapshot holds, leaving out any that are not
// finite; none when no such particle is selected
std::optional<QVector3D> centroidOf(const core::Snapshot &snapshot, const std::vector<int> &selection)
{
    const int n = std::min<int>(snapshot.particleCount(), int(snapshot.positions.size() / 3));
    QVector3D sum;
    int count = 0;
    for (const int i : selection) {
        if (i < 0 || i >= n)
            continue;
        const float *p = snapshot.positions.data() + 3 * std::size_t(i);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            continue;
        sum += QVector3D(p[0], p[1], p[2]);
        ++count;
    }
    if (count == 0)
        return std::nullopt;
    return sum / float(count);
}

}  // namespace

Sphere Viewport::particleExtent() const
{
    Sphere bounds{QVector3D(0.0f, 0.0f, 0.0f), 1.0f};
    if (m_snapshot && m_snapshot->particleCount() > 0)
        bounds = particleBounds(*m_snapshot);
    if (!(bounds.radius > 0.0f))
        bounds.radius = 1.0f;
    return bounds;
}

void Viewport::viewAlong(ViewPreset preset)
{
    m_camera.setViewportSize(size());
    m_camera.lookAlong(preset);
    if (preset == ViewPreset::Default) {
        frameAll();
        return;
    }
    // the target stays, so that what the user was looking at stays in the middle
    const Sphere bounds = particleExtent();
    updateSceneBounds(bounds);
    const Sphere framed = withEnclosedFloors(m_planes, bounds);
    m_camera.frameSphereFromTarget(framed.centre, framed.radius);
    m_framed = true;
    m_autoFramed = false;
    update();
}

void Viewport::setProjection(Projection projection)
{
    m_camera.setProjection(projection);
    update();
}

void Viewport::setFollowSelection(bool on)
{
    m_followSelection = on;
    followSelection();
}

void Viewport::followSelection()
{
    if (!m_followSelection || !m_snapshot)
        return;
    if (const std::optional<QVector3D> centroid = centroidOf(*m_snapshot, m_selection)) {
        m_camera.setTarget(*centroid);
        m_autoFramed = false;
        update();
    }
}

bool Viewport::particlesInView(const std::vector<int> &particles) const
{
    if (!m_snapshot)
        return false;
    const core::Snapshot &s = *m_snapshot;
    const int n = std::min<int>(s.particleCount(), int(s.positions.size() / 3));
    for (const int i : particles) {
        if (i < 0 || i >= n)
            return false;
        const float *p = s.positions.data() + 3 * std::size_t(i);
        const float r = std::size_t(i) < s.radii.size() ? s.radii[std::size_t(i)] : 0.0f;
        if (!m_camera.sphereInView(QVector3D(p[0], p[1], p[2]), r))
            return false;
    }
    return true;
}

}  // namespace ui
