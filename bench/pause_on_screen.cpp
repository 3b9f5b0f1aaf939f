// Each run plays the scene for a while (longer in each run, so the Pause lands at every point of a
// step), then presses Pause, Step and Step Back in turn from a second thread and times each from
// the key to the swap of the frame that shows its answer. Whether that frame's pixels differ from
// the ones before the key is checked afterwards, outside the timed part (a grab redraws the view).
#include "pause_on_screen.h"

#include "bench_common.h"

#include "session/simulation_frame.h"
#include "ui/document/document_files.h"
#include "ui/document/recent_files.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"
#include "ui/window/main_window.h"

#include <QAction>
#include <QCoreApplication>
#include <QEventLoop>
#include <QImage>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <thread>

namespace bench {

namespace {

using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point from, Clock::time_point to)
{
    return std::chrono::duration<double>(to - from).count();
}

// whether a frame answers the key pressed
using Shown = std::function<bool(const ui::SimulationFrame &frame)>;

// where a key's time went: waiting for the window to take it, the worker's answer reaching the
// window (the frame with the answer's snapshot), and drawing it
struct KeyTimes {
    double total = 0.0;    // from the press to the picture
    double queued = 0.0;   // from the press until the window handled the key
    double answer = 0.0;   // from then until the frame arrived
    double drawing = 0.0;  // from then until it was on screen
    // from the press to the first frame on screen that says the key was taken (a Step owed,
    // "taking a step…" in the status bar), where that comes before the picture; else the total
    double acknowledged = 0.0;
};

class Keyboard {
public:
    explicit Keyboard(ui::MainWindow &window) : m_window(window) {}

