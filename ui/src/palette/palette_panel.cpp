#include <finbook/model/document.h>
#include <finbook/model/io/atomic_file.h>
#include <finbook/ui/palette/palette_panel.h>
#include <finbook/ui/tools/tool_pen.h>

#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace finbook::ui {

namespace {
constexpr int kCell = 22;
constexpr int kSwatchIndexRole = Qt::UserRole; // the swatch's index in the palette shown

QIcon swatchIcon(QRgb color)
{
    QPixmap pixmap(kCell - 4, kCell - 4);
    pixmap.fill(QColor::fromRgb(color));
    QPainter painter(&pixmap);
    painter.setPen(QColor(0, 0, 0, 90));
    painter.drawRect(pixmap.rect().adjusted(0, 0, -1, -1));
    return QIcon(pixmap);
}

QString fileError(const QString &path, const QString &why)
{
    return PalettePanel::tr("\"%1\" is not a palette Finbook can read: %2.")
        .arg(QFileInfo(path).fileName(), why);
}
} // namespace

PalettePanel::PalettePanel(model::Document *document, PenTool *pen, QWidget *parent)
    : QWidget(parent)
    , m_doc(document)
    , m_pen(pen)
    , m_grid(new QListWidget(this))
    , m_name(new QLineEdit(this))
{
    setObjectName(QStringLiteral("palettePanel"));
    m_grid->setObjectName(QStringLiteral("paletteSwatches"));
    m_grid->setViewMode(QListView::ListMode); // rows in order, wrapped: a drop reorders them
    m_grid->setFlow(QListView::LeftToRight);
    m_grid->setWrapping(true);
    m_grid->setResizeMode(QListView::Adjust);
    m_grid->setUniformItemSizes(true);
    m_grid->setGridSize(QSize(kCell, kCell));
    m_grid->setIconSize(QSize(kCell - 4, kCell - 4));
    m_grid->setSpacing(0);
    m_grid->setDragDropMode(QAbstractItemView::InternalMove);
    m_grid->setDefaultDropAction(Qt::MoveAction);
    m_grid->setSelectionMode(QAbstractItemView::SingleSelection);
    m_grid->setFocusPolicy(Qt::NoFocus); // a click picks a colour; the keys stay the canvas's

    m_name->setObjectName(QStringLiteral("paletteSwatchName"));
    m_name->setPlaceholderText(tr("Swatch name"));
    m_name->setToolTip(tr("The chosen swatch's name: type and press Return to rename it"));

    const auto button = [this](const char *name, const QString &icon, const QString &text,
                               const QString &tip) {
        auto *b = new QToolButton(this);
        b->setObjectName(QString::fromLatin1(name));
        b->setAutoRaise(true);
        b->setIcon(QIcon::fromTheme(icon));
        b->setText(text);
        b->setToolTip(tip);
        if (b->icon().isNull())
            b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        b->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed); // never cut
        return b;
    };
    m_add = button("paletteAdd", QStringLiteral("list-add"), QStringLiteral("+"),
                   tr("Add the pen's colour to the palette"));
    m_recolour = button("paletteRecolour", QStringLiteral("color-picker"), tr("Set"),
                        tr("Give the chosen swatch the pen's colour"));
    m_earlier = button("paletteEarlier", QStringLiteral("go-previous"), QStringLiteral("◀"),
                       tr("Move the chosen swatch one place earlier"));
    m_later = button("paletteLater", QStringLiteral("go-next"), QStringLiteral("▶"),
                     tr("Move the chosen swatch one place later"));
    m_remove = button("paletteRemove", QStringLiteral("list-remove"), QStringLiteral("−"),
                      tr("Delete the chosen swatch from the palette"));
    m_menuButton = button("paletteMenu", QStringLiteral("open-menu"), QStringLiteral("≡"),
                          tr("Import, export, save and load palettes"));
    m_menuButton->setPopupMode(QToolButton::InstantPopup);
    auto *menu = new QMenu(m_menuButton);
    menu->addAction(tr("&Import GIMP Palette..."), this, &PalettePanel::chooseImport);
    menu->addAction(tr("&Export GIMP Palette..."), this, &PalettePanel::chooseExport);
    menu->addSeparator();
    menu->addAction(tr("&Save as User Palette..."), this, &PalettePanel::chooseSaveAsUser);
    m_loadMenu = menu->addMenu(tr("&Load User Palette"));
    connect(m_loadMenu, &QMenu::aboutToShow, this, &PalettePanel::fillLoadMenu);
    menu->addSeparator();
    menu->addAction(tr("&Reset to Finbook's Colours"), this,
                    [this] { push(model::defaultPalette(), tr("Reset Palette")); });
    m_menuButton->setMenu(menu);
    // QToolButton's size hint leaves out the menu arrow of an instant popup.
    m_menuButton->setFixedWidth(
        m_menuButton->sizeHint().width() +
        m_menuButton->style()->pixelMetric(QStyle::PM_MenuButtonIndicator, nullptr, m_menuButton));

    auto *buttons = new QHBoxLayout;
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->setSpacing(0);
    for (QToolButton *b : {m_add, m_recolour, m_earlier, m_later, m_remove})
        buttons->addWidget(b);
    buttons->addStretch(1);
    buttons->addWidget(m_menuButton);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addLayout(buttons);
    layout->addWidget(m_grid, 1);
    layout->addWidget(m_name);

    connect(m_add, &QToolButton::clicked, this, &PalettePanel::addPenColour);
    connect(m_recolour, &QToolButton::clicked, this, &PalettePanel::recolourWithPen);
    connect(m_earlier, &QToolButton::clicked, this, [this] { moveCurrent(-1); });
    connect(m_later, &QToolButton::clicked, this, [this] { moveCurrent(+1); });
    connect(m_remove, &QToolButton::clicked, this, &PalettePanel::removeCurrent);
    connect(m_name, &QLineEdit::returnPressed, this, &PalettePanel::renameCurrent);
    connect(m_grid, &QListWidget::itemClicked, this, [this](QListWidgetItem *item) {
        const int index = item->data(kSwatchIndexRole).toInt();
        const auto &swatches = m_doc->palette().swatches;
        if (index < 0 || index >= int(swatches.size()))
            return;
        PenSettings s = m_pen->settings();
        s.color = QColor::fromRgb(swatches[std::size_t(index)].color);
        m_pen->setSettings(s);
    });
    connect(m_grid, &QListWidget::currentRowChanged, this, [this] {
        showCurrentName();
        updateButtons();
    });
    // A drop has moved a row: the palette follows once the drop is over.
    connect(m_grid->model(), &QAbstractItemModel::rowsMoved, this,
            [this] { QTimer::singleShot(0, this, &PalettePanel::reorderFromGrid); });
    // The pen's colour picked elsewhere (the eyedropper, the colour button, a shortcut): the
    // swatch of that colour is the chosen one, as in Krita's and Pencil2D's palettes. A colour
    // no swatch has leaves the choice as it is, so that Set can still give it to that swatch.
    connect(m_pen, &PenTool::settingsChanged, this, [this](const PenSettings &settings) {
        const auto &swatches = m_doc->palette().swatches;
        const int current = m_grid->currentRow();
        if (current >= 0 && current < int(swatches.size()) &&
            swatches[std::size_t(current)].color == settings.color.rgb())
            return;
        for (int row = 0; row < m_grid->count(); ++row) {
            const int index = m_grid->item(row)->data(kSwatchIndexRole).toInt();
            if (index >= 0 && index < int(swatches.size()) &&
                swatches[std::size_t(index)].color == settings.color.rgb()) {
                m_grid->setCurrentRow(row);
                return;
            }
        }
    });
    connect(m_doc, &model::Document::paletteChanged, this, &PalettePanel::rebuild);
    connect(m_doc, &model::Document::documentReset, this, &PalettePanel::rebuild);
    rebuild();
}

