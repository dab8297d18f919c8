// PalettePanel: the document's palette (model/palette/palette.h) as a grid of swatches.
//
// Clicking a swatch makes its colour the pen's (which the pen, the fill and the shading use).
// The buttons add the pen's colour as a new swatch, recolour the chosen swatch with the pen's
// colour, move it earlier or later and delete it; dragging a swatch reorders too. The field
// under the grid names the chosen swatch (Return renames it). The menu button imports and
// exports GIMP palettes (.gpl: Krita, Inkscape, Pencil2D and GIMP read them), saves the palette
// as a user palette (a .gpl in the user's palette folder, userPaletteFolder()) and loads one.
// Every change to the document's palette is one undo step.
#pragma once

#include <finbook/model/palette/palette.h>

#include <QWidget>

class QLabel;
class QLineEdit;
class QListWidget;
class QMenu;
class QToolButton;

namespace finbook::model {
class Document;
}

namespace finbook::ui {

class PenTool;

class PalettePanel : public QWidget {
    Q_OBJECT
public:
    PalettePanel(model::Document *document, PenTool *pen, QWidget *parent = nullptr);

    QListWidget *grid() const { return m_grid; }
    QLineEdit *nameField() const { return m_name; }
    int currentSwatch() const; // -1 when none is chosen

    // The folder of user palettes: $FINBOOK_PALETTE_DIR when set (tests), else "palettes" in
    // the user's application data folder.
    static QString userPaletteFolder();
    // The user palettes there, by name (their files' names without ".gpl"), sorted.
    static QStringList userPalettes();

    // What the menu's entries do once their dialog has answered; each returns an empty string
    // or a sentence saying why nothing changed (also shown in a message box by the menu).
    QString importGpl(const QString &path);
    QString exportGpl(const QString &path) const;
    QString saveAsUserPalette(const QString &name) const;
    QString loadUserPalette(const QString &name);

    QSize sizeHint() const override { return {260, 180}; }

signals:
    // A sentence for the status bar (a palette saved, a file that could not be read).
    void messagePosted(const QString &message);

private:
    void rebuild();
    void push(model::Palette palette, const QString &text);
    void addPenColour();
    void recolourWithPen();
    void removeCurrent();
    void moveCurrent(int by);
    void renameCurrent();
    void reorderFromGrid();
    void showCurrentName();
    void fillLoadMenu();
    void chooseImport();
    void chooseExport();
    void chooseSaveAsUser();
    void updateButtons();

    model::Document *m_doc;
    PenTool *m_pen;
    QListWidget *m_grid;
    QLineEdit *m_name;
    QToolButton *m_add, *m_recolour, *m_earlier, *m_later, *m_remove, *m_menuButton;
    QMenu *m_loadMenu = nullptr;
    bool m_rebuilding = false;
};

} // namespace finbook::ui
