// The edit queue: edits come out in the order they went in, numbered, none lost under
// concurrent pushes.

#include "session/edit_queue.h"

#include <QtTest>
#include <thread>

class TestEditQueue : public QObject {
    Q_OBJECT

private slots:
    void numbersEditsInOrder();
    void drainEmptiesTheQueue();
    void keepsEachThreadsOrderUnderConcurrentPushes();
};

void TestEditQueue::numbersEditsInOrder()
{
    ui::EditQueue queue;
    QCOMPARE(queue.push(ui::PlayEdit{}), 1u);
    QCOMPARE(queue.push(ui::TiltEdit{7, 1.5}), 2u);
    QCOMPARE(queue.push(ui::PauseEdit{}), 3u);

    const ui::EditQueue::Batch batch = queue.drain();
    QCOMPARE(batch.lastSequence, 3u);
    QCOMPARE(batch.edits.size(), std::size_t(3));
    QVERIFY(std::holds_alternative<ui::PlayEdit>(batch.edits[0]));
    QCOMPARE(std::get<ui::TiltEdit>(batch.edits[1]).seed, 7u);
    QVERIFY(std::holds_alternative<ui::PauseEdit>(batch.edits[2]));
}

void TestEditQueue::drainEmptiesTheQueue()
{
    ui::EditQueue queue;
    QVERIFY(queue.empty());
    queue.push(ui::ResetEdit{});
    QVERIFY(!queue.empty());
    QCOMPARE(queue.drain().edits.size(), std::size_t(1));
    QVERIFY(queue.empty());

    // an empty drain still says how far the numbering has come
    const ui::EditQueue::Batch batch = queue.drain();
    QVERIFY(batch.edits.empty());
    QCOMPARE(batch.lastSequence, 1u);
}

void TestEditQueue::keepsEachThreadsOrderUnderConcurrentPushes()
{
    constexpr int kThreads = 4;
    constexpr int kPerThread = 2000;
    ui::EditQueue queue;

    // each pusher numbers its tilts thread * kPerThread + i; a drainer takes batches meanwhile
    std::vector<ui::Edit> drained;
    std::atomic<bool> done = false;
    std::thread drainer([&] {
        while (!done.load()) {
            ui::EditQueue::Batch batch = queue.drain();
            drained.insert(drained.end(), batch.edits.begin(), batch.edits.end());
        }
    });
    std::vector<std::thread> pushers;
    for (int t = 0; t < kThreads; ++t)
        pushers.emplace_back([&queue, t] {
            for (int i = 0; i < kPerThread; ++i)
                queue.push(ui::TiltEdit{std::uint64_t(t * kPerThread + i), 0.0});
        });
    for (std::thread &pusher : pushers)
        pusher.join();
    done = true;
    drainer.join();
    ui::EditQueue::Batch rest = queue.drain();
    drained.insert(drained.end(), rest.edits.begin(), rest.edits.end());

    // all arrived, each thread's in its own order
    QCOMPARE(rest.lastSequence, std::uint64_t(kThreads * kPerThread));
    QCOMPARE(drained.size(), std::size_t(kThreads * kPerThread));
    std::vector<int> next(kThreads, 0);
    for (const ui::Edit &edit : drained) {
        const auto seed = int(std::get<ui::TiltEdit>(edit).seed);
        const int thread = seed / kPerThread;
        QCOMPARE(seed % kPerThread, next[std::size_t(thread)]);
        ++next[std::size_t(thread)];
    }
}

QTEST_APPLESS_MAIN(TestEditQueue)
#include "test_edit_queue.moc"