int PalettePanel::currentSwatch() const
{
    return m_grid->currentRow();
}

void PalettePanel::rebuild()
{
    m_rebuilding = true;
    const int current = m_grid->currentRow();
    m_grid->clear();
    const model::Palette &palette = m_doc->palette();
    for (std::size_t i = 0; i < palette.swatches.size(); ++i) {
        const model::Swatch &s = palette.swatches[i];
        auto *item = new QListWidgetItem(swatchIcon(s.color), QString(), m_grid);
        item->setData(kSwatchIndexRole, int(i));
        const QString hex = QColor::fromRgb(s.color).name();
        item->setToolTip(s.name.isEmpty() ? hex : tr("%1 (%2)").arg(s.name, hex));
        item->setData(Qt::AccessibleTextRole, s.name.isEmpty() ? hex : s.name);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled);
    }
    if (m_grid->count() > 0)
        m_grid->setCurrentRow(std::clamp(current, 0, m_grid->count() - 1));
    m_rebuilding = false;
    showCurrentName();
    updateButtons();
}

void PalettePanel::push(model::Palette palette, const QString &text)
{
    if (model::sanitizedPalette(palette) == m_doc->palette())
        return;
    m_doc->undoStack()->push(new model::SetPaletteCommand(m_doc, std::move(palette), text));
}

