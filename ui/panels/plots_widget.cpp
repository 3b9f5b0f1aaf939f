#include "plots_widget.h"

#include "plot_canvas.h"
#include "core/io/safe_write.h"
#include "session/simulation_frame.h"

#include <QAction>
#include <QBuffer>
#include <QComboBox>
#include <QDir>
#include <QHBoxLayout>
#include <QImage>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {

// what each group plots: the box's entry, the vertical axis and the curves, in PlotGroup's order
struct GroupInfo {
    const char *text;
    const char *fileName;
    const char *valueLabel;
    std::vector<PlotCurve> curves;
};

const GroupInfo &groupInfo(PlotGroup group)
{
    static const GroupInfo groups[] = {
        {QT_TRANSLATE_NOOP("ui::PlotsWidget", "Energies"), "energies",
         QT_TRANSLATE_NOOP("ui::PlotsWidget", "energy [J]"),
         {{"kinetic", "J"}, {"gravitational", "J"}, {"spring", "J"}, {"total", "J"}, {"lost since reset", "J"}}},
        {QT_TRANSLATE_NOOP("ui::PlotsWidget", "Momentum"), "momentum",
         QT_TRANSLATE_NOOP("ui::PlotsWidget", "momentum [kg·m/s]"),
         {{"px", "kg·m/s"}, {"py", "kg·m/s"}, {"pz", "kg·m/s"}, {"|p|", "kg·m/s"}}},
        {QT_TRANSLATE_NOOP("ui::PlotsWidget", "Selected particle: position"), "position",
         QT_TRANSLATE_NOOP("ui::PlotsWidget", "position [m]"), {{"x", "m"}, {"y", "m"}, {"z", "m"}}},
        {QT_TRANSLATE_NOOP("ui::PlotsWidget", "Selected particle: velocity"), "velocity",
         QT_TRANSLATE_NOOP("ui::PlotsWidget", "velocity [m/s]"),
         {{"vx", "m/s"}, {"vy", "m/s"}, {"vz", "m/s"}, {"|v|", "m/s"}}},
    };
    return groups[static_cast<std::size_t>(group)];
}

constexpr PlotGroup kGroups[] = {PlotGroup::Energies, PlotGroup::Momentum, PlotGroup::Position, PlotGroup::Velocity};

bool isParticleGroup(PlotGroup group)
{
    return group == PlotGroup::Position || group == PlotGroup::Velocity;
}

// a 3-vector's components, and its length
std::vector<double> vectorSample(const Eigen::Vector3d &v, bool withLength)
{
    std::vector<double> sample{v.x(), v.y(), v.z()};
    if (withLength)
        sample.push_back(v.norm());
    return sample;
}

bool failWith(QString *error, const QString &reason)
{
    if (error)
        *error = reason;
    return false;
}

}  // namespace

PlotsWidget::PlotsWidget(QWidget *parent)
    : QWidget(parent),
      m_series{PlotSeries(groupInfo(PlotGroup::Energies).curves), PlotSeries(groupInfo(PlotGroup::Momentum).curves),
               PlotSeries(groupInfo(PlotGroup::Position).curves), PlotSeries(groupInfo(PlotGroup::Velocity).curves)},
      m_groupBox(new QComboBox(this)), m_canvas(new PlotCanvas(this))
{
    // which quantities: one entry per group
    m_groupBox->setObjectName(QStringLiteral("plotGroup"));
    for (PlotGroup group : kGroups)
        m_groupBox->addItem(tr(groupInfo(group).text), static_cast<int>(group));
    m_groupBox->setToolTip(tr("The quantities plotted against time"));
    connect(m_groupBox, &QComboBox::currentIndexChanged, this,
            [this](int index) { setGroup(static_cast<PlotGroup>(m_groupBox->itemData(index).toInt())); });
    m_canvas->setObjectName(QStringLiteral("plotCanvas"));

    // exports, from the buttons or the canvas's context menu; the window chooses the file
    m_exportPng = new QAction(tr("Export PNG…"), this);
    m_exportPng->setObjectName(QStringLiteral("actionExportPlotPng"));
    m_exportPng->setStatusTip(tr("Save the plot shown as a PNG image"));
    connect(m_exportPng, &QAction::triggered, this, [this] { emit exportRequested(PlotExport::Png); });
    m_exportCsv = new QAction(tr("Export CSV…"), this);
    m_exportCsv->setObjectName(QStringLiteral("actionExportPlotCsv"));
    m_exportCsv->setStatusTip(tr("Save the samples of the plot shown as CSV: step, time, then one column per curve; a "
                                 "row per step (every 2nd, 4th, … step in a long run)"));
    connect(m_exportCsv, &QAction::triggered, this, [this] { emit exportRequested(PlotExport::Csv); });
    m_canvas->addAction(m_exportPng);
    m_canvas->addAction(m_exportCsv);
    m_canvas->setContextMenuPolicy(Qt::ActionsContextMenu);

    // the box and the buttons above the canvas
    auto *bar = new QHBoxLayout;
    bar->addWidget(m_groupBox, 1);
    for (QAction *action : {m_exportPng, m_exportCsv}) {
        auto *button = new QToolButton(this);
        button->setDefaultAction(action);
        button->setObjectName(action->objectName().replace(QStringLiteral("action"), QStringLiteral("button")));
        bar->addWidget(button);
    }
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addWidget(m_canvas, 1);
    showGroup();
}

