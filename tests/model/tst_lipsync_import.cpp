// Lip sync timings made elsewhere (issue 49): Papagayo, Moho switch data and Rhubarb's TSV,
// JSON and XML read as their programs write them, and every kind of damage refused with one
// sentence that says what and where, and no cues.
#include <finbook/model/lipsync/lipsync_import.h>

#include <QtTest>

using namespace finbook::model::lipsync;

Q_DECLARE_METATYPE(finbook::model::lipsync::LipSyncFormat)

class TestLipSyncImport : public QObject {
    Q_OBJECT

private slots:
    void papagayoReadsAsPapagayoWritesIt();
    void prestonBlairNamesMapOntoTheNineShapes();
    void mohoSwitchDataReadsBothNamings();
    void rhubarbTsvJsonAndXmlAgree();
    void rhubarbsNineLettersAreAccepted();
    void damagedInputIsRefused_data();
    void damagedInputIsRefused();
    void countsAndSizesAreBounded();
    void formatsAreSniffed_data();
    void formatsAreSniffed();
    void importPicksTheFormatByNameThenContent();
};

namespace {

using enum MouthShape;

// Rhubarb's README, a person saying "Hi".
const QByteArray kHiTsv = "0.00\tX\n0.05\tD\n0.27\tC\n0.31\tB\n0.43\tX\n0.47\tX\n";
const QByteArray kHiJson = R"({
  "metadata": {
    "soundFile": "C:\\Users\\Daniel\\Desktop\\av\\hi\\hi.wav",
    "duration": 0.47
  },
  "mouthCues": [
    { "start": 0.00, "end": 0.05, "value": "X" },
    { "start": 0.05, "end": 0.27, "value": "D" },
    { "start": 0.27, "end": 0.31, "value": "C" },
    { "start": 0.31, "end": 0.43, "value": "B" },
    { "start": 0.43, "end": 0.47, "value": "X" }
  ]
}
)";
const QByteArray kHiXml = R"(<?xml version="1.0" encoding="utf-8"?>
<rhubarbResult>
  <metadata>
    <soundFile>C:\Users\Daniel\Desktop\av\hi\hi.wav</soundFile>
    <duration>0.47</duration>
  </metadata>
  <mouthCues>
    <mouthCue start="0.00" end="0.05">X</mouthCue>
    <mouthCue start="0.05" end="0.27">D</mouthCue>
    <mouthCue start="0.27" end="0.31">C</mouthCue>
    <mouthCue start="0.31" end="0.43">B</mouthCue>
    <mouthCue start="0.43" end="0.47">X</mouthCue>
  </mouthCues>
</rhubarbResult>
)";
const std::vector<MouthCue> kHiCues = {{0.0, X}, {0.05, D}, {0.27, C}, {0.31, B}, {0.43, X}};

// As Papagayo 1.2 saves a project: two voices, the second with blank text and no phrases.
const QByteArray kPapagayo = "lipsync version 1\n"
                             "sounds/hello.wav\n"
                             "24\n"
                             "48\n"
                             "2\n"
                             "\tVoice 1\n"
                             "\thello world\n"
                             "\t1\n"
                             "\t\thello world\n"
                             "\t\t2\n"
                             "\t\t30\n"
                             "\t\t2\n"
                             "\t\t\thello 2 10 4\n"
                             "\t\t\t\t2 etc\n"
                             "\t\t\t\t5 E\n"
                             "\t\t\t\t7 L\n"
                             "\t\t\t\t9 O\n"
                             "\t\t\tworld 14 30 4\n"
                             "\t\t\t\t14 WQ\n"
                             "\t\t\t\t18 O\n"
                             "\t\t\t\t22 L\n"
                             "\t\t\t\t26 etc\n"
                             "\tVoice 2\n"
                             "\t\n"
                             "\t0\n";

std::vector<MouthCue> atFrames(std::initializer_list<std::pair<int, MouthShape>> frames, double fps)
{
    std::vector<MouthCue> cues;
    for (const auto &[frame, shape] : frames)
        cues.push_back({frame / fps, shape});
    return cues;
}