void PalettePanel::addPenColour()
{
    model::Palette p = m_doc->palette();
    if (int(p.swatches.size()) >= model::kMaxSwatches) {
        emit messagePosted(tr("A palette holds at most %1 colours.").arg(model::kMaxSwatches));
        return;
    }
    const QRgb color = m_pen->settings().color.rgb();
    p.swatches.push_back({color, QColor::fromRgb(color).name()});
    push(std::move(p), tr("Add Swatch"));
    m_grid->setCurrentRow(m_grid->count() - 1);
}

void PalettePanel::recolourWithPen()
{
    const int i = currentSwatch();
    model::Palette p = m_doc->palette();
    if (i < 0 || i >= int(p.swatches.size()))
        return;
    p.swatches[std::size_t(i)].color = m_pen->settings().color.rgb();
    push(std::move(p), tr("Recolour Swatch"));
}

void PalettePanel::removeCurrent()
{
    const int i = currentSwatch();
    model::Palette p = m_doc->palette();
    if (i < 0 || i >= int(p.swatches.size()))
        return;
    p.swatches.erase(p.swatches.begin() + i);
    push(std::move(p), tr("Delete Swatch"));
}

void PalettePanel::moveCurrent(int by)
{
    const int i = currentSwatch();
    model::Palette p = m_doc->palette();
    const int to = i + by;
    if (i < 0 || to < 0 || to >= int(p.swatches.size()))
        return;
    std::swap(p.swatches[std::size_t(i)], p.swatches[std::size_t(to)]);
    push(std::move(p), tr("Move Swatch"));
    m_grid->setCurrentRow(to);
}

void PalettePanel::renameCurrent()
{
    const int i = currentSwatch();
    model::Palette p = m_doc->palette();
    if (i < 0 || i >= int(p.swatches.size()))
        return;
    p.swatches[std::size_t(i)].name = m_name->text();
    push(std::move(p), tr("Rename Swatch"));
    showCurrentName(); // as cleaned (one line, trimmed)
}

void PalettePanel::reorderFromGrid()
{
    if (m_rebuilding)
        return;
    const model::Palette &now = m_doc->palette();
    model::Palette p;
    p.name = now.name;
    int moved = -1;
    for (int row = 0; row < m_grid->count(); ++row) {
        const int index = m_grid->item(row)->data(kSwatchIndexRole).toInt();
        if (index < 0 || index >= int(now.swatches.size())) {
            rebuild(); // the grid no longer shows this palette: show it again
            return;
        }
        p.swatches.push_back(now.swatches[std::size_t(index)]);
        if (m_grid->item(row)->isSelected())
            moved = row;
    }
    if (p.swatches.size() != now.swatches.size()) {
        rebuild();
        return;
    }
    push(std::move(p), tr("Move Swatch"));
    if (moved >= 0)
        m_grid->setCurrentRow(moved);
}

void PalettePanel::showCurrentName()
{
    if (m_rebuilding)
        return;
    const int i = currentSwatch();
    const auto &swatches = m_doc->palette().swatches;
    const bool chosen = i >= 0 && i < int(swatches.size());
    m_name->setEnabled(chosen);
    m_name->setText(chosen ? swatches[std::size_t(i)].name : QString());
}

void PalettePanel::updateButtons()
{
    const int i = currentSwatch(), n = m_grid->count();
    m_recolour->setEnabled(i >= 0);
    m_remove->setEnabled(i >= 0);
    m_earlier->setEnabled(i > 0);
    m_later->setEnabled(i >= 0 && i + 1 < n);
}

QString PalettePanel::userPaletteFolder()
{
    const QString overridden = qEnvironmentVariable("FINBOOK_PALETTE_DIR");
    if (!overridden.isEmpty())
        return overridden;
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("palettes"));
}

