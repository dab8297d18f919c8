// `finbook export --include-reference`: the reference is painted under the drawing only when
// asked for, from a saved .finbook as a user runs the command.
#include "../model/reference_support.h"
#include "cli_run.h"

#include <finbook/model/finbook_file.h>
#include <finbook/model/reference/reference_commands.h>

#include <QTest>

using namespace finbook;
using namespace finbook::test;
using namespace cli_run;

class TestCliReference : public QObject {
    Q_OBJECT
private slots:
    void exportsTheReferenceOnlyWhenAsked()
    {
        QTemporaryDir dir;
        model::Document doc;
        model::DocumentSettings settings;
        settings.canvasSize = QSize(160, 120);
        doc.reset({model::Frame{doc.allocateId(), 1, {}}}, settings, doc.nextId());
        auto reference =
            model::importReferenceFile(writeTwoColourPng(dir.path()), QSizeF(160, 120));
        QVERIFY(reference);
        reference->opacity = 1.0;
        doc.referenceLayer().setReference(*reference);
        const QString file = dir.filePath(QStringLiteral("traced.finbook"));
        QVERIFY(!model::saveFinbook(doc, file));

        const QString plain = dir.filePath(QStringLiteral("plain/"));
        const Run without = runFinbook({QStringLiteral("export"), file, plain});
        QVERIFY2(without.code == 0, without.err.constData());
        const QString with = dir.filePath(QStringLiteral("with/"));
        const Run included = runFinbook(
            {QStringLiteral("export"), file, with, QStringLiteral("--include-reference")});
        QVERIFY2(included.code == 0, included.err.constData());

        const QImage a(plain + QStringLiteral("frame_0001.png"));
        const QImage b(with + QStringLiteral("frame_0001.png"));
        QVERIFY(!a.isNull() && !b.isNull());
        QCOMPARE(a.pixel(40, 60), qRgb(255, 255, 255));
        QCOMPARE(b.pixel(40, 60), qRgb(255, 0, 0));
        QCOMPARE(b.pixel(120, 60), qRgb(0, 0, 255));
    }
};

QTEST_MAIN(TestCliReference)
#include "tst_cli_reference.moc"
