#pragma once
// GenerateDialog: Edit › Generate…. A kind (cloth, rope, chain, block or ball of loose particles,
// soft ball), a form of its options with their units, where the middle of the result goes, and a
// preview of what it makes, remade as soon as a value changes, with the count of particles and
// springs, or what is wrong with the options (then the Add button is off). The generators and their
// checks are core's (core/model/generators.h); the main window adds the result to the scene as one
// undoable edit (ui::addGenerated). Shown with open(): modal to the window, without an event loop
// of its own, so the tests drive it like any widget. The options stay as set between openings.

#include "core/model/generators.h"

#include <Eigen/Core>
#include <QDialog>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QStackedWidget;

namespace ui {

class GeneratePreview;
class ValueSpinBox;

class GenerateDialog : public QDialog {
    Q_OBJECT

public:
    explicit GenerateDialog(QWidget *parent = nullptr);

    // the kinds, in the order of the kind box
    enum class Kind { Cloth, Rope, Chain, Block, Ball, SoftBall };

    Kind kind() const;
    // the kind's name as the box shows it ("Cloth"), for the undo step's text
    QString kindName() const;
    // what Add would add, as generated (before it is moved to position()); null while the
    // options are wrong
    std::shared_ptr<const core::SceneDesc> generated() const { return m_generated; }
    // where the middle of the generated particles' box goes, m
    Eigen::Vector3d position() const;

    QComboBox *kindBox() const { return m_kindBox; }
    GeneratePreview *preview() const { return m_preview; }
    QPushButton *addButton() const { return m_add; }
    // "1024 particles, 5953 springs", or empty while the options are wrong
    QString countText() const;
    // what is wrong with the options, or empty
    QString problemText() const;

private:
    // one kind: its form, its check and its generator, reading the options its form edits
    struct KindPage {
        QString name;
        std::function<std::optional<std::string>()> check;
        std::function<core::SceneDesc()> make;
    };
    void addKinds(QStackedWidget *pages);
    // makes the chosen kind's scene again, or says why not
    void regenerate();

    core::ClothOptions m_cloth;
    core::RopeOptions m_rope;
    core::ChainOptions m_chain;
    core::BlockOptions m_block;
    core::BallOptions m_ball;
    core::SoftBallOptions m_softBall;

    std::vector<KindPage> m_kinds;
    std::shared_ptr<const core::SceneDesc> m_generated;
    QComboBox *m_kindBox = nullptr;
    ValueSpinBox *m_position[3] = {};
    GeneratePreview *m_preview = nullptr;
    QLabel *m_count = nullptr;
    QLabel *m_problem = nullptr;
    QPushButton *m_add = nullptr;
};

}  // namespace ui