QString described(const MouthCueImport &result)
{
    if (!result.ok())
        return result.error;
    QStringList parts;
    for (const MouthCue &cue : result.cues)
        parts << QStringLiteral("%1@%2").arg(mouthShapeLetter(cue.shape)).arg(cue.start);
    return parts.join(u' ');
}

void verifyCues(const MouthCueImport &result, const std::vector<MouthCue> &expected)
{
    QVERIFY2(result.ok(), qPrintable(result.error));
    QCOMPARE(result.cues.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        QVERIFY2(qAbs(result.cues[i].start - expected[i].start) < 1e-9,
                 qPrintable(described(result)));
        QVERIFY2(result.cues[i].shape == expected[i].shape, qPrintable(described(result)));
    }
}

QByteArray withLineCount(QByteArray head, const QByteArray &line, int count)
{
    head.reserve(head.size() + line.size() * count);
    for (int i = 0; i < count; ++i)
        head += line;
    return head;
}

} // namespace

void TestLipSyncImport::papagayoReadsAsPapagayoWritesIt()
{
    // Each phoneme holds to the next; the word's last through its end frame; rest between.
    const std::vector<MouthCue> expected = atFrames({{0, X},
                                                     {2, B},
                                                     {5, C},
                                                     {7, H},
                                                     {9, E},
                                                     {11, X},
                                                     {14, F},
                                                     {18, E},
                                                     {22, H},
                                                     {26, B},
                                                     {31, X}},
                                                    24.0);
    verifyCues(parsePapagayo(kPapagayo), expected);
    QByteArray windows = kPapagayo;
    windows.replace("\n", "\r\n");
    verifyCues(parsePapagayo("\xef\xbb\xbf" + windows), expected);
    // The file's own frame rate counts, not the document's.
    QByteArray at12 = kPapagayo;
    at12.replace("\n24\n", "\n12\n");
    verifyCues(parsePapagayo(at12), atFrames({{0, X},
                                              {2, B},
                                              {5, C},
                                              {7, H},
                                              {9, E},
                                              {11, X},
                                              {14, F},
                                              {18, E},
                                              {22, H},
                                              {26, B},
                                              {31, X}},
                                             12.0));
}

void TestLipSyncImport::prestonBlairNamesMapOntoTheNineShapes()
{
    const QByteArray moho = "MohoSwitch1\n1 MBP\n2 etc\n3 E\n4 AI\n5 O\n6 U\n7 WQ\n8 FV\n9 L\n"
                            "10 rest\n11 mbp\n";
    verifyCues(
        parseMohoSwitch(moho, 10.0),
        atFrames({{0, A}, {1, B}, {2, C}, {3, D}, {4, E}, {5, F}, {7, G}, {8, H}, {9, X}, {10, A}},
                 10.0));
}

void TestLipSyncImport::mohoSwitchDataReadsBothNamings()
{
    // As Papagayo exports it: frames from 1, Preston Blair's names.
    verifyCues(parseMohoSwitch("MohoSwitch1\n1 rest\n3 MBP\n5 AI\n9 rest\n", 24.0),
               atFrames({{0, X}, {2, A}, {4, D}, {8, X}}, 24.0));
    // As Rhubarb exports it by default: its letters, so "E" is E, not Preston Blair's C.
    verifyCues(parseMohoSwitch("MohoSwitch1\n1 X\n2 D\n7 E\n9 B\n12 X\n", 24.0),
               atFrames({{0, X}, {1, D}, {6, E}, {8, B}, {11, X}}, 24.0));
    verifyCues(parseMohoSwitch("MohoSwitch1\n1 rest\n2 E\n", 24.0),
               atFrames({{0, X}, {1, C}}, 24.0));
}

void TestLipSyncImport::rhubarbTsvJsonAndXmlAgree()
{
    verifyCues(parseRhubarbTsv(kHiTsv), kHiCues);
    verifyCues(parseRhubarbJson(kHiJson), kHiCues);
    verifyCues(parseRhubarbXml(kHiXml), kHiCues);
    QByteArray spaced = kHiTsv;
    spaced.replace('\t', "   ");
    verifyCues(parseRhubarbTsv("\n" + spaced + "\n\n"), kHiCues);
}

