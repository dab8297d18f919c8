// The soundtrack in the model: import, move, volume, mute and delete as undoable commands,
// save → open → save keeping every clip's bytes, the file's bounds on sound sections, and
// recovery of a file whose sound is damaged.
#include "sound_support.h"
#include "tst_file_sample.h"

#include <finbook/model/finbook_file.h>

using namespace finbook::model;
using namespace file_test;
using namespace sound_test;

class TestSound : public QObject {
    Q_OBJECT
private slots:
    void commandsUndoExactly();
    void editsOfAGoneClipDoNothing();
    void saveReopenKeepsClipBytes();
    void fileWithoutSoundIsUnchanged();
    void clipLargerThanItsBytesIsRefused();
    void badValuesAreRefused();
    void damagedSoundIsLeftOutWhenRecovering();
    void autosaveCopyKeepsSound();
};

namespace {
Document *sampleWithSound(Document &doc)
{
    buildSample(doc);
    importClip(doc, sineWav(0.5), QStringLiteral("beat.wav"), 3);
    importClip(doc, sineWav(0.25, 22050, 880), QStringLiteral("voice ♪.wav"), 10);
    return &doc;
}
} // namespace

void TestSound::commandsUndoExactly()
{
    Document doc;
    buildSample(doc);
    const QByteArray before = serializeFinbook(doc);
    const Id a = importClip(doc, sineWav(0.5), QStringLiteral("a.wav"));
    const Id b = importClip(doc, sineWav(0.2), QStringLiteral("b.wav"), 4);
    QCOMPARE(doc.soundtrack().clips().size(), std::size_t(2));
    QVERIFY(a != b && a != kNoId);
    QVERIFY(doc.nextId() > b);
    const QByteArray imported = serializeFinbook(doc);

    for (auto *command : {moveSoundClipCommand(&doc, a, 7).release(),
                          soundClipVolumeCommand(&doc, a, 0.5).release(),
                          soundClipMutedCommand(&doc, b, true).release()}) {
        QVERIFY(command);
        doc.undoStack()->push(command);
    }
    doc.undoStack()->push(new RemoveSoundClipCommand(&doc, a));
    QCOMPARE(doc.soundtrack().clips().size(), std::size_t(1));
    QVERIFY(doc.soundtrack().clip(b)->muted);
    const QByteArray edited = serializeFinbook(doc);

    // No-op edits make no command; out-of-range values are clamped; NaN is refused.
    QVERIFY(!soundClipMutedCommand(&doc, b, true));
    QVERIFY(!moveSoundClipCommand(&doc, b, 4));
    QVERIFY(!soundClipVolumeCommand(&doc, b, std::nan("")));
    QVERIFY(!moveSoundClipCommand(&doc, a, 3)); // deleted

    doc.undoStack()->undo(); // delete
    const SoundClip *restored = doc.soundtrack().clip(a);
    QVERIFY(restored);
    QCOMPARE(restored->start, qint64(7));
    QCOMPARE(restored->volume, 0.5);
    QCOMPARE(doc.soundtrack().indexOf(a), 0); // back where it was
    doc.undoStack()->setIndex(2);
    QCOMPARE(serializeFinbook(doc), imported);
    doc.undoStack()->setIndex(0);
    QCOMPARE(serializeFinbook(doc), before);
    QVERIFY(doc.soundtrack().isEmpty());
    doc.undoStack()->setIndex(doc.undoStack()->count());
    QCOMPARE(serializeFinbook(doc), edited);

    auto clamped = moveSoundClipCommand(&doc, b, -20);
    QVERIFY(clamped);
    clamped->redo();
    QCOMPARE(doc.soundtrack().clip(b)->start, qint64(0));
    auto loud = soundClipVolumeCommand(&doc, b, 100.0);
    loud->redo();
    QCOMPARE(doc.soundtrack().clip(b)->volume, kMaxSoundVolume);
}

