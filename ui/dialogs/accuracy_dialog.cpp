#include "accuracy_dialog.h"

#include "ui/panels/slider_scale.h"
#include "ui/panels/status_text.h"
#include "ui/panels/value_spin_box.h"

#include "core/integrators/accuracy_planner.h"
#include "core/model/parameters.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace ui {

namespace {

constexpr double kDefaultTolerance = 1e-6;  // m per step

enum Column { Integrator, Substeps, LocalError, Cost, Note, ColumnCount };

}  // namespace

AccuracyDialog::AccuracyDialog(QWidget *parent)
    : QDialog(parent), m_tolerance(new ValueSpinBox(sliderScale(core::parameterInfo(core::Parameter::Tolerance)), this)),
      m_plan(new QPushButton(tr("&Plan and Apply"), this)), m_preview(new QPushButton(tr("Pre&view"), this)),
      m_adaptive(new QPushButton(tr("Use &Adaptive RK45"), this)), m_summary(new QLabel(this)),
      m_table(new QTableWidget(0, ColumnCount, this))
{
    setObjectName(QStringLiteral("accuracyDialog"));
    setWindowTitle(tr("Accuracy"));

    // the tolerance, in m per step, and the button that plans for it (Return presses it)
    m_tolerance->setObjectName(QStringLiteral("accuracyTolerance"));
    m_tolerance->setValue(kDefaultTolerance);
    m_tolerance->setMinimumWidth(110);
    m_tolerance->setToolTip(tr("The local position error one step of the integrator (a sub-step) may make"));
    m_plan->setObjectName(QStringLiteral("accuracyPlan"));
    m_plan->setDefault(true);
    m_plan->setToolTip(tr("Measure every fixed-step integrator on the running state and apply the cheapest "
                          "that keeps under the tolerance (one undoable edit)"));
    m_preview->setObjectName(QStringLiteral("accuracyPreview"));
    m_preview->setToolTip(tr("Measure every fixed-step integrator on the running state and show which would be "
                             "picked, without changing the scene"));
    m_adaptive->setObjectName(QStringLiteral("accuracyAdaptive"));
    m_adaptive->setToolTip(tr("Use adaptive-rk45 with this tolerance: it chooses its own sub-steps to keep each "
                              "step's local error under it (one undoable edit)"));
    m_adaptive->setAutoDefault(false);
    m_preview->setAutoDefault(false);
    auto *field = new QHBoxLayout;
    field->addWidget(m_tolerance, 1);
    field->addWidget(new QLabel(tr("m/step"), this));
    field->addWidget(m_preview);
    field->addWidget(m_plan);
    auto *form = new QFormLayout;
    form->addRow(tr("Local error per step"), field);
    connect(m_plan, &QPushButton::clicked, this, [this] {
        if (const std::optional<double> tolerance = acceptedTolerance())
            emit planRequested(*tolerance, true);
    });
    connect(m_preview, &QPushButton::clicked, this, [this] {
        if (const std::optional<double> tolerance = acceptedTolerance())
            emit planRequested(*tolerance, false);
    });
    connect(m_adaptive, &QPushButton::clicked, this, [this] {
        if (const std::optional<double> tolerance = acceptedTolerance())
            emit adaptiveRequested(*tolerance);
    });

    // what was picked and why
    m_summary->setObjectName(QStringLiteral("accuracySummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setText(tr("Springlab measures the local error of each integrator by step doubling on the running "
                          "state, finds the fewest substeps that keep it under the tolerance, and picks the "
                          "cheapest by the measured cost of a force evaluation on this machine."));

    // the candidates
    m_table->setObjectName(QStringLiteral("accuracyTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Integrator"), tr("Substeps"), tr("Local error (m/step)"), tr("Cost per simulated s"), tr("Note")});
    m_table->verticalHeader()->hide();
    // every column as wide as its header and cells, the notes in what is left (elided, whole in
    // their tooltips)
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(Note, QHeaderView::Stretch);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    auto *adaptive = new QHBoxLayout;
    adaptive->addStretch(1);
    adaptive->addWidget(m_adaptive);
    layout->addLayout(adaptive);
    addAdaptiveRow();
    resize(720, 380);
}

QString AccuracyDialog::summary() const
{
    return m_summary->text();
}

void AccuracyDialog::setPlanning(bool planning)
{
    m_plan->setEnabled(!planning);
    m_preview->setEnabled(!planning);
    if (planning)
        m_summary->setText(tr("Planning for %1 m/step…").arg(scientificText(m_tolerance->value())));
}

void AccuracyDialog::showSummary(const QString &summary)
{
    m_summary->setText(summary);
}

std::optional<double> AccuracyDialog::acceptedTolerance()
{
    // a tolerance outside the table's range is refused here and never planned for
    const double tolerance = m_tolerance->value();
    if (const std::optional<std::string> problem = core::checkParameter(core::Parameter::Tolerance, tolerance)) {
        m_summary->setText(tr("The tolerance %1; not planned").arg(QString::fromStdString(*problem)));
        return std::nullopt;
    }
    return tolerance;
}

void AccuracyDialog::addAdaptiveRow()
{
    // not measured by the planner: it keeps under the tolerance by choosing its own sub-steps
    const int r = m_table->rowCount();
    m_table->insertRow(r);
    const std::string_view name = core::integratorName(core::Integrator::AdaptiveRk45);
    const QString cells[ColumnCount] = {
        QString::fromLatin1(name.data(), qsizetype(name.size())),
        tr("its own"),
        tr("≤ the tolerance"),
        tr("not measured"),
        tr("chooses its own sub-steps to keep under the tolerance; Use Adaptive RK45 applies it"),
    };
    for (int c = 0; c < ColumnCount; ++c) {
        auto *item = new QTableWidgetItem(cells[c]);
        item->setToolTip(cells[c]);
        m_table->setItem(r, c, item);
    }
}

void AccuracyDialog::showPlan(const core::AccuracyPlan &plan, const QString &summary)
{
    setPlanning(false);
    m_summary->setText(summary);

    // a row per integrator, the pick in bold
    m_table->setRowCount(0);
    for (std::size_t i = 0; i < plan.candidates.size(); ++i) {
        const core::PlanCandidate &row = plan.candidates[i];
        const int r = m_table->rowCount();
        m_table->insertRow(r);
        const std::string_view name = core::integratorName(row.integrator);
        QString note = QString::fromStdString(row.reason);
        if (static_cast<int>(i) == plan.chosen)
            note = tr("picked: the cheapest");
        else if (row.feasible && row.stabilityLimited)
            note = tr("substeps set by its stability limit");
        const QString cells[ColumnCount] = {
            QString::fromLatin1(name.data(), qsizetype(name.size())),
            row.feasible ? QString::number(row.substeps) : QStringLiteral("—"),
            row.feasible ? scientificText(row.localError) : QStringLiteral("—"),
            row.feasible ? durationText(row.secondsPerSimulatedSecond) : QStringLiteral("—"),
            note,
        };
        for (int c = 0; c < ColumnCount; ++c) {
            auto *item = new QTableWidgetItem(cells[c]);
            item->setToolTip(cells[c]);
            if (static_cast<int>(i) == plan.chosen) {
                QFont bold = item->font();
                bold.setBold(true);
                item->setFont(bold);
            }
            m_table->setItem(r, c, item);
        }
    }
    addAdaptiveRow();
}

}  // namespace ui