void TestLipSyncImport::rhubarbsNineLettersAreAccepted()
{
    const std::vector<MouthCue> all = {{0.0, A}, {0.1, B}, {0.2, C}, {0.3, D}, {0.4, E},
                                       {0.5, F}, {0.6, G}, {0.7, H}, {0.8, X}};
    verifyCues(parseRhubarbTsv("0\tA\n0.1\tB\n0.2\tC\n0.3\tD\n0.4\te\n0.5\tF\n0.6\tg\n0.7\th\n"
                               "0.8\tX\n"),
               all);
    verifyCues(parseRhubarbJson(R"({"mouthCues":[{"start":0,"value":"A"},{"start":0.1,"value":"B"},
        {"start":0.2,"value":"C"},{"start":0.3,"value":"D"},{"start":0.4,"value":"E"},
        {"start":0.5,"value":"F"},{"start":0.6,"value":"G"},{"start":0.7,"value":"H"},
        {"start":0.8,"value":"X"}]})"),
               all);
    verifyCues(
        parseRhubarbXml("<rhubarbResult><mouthCues><mouthCue start='0'>A</mouthCue>"
                        "<mouthCue start='0.1'>B</mouthCue><mouthCue start='0.2'>C</mouthCue>"
                        "<mouthCue start='0.3'>D</mouthCue><mouthCue start='0.4'>E</mouthCue>"
                        "<mouthCue start='0.5'>F</mouthCue><mouthCue start='0.6'>G</mouthCue>"
                        "<mouthCue start='0.7'>H</mouthCue><mouthCue start='0.8'>X</mouthCue>"
                        "</mouthCues></rhubarbResult>"),
        all);
}

