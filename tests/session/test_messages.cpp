// The message queue: messages come out in the order they went in, numbered, none lost under
// concurrent pushes.

#include "session/messages.h"

#include <QtTest>
#include <thread>

class TestMessages : public QObject {
    Q_OBJECT

private slots:
    void numbersMessagesInOrder();
    void drainEmptiesTheQueue();
    void keepsEachThreadsOrderUnderConcurrentPushes();
};

void TestMessages::numbersMessagesInOrder()
{
    ui::MessageQueue queue;
    QCOMPARE(queue.push(ui::Play{}), 1u);
    QCOMPARE(queue.push(ui::TiltEdit{7, 1.5}), 2u);
    QCOMPARE(queue.push(ui::Pause{}), 3u);

    const ui::MessageQueue::Batch batch = queue.drain();
    QCOMPARE(batch.lastSequence, 3u);
    QCOMPARE(batch.messages.size(), std::size_t(3));
    QVERIFY(std::holds_alternative<ui::Play>(batch.messages[0]));
    QCOMPARE(std::get<ui::TiltEdit>(batch.messages[1]).seed, 7u);
    QVERIFY(std::holds_alternative<ui::Pause>(batch.messages[2]));
}

void TestMessages::drainEmptiesTheQueue()
{
    ui::MessageQueue queue;
    QVERIFY(queue.empty());
    queue.push(ui::Reset{});
    QVERIFY(!queue.empty());
    QCOMPARE(queue.drain().messages.size(), std::size_t(1));
    QVERIFY(queue.empty());

    // an empty drain still says how far the numbering has come
    const ui::MessageQueue::Batch batch = queue.drain();
    QVERIFY(batch.messages.empty());
    QCOMPARE(batch.lastSequence, 1u);
}

void TestMessages::keepsEachThreadsOrderUnderConcurrentPushes()
{
    constexpr int kThreads = 4;
    constexpr int kPerThread = 2000;
    ui::MessageQueue queue;

    // each pusher numbers its tilts thread * kPerThread + i; a drainer takes batches meanwhile
    std::vector<ui::Message> drained;
    std::atomic<bool> done = false;
    std::thread drainer([&] {
        while (!done.load()) {
            ui::MessageQueue::Batch batch = queue.drain();
            drained.insert(drained.end(), batch.messages.begin(), batch.messages.end());
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
    ui::MessageQueue::Batch rest = queue.drain();
    drained.insert(drained.end(), rest.messages.begin(), rest.messages.end());

    // all arrived, each thread's in its own order
    QCOMPARE(rest.lastSequence, std::uint64_t(kThreads * kPerThread));
    QCOMPARE(drained.size(), std::size_t(kThreads * kPerThread));
    std::vector<int> next(kThreads, 0);
    for (const ui::Message &message : drained) {
        const auto seed = int(std::get<ui::TiltEdit>(message).seed);
        const int thread = seed / kPerThread;
        QCOMPARE(seed % kPerThread, next[std::size_t(thread)]);
        ++next[std::size_t(thread)];
    }
}

QTEST_APPLESS_MAIN(TestMessages)
#include "test_messages.moc"
