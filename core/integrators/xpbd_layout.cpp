#include "core/integrators/xpbd_layout.h"

#include "core/model/model.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdlib>

namespace core {

namespace {

// greedyColours into `colour`, with `ends` and `used` as scratch
void colourGreedily(const Model &model, const std::vector<int> &springs, std::vector<int> &colour,
                    std::vector<int> &ends, std::vector<std::uint64_t> &used)
{
    // the free ends the springs touch, numbered locally, and how many of the springs each has
    ends.clear();
    for (int k : springs)
        for (int end : {model.springA[std::size_t(k)], model.springB[std::size_t(k)]})
            if (!model.isPinned(end))
                ends.push_back(end);
    std::sort(ends.begin(), ends.end());
    int degree = 0;
    for (std::size_t i = 0; i < ends.size();) {
        std::size_t j = i;
        while (j < ends.size() && ends[j] == ends[i])
            ++j;
        degree = std::max(degree, int(j - i));
        i = j;
    }
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    const auto local = [&](int particle) {
        return std::size_t(std::lower_bound(ends.begin(), ends.end(), particle) - ends.begin());
    };
    // each free end's colours as bits, 64 to a word; a spring's colour is at most the number of
    // springs at its two ends, so 2 × the largest degree + 1 colours are enough
    const std::size_t words = std::size_t(2 * degree) / 64 + 1;
    used.assign(ends.size() * words, 0);
    colour.assign(springs.size(), 0);
    for (std::size_t s = 0; s < springs.size(); ++s) {
        const int k = springs[s];
        std::size_t at[2];
        int moving = 0;
        for (int end : {model.springA[std::size_t(k)], model.springB[std::size_t(k)]})
            if (!model.isPinned(end))
                at[moving++] = local(end) * words;
        int c = 0;
        for (std::size_t word = 0; word < words; ++word) {
            std::uint64_t taken = 0;
            for (int e = 0; e < moving; ++e)
                taken |= used[at[e] + word];
            if (~taken != 0) {
                c = int(word) * 64 + std::countr_one(taken);
                break;
            }
        }
        colour[s] = c;
        for (int e = 0; e < moving; ++e)
            used[at[e] + std::size_t(c / 64)] |= std::uint64_t(1) << (c % 64);
    }
}

}  // namespace

std::vector<int> greedyColours(const Model &model, const std::vector<int> &springs)
{
    std::vector<int> colour, ends;
    std::vector<std::uint64_t> used;
    colourGreedily(model, springs, colour, ends, used);
    return colour;
}

namespace {

// one slot appended: spring k with its free end as end a
void addSlot(const Model &model, XpbdLayout &layout, int k)
{
    int a = model.springA[std::size_t(k)];
    int b = model.springB[std::size_t(k)];
    if (model.isPinned(a))
        std::swap(a, b);  // the projection gives the same bits either way round (xpbd.cpp)
    layout.spring.push_back(k);
    layout.a.push_back(a);
    layout.b.push_back(b);
    layout.wa.push_back(model.invMass[a]);
    layout.wb.push_back(model.invMass[b]);
    layout.restLength.push_back(model.restLength[k]);
    layout.stiffness.push_back(model.stiffness[k]);
    layout.damping.push_back(model.damping[k]);
}

// a task from springs (in spring order): its colours, each a batch of the springs with both ends
// free and one of those with one
void addTask(const Model &model, XpbdLayout &layout, const std::vector<int> &springs, XpbdLayoutScratch &scratch)
{
    if (springs.empty())
        return;
    colourGreedily(model, springs, scratch.colour, scratch.ends, scratch.used);
    const std::vector<int> &colour = scratch.colour;
    // batch 2 c: colour c's springs with both ends free; 2 c + 1: those with one; each in spring order
    std::vector<int> &batch = scratch.batch;
    batch.assign(springs.size(), 0);
    int batches = 0;
    for (std::size_t s = 0; s < springs.size(); ++s) {
        const int k = springs[s];
        const bool pinnedEnd = model.isPinned(model.springA[std::size_t(k)]) || model.isPinned(model.springB[std::size_t(k)]);
        batch[s] = 2 * colour[s] + (pinnedEnd ? 1 : 0);
        batches = std::max(batches, batch[s] + 1);
    }
    std::vector<int> &start = scratch.start;
    start.assign(std::size_t(batches) + 1, 0);
    for (int i : batch)
        start[std::size_t(i) + 1] += 1;
    for (int i = 0; i < batches; ++i)
        start[std::size_t(i) + 1] += start[std::size_t(i)];
    std::vector<int> &sorted = scratch.sorted;
    sorted.assign(springs.size(), 0);
    std::vector<int> &fill = scratch.fill;
    fill.assign(start.begin(), start.end() - 1);
    for (std::size_t s = 0; s < springs.size(); ++s)
        sorted[std::size_t(fill[std::size_t(batch[s])]++)] = springs[s];
    for (int i = 0; i < batches; ++i) {
        if (start[std::size_t(i)] == start[std::size_t(i) + 1])
            continue;
        for (int s = start[std::size_t(i)]; s < start[std::size_t(i) + 1]; ++s)
            addSlot(model, layout, sorted[std::size_t(s)]);
        layout.batchStart.push_back(layout.slotCount());
        layout.batchMovesB.push_back(i % 2 == 0 ? 1 : 0);
    }
    layout.taskStart.push_back(layout.batchCount());
}

}  // namespace

void layOutXpbd(const Model &model, const std::vector<std::uint8_t> *broken, XpbdLayout &layout,
                XpbdLayoutScratch &scratch)
{
    static std::atomic<std::uint64_t> made{0};
    layout.id = made.fetch_add(1, std::memory_order_relaxed) + 1;
    for (std::vector<int> *list : {&layout.spring, &layout.a, &layout.b, &layout.batchStart, &layout.taskStart,
                                   &layout.phaseStart})
        list->clear();
    for (std::vector<double> *list : {&layout.wa, &layout.wb, &layout.restLength, &layout.stiffness, &layout.damping})
        list->clear();
    layout.batchMovesB.clear();
    layout.batchStart.push_back(0);
    layout.taskStart.push_back(0);
    layout.phaseStart.push_back(0);
    // each spring to its block, seam or the far list
    const int blocks = (model.particleCount() + kXpbdBlock - 1) / kXpbdBlock;
    scratch.own.resize(static_cast<std::size_t>(blocks));
    scratch.seam.resize(static_cast<std::size_t>(blocks));
    for (std::vector<int> &list : scratch.own)
        list.clear();
    for (std::vector<int> &list : scratch.seam)
        list.clear();
    scratch.far.clear();
    for (int k = 0; k < model.springCount(); ++k) {
        const int a = model.springA[std::size_t(k)];
        const int b = model.springB[std::size_t(k)];
        const bool moveA = !model.isPinned(a);
        const bool moveB = !model.isPinned(b);
        if ((!moveA && !moveB) || !(model.stiffness[k] > 0.0))
            continue;  // nothing to move, or no constraint
        if (broken && (*broken)[std::size_t(k)] != 0)
            continue;  // gone for good
        const int qa = (moveA ? a : b) / kXpbdBlock;
        const int qb = (moveB ? b : a) / kXpbdBlock;
        if (qa == qb)
            scratch.own[std::size_t(qa)].push_back(k);
        else if (std::abs(qa - qb) == 1)
            scratch.seam[std::size_t(std::min(qa, qb))].push_back(k);
        else
            scratch.far.push_back(k);
    }
    const auto endPhase = [&] {
        if (layout.taskCount() > layout.phaseStart.back())
            layout.phaseStart.push_back(layout.taskCount());
    };
    for (const auto &springs : scratch.own)
        addTask(model, layout, springs, scratch);
    endPhase();
    for (int parity : {0, 1}) {
        for (int q = parity; q < blocks; q += 2)
            addTask(model, layout, scratch.seam[std::size_t(q)], scratch);
        endPhase();
    }
    addTask(model, layout, scratch.far, scratch);
    endPhase();
}

XpbdLayout xpbdLayout(const Model &model)
{
    XpbdLayout layout;
    XpbdLayoutScratch scratch;
    layOutXpbd(model, nullptr, layout, scratch);
    return layout;
}

}  // namespace core
