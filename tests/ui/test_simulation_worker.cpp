// SimulationWorker on the test's own thread, every frame it publishes taken as it comes: a frame
// answering a message on a scene whose snapshot is slow to make goes at once with the snapshot
// before it, marked behind, and the snapshot of the state it stopped at follows in the same tick;
// where the snapshot is quick, the answer brings it. A Step on a scene whose steps are slow is
// answered by a frame that owes it before it is taken. A snapshot the window let go is filled
// again for a later frame; one it holds is never touched. Waits are on frames, never fixed sleeps.

#include "ui/simulation/simulation_worker.h"

#include "core/model/generators.h"

#include <QtTest>

#include <memory>
#include <set>
#include <vector>

namespace {

// a 32 × 32 cloth whose steps are slow (5000 sub-steps), so that messages are answered first
std::shared_ptr<const core::SceneDesc> slowCloth()
{
    core::ClothOptions options;
    options.rows = options.cols = 32;
    auto scene = std::make_shared<core::SceneDesc>(core::makeCloth(options));
    scene->settings.timeStep = 0.01;
    scene->settings.substeps = 5000;
    return scene;
}

// the worker with its queues, on this thread, keeping every frame it publishes
struct Worker {
    ui::MessageQueue messages;
    ui::ReplyQueue replies;
    ui::LatestMailbox<ui::SimulationFrame> mailbox;
    ui::SimulationWorker worker{messages, replies, mailbox};
    std::vector<std::shared_ptr<const ui::SimulationFrame>> frames;

    Worker()
    {
        QObject::connect(&worker, &ui::SimulationWorker::frameReady, &worker, [this] {
            while (auto frame = mailbox.take())
                frames.push_back(std::move(frame));
        });
    }

    // sends a message and waits for the first frame that has applied it; its index in frames
    std::optional<std::size_t> send(ui::Message message)
    {
        const std::uint64_t sequence = messages.push(std::move(message));
        ui::SimulationWorker::postWake(&worker);
        std::optional<std::size_t> at;
        (void)QTest::qWaitFor(
            [&] {
                for (std::size_t i = 0; i < frames.size() && !at; ++i)
                    if (frames[i]->appliedMessage >= sequence)
                        at = i;
                return at.has_value();
            },
            30000);
        return at;
    }
};

}  // namespace

class TestSimulationWorker : public QObject {
    Q_OBJECT

private slots:
    void pauseOnASlowSnapshotIsAnsweredBeforeItsPicture();
    void pauseOnAQuickSnapshotBringsIt();
    void stepOnASlowSceneIsAnsweredBeforeItIsTaken();
    void snapshotsLetGoAreFilledAgainOthersKept();
};

void TestSimulationWorker::pauseOnASlowSnapshotIsAnsweredBeforeItsPicture()
{
    // every snapshot counts as slow (the threshold at 0 particles and springs); frames of new steps alone are never due, so the steps run
    // ahead of the snapshot last shown
    Worker w;
    w.worker.setSlowSnapshotElements(0);
    QVERIFY(w.send(ui::SetSceneEdit{slowCloth(), ui::SceneChange::Replace}));
    w.worker.frameIntervalNs().store(std::int64_t(3600) * 1000000000, std::memory_order_relaxed);
    QVERIFY(w.send(ui::Play{}));
    // ticks of the worker's timer: steps taken, none shown
    QVERIFY(QTest::qWaitFor([&] { return w.worker.stepsTaken() >= 2; }, 30000));

    const std::size_t before = w.frames.size();
    const std::optional<std::size_t> answer = w.send(ui::Pause{});
    QVERIFY(answer);
    QVERIFY(*answer >= before);
    const auto &paused = w.frames[*answer];
    QVERIFY(!paused->running);
    QVERIFY(paused->snapshotBehind);
    QVERIFY2(paused->shownStep > paused->snapshot->step, "steps were taken since the last snapshot");
    QCOMPARE(paused->snapshot.get(), w.frames[*answer - 1]->snapshot.get());  // the one before, not a new one

    // the next frame, in the same tick, brings the picture of the step the run stopped at
    QVERIFY(QTest::qWaitFor([&] { return w.frames.size() > *answer + 1; }, 30000));
    const auto &shown = w.frames[*answer + 1];
    QVERIFY(!shown->snapshotBehind);
    QVERIFY(!shown->running);
    QCOMPARE(shown->appliedMessage, paused->appliedMessage);
    QCOMPARE(shown->snapshot->step, paused->shownStep);
    QCOMPARE(shown->shownStep, paused->shownStep);
}