void PlotsWidget::addFrame(const SimulationFrame &frame)
{
    if (!frame.snapshot)
        return;
    // a scene is being replaced: pass over the old one's frames, then start over
    if (m_startOverAfter != 0) {
        if (frame.appliedMessage < m_startOverAfter)
            return;
        m_startOverAfter = 0;
        for (PlotSeries &series : m_series)
            series.clear();
    }

    // once the run goes on from a step scrubbed to, what the curves drew after it is gone, as on
    // the timeline (while a past step is shown, the curves stay as the run drew them: the samples
    // are always of the run's own steps)
    if (frame.timeline.resumes != m_resumes) {
        m_resumes = frame.timeline.resumes;
        for (PlotSeries &series : m_series)
            series.dropAfter(frame.timeline.resumedAt);
    }
    if (!frame.samples)
        return;
    for (const StepSample &sample : *frame.samples)
        if (sample.sequence > m_lastSample)
            addSample(sample);
    m_lastSample = std::max(m_lastSample, frame.samples->back().sequence);
    m_canvas->update();
}

void PlotsWidget::addSample(const StepSample &sample)
{
    // energies, and what has gone since the last reset
    const core::Energies &energies = sample.energies;
    const double total = energies.total();
    auto add = [&](PlotGroup group, const std::vector<double> &values) {
        m_series[static_cast<std::size_t>(group)].add(sample.step, sample.time, values);
    };
    add(PlotGroup::Energies, {energies.kinetic, energies.gravitational, energies.spring, total,
                              sample.initialTotal - total});
    add(PlotGroup::Momentum, vectorSample(sample.momentum, true));

    // the selected particle, once the worker follows it
    if (m_particle >= 0 && sample.particle == m_particle) {
        add(PlotGroup::Position, vectorSample(sample.position, false));
        add(PlotGroup::Velocity, vectorSample(sample.velocity, true));
    }
}

void PlotsWidget::setParticle(int particle)
{
    if (particle == m_particle)
        return;
    m_particle = particle;
    m_series[static_cast<std::size_t>(PlotGroup::Position)].clear();
    m_series[static_cast<std::size_t>(PlotGroup::Velocity)].clear();
    showGroup();
}

void PlotsWidget::startOverAfter(std::uint64_t edit)
{
    m_startOverAfter = edit;
}

void PlotsWidget::setGroup(PlotGroup group)
{
    m_group = group;
    m_groupBox->setCurrentIndex(m_groupBox->findData(static_cast<int>(group)));
    showGroup();
}

void PlotsWidget::showGroup()
{
    // the canvas draws the group's series, titled and labelled for it
    const GroupInfo &info = groupInfo(m_group);
    m_canvas->setSeries(&shownSeries());
    m_canvas->setValueLabel(tr(info.valueLabel));
    QString title;
    QString tip;
    QString empty = tr("Play (F4) or step (F6) the simulation to plot it");
    if (m_group == PlotGroup::Energies) {
        title = tr("lost since reset = total at the last reset − total now");
        tip = tr("Energy lost since the last reset or scene load: to damping, drag and inelastic contacts, and also "
                 "the integrator's own drift and work done by the mouse, the steering or edits");
    } else if (isParticleGroup(m_group) && m_particle >= 0)
        title = tr("Particle %1").arg(m_particle);
    else if (isParticleGroup(m_group))
        empty = tr("Select a particle to plot its position and velocity");
    m_canvas->setTitle(title);
    m_canvas->setToolTip(tip);
    m_canvas->setEmptyText(empty);
}

bool PlotsWidget::savePng(const QString &path, QString *error) const
{
    // the canvas as drawn now, written atomically
    const QImage image = m_canvas->grab().toImage();
    QByteArray png;
    QBuffer buffer(&png);
    if (image.isNull() || !buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG"))
        return failWith(error, tr("Export PNG: cannot write %1: %2").arg(QDir::toNativeSeparators(path), tr("no image")));
    if (const QString failure = io::writeFileAtomically(path, png); !failure.isEmpty())
        return failWith(error, tr("Export PNG: cannot write %1: %2").arg(QDir::toNativeSeparators(path), failure));
    return true;
}

bool PlotsWidget::saveCsv(const QString &path, QString *error) const
{
    // the shown series' samples, written atomically
    const std::string text = shownSeries().csv();
    const QByteArray bytes(text.data(), static_cast<qsizetype>(text.size()));
    if (const QString failure = io::writeFileAtomically(path, bytes); !failure.isEmpty())
        return failWith(error, tr("Export CSV: cannot write %1: %2").arg(QDir::toNativeSeparators(path), failure));
    return true;
}

QString PlotsWidget::suggestedName() const
{
    const QString name = QString::fromLatin1(groupInfo(m_group).fileName);
    if (isParticleGroup(m_group) && m_particle >= 0)
        return QStringLiteral("particle-%1-%2").arg(m_particle).arg(name);
    return name;
}

}  // namespace ui