QStringList PalettePanel::userPalettes()
{
    QStringList names;
    const QFileInfoList files =
        QDir(userPaletteFolder())
            .entryInfoList({QStringLiteral("*.gpl")}, QDir::Files, QDir::Name | QDir::IgnoreCase);
    for (const QFileInfo &f : files)
        names << f.completeBaseName();
    return names;
}

QString PalettePanel::importGpl(const QString &path)
{
    QFile file(path);
    // A palette file is small; one of more than a few megabytes is not a palette.
    if (file.size() > 8 * 1024 * 1024)
        return fileError(path, tr("it is far larger than a palette"));
    if (!file.open(QIODevice::ReadOnly))
        return fileError(path, file.errorString());
    const Expected<model::Palette, QString> palette = model::readGpl(file.readAll());
    if (!palette)
        return fileError(path, palette.error());
    model::Palette p = *palette;
    if (p.name.isEmpty())
        p.name = QFileInfo(path).completeBaseName();
    push(std::move(p), tr("Import Palette"));
    return {};
}

QString PalettePanel::exportGpl(const QString &path) const
{
    if (const auto failure = model::writeFileAtomically(path, model::writeGpl(m_doc->palette())))
        return tr("The palette could not be saved as \"%1\": %2")
            .arg(QFileInfo(path).fileName(),
                 model::describeWriteFailure(*failure, QFileInfo(path).absolutePath()));
    return {};
}

QString PalettePanel::saveAsUserPalette(const QString &name) const
{
    QString clean = name.simplified();
    // A file name on every system: no separators, no leading dot.
    clean.replace(QRegularExpression(QStringLiteral("[/\\\\:*?\"<>|]")), QStringLiteral("-"));
    while (clean.startsWith(QLatin1Char('.')))
        clean.remove(0, 1);
    if (clean.isEmpty())
        return tr("A user palette needs a name.");
    if (!QDir().mkpath(userPaletteFolder()))
        return tr("The folder for user palettes (%1) could not be made.")
            .arg(QDir::toNativeSeparators(userPaletteFolder()));
    model::Palette p = m_doc->palette();
    p.name = clean;
    const QString path = QDir(userPaletteFolder()).filePath(clean + QStringLiteral(".gpl"));
    if (const auto failure = model::writeFileAtomically(path, model::writeGpl(p)))
        return tr("The palette could not be saved as \"%1\": %2")
            .arg(clean, model::describeWriteFailure(*failure, userPaletteFolder()));
    return {};
}

QString PalettePanel::loadUserPalette(const QString &name)
{
    return importGpl(QDir(userPaletteFolder()).filePath(name + QStringLiteral(".gpl")));
}

void PalettePanel::fillLoadMenu()
{
    m_loadMenu->clear();
    const QStringList names = userPalettes();
    if (names.isEmpty()) {
        m_loadMenu->addAction(tr("(no user palettes yet)"))->setEnabled(false);
        return;
    }
    for (const QString &name : names)
        m_loadMenu->addAction(name, this, [this, name] {
            const QString error = loadUserPalette(name);
            if (!error.isEmpty())
                QMessageBox::warning(this, tr("Load Palette"), error);
        });
}

void PalettePanel::chooseImport()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Import GIMP Palette"), QString(),
                                                      tr("GIMP palettes (*.gpl);;All files (*)"));
    if (path.isEmpty())
        return;
    const QString error = importGpl(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Import Palette"), error);
}

void PalettePanel::chooseExport()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Export GIMP Palette"),
                                                m_doc->palette().name + QStringLiteral(".gpl"),
                                                tr("GIMP palettes (*.gpl)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QLatin1String(".gpl"), Qt::CaseInsensitive))
        path += QStringLiteral(".gpl");
    const QString error = exportGpl(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export Palette"), error);
    else
        emit messagePosted(tr("Palette saved as \"%1\".").arg(QFileInfo(path).fileName()));
}

void PalettePanel::chooseSaveAsUser()
{
    bool ok = false;
    const QString name =
        QInputDialog::getText(this, tr("Save as User Palette"), tr("Name of the palette:"),
                              QLineEdit::Normal, m_doc->palette().name, &ok);
    if (!ok)
        return;
    const QString error = saveAsUserPalette(name);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Save Palette"), error);
    else
        emit messagePosted(tr("Saved as the user palette \"%1\"; Palette > Load User Palette "
                              "brings it into any drawing.")
                               .arg(name.simplified()));
}

} // namespace finbook::ui