void TestSound::editsOfAGoneClipDoNothing()
{
    Document doc;
    buildSample(doc);
    const Id a = importClip(doc, sineWav(0.1), QStringLiteral("a.wav"));
    auto move = moveSoundClipCommand(&doc, a, 5);
    RemoveSoundClipCommand remove(&doc, a);
    remove.redo();
    move->redo();
    move->undo();
    QVERIFY(doc.soundtrack().isEmpty());
    RemoveSoundClipCommand again(&doc, a);
    QVERIFY(again.isObsolete());
    // A new document (reset) has no sound.
    importClip(doc, sineWav(0.1), QStringLiteral("b.wav"));
    doc.reset(std::vector<Frame>{}, DocumentSettings(), 1);
    QVERIFY(doc.soundtrack().isEmpty());
}

void TestSound::saveReopenKeepsClipBytes()
{
    Document doc;
    sampleWithSound(doc);
    doc.undoStack()->push(
        soundClipMutedCommand(&doc, doc.soundtrack().clips()[1].id, true).release());
    doc.undoStack()->push(
        soundClipVolumeCommand(&doc, doc.soundtrack().clips()[0].id, 1.75).release());
    const QByteArray bytes = serializeFinbook(doc);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("sound.finbook"));
    QVERIFY(!saveFinbook(doc, path));
    Document reopened;
    const auto failure = openFinbook(reopened, path);
    QVERIFY2(!failure, failure ? qPrintable(failure->message) : "");
    QCOMPARE(reopened.soundtrack().clips(), doc.soundtrack().clips());
    for (std::size_t i = 0; i < doc.soundtrack().clips().size(); ++i)
        QCOMPARE(reopened.soundtrack().clips()[i].bytes, doc.soundtrack().clips()[i].bytes);
    QCOMPARE(serializeFinbook(reopened), bytes);
    QCOMPARE(reopened.soundtrack().clips()[1].name, QStringLiteral("voice ♪.wav"));
    // New ids never take a clip's id.
    QVERIFY(reopened.nextId() > doc.soundtrack().clips()[1].id);
    // One SOND section per clip, after the frames.
    QVERIFY(sectionPayload(bytes, "SOND") > sectionPayload(bytes, "FRAM"));
    QCOMPARE(bytes.count("SOND"), 2);
}

void TestSound::fileWithoutSoundIsUnchanged()
{
    Document doc;
    buildSample(doc);
    const QByteArray plain = serializeFinbook(doc);
    QVERIFY(!plain.contains("SOND"));
    const Id a = importClip(doc, sineWav(0.1), QStringLiteral("a.wav"));
    doc.undoStack()->push(new RemoveSoundClipCommand(&doc, a));
    // The removed clip's id is gone with it: the next free id is as before.
    QCOMPARE(serializeFinbook(doc), plain);
}

void TestSound::clipLargerThanItsBytesIsRefused()
{
    Document doc;
    sampleWithSound(doc);
    QByteArray bytes = serializeFinbook(doc);
    const qsizetype payload = sectionPayload(bytes, "SOND");
    const quint32 nameBytes = qFromLittleEndian<quint32>(bytes.constData() + payload + 25);
    const qsizetype dataAt = payload + 29 + nameBytes;
    const quint64 real = qFromLittleEndian<quint64>(bytes.constData() + dataAt);
    QCOMPARE(real, quint64(sineWav(0.5).size()));
    for (quint64 claimed : {real + 1, real * 1000, quint64(1) << 62}) {
        QByteArray patched = bytes;
        qToLittleEndian<quint64>(claimed, patched.data() + dataAt);
        refreshChecksums(patched);
        QString message;
        const FileErrorCode code = errorOf(patched, &message);
        QVERIFY2(code == FileErrorCode::BadValue || code == FileErrorCode::TooLarge,
                 qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("sound clip 1"), Qt::CaseInsensitive),
                 qPrintable(message));
    }
    // A file cut inside the sound: incomplete, and opening anyway keeps the drawing.
    QByteArray cut = bytes.left(dataAt + 100);
    QCOMPARE(errorOf(cut), FileErrorCode::Truncated);
    QStringList problems;
    auto recovered = recoverFinbook(cut, &problems);
    QVERIFY(recovered);
    QCOMPARE(recovered->frames.size(), doc.frames().size());
    QVERIFY(recovered->sound.empty());
}

