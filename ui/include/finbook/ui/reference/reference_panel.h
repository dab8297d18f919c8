// The Reference panel: the reference layer's visibility, lock, opacity, place, scale, rotation
// and (for a video) rate, and removing it. Every change is an undoable reference command;
// the panel follows the document (undo, open, import) through referenceChanged.
#pragma once

#include <finbook/model/reference/reference_commands.h>

#include <QStringList>
#include <QWidget>

#include <optional>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;

namespace finbook::model {
class Document;
}

namespace finbook::ui {

class ReferencePanel : public QWidget {
    Q_OBJECT
public:
    explicit ReferencePanel(model::Document *document, QWidget *parent = nullptr);

    QSlider *opacitySlider() const { return m_opacity; }
    QCheckBox *visibleBox() const { return m_visible; }
    QCheckBox *lockedBox() const { return m_locked; }
    QDoubleSpinBox *xBox() const { return m_x; }
    QDoubleSpinBox *yBox() const { return m_y; }
    QDoubleSpinBox *scaleBox() const { return m_scale; }
    QDoubleSpinBox *rotationBox() const { return m_rotation; }
    QDoubleSpinBox *rateBox() const { return m_rate; }
    QLabel *rateLabel() const { return m_rateLabel; }

private:
    void refresh();
    void edit(model::ReferenceEdit edit);

    model::Document *m_doc;
    QLabel *m_name = nullptr;
    QCheckBox *m_visible = nullptr;
    QCheckBox *m_locked = nullptr;
    QSlider *m_opacity = nullptr;
    QDoubleSpinBox *m_x = nullptr;
    QDoubleSpinBox *m_y = nullptr;
    QDoubleSpinBox *m_scale = nullptr;
    QDoubleSpinBox *m_rotation = nullptr;
    QDoubleSpinBox *m_rate = nullptr;
    QLabel *m_rateLabel = nullptr;
    QPushButton *m_remove = nullptr;
    bool m_refreshing = false;
};

// Reads `path` and pushes the command that imports it as the document's reference. The
// sentence to show when the file is refused (the document is then unchanged).
std::optional<QString> importReference(model::Document &document, const QString &path);
// The same for several pictures, imported as one sequence (one picture per frame) in the
// order given; one path is importReference(document, path).
std::optional<QString> importReference(model::Document &document, const QStringList &paths);

// Asks for the files to import as a reference (File → Import Reference…): one picture or
// video, several pictures, or one picture of a numbered run (shot_0001.png …), which offers
// the whole run. Empty when cancelled.
QStringList chooseReferenceFiles(QWidget *parent, const QString &folder);

// The file-dialog filter of what importReference reads.
QString referenceFileFilter();

} // namespace finbook::ui