void TestLipSyncImport::damagedInputIsRefused_data()
{
    QTest::addColumn<LipSyncFormat>("format");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("where"); // a part of the message that says where, or ""
    const auto pgo = LipSyncFormat::Papagayo;
    const auto dat = LipSyncFormat::MohoSwitch;
    const auto tsv = LipSyncFormat::RhubarbTsv;
    const auto json = LipSyncFormat::RhubarbJson;
    const auto xml = LipSyncFormat::RhubarbXml;
    const auto row = [](const char *name, LipSyncFormat format, const QByteArray &bytes,
                        const char *where = "") {
        QTest::newRow(name) << format << bytes << QString::fromLatin1(where);
    };
    const auto papagayo = [](const char *from, const char *to) {
        QByteArray bytes = kPapagayo;
        const qsizetype at = bytes.indexOf(from);
        Q_ASSERT(at >= 0);
        return bytes.replace(at, qsizetype(qstrlen(from)), to);
    };
    // Empty.
    for (const auto format : {pgo, dat, tsv, json, xml}) {
        const QByteArray name = "empty " + QByteArray::number(int(format));
        row(name.constData(), format, "");
        row((name + " blanks").constData(), format, " \n\t\r\n");
        row((name + " bom").constData(), format, "\xef\xbb\xbf");
    }
    // Wrong header or root.
    row("pgo header", pgo, papagayo("version 1", "version 2"), "Line 1");
    row("pgo is tsv", pgo, kHiTsv, "Line 1");
    row("dat header", dat, "MohoSwitch2\n1 rest\n", "Line 1");
    row("json root", json, R"({"metadata": {"duration": 1}})");
    row("json array", json, "[1, 2]");
    row("xml root", xml, "<lipsync><mouthCues/></lipsync>", "Line 1");
    // Not numbers.
    row("pgo fps", pgo, papagayo("\n24\n", "\nfast\n"), "Line 3");
    row("pgo frame", pgo, papagayo("5 E", "five E"), "Line 15");
    row("pgo count", pgo, papagayo("hello 2 10 4", "hello 2 10 four"), "Line 13");
    row("dat frame", dat, "MohoSwitch1\n1 rest\nthree MBP\n", "Line 3");
    row("tsv time", tsv, "0.00\tX\nsoon\tD\n", "Line 2");
    row("json time", json, R"({"mouthCues":[{"start":"0.5","value":"X"}]})", "cue 1");
    row("xml time", xml,
        "<rhubarbResult><mouthCues>\n<mouthCue start='zero'>X</mouthCue>"
        "</mouthCues></rhubarbResult>",
        "Line 2");
    row("xml end", xml,
        "<rhubarbResult><mouthCues>\n<mouthCue start='1' end='0.5'>X</mouthCue>"
        "</mouthCues></rhubarbResult>",
        "Line 2");
    row("json end", json, R"({"mouthCues":[{"start":1,"end":0.5,"value":"X"}]})", "cue 1");
    row("json end text", json, R"({"mouthCues":[{"start":1,"end":"late","value":"X"}]})", "cue 1");
    // Times going backwards.
    row("pgo backwards", pgo, papagayo("7 L", "4 L"), "Line 16");
    row("dat backwards", dat, "MohoSwitch1\n5 rest\n3 MBP\n", "Line 3");
    row("tsv backwards", tsv, "0.5\tX\n0.2\tD\n", "Line 2");
    row("json backwards", json,
        R"({"mouthCues":[{"start":0.5,"value":"X"},{"start":0.2,"value":"D"}]})", "cue 2");
    row("xml backwards", xml,
        "<rhubarbResult><mouthCues><mouthCue start='0.5'>X</mouthCue>\n"
        "<mouthCue start='0.2'>D</mouthCue></mouthCues></rhubarbResult>",
        "Line 2");
    row("pgo phoneme after its word", pgo, papagayo("9 O", "11 O"), "Line 17");
    row("pgo word ends before it starts", pgo, papagayo("world 14 30", "world 14 12"), "Line 18");
    // Unknown shapes.
    row("pgo shape", pgo, papagayo("5 E", "5 OO"), "Line 15");
    row("dat shape", dat, "MohoSwitch1\n1 rest\n2 smile\n", "Line 3");
    row("dat letters and unknown", dat, "MohoSwitch1\n1 X\n2 Q\n", "Line 3");
    row("dat letters among names", dat, "MohoSwitch1\n1 rest\n2 D\n", "Line 3");
    row("tsv shape", tsv, "0.00\tQ\n", "Line 1");
    row("tsv two letters", tsv, "0.00\tXX\n", "Line 1");
    row("tsv circled", tsv, "0.00\t\xe2\x92\xb6\n", "Line 1");
    row("json shape", json, R"({"mouthCues":[{"start":0,"value":"Z"}]})", "cue 1");
    row("json no shape", json, R"({"mouthCues":[{"start":0}]})", "cue 1");
    row("xml shape", xml,
        "<rhubarbResult><mouthCues><mouthCue start='0'>I</mouthCue>"
        "</mouthCues></rhubarbResult>",
        "Line 1");
    // Negative times.
    row("pgo negative", pgo, papagayo("2 etc", "-2 etc"), "Line 14");
    row("dat zero", dat, "MohoSwitch1\n0 rest\n", "Line 2");
    row("dat negative", dat, "MohoSwitch1\n-3 rest\n", "Line 2");
    row("tsv negative", tsv, "-0.1\tX\n", "Line 1");
    row("json negative", json, R"({"mouthCues":[{"start":-1,"value":"X"}]})", "cue 1");
    row("xml negative", xml,
        "<rhubarbResult><mouthCues><mouthCue start='-1'>X</mouthCue>"
        "</mouthCues></rhubarbResult>",
        "Line 1");
    // NaN and infinities.
    row("pgo fps nan", pgo, papagayo("\n24\n", "\nnan\n"), "Line 3");
    row("pgo fps inf", pgo, papagayo("\n24\n", "\ninf\n"), "Line 3");
    row("tsv nan", tsv, "nan\tX\n", "Line 1");
    row("tsv inf", tsv, "0\tX\ninf\tD\n", "Line 2");
    row("tsv overflow", tsv, "1e999\tX\n", "Line 1");
    row("json overflow", json, R"({"mouthCues":[{"start":1e999,"value":"X"}]})");
    row("xml nan", xml,
        "<rhubarbResult><mouthCues><mouthCue start='NaN'>X</mouthCue>"
        "</mouthCues></rhubarbResult>",
        "Line 1");
    row("xml inf", xml,
        "<rhubarbResult><mouthCues><mouthCue start='inf'>X</mouthCue>"
        "</mouthCues></rhubarbResult>",
        "Line 1");
    row("tsv too late", tsv, "90000\tX\n", "Line 1");
    // Huge counts (declared) and truncation.
    row("pgo voices", pgo, papagayo("48\n2\n", "48\n99999999\n"), "Line 5");
    row("pgo phonemes", pgo, papagayo("hello 2 10 4", "hello 2 10 2000000"), "Line 13");
    row("pgo words", pgo, papagayo("\t\t2\n\t\t\thello", "\t\t1000000000000\n\t\t\thello"),
        "Line 12");
    row("pgo truncated", pgo, kPapagayo.first(kPapagayo.indexOf("\t\t\t\t7 L")), "line 15");
    row("pgo many voices missing", pgo, papagayo("48\n2\n", "48\n3\n"));
    row("pgo frame after a day", pgo, papagayo("26 etc", "9999999999 etc"), "Line 22");
    row("json truncated", json, kHiJson.first(kHiJson.size() / 2));
    row("json not json", json, "mouthCues: yes");
    row("xml truncated", xml, kHiXml.first(kHiXml.size() / 2));
    row("xml unclosed cue", xml, kHiXml.first(kHiXml.indexOf("</mouthCue>")));
    row("xml nested", xml,
        "<rhubarbResult><mouthCues><mouthCue start='0'><b>X</b></mouthCue>"
        "</mouthCues></rhubarbResult>");
    row("xml empty root", xml, "<rhubarbResult/>");
    row("tsv three fields", tsv, "0\tX\textra\n", "Line 1");
    row("dat no shapes", dat, "MohoSwitch1\n");
}

