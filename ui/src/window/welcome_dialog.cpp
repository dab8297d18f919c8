#include <finbook/ui/window/welcome_dialog.h>

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace finbook::ui {

namespace {
const QString kSeenKey = QStringLiteral("welcome/seen");
const QString kAtStartKey = QStringLiteral("welcome/atStart");
} // namespace

bool WelcomeDialog::shouldShowAtStart()
{
    QSettings settings;
    return !settings.value(kSeenKey, false).toBool() || settings.value(kAtStartKey, false).toBool();
}

void WelcomeDialog::markShown()
{
    QSettings().setValue(kSeenKey, true);
}

WelcomeDialog::WelcomeDialog(const QStringList &recentFiles, QWidget *parent)
    : QDialog(parent)
    , m_recent(new QListWidget(this))
    , m_walkthrough(new QTextBrowser(this))
    , m_atStart(new QCheckBox(tr("Show this page whenever Finbook starts"), this))
{
    setObjectName(QStringLiteral("welcomeDialog"));
    setWindowTitle(tr("Welcome to Finbook"));
    resize(820, 520);

    const auto button = [this](const char *name, const QString &text, const QString &tip) {
        auto *b = new QPushButton(text, this);
        b->setObjectName(QString::fromLatin1(name));
        b->setToolTip(tip);
        b->setMinimumHeight(34);
        return b;
    };
    m_new = button("welcomeNew", tr("&New Animation"), tr("Start an empty animation"));
    m_open = button("welcomeOpen", tr("&Open..."), tr("Open a .finbook file"));
    m_example = button("welcomeExample", tr("Open the &Example"),
                       tr("A short walk cycle drawn with Finbook, to look at and change"));
    m_manual = button("welcomeManual", tr("Read the &Manual"),
                      tr("The Finbook Manual (F1 opens it at the tool in hand)"));
    m_recent->setObjectName(QStringLiteral("welcomeRecent"));
    for (const QString &path : recentFiles) {
        auto *item = new QListWidgetItem(QFileInfo(path).fileName(), m_recent);
        item->setToolTip(path);
        item->setData(Qt::UserRole, path);
    }
    if (recentFiles.isEmpty()) {
        auto *none = new QListWidgetItem(tr("(no recent files yet)"), m_recent);
        none->setFlags(Qt::NoItemFlags);
    }

    m_walkthrough->setObjectName(QStringLiteral("welcomeWalkthrough"));
    m_walkthrough->setOpenLinks(false);
    m_walkthrough->setHtml(
        tr("<h2>Draw — bend — play</h2>"
           "<p><b>1. Draw.</b> Take the pen (<b>B</b>) and draw a character; a tablet's pressure "
           "shapes the line. Close its outline loosely: small gaps close by themselves. Pick a "
           "colour in the Palette and click inside with the fill (<b>F</b>).</p>"
           "<p><b>2. Bend.</b> Instead of drawing the next frame again, duplicate the frame "
           "(<b>Ctrl+D</b>) and bend the copy: click the drawing with the bone tool (<b>K</b>) "
           "and drag a bone, or put pins on it (<b>P</b>) and drag one; the rest follows as if "
           "drawn on rubber. The bent drawing is lines again: keep drawing on it.</p>"
           "<p><b>3. Play.</b> Press <b>Return</b> to play; Frame → In-betweens fills the "
           "frames between two poses. Onion skin (<b>O</b>) shows the neighbours faintly. Save "
           "with <b>Ctrl+S</b>, export a GIF, a video or a Lottie animation with File → "
           "Export.</p>"
           "<p><a href=\"getting-started.md\">Read “Getting Started” in the manual</a>, or press "
           "<b>F1</b> at any time for the page of the tool in hand.</p>"));
    m_atStart->setObjectName(QStringLiteral("welcomeAtStart"));
    m_atStart->setChecked(QSettings().value(kAtStartKey, false).toBool());

    auto *left = new QVBoxLayout;
    for (QPushButton *b : {m_new, m_open, m_example, m_manual})
        left->addWidget(b);
    left->addSpacing(8);
    left->addWidget(new QLabel(tr("Recent files:"), this));
    left->addWidget(m_recent, 1);
    auto *columns = new QHBoxLayout;
    columns->addLayout(left, 2);
    columns->addWidget(m_walkthrough, 3);
    auto *close = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_atStart);
    bottom->addStretch(1);
    bottom->addWidget(close);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addLayout(bottom);

    const auto choose = [this](auto signal) {
        return [this, signal] {
            accept();
            emit(this->*signal)();
        };
    };
    connect(m_new, &QPushButton::clicked, this, choose(&WelcomeDialog::newRequested));
    connect(m_open, &QPushButton::clicked, this, choose(&WelcomeDialog::openRequested));
    connect(m_example, &QPushButton::clicked, this, choose(&WelcomeDialog::exampleRequested));
    connect(m_manual, &QPushButton::clicked, this, [this] {
        accept();
        emit manualRequested(QStringLiteral("getting-started.md"));
    });
    connect(m_recent, &QListWidget::itemActivated, this, [this](QListWidgetItem *item) {
        const QString path = item->data(Qt::UserRole).toString();
        if (path.isEmpty())
            return;
        accept();
        emit recentRequested(path);
    });
    connect(m_walkthrough, &QTextBrowser::anchorClicked, this, [this](const QUrl &url) {
        accept();
        emit manualRequested(url.path().section(QLatin1Char('/'), -1));
    });
    connect(m_atStart, &QCheckBox::toggled, this,
            [](bool on) { QSettings().setValue(kAtStartKey, on); });
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    markShown();
}

} // namespace finbook::ui
