#include "colour_xpbd.h"

#include "core/parallel.h"
#include "core/passes.h"
#include "core/integrators/xpbd_layout.h"

#include <numeric>

namespace bench {

ColourXpbd colourXpbd(const core::Model &model)
{
    std::vector<int> springs(std::size_t(model.springCount()));
    std::iota(springs.begin(), springs.end(), 0);
    const std::vector<int> colour = core::greedyColours(model, springs);
    ColourXpbd out;
    int colours = 0;
    for (int c : colour)
        colours = std::max(colours, c + 1);
    out.colourStart.assign(std::size_t(colours) + 1, 0);
    for (int c : colour)
        out.colourStart[std::size_t(c) + 1] += 1;
    for (int c = 0; c < colours; ++c)
        out.colourStart[std::size_t(c) + 1] += out.colourStart[std::size_t(c)];
    std::vector<int> fill(out.colourStart.begin(), out.colourStart.end() - 1);
    out.order.resize(springs.size());
    for (std::size_t k = 0; k < springs.size(); ++k)
        out.order[std::size_t(fill[std::size_t(colour[k])]++)] = int(k);
    return out;
}

namespace {

void project(const core::Model &model, const core::State &state, const Eigen::Matrix3Xd &start, Eigen::Matrix3Xd &x,
             int k, double h)
{
    if (state.isBroken(k))
        return;
    const int a = model.springA[std::size_t(k)];
    const int b = model.springB[std::size_t(k)];
    const double wa = model.invMass[a];
    const double wb = model.invMass[b];
    const double stiffness = model.stiffness[k];
    if (!(wa + wb > 0.0) || !(stiffness > 0.0))
        return;
    const Eigen::Vector3d d = x.col(a) - x.col(b);
    const double length = d.norm();
    if (!(length > 0.0))
        return;
    const Eigen::Vector3d n = d / length;
    const double compliance = 1.0 / (stiffness * h * h);
    const double gamma = model.damping[k] / (stiffness * h);
    const double closing = n.dot((x.col(a) - start.col(a)) - (x.col(b) - start.col(b)));
    const double lambda =
        (-(length - model.restLength[k]) - gamma * closing) / ((1.0 + gamma) * (wa + wb) + compliance);
    x.col(a) += (wa * lambda) * n;
    x.col(b) -= (wb * lambda) * n;
}

}  // namespace

void colourXpbdSubStep(const core::Model &model, const ColourXpbd &colours, core::State &state,
                       core::Workspace &work, double h)
{
    Eigen::Matrix3Xd &start = core::scratch(state, work, 0);
    core::computeExternalForces(model, state, work);
    for (int i : model.freeParticles) {
        const double w = model.invMass[i];
        state.velocity.col(i) = (state.velocity.col(i) + (h * w) * work.force.col(i)) / (1.0 + h * model.viscosity * w);
    }
    start = state.position;
    state.position += h * state.velocity;
    for (std::size_t c = 0; c + 1 < colours.colourStart.size(); ++c) {
        const int first = colours.colourStart[c];
        const int count = colours.colourStart[c + 1] - first;
        core::parallelChunks(count, [&](int begin, int end) {
            for (int s = begin; s < end; ++s)
                project(model, state, start, state.position, colours.order[std::size_t(first + s)], h);
        });
    }
    const double perSecond = 1.0 / h;
    for (int i : model.freeParticles)
        state.velocity.col(i) = (state.position.col(i) - start.col(i)) * perSecond;
}

}  // namespace bench
