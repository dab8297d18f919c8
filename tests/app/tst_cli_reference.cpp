// `finbook export --include-reference`: the reference is painted under the drawing only when
// asked for, from a saved .finbook as a user runs the command.
#include "../model/reference_support.h"
#include "../model/sound_support.h"
#include "cli_run.h"

#include <finbook/model/finbook_file.h>
#include <finbook/model/reference/reference_commands.h>
#include <finbook/model/reference/reference_media.h>

#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
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
        doc.reset({model::Frame{doc.allocateId(), 1, {}, {}}}, settings, doc.nextId());
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

    // `finbook info` says what media a file carries: a script can check a file has its sound
    // before exporting a video.
    void infoCountsSoundAndReference()
    {
        QTemporaryDir dir;
        model::Document doc;
        model::DocumentSettings settings;
        settings.canvasSize = QSize(160, 120);
        const model::Id frame = doc.allocateId(); // before nextId() is read
        doc.reset({model::Frame{frame, 1, {}, {}}}, settings, doc.nextId());
        const QString bare = dir.filePath(QStringLiteral("bare.finbook"));
        QVERIFY(!model::saveFinbook(doc, bare));

        const QByteArray beat = sound_test::sineWav(0.3);
        const QByteArray voice = sound_test::sineWav(0.2, 22050, 880);
        sound_test::importClip(doc, beat, QStringLiteral("beat.wav"));
        const model::Id muted = sound_test::importClip(doc, voice, QStringLiteral("voice.wav"), 4);
        doc.undoStack()->push(model::soundClipMutedCommand(&doc, muted, true).release());
        auto reference =
            model::importReferenceFile(writeTwoColourPng(dir.path()), QSizeF(160, 120));
        QVERIFY(reference);
        doc.referenceLayer().setReference(*reference);
        const QString full = dir.filePath(QStringLiteral("full.finbook"));
        const auto saved = model::saveFinbook(doc, full);
        QVERIFY2(!saved, saved ? qPrintable(saved->message) : "");

        const auto info = [](const QString &file) {
            const Run run = runFinbook({QStringLiteral("info"), file});
            return run.code == 0 ? QJsonDocument::fromJson(run.out).object() : QJsonObject{};
        };
        const QJsonObject none = info(bare);
        QCOMPARE(none[QStringLiteral("sound_clips")].toInteger(-1), 0);
        QCOMPARE(none[QStringLiteral("sound_bytes")].toInteger(-1), 0);
        QCOMPARE(none[QStringLiteral("reference")].toString(), QStringLiteral("none"));
        QCOMPARE(none[QStringLiteral("reference_bytes")].toInteger(-1), 0);

        const QJsonObject both = info(full);
        QCOMPARE(both[QStringLiteral("sound_clips")].toInteger(), 2);
        QCOMPARE(both[QStringLiteral("sound_clips_audible")].toInteger(), 1);
        QCOMPARE(both[QStringLiteral("sound_bytes")].toInteger(), beat.size() + voice.size());
        QCOMPARE(both[QStringLiteral("reference")].toString(), QStringLiteral("image"));
        QCOMPARE(both[QStringLiteral("reference_bytes")].toInteger(), reference->bytes.size());
        QCOMPARE(both[QStringLiteral("reference_pictures")].toInteger(-1), 0);

        // A sequence counts every picture's bytes.
        QTemporaryDir small;
        const QString first = writeTwoColourPng(small.path(), QSize(40, 30));
        const QString second = small.filePath(QStringLiteral("two_b.png"));
        QImage green(QSize(50, 30), QImage::Format_RGB32);
        green.fill(Qt::green);
        QVERIFY(green.save(second));
        auto sequence = model::importReferenceSequence({first, second}, QSizeF(160, 120));
        QVERIFY2(sequence, sequence ? "" : qPrintable(sequence.error()));
        doc.referenceLayer().setReference(*sequence);
        const QString sequenced = dir.filePath(QStringLiteral("sequence.finbook"));
        QVERIFY(!model::saveFinbook(doc, sequenced));
        const QJsonObject pictures = info(sequenced);
        QCOMPARE(pictures[QStringLiteral("reference")].toString(), QStringLiteral("sequence"));
        QCOMPARE(pictures[QStringLiteral("reference_pictures")].toInteger(), 2);
        QCOMPARE(pictures[QStringLiteral("reference_bytes")].toInteger(),
                 QFileInfo(first).size() + QFileInfo(second).size());
    }
};

QTEST_MAIN(TestCliReference)
#include "tst_cli_reference.moc"