void TestSound::badValuesAreRefused()
{
    Document doc;
    sampleWithSound(doc);
    const QByteArray bytes = serializeFinbook(doc);
    const qsizetype payload = sectionPayload(bytes, "SOND");
    struct Patch {
        qsizetype at;
        quint64 value;
        int width;
        const char *says;
    };
    const Patch patches[] = {
        {8, quint64(kMaxSoundStart) + 1, 8, "starts at"},
        {8, quint64(-5), 8, "starts at"},
        {16, std::bit_cast<quint64>(std::nan("")), 8, "volume"},
        {16, std::bit_cast<quint64>(-1.0), 8, "volume"},
        {24, 0x80, 1, "flags"},
        {25, 100000, 4, "name"},
        {0, 0, 8, "no id"},
    };
    for (const Patch &p : patches) {
        QByteArray patched = bytes;
        if (p.width == 8)
            qToLittleEndian<quint64>(p.value, patched.data() + payload + p.at);
        else if (p.width == 4)
            qToLittleEndian<quint32>(quint32(p.value), patched.data() + payload + p.at);
        else
            patched[payload + p.at] = char(p.value);
        refreshChecksums(patched);
        QString message;
        QVERIFY(errorOf(patched, &message) != FileErrorCode(-1));
        QVERIFY2(message.contains(QLatin1String(p.says)), qPrintable(message));
    }
    // A sound section before the frames is out of place.
    QByteArray early = bytes;
    const qsizetype start = payload - 12;
    const quint64 length = qFromLittleEndian<quint64>(bytes.constData() + start + 4);
    const QByteArray section = early.mid(start, 12 + qsizetype(length) + 4);
    early.remove(start, section.size());
    early.insert(sectionPayload(early, "FRAM") - 12, section);
    QString message;
    QCOMPARE(errorOf(early, &message), FileErrorCode::BadValue);
    QVERIFY2(message.contains(QStringLiteral("before the frames")), qPrintable(message));
}

void TestSound::damagedSoundIsLeftOutWhenRecovering()
{
    Document doc;
    sampleWithSound(doc);
    QByteArray bytes = serializeFinbook(doc);
    const qsizetype payload = sectionPayload(bytes, "SOND");
    bytes[payload + 29 + 8 + 8 + 30] = char(bytes[payload + 29 + 8 + 8 + 30] ^ 0x55);
    QCOMPARE(errorOf(bytes), FileErrorCode::Damaged);
    QStringList problems;
    auto recovered = recoverFinbook(bytes, &problems);
    QVERIFY(recovered);
    QCOMPARE(recovered->sound.size(), std::size_t(2)); // read, with the problem noted
    QVERIFY(!problems.isEmpty());
    compareFrames(recovered->frames, doc.frames());
}

void TestSound::autosaveCopyKeepsSound()
{
    Document doc;
    sampleWithSound(doc);
    const QByteArray copy =
        serializeFinbook(doc.frames(), doc.settings(), {{"rcvy", "{}"}}, doc.soundtrack().clips());
    auto loaded = readFinbook(copy);
    QVERIFY(loaded);
    QCOMPARE(loaded->sound, doc.soundtrack().clips());
    Document adopted;
    adoptLoadedDocument(adopted, std::move(*loaded));
    QCOMPARE(adopted.soundtrack().clips(), doc.soundtrack().clips());
}

QTEST_GUILESS_MAIN(TestSound)
#include "tst_sound.moc"
