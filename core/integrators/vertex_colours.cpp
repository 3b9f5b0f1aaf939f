#include "core/integrators/vertex_colours.h"

#include "core/model/model.h"

#include <algorithm>

namespace core {

void colourVertices(const Model &model, std::vector<int> &order, std::vector<int> &colours)
{
    colourVertices(model, {}, order, colours);
}

void colourVertices(const Model &model, const std::vector<std::uint8_t> &broken, std::vector<int> &order,
                    std::vector<int> &colours)
{
    const int n = model.particleCount();
    std::vector<int> colour(static_cast<std::size_t>(n), -1);
    std::vector<int> takenBy;  // takenBy[c] == i: colour c is a neighbour's of particle i
    int count = 0;
    for (int i = 0; i < n; ++i) {
        if (model.isPinned(i))
            continue;
        for (int e = model.springOffsets[static_cast<std::size_t>(i)];
             e < model.springOffsets[static_cast<std::size_t>(i) + 1]; ++e) {
            const int end = model.springEnds[static_cast<std::size_t>(e)];
            const auto k = static_cast<std::size_t>(end / 2);
            if (!broken.empty() && broken[k] != 0)
                continue;
            const int other = end % 2 == 0 ? model.springB[k] : model.springA[k];
            const int c = colour[static_cast<std::size_t>(other)];
            if (c >= 0)
                takenBy[static_cast<std::size_t>(c)] = i;
        }
        int c = 0;
        while (c < count && takenBy[static_cast<std::size_t>(c)] == i)
            ++c;
        if (c == count) {
            takenBy.push_back(-1);
            ++count;
        }
        colour[static_cast<std::size_t>(i)] = c;
    }
    // counting sort by colour, ascending index within one
    colours.assign(static_cast<std::size_t>(count) + 1, 0);
    for (int i = 0; i < n; ++i)
        if (colour[static_cast<std::size_t>(i)] >= 0)
            colours[static_cast<std::size_t>(colour[static_cast<std::size_t>(i)]) + 1] += 1;
    for (int c = 0; c < count; ++c)
        colours[static_cast<std::size_t>(c) + 1] += colours[static_cast<std::size_t>(c)];
    order.assign(static_cast<std::size_t>(colours.back()), 0);
    std::vector<int> next(colours.begin(), colours.end() - 1);
    for (int i = 0; i < n; ++i)
        if (const int c = colour[static_cast<std::size_t>(i)]; c >= 0)
            order[static_cast<std::size_t>(next[static_cast<std::size_t>(c)]++)] = i;
}

}  // namespace core
