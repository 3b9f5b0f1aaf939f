#pragma once
// PlotsWidget: the plots dock. It keeps one series per group of quantities (energies, momentum,
// the selected particle's position and its velocity), adds to each the samples of every step that
// the worker's frames carry (session/step_samples.h: taken on the worker after each step, so the
// plots miss no step however seldom the window draws), and shows the group chosen in its box on a
// PlotCanvas. A long run's series keep every 2nd, 4th, … step (plot_series.h). Export PNG and Export CSV
// (its buttons, or the canvas's context menu) ask the main window for a file through
// exportRequested(), so that the file dialog stays the window's, and tests can answer it.
//
// The core does not book energy lost to damping, drag or contacts; the energies plot shows "lost
// since reset" as the total energy at the last reset or scene load less the total now. That also
// counts the integrator's own drift and work done by the mouse, the steering or edits.

#include "plot_series.h"

#include <QString>
#include <QWidget>

#include <array>
#include <cstdint>

class QAction;
class QComboBox;

namespace ui {

class PlotCanvas;
struct SimulationFrame;
struct StepSample;

enum class PlotGroup { Energies, Momentum, Position, Velocity };
enum class PlotExport { Png, Csv };

class PlotsWidget : public QWidget {
    Q_OBJECT

public:
    explicit PlotsWidget(QWidget *parent = nullptr);

    // a frame from the worker: its samples not seen before, a sample of every group per step
    void addFrame(const SimulationFrame &frame);
    // the particle whose position and velocity are plotted, an index into the scene (-1: none);
    // another particle starts those two plots over, with the samples that follow it (the window
    // tells the worker which particle to follow: SimulationController::setPlottedParticle)
    void setParticle(int particle);
    int particle() const { return m_particle; }
    // frames from before the worker applied this edit are of the scene being replaced: they are
    // passed over, and the first one after it starts every plot over
    void startOverAfter(std::uint64_t edit);

    PlotGroup group() const { return m_group; }
    void setGroup(PlotGroup group);
    const PlotSeries &series(PlotGroup group) const { return m_series[static_cast<std::size_t>(group)]; }
    const PlotSeries &shownSeries() const { return series(m_group); }

    PlotCanvas *canvas() const { return m_canvas; }
    QComboBox *groupBox() const { return m_groupBox; }
    QAction *exportPngAction() const { return m_exportPng; }
    QAction *exportCsvAction() const { return m_exportCsv; }

    // the shown plot as an image of the canvas, or its samples as CSV; false, and why, on failure
    bool savePng(const QString &path, QString *error = nullptr) const;
    bool saveCsv(const QString &path, QString *error = nullptr) const;
    // a file name (without extension) for the shown plot: "energies", "particle-12-position"
    QString suggestedName() const;

signals:
    void exportRequested(ui::PlotExport format);

private:
    void showGroup();
    void addSample(const StepSample &sample);

    std::array<PlotSeries, 4> m_series;
    std::uint64_t m_resumes = 0;  // the timeline's resumes seen
    std::uint64_t m_lastSample = 0;  // the sequence number of the newest sample added
    PlotGroup m_group = PlotGroup::Energies;
    int m_particle = -1;
    std::uint64_t m_startOverAfter = 0;  // 0: no scene is being replaced

    QComboBox *m_groupBox = nullptr;
    PlotCanvas *m_canvas = nullptr;
    QAction *m_exportPng = nullptr;
    QAction *m_exportCsv = nullptr;
};

}  // namespace ui
