// core::ThreadChooser: the thread count a run steps with, chosen from the steps' own wall times.
// Driven by a model machine whose step times are given, so the choices are the same on any
// machine and at any load.
#include "core/thread_chooser.h"
#include "core/threads.h"

#include <QtTest>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>

namespace {

// steps the chooser on a machine whose step at n threads takes seconds(n); returns the counts
// it stepped with
std::vector<int> run(core::ThreadChooser &chooser, int steps, const std::function<double(int)> &seconds)
{
    std::vector<int> used;
    for (int i = 0; i < steps; ++i) {
        used.push_back(chooser.threads());
        chooser.stepped(seconds(chooser.threads()));
    }
    return used;
}

// a machine whose other programs' use of the cores is not known (the trials alone choose)
double unknown() { return std::numeric_limits<double>::quiet_NaN(); }

// a 2-core machine at rest: two threads take 0.55 of one's time (a 10 ms step on one)
double idle(int threads) { return threads == 1 ? 0.010 : 0.0055; }
// the same machine with one core busy: the second thread waits for its core, 7 times slower
double busy(int threads) { return threads == 1 ? 0.010 : 0.070; }

}  // namespace

class TestThreadChooser : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void aBusyCoreIsLeftAlone();
    void anIdleMachineGetsEveryThread();
    void noGainKeepsOneThread();
    void aMachineThatGetsBusyIsSeenWithinASecond();
    void aMachineThatGetsFreeIsUsedAgain();
    void longStepsAreTriedOneAtATime();
    void theLadderDoubles();
    void startOverTriesAgain();
    void theUsersCountStands();
    void countsWithoutFreeCoresAreNotTried();
    void aChoiceConfirmedStandsLonger();
    void procStatSaysWhatIsFree();
};

void TestThreadChooser::initTestCase()
{
    qunsetenv("OMP_NUM_THREADS");
    QVERIFY(!core::ThreadChooser::userSetThreads());
}

void TestThreadChooser::aBusyCoreIsLeftAlone()
{
    core::ThreadChooser chooser(2, unknown);
    QVERIFY(chooser.trying());
    const std::vector<int> used = run(chooser, 100, busy);
    QVERIFY(!chooser.trying());
    QCOMPARE(chooser.chosen(), 1);
    // the trial costs one step at two threads (seven times one thread's: dropped at once), then
    // every step runs on one
    QCOMPARE(std::count(used.begin(), used.end(), 2), 1);
    QCOMPARE(used.back(), 1);
}

void TestThreadChooser::anIdleMachineGetsEveryThread()
{
    core::ThreadChooser chooser(2, unknown);
    const std::vector<int> used = run(chooser, 100, idle);
    QCOMPARE(chooser.chosen(), 2);
    QCOMPARE(used.back(), 2);
    // one thread for its trial (which also measures the other programs), then two
    const auto ones = std::count(used.begin(), used.end(), 1);
    QVERIFY2(double(ones) * idle(1) <= core::ThreadChooser::kProbeSeconds + idle(1), qPrintable(QString::number(ones)));
}

void TestThreadChooser::noGainKeepsOneThread()
{
    // a small scene: the threads' start and join cost what they save (5% faster is not enough)
    core::ThreadChooser chooser(2, unknown);
    run(chooser, 100, [](int threads) { return threads == 1 ? 0.010 : 0.0096; });
    QCOMPARE(chooser.chosen(), 1);
}

void TestThreadChooser::aMachineThatGetsBusyIsSeenWithinASecond()
{
    core::ThreadChooser chooser(2, unknown);
    run(chooser, 100, idle);
    QCOMPARE(chooser.chosen(), 2);
    const int choicesBefore = chooser.choices();
    // another program takes a core: the steps at two threads slow down and the counts are tried
    // again at once, not after the kept time
    double spent = 0.0;
    int steps = 0;
    while (chooser.threads() != 1 || chooser.trying()) {
        const double seconds = busy(chooser.threads());
        chooser.stepped(seconds);
        spent += seconds;
        QVERIFY2(++steps < 1000, "never chose one thread");
    }
    QVERIFY2(spent < 1.0, qPrintable(QString::number(spent)));
    QCOMPARE(chooser.chosen(), 1);
    QVERIFY(chooser.choices() > choicesBefore);
}

void TestThreadChooser::aMachineThatGetsFreeIsUsedAgain()
{
    core::ThreadChooser chooser(2, unknown);
    run(chooser, 100, busy);
    QCOMPARE(chooser.chosen(), 1);
    // the other program ends: one thread's steps take no longer, so only the kept time's end
    // tries again; then two threads are chosen
    const int steps = int(core::ThreadChooser::kKeepSeconds / idle(1)) + 50;
    const std::vector<int> used = run(chooser, steps, idle);
    QCOMPARE(chooser.chosen(), 2);
    QCOMPARE(used.back(), 2);
}

void TestThreadChooser::longStepsAreTriedOneAtATime()
{
    // a million particles: a step of seconds is trial enough
    core::ThreadChooser chooser(2, unknown);
    run(chooser, 2, [](int threads) { return threads == 1 ? 2.0 : 14.0; });
    QVERIFY(!chooser.trying());
    QCOMPARE(chooser.chosen(), 1);
}

