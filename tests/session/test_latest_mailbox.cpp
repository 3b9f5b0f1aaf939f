// The latest-wins mailbox: the consumer gets the newest value, once, and never one that is half
// written.

#include "session/latest_mailbox.h"

#include <QtTest>
#include <array>
#include <thread>

namespace {

// every field holds the same number, so a torn value would show two different numbers
struct Stamp {
    std::array<std::uint64_t, 64> fields{};
    explicit Stamp(std::uint64_t n) { fields.fill(n); }
    bool whole() const
    {
        return std::all_of(fields.begin(), fields.end(), [this](std::uint64_t f) { return f == fields[0]; });
    }
};

}  // namespace

class TestLatestMailbox : public QObject {
    Q_OBJECT

private slots:
    void latestWins();
    void publishSaysWhenTheBoxWasEmpty();
    void neverTornNeverOlder();
};

void TestLatestMailbox::latestWins()
{
    ui::LatestMailbox<Stamp> box;
    QVERIFY(box.take() == nullptr);
    box.publish(std::make_shared<const Stamp>(1));
    box.publish(std::make_shared<const Stamp>(2));
    box.publish(std::make_shared<const Stamp>(3));
    const std::shared_ptr<const Stamp> taken = box.take();
    QVERIFY(taken);
    QCOMPARE(taken->fields[0], 3u);
    QVERIFY(box.take() == nullptr);
}

void TestLatestMailbox::publishSaysWhenTheBoxWasEmpty()
{
    ui::LatestMailbox<Stamp> box;
    QVERIFY(box.publish(std::make_shared<const Stamp>(1)));
    QVERIFY(!box.publish(std::make_shared<const Stamp>(2)));
    box.take();
    QVERIFY(box.publish(std::make_shared<const Stamp>(3)));
}

void TestLatestMailbox::neverTornNeverOlder()
{
    constexpr std::uint64_t kCount = 100000;
    ui::LatestMailbox<Stamp> box;
    std::thread producer([&box] {
        for (std::uint64_t n = 1; n <= kCount; ++n)
            box.publish(std::make_shared<const Stamp>(n));
    });

    // the consumer sees whole values in increasing order, ending with the last one
    std::uint64_t last = 0;
    int torn = 0;
    int older = 0;
    while (last < kCount) {
        const std::shared_ptr<const Stamp> stamp = box.take();
        if (!stamp)
            continue;
        torn += stamp->whole() ? 0 : 1;
        older += stamp->fields[0] > last ? 0 : 1;
        last = stamp->fields[0];
    }
    producer.join();
    QCOMPARE(torn, 0);
    QCOMPARE(older, 0);
    QCOMPARE(last, kCount);
}

QTEST_APPLESS_MAIN(TestLatestMailbox)
#include "test_latest_mailbox.moc"
