#pragma once
// GeneratePreview: the Generate dialog's picture of what a generator makes, drawn with QPainter in
// an oblique projection (x to the right, y up, -z receding up and to the right at half scale), fitted
// to the widget, in the viewport's palette: springs as lines, particles as discs to scale (pinned
// in violet). A huge scene is thinned to every k-th item so that a repaint stays quick.

#include "core/model/scene.h"

#include <QWidget>
#include <memory>

namespace ui {

class GeneratePreview : public QWidget {
    Q_OBJECT

public:
    explicit GeneratePreview(QWidget *parent = nullptr);

    // what to draw; null draws an empty frame
    void setScene(std::shared_ptr<const core::SceneDesc> scene);
    const std::shared_ptr<const core::SceneDesc> &scene() const { return m_scene; }

    // what the latest paint drew, and how many paints there were, for the tests
    int paintCount() const { return m_paints; }
    int drawnParticles() const { return m_drawnParticles; }
    int drawnSprings() const { return m_drawnSprings; }

    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    std::shared_ptr<const core::SceneDesc> m_scene;
    int m_paints = 0;
    int m_drawnParticles = 0;
    int m_drawnSprings = 0;
};

}  // namespace ui
