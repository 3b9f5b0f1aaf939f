#include "core/model/snapshot.h"

namespace core {

std::shared_ptr<const Snapshot> makeSnapshot(const Model &model, const State &state, const std::optional<Blowup> &blowup)
{
    auto snapshot = std::make_shared<Snapshot>();
    fillSnapshot(*snapshot, model, state, blowup);
    return snapshot;
}

void fillSnapshot(Snapshot &into, const Model &model, const State &state, const std::optional<Blowup> &blowup)
{
    // a fresh snapshot, so that nothing of the old one's values stays, given the old one's
    // arrays that are filled whole below (the others start empty, as they would)
    Snapshot fresh;
    fresh.positions = std::move(into.positions);
    fresh.velocities = std::move(into.velocities);
    fresh.radii = std::move(into.radii);
    fresh.pinned = std::move(into.pinned);
    fresh.springEnds = std::move(into.springEnds);
    fresh.springStrain = std::move(into.springStrain);
    fresh.springBroken = std::move(into.springBroken);
    fresh.step = state.step;
    fresh.time = state.time;

    // particles
    const int n = model.particleCount();
    fresh.positions.resize(3 * static_cast<std::size_t>(n));
    fresh.velocities.resize(3 * static_cast<std::size_t>(n));
    fresh.radii.resize(static_cast<std::size_t>(n));
    fresh.pinned.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const auto at = static_cast<std::size_t>(i);
        for (int axis = 0; axis < 3; ++axis) {
            fresh.positions[3 * at + static_cast<std::size_t>(axis)] = static_cast<float>(state.position(axis, i));
            fresh.velocities[3 * at + static_cast<std::size_t>(axis)] = static_cast<float>(state.velocity(axis, i));
        }
        fresh.radii[at] = static_cast<float>(model.radius[i]);
        fresh.pinned[at] = model.isPinned(i) ? 1 : 0;
    }

    if (state.orientation.cols() == n) {
        fresh.orientations.resize(4 * static_cast<std::size_t>(n));
        fresh.angularVelocities.resize(3 * static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < 4; ++k) {
                fresh.orientations[4 * std::size_t(i) + std::size_t(k)] = static_cast<float>(state.orientation(k, i));
                if (k < 3)
                    fresh.angularVelocities[3 * std::size_t(i) + std::size_t(k)] =
                        static_cast<float>(state.angularVelocity(k, i));
            }
    }

    // springs: both ends, and the strain that colours them
    const int springs = model.springCount();
    fresh.springEnds.resize(6 * static_cast<std::size_t>(springs));
    fresh.springStrain.resize(static_cast<std::size_t>(springs));
    for (int k = 0; k < springs; ++k) {
        const auto at = static_cast<std::size_t>(k);
        const auto a = state.position.col(model.springA[at]);
        const auto b = state.position.col(model.springB[at]);
        for (int axis = 0; axis < 3; ++axis) {
            fresh.springEnds[6 * at + static_cast<std::size_t>(axis)] = static_cast<float>(a[axis]);
            fresh.springEnds[6 * at + 3 + static_cast<std::size_t>(axis)] = static_cast<float>(b[axis]);
        }
        const double rest = model.restLength[k];
        fresh.springStrain[at] = rest > 0.0 ? static_cast<float>(((a - b).norm() - rest) / rest) : 0.0f;
    }

    fresh.springBroken = state.springBroken;
    fresh.breakCount = state.breaks.size();
    fresh.triangles = model.triangles;
    if (model.embedded) {
        fresh.embedded = model.embedded;
        embeddedPositions(*model.embedded, state.position, fresh.embeddedPositions);
    }

    // diagnostics
    fresh.energies = energies(model, state);
    fresh.momentum = momentum(model, state);
    fresh.blowup = blowup;
    into = std::move(fresh);
}

}  // namespace core
