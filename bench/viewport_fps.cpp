// viewport_fps: frames per second of the viewport for 1k, 10k and 100k particles, impostor quads
// against an instanced mesh sphere. Each frame gets a new snapshot (positions streamed, style kept),
// as while a simulation runs. Each run lasts at least --seconds and three frames; the table gives
// the median of --runs runs and their range. --cloth N,M,...: N × N cloths instead (the generator's,
// drawn as the editor draws them by default: a sheet that hides its spheres and springs).
//
// Without a display, run it under a virtual X server:
//   xvfb-run -a -s "-screen 0 1280x1024x24" build/release/bench/viewport_fps

#include "bench_common.h"
#include "ui/viewport/viewport.h"

#include "core/model/generators.h"
#include "core/model/model.h"
#include "core/model/snapshot.h"
#include "core/model/state.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSurfaceFormat>
#include <QTextStream>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace {

// a jittered cube lattice of n particles, 1 m apart, every 20th pinned; `phase` moves them a little
std::shared_ptr<const core::Snapshot> lattice(int n, float phase)
{
    auto s = std::make_shared<core::Snapshot>();
    const int side = int(std::ceil(std::cbrt(double(n))));
    std::mt19937 random(12345);
    std::uniform_real_distribution<float> jitter(-0.15f, 0.15f);
    s->positions.reserve(std::size_t(n) * 3);
    for (int i = 0; i < n; ++i) {
        const int x = i % side, y = (i / side) % side, z = i / (side * side);
        s->positions.push_back(float(x) + jitter(random) + 0.05f * std::sin(phase + float(i)));
        s->positions.push_back(float(y) + jitter(random));
        s->positions.push_back(float(z) + jitter(random));
    }
    s->radii.assign(std::size_t(n), 0.3f);
    s->pinned.assign(std::size_t(n), 0);
    for (int i = 0; i < n; i += 20)
        s->pinned[std::size_t(i)] = 1;
    return s;
}

// a side × side cloth from the generator, flat; `phase` ripples it a little
std::shared_ptr<const core::Snapshot> cloth(int side, float phase)
{
    core::ClothOptions options;
    options.rows = options.cols = side;
    const core::SceneDesc scene = core::makeCloth(options);
    const auto model = core::compileModel(scene);
    auto snapshot = std::make_shared<core::Snapshot>(*core::makeSnapshot(*model, core::makeState(*model, scene)));
    for (std::size_t i = 0; i < snapshot->positions.size(); i += 3)
        snapshot->positions[i + 1] += 0.01f * std::sin(phase + 0.1f * float(i % 997));
    return snapshot;
}

// shows one snapshot and returns when it is on screen (false if it never got there)
bool showFrame(ui::Viewport &viewport, std::shared_ptr<const core::Snapshot> snapshot)
{
    QEventLoop loop;
    bool swapped = false;
    const auto connection = QObject::connect(&viewport, &QOpenGLWidget::frameSwapped, &loop, [&] {
        swapped = true;
        loop.quit();
    });
    QTimer::singleShot(120000, &loop, &QEventLoop::quit);
    viewport.setSnapshot(std::move(snapshot));
    loop.exec();
    QObject::disconnect(connection);
    return swapped;
}

// frames per second over one run; `next`: the frame to show first, the other one is on screen
// (the view does not draw the snapshot it shows again)
double measure(ui::Viewport &viewport, const std::shared_ptr<const core::Snapshot> frames[2], int &next,
               double minSeconds)
{
    QElapsedTimer clock;
    clock.start();
    int count = 0;
    while (count < 3 || clock.nsecsElapsed() * 1e-9 < minSeconds) {
        if (!showFrame(viewport, frames[next]))
            return 0.0;
        next = 1 - next;
        ++count;
    }
    return count / (clock.nsecsElapsed() * 1e-9);
}

}  // namespace