void TestSimulationWorker::pauseOnAQuickSnapshotBringsIt()
{
    // the same run with the threshold as shipped: a 32 × 32 cloth is far below it, so the answer
    // brings the snapshot of the step it stopped at itself
    Worker w;
    QVERIFY(w.send(ui::SetSceneEdit{slowCloth(), ui::SceneChange::Replace}));
    w.worker.frameIntervalNs().store(std::int64_t(3600) * 1000000000, std::memory_order_relaxed);
    QVERIFY(w.send(ui::Play{}));
    QVERIFY(QTest::qWaitFor([&] { return w.worker.stepsTaken() >= 2; }, 30000));
    const std::optional<std::size_t> answer = w.send(ui::Pause{});
    QVERIFY(answer);
    const auto &paused = w.frames[*answer];
    QVERIFY(!paused->running);
    QVERIFY(!paused->snapshotBehind);
    QCOMPARE(paused->snapshot->step, paused->shownStep);
    QVERIFY(paused->shownStep > 0);
}

void TestSimulationWorker::stepOnASlowSceneIsAnsweredBeforeItIsTaken()
{
    // paused after slow steps: a Step is answered by a frame that owes it, at the step shown,
    // and the frame with the step taken follows
    Worker w;
    QVERIFY(w.send(ui::SetSceneEdit{slowCloth(), ui::SceneChange::Replace}));
    QVERIFY(w.send(ui::StepOnce{}));  // the first step, in place: now the steps are known to be slow
    const std::optional<std::size_t> paused = w.send(ui::Pause{});
    QVERIFY(paused);
    const std::uint64_t from = w.frames[*paused]->shownStep;
    QCOMPARE(from, 1u);

    const std::optional<std::size_t> answer = w.send(ui::StepOnce{});
    QVERIFY(answer);
    const auto &owed = w.frames[*answer];
    QCOMPARE(owed->stepsOwed, 1u);
    QCOMPARE(owed->shownStep, from);
    QVERIFY(QTest::qWaitFor([&] { return w.frames.back()->stepsOwed == 0; }, 30000));
    QCOMPARE(w.frames.back()->shownStep, from + 1);
    QCOMPARE(w.frames.back()->snapshot->step, from + 1);
}

void TestSimulationWorker::snapshotsLetGoAreFilledAgainOthersKept()
{
    core::ClothOptions options;
    options.rows = options.cols = 8;
    Worker w;
    QVERIFY(w.send(ui::SetSceneEdit{std::make_shared<core::SceneDesc>(core::makeCloth(options)), ui::SceneChange::Replace}));
    // a frame held all along, as the view holds the one it draws, and a copy of what it showed
    const std::optional<std::size_t> heldAt = w.send(ui::StepOnce{});
    QVERIFY(heldAt);
    const std::shared_ptr<const ui::SimulationFrame> held = w.frames[*heldAt];
    const std::uint64_t heldStep = held->snapshot->step;
    const std::vector<float> heldPositions = held->snapshot->positions;

    // Steps, each frame let go once the next is in: their snapshots' memory goes round a few
    std::set<const float *> memory;
    std::uint64_t step = heldStep;
    for (int i = 0; i < 12; ++i) {
        QVERIFY(w.send(ui::StepOnce{}));
        const std::shared_ptr<const ui::SimulationFrame> frame = w.frames.back();
        QCOMPARE(frame->snapshot->step, ++step);
        memory.insert(frame->snapshot->positions.data());
        w.frames = {frame};
    }
    QCOMPARE_LE(memory.size(), std::size_t(3));
    // the held one is as it was
    QCOMPARE(held->snapshot->step, heldStep);
    QCOMPARE(held->snapshot->positions, heldPositions);
    QVERIFY(!memory.count(held->snapshot->positions.data()));
}

QTEST_GUILESS_MAIN(TestSimulationWorker)
#include "test_simulation_worker.moc"
