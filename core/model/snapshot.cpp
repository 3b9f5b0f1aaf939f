#include "core/model/snapshot.h"

namespace core {

std::shared_ptr<const Snapshot> makeSnapshot(const Model &model, const State &state, const std::optional<Blowup> &blowup)
{
    auto snapshot = std::make_shared<Snapshot>();
    snapshot->step = state.step;
    snapshot->time = state.time;

    // particles
    const int n = model.particleCount();
    snapshot->positions.resize(3 * static_cast<std::size_t>(n));
    snapshot->velocities.resize(3 * static_cast<std::size_t>(n));
    snapshot->radii.resize(static_cast<std::size_t>(n));
    snapshot->pinned.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const auto at = static_cast<std::size_t>(i);
        for (int axis = 0; axis < 3; ++axis) {
            snapshot->positions[3 * at + static_cast<std::size_t>(axis)] = static_cast<float>(state.position(axis, i));
            snapshot->velocities[3 * at + static_cast<std::size_t>(axis)] = static_cast<float>(state.velocity(axis, i));
        }
        snapshot->radii[at] = static_cast<float>(model.radius[i]);
        snapshot->pinned[at] = model.isPinned(i) ? 1 : 0;
    }

    if (state.orientation.cols() == n) {
        snapshot->orientations.resize(4 * static_cast<std::size_t>(n));
        snapshot->angularVelocities.resize(3 * static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < 4; ++k) {
                snapshot->orientations[4 * std::size_t(i) + std::size_t(k)] = static_cast<float>(state.orientation(k, i));
                if (k < 3)
                    snapshot->angularVelocities[3 * std::size_t(i) + std::size_t(k)] =
                        static_cast<float>(state.angularVelocity(k, i));
            }
    }

    // springs: both ends, and the strain that colours them
    const int springs = model.springCount();
    snapshot->springEnds.resize(6 * static_cast<std::size_t>(springs));
    snapshot->springStrain.resize(static_cast<std::size_t>(springs));
    for (int k = 0; k < springs; ++k) {
        const auto at = static_cast<std::size_t>(k);
        const auto a = state.position.col(model.springA[at]);
        const auto b = state.position.col(model.springB[at]);
        for (int axis = 0; axis < 3; ++axis) {
            snapshot->springEnds[6 * at + static_cast<std::size_t>(axis)] = static_cast<float>(a[axis]);
            snapshot->springEnds[6 * at + 3 + static_cast<std::size_t>(axis)] = static_cast<float>(b[axis]);
        }
        const double rest = model.restLength[k];
        snapshot->springStrain[at] = rest > 0.0 ? static_cast<float>(((a - b).norm() - rest) / rest) : 0.0f;
    }

    snapshot->springBroken = state.springBroken;
    snapshot->breakCount = state.breaks.size();
    snapshot->triangles = model.triangles;
    if (model.embedded) {
        snapshot->embedded = model.embedded;
        embeddedPositions(*model.embedded, state.position, snapshot->embeddedPositions);
    }

    // diagnostics
    snapshot->energies = energies(model, state);
    snapshot->momentum = momentum(model, state);
    snapshot->blowup = blowup;
    return snapshot;
}

}  // namespace core
