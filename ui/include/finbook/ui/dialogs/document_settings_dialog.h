// DocumentSettingsDialog: frame rate, canvas size, background colour, loop and play range.
// OK pushes one ChangeSettingsCommand (nothing when nothing changed), so the whole change is
// one undo step. Play range fields are 1-based; an end of 0 shows "Last" (playEnd = -1).
#pragma once

#include <finbook/model/document.h>

#include <QDialog>

class QCheckBox;
class QPushButton;
class QSpinBox;

namespace finbook::ui {

class DocumentSettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit DocumentSettingsDialog(model::Document *document, QWidget *parent = nullptr);

    // Shows the dialog modally and applies it on OK. True if the settings changed.
    static bool edit(model::Document *document, QWidget *parent);

    void setSettings(const model::DocumentSettings &settings);
    // What the fields say, clamped to what the editor supports.
    model::DocumentSettings settings() const;
    // Pushes the ChangeSettingsCommand; true if anything changed.
    bool apply();
    void accept() override;

    QSpinBox *fpsBox() const { return m_fps; }
    QSpinBox *widthBox() const { return m_width; }
    QSpinBox *heightBox() const { return m_height; }
    QCheckBox *loopBox() const { return m_loop; }
    QSpinBox *playStartBox() const { return m_start; }
    QSpinBox *playEndBox() const { return m_end; }
    QPushButton *backgroundButton() const { return m_backgroundButton; }
    void setBackground(QColor color);

private:
    void chooseBackground();

    model::Document *m_doc;
    QSpinBox *m_fps;
    QSpinBox *m_width;
    QSpinBox *m_height;
    QPushButton *m_backgroundButton;
    QColor m_background;
    QCheckBox *m_loop;
    QSpinBox *m_start;
    QSpinBox *m_end;
};

} // namespace finbook::ui
