#include "core/springs/spring_layout.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace core {

namespace {

// the runs with an end in each block of kSpringBlock particles, ascending (SpringLayout::blockRuns)
void indexByBlock(const std::vector<SpringRun> &runs, int particles, std::vector<int> &offsets, std::vector<int> &list)
{
    const int blocks = (particles + kSpringBlock - 1) / kSpringBlock;
    std::vector<std::vector<int>> byBlock(static_cast<std::size_t>(blocks));
    for (int r = 0; r < static_cast<int>(runs.size()); ++r) {
        const SpringRun &run = runs[static_cast<std::size_t>(r)];
        for (const int end : {run.a, run.b})
            for (int q = end / kSpringBlock; q <= (end + run.count - 1) / kSpringBlock; ++q) {
                std::vector<int> &blockList = byBlock[static_cast<std::size_t>(q)];
                if (blockList.empty() || blockList.back() != r)
                    blockList.push_back(r);
            }
    }
    offsets.assign(1, 0);
    for (const std::vector<int> &blockList : byBlock) {
        list.insert(list.end(), blockList.begin(), blockList.end());
        offsets.push_back(static_cast<int>(list.size()));
    }
}

// whether springs [first, last) all have spring first's rest length, stiffness and damping, to the bit
bool sameParameters(const SpringList &springs, int first, int last)
{
    const auto same = [&](const Eigen::VectorXd &values) {
        return (values.segment(first, last - first).array() == values[first]).all();
    };
    return same(springs.restLength) && same(springs.stiffness) && same(springs.damping);
}

// the list cut into runs of springs whose ends both step by one, and how far their ends reach
void cutIntoRuns(const SpringList &springs, SpringLayout &layout)
{
    const int count = static_cast<int>(springs.a.size());
    for (int k = 0; k < count;) {
        SpringRun run{k, 1, springs.a[static_cast<std::size_t>(k)], springs.b[static_cast<std::size_t>(k)]};
        while (k + run.count < count && springs.a[static_cast<std::size_t>(k + run.count)] == run.a + run.count &&
               springs.b[static_cast<std::size_t>(k + run.count)] == run.b + run.count)
            ++run.count;
        run.uniform = sameParameters(springs, run.first, run.first + run.count);
        layout.runs.push_back(run);
        layout.reach = std::max(layout.reach, std::abs(run.b - run.a));
        k += run.count;
    }
}

// whether run `next`, which follows `last` in the list, can join it (SpringLayout::JoinedRuns)
bool joins(const SpringRun &last, const SpringRun &next)
{
    const int gap = next.a - (last.a + last.count);
    return last.count < kJoinRunsBelow && next.count < kJoinRunsBelow && next.b - next.a == last.b - last.a &&
           gap >= 0 && gap <= kJoinGap;
}

// SpringLayout::joined, or nothing where no two runs join
void joinShortRuns(const SpringList &springs, SpringLayout &layout)
{
    const std::vector<SpringRun> &runs = layout.runs;
    bool any = false;
    for (std::size_t r = 1; r < runs.size() && !any; ++r)
        any = joins(runs[r - 1], runs[r]);
    if (!any)
        return;
    // the joined runs, each with its springs' place in the padded arrays
    SpringLayout::JoinedRuns &joined = layout.joined;
    std::vector<std::pair<int, int>> pieces;  // (padded index, spring) of each run's first spring
    int padded = 0;
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const SpringRun &run = runs[r];
        if (r > 0 && joins(runs[r - 1], run)) {
            SpringRun &into = joined.runs.back();
            into.count = run.a - into.a + run.count;
            into.uniform = false;  // the padding's parameters are not the springs'
        } else {
            joined.runs.push_back(SpringRun{padded, run.count, run.a, run.b, run.uniform});
        }
        pieces.emplace_back(joined.runs.back().first + (run.a - joined.runs.back().a), run.first);
        padded = joined.runs.back().first + joined.runs.back().count;
    }
    // padding: no rest length, stiffness or damping, so a force of ±0
    joined.restLength.setZero(padded);
    joined.stiffness.setZero(padded);
    joined.damping.setZero(padded);
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const auto [at, spring] = pieces[r];
        joined.restLength.segment(at, runs[r].count) = springs.restLength.segment(spring, runs[r].count);
        joined.stiffness.segment(at, runs[r].count) = springs.stiffness.segment(spring, runs[r].count);
        joined.damping.segment(at, runs[r].count) = springs.damping.segment(spring, runs[r].count);
    }
}

}  // namespace

SpringLayout makeSpringLayout(const SpringList &springs)
{
    SpringLayout layout;
    cutIntoRuns(springs, layout);

    // the pass: by runs when they are 8 springs long or more on average, else gathered
    const int count = static_cast<int>(springs.a.size());
    const bool longRuns = !layout.runs.empty() && count >= 8 * static_cast<int>(layout.runs.size());
    layout.pass = longRuns ? SpringPass::Runs : SpringPass::Gathered;

    // which runs reach into each block of particles, for the fused sub-step, and the short ones
    // joined where no spring can break (a state with broken flags steps by the list's runs)
    layout.blocks = longRuns && layout.reach <= kSpringBlock;
    if (layout.blocks) {
        indexByBlock(layout.runs, springs.particles, layout.blockRunOffsets, layout.blockRuns);
        if (!springs.breakable)
            joinShortRuns(springs, layout);
        if (!layout.joined.runs.empty())
            indexByBlock(layout.joined.runs, springs.particles, layout.joined.blockRunOffsets,
                         layout.joined.blockRuns);
    }
    return layout;
}

}  // namespace core