    // presses the key after `delay` from a second thread, so that it waits in the window's queue
    // like one from the keyboard, and returns the times from the press to the swap of the first
    // frame for which `answered` holds with its snapshot drawn; nullopt after `timeout` seconds
    std::optional<KeyTimes> press(Qt::Key key, Qt::KeyboardModifiers modifiers, double delay, const Shown &answered,
                                  double timeout, const Shown &acknowledges = {})
    {
        ui::Viewport &viewport = *m_window.viewport();
        QEventLoop loop;
        std::optional<KeyTimes> times;
        // pressedAt is written by the presser before it posts the key, read here after it is handled
        Clock::time_point pressedAt, handledAt, arrivedAt;
        bool handled = false, arrived = false;
        std::optional<double> acknowledged;
        const auto answers = [&](const std::shared_ptr<const ui::SimulationFrame> &frame) {
            return frame && frame->snapshot && !frame->snapshotBehind && answered(*frame);
        };
        const auto check = [&] {
            if (!handled || times)
                return;
            const std::shared_ptr<const ui::SimulationFrame> frame = m_window.controller()->frame();
            if (!acknowledged && acknowledges && frame && acknowledges(*frame))
                acknowledged = secondsBetween(pressedAt, Clock::now());
            if (answers(frame) && viewport.snapshot() == frame->snapshot) {
                const Clock::time_point now = Clock::now();
                if (!arrived)
                    arrivedAt = now;
                times = KeyTimes{secondsBetween(pressedAt, now), secondsBetween(pressedAt, handledAt),
                                 secondsBetween(handledAt, arrivedAt), secondsBetween(arrivedAt, now),
                                 acknowledged.value_or(secondsBetween(pressedAt, now))};
                loop.quit();
            }
        };
        const QMetaObject::Connection changed =
            QObject::connect(m_window.controller(), &ui::SimulationController::frameChanged, &loop, [&] {
                if (handled && !arrived && answers(m_window.controller()->frame())) {
                    arrived = true;
                    arrivedAt = Clock::now();
                }
            });
        const QMetaObject::Connection swapped = QObject::connect(&viewport, &QOpenGLWidget::frameSwapped, &loop, check);
        QTimer deadline;
        deadline.setSingleShot(true);
        QObject::connect(&deadline, &QTimer::timeout, &loop, &QEventLoop::quit);
        deadline.start(static_cast<int>((delay + timeout) * 1000.0));
        std::thread presser([&] {
            std::this_thread::sleep_for(std::chrono::duration<double>(delay));
            pressedAt = Clock::now();
            QMetaObject::invokeMethod(
                &m_window,
                [&, key, modifiers] {
                    handledAt = Clock::now();
                    handled = true;
                    QTest::keyClick(&m_window, key, modifiers);
                },
                Qt::QueuedConnection);
        });
        loop.exec();
        presser.join();
        QObject::disconnect(changed);
        QObject::disconnect(swapped);
        return times;
    }

private:
    ui::MainWindow &m_window;
};

// waits (processing events) until `done` holds, checked every 10 ms; false after `timeout` s
bool waitFor(const std::function<bool()> &done, double timeout)
{
    const Clock::time_point start = Clock::now();
    while (!done()) {
        if (secondsBetween(start, Clock::now()) > timeout)
            return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

// the pixels of the view that differ between two grabs of it
qint64 changedPixels(const QImage &before, const QImage &after)
{
    if (before.size() != after.size())
        return qint64(after.width()) * after.height();
    const QImage a = before.convertToFormat(QImage::Format_RGB32), b = after.convertToFormat(QImage::Format_RGB32);
    qint64 changed = 0;
    for (int y = 0; y < a.height(); ++y) {
        const auto *rowA = reinterpret_cast<const QRgb *>(a.constScanLine(y));
        const auto *rowB = reinterpret_cast<const QRgb *>(b.constScanLine(y));
        for (int x = 0; x < a.width(); ++x)
            changed += rowA[x] != rowB[x];
    }
    return changed;
}

QString ms(double seconds)
{
    return QString::number(seconds * 1e3, 'f', 0);
}

// "412 ms (queued 3, answered 380, drawn 29)"
QString timesText(const std::optional<KeyTimes> &times)
{
    if (!times)
        return QStringLiteral("not shown");
    return QStringLiteral("%1 ms (queued %2, answered %3, drawn %4; acknowledged on screen %5)")
        .arg(ms(times->total), ms(times->queued), ms(times->answer), ms(times->drawing), ms(times->acknowledged));
}

void printFigure(QTextStream &out, const char *what, const std::vector<KeyTimes> &times, int runs)
{
    if (times.empty()) {
        out << what << ": never shown\n";
        return;
    }
    const auto medianOf = [&](double KeyTimes::*part) {
        std::vector<double> values;
        for (const KeyTimes &t : times)
            values.push_back(t.*part);
        return median(values);
    };
    double largest = 0.0;
    for (const KeyTimes &t : times)
        largest = std::max(largest, t.total);
    out << what << ": median " << ms(medianOf(&KeyTimes::total)) << " ms, largest " << ms(largest) << " ms ("
        << times.size() << " of " << runs << " shown; medians: queued " << ms(medianOf(&KeyTimes::queued))
        << ", answered " << ms(medianOf(&KeyTimes::answer)) << ", drawn " << ms(medianOf(&KeyTimes::drawing))
        << ", acknowledged on screen " << ms(medianOf(&KeyTimes::acknowledged)) << ")\n";
}

}  // namespace

int runPauseOnScreen(const PauseLatencyOptions &options, QTextStream &out, QTextStream &err)
{
    // the editor's settings, autosave and recovery in a throwaway folder, never the user's
    QTemporaryDir settings;
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("SpringlabBench"));
    QCoreApplication::setApplicationName(QStringLiteral("pause"));
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings.path());

