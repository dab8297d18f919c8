// Names Finbook gives to new things ("Object", "Object 2", "Frame 3") come in the user's
// language. A pseudo-translation marks every string of Finbook's own contexts with ⟪ ⟫; the
// names made through the real actions must carry the marks.
#include "tst_window_support.h"

#include <finbook/model/frame_list_model.h>
#include <finbook/model/object_list_model.h>
#include <finbook/ui/panels/objects_panel.h>
#include <finbook/ui/timeline/timeline_view.h>
#include <finbook/ui/window/editor_state.h>

#include <QTranslator>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {
class PseudoTranslator : public QTranslator {
public:
    bool isEmpty() const override { return false; }
    QString translate(const char *context, const char *source, const char *, int) const override
    {
        // Qt's own contexts (QShortcut, QDialogButtonBox...) stay: key names must parse.
        if (!context || context[0] == 'Q' || !source || !*source)
            return {};
        return QStringLiteral("\u27ea") + QString::fromUtf8(source) + QStringLiteral("\u27eb");
    }
};

bool marked(const QString &text)
{
    return text.contains(QChar(0x27ea)) && text.contains(QChar(0x27eb));
}
} // namespace

class TestTranslatedNames : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        m_settings = std::make_unique<IsolatedSettings>();
        QVERIFY(QCoreApplication::installTranslator(&m_translator));
    }
    void cleanupTestCase() { QCoreApplication::removeTranslator(&m_translator); }

    void newThingsHaveTranslatedNames();

private:
    std::unique_ptr<IsolatedSettings> m_settings;
    PseudoTranslator m_translator;
};

void TestTranslatedNames::newThingsHaveTranslatedNames()
{
    ui::MainWindow window;
    QVERIFY(showActive(window));
    model::Document *doc = window.document();
    // A new document's object.
    QVERIFY2(marked(doc->frameAt(0).groups[0].name), qPrintable(doc->frameAt(0).groups[0].name));
    // A new frame's object, and a new object.
    window.action(QStringLiteral("frame.insertAfter"))->trigger();
    QCOMPARE(doc->frameCount(), 2);
    const model::Frame &frame = doc->frameAt(window.editorState()->currentFrameIndex());
    QVERIFY2(marked(frame.groups[0].name), qPrintable(frame.groups[0].name));
    window.action(QStringLiteral("object.new"))->trigger();
    const model::StrokeGroup *added = window.editorState()->currentGroup();
    QVERIFY2(added && marked(added->name) && added->name.contains(QLatin1Char('2')),
             qPrintable(added ? added->name : QString()));
    // What the panels call them.
    auto *timeline = window.findChild<ui::TimelineView *>();
    const QString frameName = timeline->model()->index(1, 0).data(Qt::ToolTipRole).toString();
    QVERIFY2(marked(frameName) && frameName.contains(QLatin1Char('2')), qPrintable(frameName));
    auto *objects = window.findChild<ui::ObjectsPanel *>();
    const QString objectTip = objects->objectModel()->index(0, 0).data(Qt::ToolTipRole).toString();
    QVERIFY2(objectTip.isEmpty() || marked(objectTip), qPrintable(objectTip));
    // The undo history names the steps.
    QVERIFY2(marked(doc->undoStack()->undoText()), qPrintable(doc->undoStack()->undoText()));
}

QTEST_MAIN(TestTranslatedNames)
#include "tst_translated_names.moc"
