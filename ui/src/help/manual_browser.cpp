#include <finbook/ui/help/manual_browser.h>

#include <QDesktopServices>
#include <QFile>
#include <QHBoxLayout>
#include <QHash>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QSplitter>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QToolButton>
#include <QUrl>
#include <QVBoxLayout>

#include <algorithm>

namespace finbook::ui {

namespace {
const QString kRoot = QStringLiteral("qrc:/manual/");
constexpr int kFileRole = Qt::UserRole;
} // namespace

QList<ManualBrowser::Page> ManualBrowser::pages()
{
    return {
        {QStringLiteral("index.md"), tr("Contents")},
        {QStringLiteral("getting-started.md"), tr("Getting Started: Draw, Bend, Play")},
        {QStringLiteral("drawing.md"), tr("Drawing and the View")},
        {QStringLiteral("fills-and-shading.md"), tr("Fills and Shading")},
        {QStringLiteral("pins.md"), tr("Pins")},
        {QStringLiteral("cage.md"), tr("Cages")},
        {QStringLiteral("bones.md"), tr("Bones and Skeletons")},
        {QStringLiteral("inbetweens.md"), tr("In-betweens")},
        {QStringLiteral("timeline.md"), tr("Timeline, Layers and Sound")},
        {QStringLiteral("lip-sync.md"), tr("Swapping Drawings and Lip Sync")},
        {QStringLiteral("camera.md"), tr("Camera")},
        {QStringLiteral("pictures.md"), tr("Pictures as Objects")},
        {QStringLiteral("reference.md"), tr("Reference Pictures and Video")},
        {QStringLiteral("exporting.md"), tr("Exporting")},
        {QStringLiteral("files.md"), tr("Saving, Autosave and Recovery")},
        {QStringLiteral("command-line.md"), tr("The Command Line")},
        {QStringLiteral("shortcuts.md"), tr("Keyboard Shortcuts")},
        {QStringLiteral("installing.md"), tr("Installing")},
    };
}

QString ManualBrowser::pageForTool(const QString &toolId)
{
    static const QHash<QString, QString> pageOf{
        {QStringLiteral("tool.pen"), QStringLiteral("drawing.md")},
        {QStringLiteral("tool.eraser"), QStringLiteral("drawing.md")},
        {QStringLiteral("tool.select"), QStringLiteral("drawing.md")},
        {QStringLiteral("tool.eyedropper"), QStringLiteral("drawing.md")},
        {QStringLiteral("tool.hand"), QStringLiteral("drawing.md")},
        {QStringLiteral("tool.fill"), QStringLiteral("fills-and-shading.md")},
        {QStringLiteral("tool.pin"), QStringLiteral("pins.md")},
        {QStringLiteral("tool.cage"), QStringLiteral("cage.md")},
        {QStringLiteral("tool.bone"), QStringLiteral("bones.md")},
        {QStringLiteral("tool.camera"), QStringLiteral("camera.md")},
        {QStringLiteral("tool.reference"), QStringLiteral("reference.md")},
    };
    return pageOf.value(toolId, QStringLiteral("index.md"));
}

QString ManualBrowser::pageText(const QString &file)
{
    QFile f(QStringLiteral(":/manual/") + file);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll());
}

