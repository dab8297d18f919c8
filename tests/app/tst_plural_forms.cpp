// Counted texts in English: "%n frame(s)" in the source reads "1 frame" / "2 frames" through the
// English plural catalogue (translations/en/finbook_en.ts, plural forms only), which the app
// (app/translations.cpp) installs for English and for any language without a catalogue. Every
// counted message the full catalogues have, the English one has, with both forms and no "(s)" left.
#include "tst_translations_support.h"

#include <finbook/model/commands.h>
#include <finbook/model/document.h>
#include <finbook/model/frame_list_model.h>

#include <QCoreApplication>
#include <QRegularExpression>
#include <QTranslator>
#include <QtTest>

using namespace finbook;
using namespace finbook::test;

namespace {
const QString kEnglish = QStringLiteral(FINBOOK_SOURCE_DIR "/translations/en/finbook_en.ts");
const QString kGerman = QStringLiteral(FINBOOK_SOURCE_DIR "/translations/finbook_de.ts");
const QString kQm = QStringLiteral(FINBOOK_BINARY_DIR "/bin/translations/finbook_en.qm");
} // namespace

class TestPluralForms : public QObject {
    Q_OBJECT
private slots:
    void englishHasEveryCountedMessage();
    void countsReadAsEnglish();
};

void TestPluralForms::englishHasEveryCountedMessage()
{
    const Catalogue english = readCatalogue(kEnglish);
    QVERIFY2(english.error.isEmpty(), qPrintable(english.error));
    QCOMPARE(english.language, QStringLiteral("en"));
    const Catalogue german = readCatalogue(kGerman);
    QSet<QString> counted;
    for (const Message &m : english.messages) {
        if (isObsolete(m))
            continue;
        QVERIFY2(m.numerus, qPrintable(m.source + QStringLiteral(": not a counted message")));
        QVERIFY2(m.type.isEmpty(), qPrintable(m.source));
        QCOMPARE(m.translations.size(), 2);
        static const QRegularExpression optional(QStringLiteral("\\(\\w+\\)"));
        for (const QString &form : m.translations) {
            QVERIFY2(form.contains(QLatin1String("%n")), qPrintable(form));
            QVERIFY2(!form.contains(optional), qPrintable(form));
            QCOMPARE(placeholders(form), placeholders(m.source));
        }
        counted.insert(m.context + QLatin1Char('|') + m.source);
    }
    int numerus = 0;
    for (const Message &m : german.messages)
        if (m.numerus && !isObsolete(m)) {
            ++numerus;
            QVERIFY2(counted.contains(m.context + QLatin1Char('|') + m.source),
                     qPrintable(m.source + QStringLiteral(": missing from finbook_en.ts")));
        }
    QVERIFY(numerus >= 10);
}

void TestPluralForms::countsReadAsEnglish()
{
    QTranslator english;
    QVERIFY(english.load(kQm));
    QCoreApplication::installTranslator(&english);
    model::Document doc;
    doc.undoStack()->push(new model::InsertFrameCommand(&doc, 0));
    model::FrameListModel frames(&doc);
    const auto tip = [&] { return frames.index(0).data(Qt::ToolTipRole).toString(); };
    doc.undoStack()->push(new model::SetFrameHoldCommand(&doc, doc.frameAt(0).id, 3));
    QCOMPARE(tip(), QStringLiteral("Frame 1, held for 3 frames"));
    QCOMPARE(QCoreApplication::translate("finbook::model::FrameListModel",
                                         "Frame %1, held for %n frame(s)", nullptr, 1),
             QStringLiteral("Frame %1, held for 1 frame"));
    QCoreApplication::removeTranslator(&english);
    QCOMPARE(tip(), QStringLiteral("Frame 1, held for 3 frame(s)")); // the bare source text
}

QTEST_MAIN(TestPluralForms)
#include "tst_plural_forms.moc"
