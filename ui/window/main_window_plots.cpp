// MainWindow's plots dock: energies, momentum and the selected particle's motion against time,
// fed by the samples of every step that the frames carry, and its exports through the window's
// file dialog.

#include "main_window.h"

#include "ui/document/document_files.h"
#include "ui/viewport/edit_tools.h"
#include "ui/panels/plots_widget.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QStatusBar>

namespace ui {

void MainWindow::createPlotsDock()
{
    // below the view, hidden until asked for (View › Plots, F8)
    m_plots = new PlotsWidget;
    m_plots->setObjectName(QStringLiteral("plots"));
    m_plotsDock = new QDockWidget(tr("Plots"), this);
    m_plotsDock->setObjectName(QStringLiteral("plotsDock"));
    m_plotsDock->setWidget(m_plots);
    QAction *toggle = addHiddenDock(m_plotsDock, Qt::BottomDockWidgetArea, "actionPlots",
                                    tr("Show or hide the plots of energy, momentum and the selected particle against "
                                       "time"));
    toggle->setShortcut(Qt::Key_F8);

    // the first particle selected is the one plotted, and the worker samples its motion
    connect(m_tools, &EditTools::selectionChanged, this, [this] {
        const std::vector<int> &particles = m_tools->selection().particles;
        const int particle = particles.empty() ? -1 : particles.front();
        m_plots->setParticle(particle);
        m_controller->setPlottedParticle(particle);
    });
    connect(m_plots, &PlotsWidget::exportRequested, this, &MainWindow::exportPlot);
}

void MainWindow::exportPlot(PlotExport format)
{
    // a file for the plot shown, named after the scene and the plot
    const bool png = format == PlotExport::Png;
    const QString title = png ? tr("Export plot as PNG") : tr("Export plot data as CSV");
    const QString suggested = QDir(m_document->folder()).filePath(QStringLiteral("%1-%2.%3")
                                                        .arg(m_document->displayName(), m_plots->suggestedName(),
                                                             png ? QStringLiteral("png") : QStringLiteral("csv")));
    const QString path = m_prompts.chooseFile(FileDialogMode::Save, title, suggested,
                                    png ? tr("PNG images (*.png)") : tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    // never over the scene or a recovery file, by any name
    if (const QString refused = m_files->protectedFileAt(path); !refused.isEmpty()) {
        m_prompts.ask(QMessageBox::Warning, title, tr("%1: cannot save: %2").arg(QDir::toNativeSeparators(path), refused));
        return;
    }
    QString error;
    if (!(png ? m_plots->savePng(path, &error) : m_plots->saveCsv(path, &error))) {
        m_prompts.ask(QMessageBox::Warning, title, error);
        return;
    }
    statusBar()->showMessage(tr("Plot saved to %1").arg(QDir::toNativeSeparators(path)), 5000);
}

}  // namespace ui