void TestLipSyncImport::damagedInputIsRefused()
{
    QFETCH(LipSyncFormat, format);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, where);
    const MouthCueImport result = parseMouthCues(bytes, format, 24.0);
    QVERIFY2(!result.ok(), qPrintable(described(result)));
    QVERIFY(result.cues.empty());
    QVERIFY2(result.error.endsWith(u'.') && !result.error.contains(u'\n'),
             qPrintable(result.error));
    QVERIFY2(result.error.contains(where), qPrintable(result.error));
}

void TestLipSyncImport::countsAndSizesAreBounded()
{
    // One cue more than the bound, in a file well under the size bound.
    const QByteArray tsv = withLineCount({}, "0\tX\n", kMaxMouthCues + 1);
    QVERIFY(tsv.size() < kMaxLipSyncFileBytes);
    const MouthCueImport tooManyTsv = parseRhubarbTsv(tsv);
    QVERIFY(!tooManyTsv.ok() && tooManyTsv.cues.empty());
    QVERIFY2(tooManyTsv.error.contains(QString::number(kMaxMouthCues)),
             qPrintable(tooManyTsv.error));
    const MouthCueImport tooManyDat =
        parseMohoSwitch(withLineCount("MohoSwitch1\n", "1 X\n", kMaxMouthCues + 1), 24.0);
    QVERIFY(!tooManyDat.ok() && tooManyDat.cues.empty());
    // Exactly the bound is read.
    const MouthCueImport atBound = parseRhubarbTsv(withLineCount({}, "0\tX\n", kMaxMouthCues));
    QVERIFY2(atBound.ok(), qPrintable(atBound.error));
    QCOMPARE(atBound.cues.size(), size_t(1)); // one X, repeated
    // Larger than the size bound: refused whatever it holds.
    QByteArray huge = kHiTsv;
    huge.append(kMaxLipSyncFileBytes, '\n');
    for (const auto format :
         {LipSyncFormat::Papagayo, LipSyncFormat::MohoSwitch, LipSyncFormat::RhubarbTsv,
          LipSyncFormat::RhubarbJson, LipSyncFormat::RhubarbXml}) {
        const MouthCueImport result = parseMouthCues(huge, format, 24.0);
        QVERIFY(!result.ok() && result.cues.empty());
        QVERIFY2(result.error.contains(u"MiB"), qPrintable(result.error));
    }
    // A frame rate the document cannot have.
    for (const double fps : {0.0, -24.0, std::nan(""), qInf(), 1e9}) {
        const MouthCueImport result = parseMohoSwitch("MohoSwitch1\n1 rest\n", fps);
        QVERIFY2(!result.ok() && result.cues.empty(), qPrintable(QString::number(fps)));
    }
}