ManualBrowser::ManualBrowser(QWidget *parent)
    : QWidget(parent, Qt::Window)
    , m_search(new QLineEdit(this))
    , m_contents(new QListWidget(this))
    , m_text(new QTextBrowser(this))
{
    setObjectName(QStringLiteral("manualBrowser"));
    setWindowTitle(tr("Finbook Manual"));
    resize(980, 720);

    const auto button = [this](const char *name, const QString &icon, const QString &text) {
        auto *b = new QToolButton(this);
        b->setObjectName(QString::fromLatin1(name));
        b->setIcon(QIcon::fromTheme(icon));
        b->setText(text);
        b->setToolTip(text);
        b->setToolButtonStyle(b->icon().isNull() ? Qt::ToolButtonTextOnly : Qt::ToolButtonIconOnly);
        b->setAutoRaise(true);
        return b;
    };
    m_back = button("manualBack", QStringLiteral("go-previous"), tr("Back"));
    m_forward = button("manualForward", QStringLiteral("go-next"), tr("Forward"));
    m_home = button("manualHome", QStringLiteral("go-home"), tr("Contents"));
    m_back->setEnabled(false);
    m_forward->setEnabled(false);

    m_search->setObjectName(QStringLiteral("manualSearch"));
    m_search->setPlaceholderText(tr("Search the manual"));
    m_search->setClearButtonEnabled(true);
    m_contents->setObjectName(QStringLiteral("manualContents"));
    for (const Page &page : pages()) {
        auto *item = new QListWidgetItem(page.title, m_contents);
        item->setData(kFileRole, page.file);
    }
    m_text->setObjectName(QStringLiteral("manualText"));
    m_text->setOpenLinks(false); // pages open here, the web in the browser
    m_text->setSearchPaths({QStringLiteral(":/manual")});

    auto *side = new QWidget(this);
    auto *sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    auto *nav = new QHBoxLayout;
    for (QToolButton *b : {m_back, m_forward, m_home})
        nav->addWidget(b);
    nav->addStretch(1);
    sideLayout->addLayout(nav);
    sideLayout->addWidget(m_search);
    sideLayout->addWidget(m_contents, 1);
    auto *splitter = new QSplitter(this);
    splitter->addWidget(side);
    splitter->addWidget(m_text);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({240, 740});
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(splitter);

    connect(m_contents, &QListWidget::itemActivated, this,
            [this](QListWidgetItem *item) { openPage(item->data(kFileRole).toString()); });
    connect(m_contents, &QListWidget::itemClicked, this,
            [this](QListWidgetItem *item) { openPage(item->data(kFileRole).toString()); });
    connect(m_search, &QLineEdit::textChanged, this, &ManualBrowser::search);
    connect(m_search, &QLineEdit::returnPressed, this, &ManualBrowser::openFirstHit);
    connect(m_back, &QToolButton::clicked, m_text, &QTextBrowser::backward);
    connect(m_forward, &QToolButton::clicked, m_text, &QTextBrowser::forward);
    connect(m_home, &QToolButton::clicked, this, [this] { openPage(QStringLiteral("index.md")); });
    connect(m_text, &QTextBrowser::backwardAvailable, m_back, &QToolButton::setEnabled);
    connect(m_text, &QTextBrowser::forwardAvailable, m_forward, &QToolButton::setEnabled);
    connect(m_text, &QTextBrowser::sourceChanged, this, &ManualBrowser::showCurrentInContents);
    connect(m_text, &QTextBrowser::anchorClicked, this, [this](const QUrl &url) {
        if (url.scheme() == QLatin1String("http") || url.scheme() == QLatin1String("https") ||
            url.scheme() == QLatin1String("mailto")) {
            QDesktopServices::openUrl(url);
            return;
        }
        const QString file = url.path().section(QLatin1Char('/'), -1);
        openPage(file);
    });
    openPage(QStringLiteral("index.md"));
}

void ManualBrowser::openPage(const QString &file)
{
    const QList<Page> all = pages();
    const bool known =
        std::any_of(all.cbegin(), all.cend(), [&](const Page &p) { return p.file == file; });
    const QString shown = known ? file : QStringLiteral("index.md");
    m_text->setSource(QUrl(kRoot + shown), QTextDocument::MarkdownResource);
    showCurrentInContents();
    // The words searched for, highlighted where they first appear on the page.
    if (!m_words.isEmpty()) {
        QList<QTextEdit::ExtraSelection> marks;
        for (const QString &word : m_words) {
            QTextCursor at = m_text->document()->find(word);
            while (!at.isNull() && marks.size() < 500) {
                QTextEdit::ExtraSelection mark;
                mark.cursor = at;
                mark.format.setBackground(QColor(255, 230, 120));
                marks << mark;
                at = m_text->document()->find(word, at);
            }
        }
        m_text->setExtraSelections(marks);
        if (!marks.isEmpty()) {
            m_text->setTextCursor(marks.front().cursor);
            m_text->ensureCursorVisible();
        }
    } else {
        m_text->setExtraSelections({});
    }
}

QString ManualBrowser::currentPage() const
{
    return m_text->source().path().section(QLatin1Char('/'), -1);
}

int ManualBrowser::search(const QString &text)
{
    m_words = text.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    int hits = 0;
    for (int row = 0; row < m_contents->count(); ++row) {
        QListWidgetItem *item = m_contents->item(row);
        bool all = true;
        if (!m_words.isEmpty()) {
            const QString page =
                pageText(item->data(kFileRole).toString()) + QLatin1Char(' ') + item->text();
            for (const QString &word : m_words)
                all = all && page.contains(word, Qt::CaseInsensitive);
        }
        item->setHidden(!all);
        hits += all;
    }
    return hits;
}

void ManualBrowser::openFirstHit()
{
    for (int row = 0; row < m_contents->count(); ++row)
        if (!m_contents->item(row)->isHidden()) {
            m_contents->setCurrentRow(row);
            openPage(m_contents->item(row)->data(kFileRole).toString());
            return;
        }
}

void ManualBrowser::showCurrentInContents()
{
    const QString file = currentPage();
    for (int row = 0; row < m_contents->count(); ++row)
        if (m_contents->item(row)->data(kFileRole).toString() == file) {
            const QSignalBlocker quiet(m_contents);
            m_contents->setCurrentRow(row, QItemSelectionModel::ClearAndSelect);
        }
}

} // namespace finbook::ui