int main(int argc, char **argv)
{
    // GL is set up before the application exists
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat::setDefaultFormat(ui::Viewport::requestedFormat());
    QApplication app(argc, argv);

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Frames per second of the viewport, impostors against meshes."));
    parser.addHelpOption();
    const QCommandLineOption particlesOption(QStringLiteral("particles"),
                                             QStringLiteral("Comma-separated particle counts."), QStringLiteral("list"),
                                             QStringLiteral("1000,10000,100000"));
    const QCommandLineOption runsOption(QStringLiteral("runs"),
                                        QStringLiteral("Runs per measurement (the median is shown)."),
                                        QStringLiteral("n"), QStringLiteral("5"));
    const QCommandLineOption secondsOption(QStringLiteral("seconds"), QStringLiteral("Shortest run, seconds."),
                                           QStringLiteral("s"), QStringLiteral("2"));
    const QCommandLineOption sizeOption(QStringLiteral("size"), QStringLiteral("Viewport size WxH."),
                                        QStringLiteral("size"), QStringLiteral("992x678"));
    const QCommandLineOption drawingOption(QStringLiteral("drawing"), QStringLiteral("impostor, mesh or both."),
                                           QStringLiteral("which"), QStringLiteral("both"));
    const QCommandLineOption clothOption(QStringLiteral("cloth"),
                                         QStringLiteral("Comma-separated sides of square cloths, drawn as sheets, "
                                                        "instead of particle lattices."),
                                         QStringLiteral("list"));
    parser.addOptions({particlesOption, runsOption, secondsOption, sizeOption, drawingOption, clothOption});
    parser.process(app);

    std::vector<int> counts;
    const bool cloths = parser.isSet(clothOption);
    for (const QString &text : parser.value(cloths ? clothOption : particlesOption).split(QLatin1Char(','), Qt::SkipEmptyParts))
        counts.push_back(std::max(cloths ? 2 : 1, text.toInt()));
    const int runs = std::max(1, parser.value(runsOption).toInt());
    const double seconds = std::max(0.0, parser.value(secondsOption).toDouble());
    const QStringList size = parser.value(sizeOption).split(QLatin1Char('x'));
    const QSize viewportSize(size.value(0).toInt(), size.value(1).toInt());
    const QString which = parser.value(drawingOption);
    std::vector<std::pair<ui::ParticleDrawing, QString>> drawings;
    if (which != QLatin1String("mesh"))
        drawings.emplace_back(ui::ParticleDrawing::Impostor, QStringLiteral("impostor"));
    if (which != QLatin1String("impostor"))
        drawings.emplace_back(ui::ParticleDrawing::Mesh,
                              QStringLiteral("mesh (%1 triangles)").arg(20 << (2 * ui::kSphereMeshSubdivisions)));

    ui::Viewport viewport;
    viewport.resize(viewportSize.isValid() ? viewportSize : QSize(992, 678));
    viewport.show();

    QTextStream out(stdout);
    out << "viewport " << viewport.width() << "x" << viewport.height() << ", median of " << runs
        << " runs of at least " << seconds << " s\n\n";
    out << (cloths ? "| cloth |" : "| particles |");
    for (const auto &drawing : drawings)
        out << " " << drawing.second << " fps (range) |";
    out << "\n|---:|";
    for (std::size_t i = 0; i < drawings.size(); ++i)
        out << "---:|";
    out << "\n";
    out.flush();

    for (int n : counts) {
        // two frames to alternate, framed once
        const std::shared_ptr<const core::Snapshot> frames[2] = {cloths ? cloth(n, 0.0f) : lattice(n, 0.0f),
                                                                 cloths ? cloth(n, 1.0f) : lattice(n, 1.0f)};
        if (cloths)
            out << "| " << n << " × " << n << " |";
        else
            out << "| " << n << " |";
        for (const auto &[drawing, name] : drawings) {
            viewport.setParticleDrawing(drawing);
            viewport.frameAll();
            showFrame(viewport, frames[0]);
            viewport.frameAll();
            showFrame(viewport, frames[1]);
            std::vector<double> fps;
            int next = 0;
            for (int run = 0; run < runs; ++run)
                fps.push_back(measure(viewport, frames, next, seconds));
            const auto [lo, hi] = std::minmax_element(fps.begin(), fps.end());
            const QString cell = QStringLiteral(" %1 (%2–%3) |").arg(bench::median(fps), 0, 'f', 2).arg(*lo, 0, 'f', 2);
            out << cell.arg(*hi, 0, 'f', 2);
            out.flush();
        }
        out << "\n";
        out.flush();
    }
    out << "\nframebuffer samples: " << viewport.samples() << "\n";
    return 0;
}