    ui::MainWindow window;
    window.resize(1280, 900);
    window.show();
    window.activateWindow();
    if (!QTest::qWaitForWindowActive(&window)) {
        err << "springlab-bench: the window never became active (is there a display? try xvfb-run)\n";
        return 1;
    }
    window.files()->recentFiles()->setRemembering(false);
    QString error;
    if (!window.files()->start(options.scene, &error)) {
        err << "springlab-bench: " << error << '\n';
        return 1;
    }
    ui::SimulationController &controller = *window.controller();
    controller.setTimelineBudget(std::size_t(options.timelineMegabytes) << 20);
    const auto frame = [&] { return controller.frame(); };
    // the scene on screen, paused: the frame that answers a message sent after it was opened
    const std::uint64_t opened = controller.sync();
    if (!waitFor(
            [&] {
                return frame() && frame()->appliedMessage >= opened && !frame()->snapshotBehind &&
                       window.viewport()->snapshot() == frame()->snapshot;
            },
            120.0)) {
        err << "springlab-bench: the scene never showed\n";
        return 1;
    }
    const std::size_t particles = frame()->snapshot->particleCount();
    out << "pause on screen: " << options.scene << ", " << particles << " particles, window "
        << window.width() << " x " << window.height() << ", view " << window.viewport()->width() << " x "
        << window.viewport()->height() << "\n"
        << machineDescription() << "; " << (options.busy ? "a loop keeps one core busy" : "nothing else run")
        << "; load average " << loadAverage() << "\n";
    std::optional<BusyCore> busy;
    if (options.busy)
        busy.emplace();

    Keyboard keyboard(window);
    const double timeout = 120.0;
    std::vector<KeyTimes> pauses, steps, stepsBack;
    for (int r = 0; r < options.runs; ++r) {
        // play for a while, longer each run, until a step has been shown
        const std::uint64_t from = frame()->snapshot->step;
        QTest::keyClick(&window, Qt::Key_F4);
        if (!waitFor([&] { return frame()->running && frame()->snapshot->step > from; }, timeout)) {
            err << "springlab-bench: the run never showed a step\n";
            return 1;
        }
        const double play = 0.5 + 0.37 * r;
        const std::optional<KeyTimes> pause = keyboard.press(
            Qt::Key_F4, Qt::NoModifier, play, [](const ui::SimulationFrame &f) { return !f.running; }, timeout);
        if (!pause || !waitFor([&] { return frame()->stepsOwed == 0 && !frame()->snapshotBehind; }, timeout)) {
            err << "springlab-bench: the Pause never showed\n";
            return 1;
        }
        pauses.push_back(*pause);

        // paused: a Step, then a Step Back to where it came from; each key after a moment's quiet
        const QImage paused = window.viewport()->grabFramebuffer();
        const std::uint64_t before = frame()->snapshot->step;
        const std::optional<KeyTimes> step = keyboard.press(
            Qt::Key_F6, Qt::NoModifier, 0.2, [&](const ui::SimulationFrame &f) { return f.snapshot->step == before + 1; },
            timeout, [](const ui::SimulationFrame &f) { return f.stepsOwed > 0; });
        if (step)
            steps.push_back(*step);
        const QImage stepped = window.viewport()->grabFramebuffer();
        const bool canStepBack = window.findChild<QAction *>(QStringLiteral("actionStepBack"))->isEnabled();
        std::optional<KeyTimes> stepBack;
        if (canStepBack) {
            stepBack = keyboard.press(
                Qt::Key_F6, Qt::ShiftModifier, 0.2,
                [&](const ui::SimulationFrame &f) { return f.snapshot->step == before && f.timeline.scrubStep; },
                timeout);
            if (stepBack)
                stepsBack.push_back(*stepBack);
        }
        const QImage back = window.viewport()->grabFramebuffer();
        out << "run " << r << ": played " << play << " s\n  Pause " << timesText(pause) << "\n  Step "
            << timesText(step) << ", " << changedPixels(paused, stepped) << " pixels changed\n  Step Back "
            << (canStepBack ? timesText(stepBack) : QStringLiteral("- (nothing recorded)")) << ", "
            << changedPixels(stepped, back) << " pixels changed\n";
        out.flush();
    }
    busy.reset();
    printFigure(out, "Pause, key to picture", pauses, options.runs);
    printFigure(out, "Step, key to picture", steps, options.runs);
    printFigure(out, "Step Back, key to picture", stepsBack, options.runs);
    out << "load average after: " << loadAverage() << "\n";
    return 0;
}

}  // namespace bench