void TestLipSyncImport::formatsAreSniffed_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<std::optional<LipSyncFormat>>("format");
    QTest::newRow("pgo") << kPapagayo << std::optional(LipSyncFormat::Papagayo);
    QTest::newRow("dat") << QByteArray("\xef\xbb\xbfMohoSwitch1\n1 X\n")
                         << std::optional(LipSyncFormat::MohoSwitch);
    QTest::newRow("tsv") << kHiTsv << std::optional(LipSyncFormat::RhubarbTsv);
    QTest::newRow("json") << kHiJson << std::optional(LipSyncFormat::RhubarbJson);
    QTest::newRow("xml") << kHiXml << std::optional(LipSyncFormat::RhubarbXml);
    QTest::newRow("text") << QByteArray("Hello, world\n") << std::optional<LipSyncFormat>();
    QTest::newRow("empty") << QByteArray() << std::optional<LipSyncFormat>();
}

void TestLipSyncImport::formatsAreSniffed()
{
    QFETCH(QByteArray, bytes);
    QFETCH(std::optional<LipSyncFormat>, format);
    QCOMPARE(sniffLipSyncFormat(bytes), format);
}

void TestLipSyncImport::importPicksTheFormatByNameThenContent()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const auto write = [&dir](const QString &name, const QByteArray &bytes) {
        QFile file(dir.filePath(name));
        if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
            qFatal("cannot write %s", qPrintable(file.fileName()));
        return file.fileName();
    };
    verifyCues(importMouthCues(write(QStringLiteral("hi.tsv"), kHiTsv), 24.0), kHiCues);
    verifyCues(importMouthCues(write(QStringLiteral("hi.JSON"), kHiJson), 24.0), kHiCues);
    verifyCues(importMouthCues(write(QStringLiteral("hi.xml"), kHiXml), 24.0), kHiCues);
    verifyCues(importMouthCues(write(QStringLiteral("output.txt"), kHiTsv), 24.0), kHiCues);
    verifyCues(
        importMouthCues(write(QStringLiteral("hi.dat"), "MohoSwitch1\n1 rest\n4 AI\n"), 12.0),
        {{0.0, X}, {0.25, D}});
    const MouthCueImport pgo = importMouthCues(write(QStringLiteral("hello.lip"), kPapagayo), 30.0);
    QVERIFY2(pgo.ok(), qPrintable(pgo.error));
    QCOMPARE(pgo.cues[1].start, 2 / 24.0); // the file's rate, not the document's
    // The name decides when it is known: TSV in a .json file is damaged JSON.
    QVERIFY(!importMouthCues(write(QStringLiteral("wrong.json"), kHiTsv), 24.0).ok());
    const MouthCueImport unknown =
        importMouthCues(write(QStringLiteral("notes.txt"), "Hello, world\n"), 24.0);
    QVERIFY(!unknown.ok() && unknown.cues.empty());
    QVERIFY2(unknown.error.contains(u"notes.txt"), qPrintable(unknown.error));
    const MouthCueImport missing = importMouthCues(dir.filePath(QStringLiteral("none.tsv")), 24.0);
    QVERIFY(!missing.ok() && missing.cues.empty());
    QVERIFY2(missing.error.contains(u"none.tsv"), qPrintable(missing.error));
    QByteArray huge = kHiTsv;
    huge.append(kMaxLipSyncFileBytes, '\n');
    const MouthCueImport tooLarge = importMouthCues(write(QStringLiteral("huge.tsv"), huge), 24.0);
    QVERIFY(!tooLarge.ok() && tooLarge.cues.empty());
    QVERIFY(lipSyncFileFilter().contains(u"*.pgo"));
}

QTEST_APPLESS_MAIN(TestLipSyncImport)
#include "tst_lipsync_import.moc"