void TestThreadChooser::theLadderDoubles()
{
    // an 8-thread machine with half its cores busy: four threads are best
    core::ThreadChooser chooser(8, unknown);
    std::vector<int> tried;
    const auto seconds = [&tried](int threads) {
        if (tried.empty() || tried.back() != threads)
            tried.push_back(threads);
        return threads <= 4 ? 0.04 / threads : 0.5;
    };
    run(chooser, 100, seconds);
    QCOMPARE(chooser.chosen(), 4);
    const std::vector<int> order{1, 2, 4, 8, 4};
    QVERIFY(tried.size() >= order.size());
    QVERIFY(std::equal(order.begin(), order.end(), tried.begin()));

    core::ThreadChooser six(6, unknown);
    const std::vector<int> used = run(six, 40, [](int threads) { return 0.05 / threads; });
    QCOMPARE(six.chosen(), 6);
    for (int count : used)
        QVERIFY(count == 1 || count == 2 || count == 4 || count == 6);
}

void TestThreadChooser::startOverTriesAgain()
{
    core::ThreadChooser chooser(2, unknown);
    run(chooser, 100, busy);
    QCOMPARE(chooser.chosen(), 1);
    chooser.startOver();
    QVERIFY(chooser.trying());
    QCOMPARE(chooser.chosen(), 0);
    QCOMPARE(chooser.threads(), 1);
    run(chooser, 100, idle);
    QCOMPARE(chooser.chosen(), 2);
}

void TestThreadChooser::theUsersCountStands()
{
    qputenv("OMP_NUM_THREADS", "1");
    core::ThreadChooser chooser(2, unknown);
    qunsetenv("OMP_NUM_THREADS");
    QVERIFY(!chooser.trying());
    const std::vector<int> used = run(chooser, 50, idle);
    QCOMPARE(chooser.chosen(), used.front());
    for (int count : used)
        QCOMPARE(count, used.front());
}

void TestThreadChooser::countsWithoutFreeCoresAreNotTried()
{
    // the other programs kept one of two cores busy: two threads are not even tried
    core::ThreadChooser chooser(2, [] { return 1.0; });
    const std::vector<int> used = run(chooser, 100, busy);
    QCOMPARE(chooser.chosen(), 1);
    QCOMPARE(std::count(used.begin(), used.end(), 2), 0);
    // on an 8-thread machine with 4.1 cores free, 8 is left out and 4 chosen
    core::ThreadChooser eight(8, [] { return 4.1; });
    const std::vector<int> tried = run(eight, 100, [](int threads) { return 0.04 / threads; });
    QCOMPARE(eight.chosen(), 4);
    QCOMPARE(std::count(tried.begin(), tried.end(), 8), 0);
    // at rest: both tried, two chosen
    core::ThreadChooser rest(2, [] { return 2.0; });
    run(rest, 100, idle);
    QCOMPARE(rest.chosen(), 2);
}

void TestThreadChooser::aChoiceConfirmedStandsLonger()
{
    // each round that keeps the choice doubles the while before the next (its trial of a losing
    // count is the rounds' cost); a changed choice starts from the shortest again
    core::ThreadChooser chooser(2, unknown);
    run(chooser, 50, busy);
    QCOMPARE(chooser.keepSeconds(), core::ThreadChooser::kKeepSeconds);
    const int before = chooser.choices();
    run(chooser, int(3.5 * core::ThreadChooser::kKeepSeconds / busy(1)), busy);
    QCOMPARE(chooser.choices(), before + 2);
    QCOMPARE(chooser.keepSeconds(), 4.0 * core::ThreadChooser::kKeepSeconds);
    run(chooser, int(100.0 / busy(1)), busy);
    QCOMPARE(chooser.keepSeconds(), core::ThreadChooser::kLongestKeepSeconds);
    int steps = 0;
    while (chooser.chosen() != 2 && steps++ < 10000)
        chooser.stepped(idle(chooser.threads()));
    QCOMPARE(chooser.chosen(), 2);
    QCOMPARE(chooser.keepSeconds(), core::ThreadChooser::kKeepSeconds);
    QVERIFY(double(steps) * idle(1) <= core::ThreadChooser::kLongestKeepSeconds + 1.0);
}

void TestThreadChooser::procStatSaysWhatIsFree()
{
    if (!QFile::exists(QStringLiteral("/proc/stat")))
        QSKIP("no /proc/stat here");
    core::freeCoresFromProcStat();  // the first look: a start, nothing to compare with
    // this thread busy for 0.2 s: what the others left free is between none and every core
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
    volatile double sink = 0.0;
    while (std::chrono::steady_clock::now() < until)
        sink = sink + 1.0;
    const double free = core::freeCoresFromProcStat();
    QVERIFY2(std::isfinite(free) && free >= 0.0 && free <= double(core::maxThreadCount()), qPrintable(QString::number(free)));
}

QTEST_APPLESS_MAIN(TestThreadChooser)
#include "test_thread_chooser.moc"
