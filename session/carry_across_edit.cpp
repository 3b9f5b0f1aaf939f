#include "carry_across_edit.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace ui {

namespace {

// the same two ends: the same spring, whatever its values
bool sameEnds(const core::SpringDesc &x, const core::SpringDesc &y)
{
    return x.a == y.a && x.b == y.b;
}

}  // namespace

bool sameStructure(const core::SceneDesc &a, const core::SceneDesc &b)
{
    return a.particles == b.particles && a.planes == b.planes &&
           std::equal(a.springs.begin(), a.springs.end(), b.springs.begin(), b.springs.end(), sameEnds);
}

bool carryAcrossEdit(const core::SceneDesc *previous, const core::SceneDesc &scene, const core::Model &model,
                     SceneChange change, core::State &state)
{
    // each kind of edit carries what it can, else falls to the next, which carries less
    const bool sameCount = previous && scene.particles.size() == previous->particles.size();
    switch (change) {
    case SceneChange::InitialConditions:
        // the run goes on as it is; its broken springs follow the spring list
        if (sameCount) {
            carryBrokenSprings(*previous, scene, model, state);
            core::fitSpin(model, state);
            return true;
        }
        [[fallthrough]];
    case SceneChange::Parameters:
        // same particles: the state stays valid as it is, broken springs included
        if (sameCount) {
            core::fitSpringBreaks(model, state);
            core::fitSpin(model, state);
            return true;
        }
        [[fallthrough]];
    case SceneChange::Structure:
        if (previous && state.position.cols() == static_cast<Eigen::Index>(previous->particles.size())) {
            state = carryMotion(*previous, scene, model, state);
            return true;
        }
        [[fallthrough]];
    case SceneChange::Replace:
        break;
    }
    return false;
}

core::State carryMotion(const core::SceneDesc &previous, const core::SceneDesc &scene, const core::Model &model,
                        const core::State &state)
{
    // each new particle's old self, found by walking both lists in step
    const auto &before = previous.particles;
    const auto &after = scene.particles;
    core::State rebuilt = core::makeState(model, scene);
    std::size_t next = 0;
    for (std::size_t i = 0; i < after.size(); ++i) {
        std::size_t from = before.size();
        if (before.size() == after.size()) {
            from = before[i] == after[i] ? i : before.size();
        } else {
            std::size_t k = next;
            while (k < before.size() && !(before[k] == after[i]))
                ++k;
            if (k < before.size()) {
                from = k;
                next = k + 1;
            }
        }
        if (from >= before.size() || after[i].pinned)
            continue;
        const auto col = static_cast<Eigen::Index>(i);
        const auto old = static_cast<Eigen::Index>(from);
        rebuilt.position.col(col) = state.position.col(old);
        rebuilt.velocity.col(col) = state.velocity.col(old);
        if (rebuilt.angularVelocity.cols() > 0 && state.angularVelocity.cols() == state.position.cols()) {
            rebuilt.angularVelocity.col(col) = state.angularVelocity.col(old);
            rebuilt.orientation.col(col) = state.orientation.col(old);
        }
    }
    // springs broken in the run stay broken while the spring list is the same
    const bool sameSprings = !state.springBroken.empty() && rebuilt.springBroken.size() == state.springBroken.size() &&
                             std::equal(previous.springs.begin(), previous.springs.end(), scene.springs.begin(),
                                        scene.springs.end(), sameEnds);
    if (sameSprings) {
        rebuilt.springBroken = state.springBroken;
        rebuilt.breaks = state.breaks;
        core::fitSpringBreaks(model, rebuilt);  // the capacity for every break again
    }
    rebuilt.time = state.time;
    rebuilt.step = state.step;
    return rebuilt;
}

void carryBrokenSprings(const core::SceneDesc &previous, const core::SceneDesc &scene, const core::Model &model,
                        core::State &state)
{
    const auto &before = previous.springs;
    const auto &after = scene.springs;
    if (before.size() == after.size()) {
        core::fitSpringBreaks(model, state);
        return;
    }
    // each spring of the shorter list in the longer
    const bool fewer = after.size() < before.size();
    const auto &shorter = fewer ? after : before;
    const auto &longer = fewer ? before : after;
    std::vector<std::size_t> partner(shorter.size());
    std::size_t k = 0;
    for (std::size_t j = 0; j < shorter.size(); ++j) {
        while (k < longer.size() && !(longer[k] == shorter[j]))
            ++k;
        partner[j] = std::min(k, longer.size() - 1);
        ++k;
    }
    // the flags in the new list's order: a spring only the longer new list has broke in this run
    std::vector<std::uint8_t> broken(after.size(), fewer ? 0 : 1);
    std::vector<int> newIndex(before.size(), -1);  // each old spring's index in the new list
    for (std::size_t j = 0; j < shorter.size(); ++j) {
        const std::size_t oldIndex = fewer ? partner[j] : j;
        const std::size_t index = fewer ? j : partner[j];
        broken[index] = state.isBroken(static_cast<int>(oldIndex)) ? 1 : 0;
        newIndex[oldIndex] = static_cast<int>(index);
    }
    // the break log, renumbered; a spring left out leaves it
    std::vector<core::SpringBreak> breaks;
    for (core::SpringBreak b : state.breaks)
        if (newIndex[static_cast<std::size_t>(b.spring)] >= 0) {
            b.spring = newIndex[static_cast<std::size_t>(b.spring)];
            breaks.push_back(b);
        }
    const bool any = std::find(broken.begin(), broken.end(), std::uint8_t(1)) != broken.end();
    state.springBroken = any || model.plan.springBreaks ? std::move(broken) : std::vector<std::uint8_t>{};
    state.breaks = std::move(breaks);
    core::fitSpringBreaks(model, state);  // the capacity for every break
}

}  // namespace ui
