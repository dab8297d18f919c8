// Shared by the .finbook tests: a small document that uses every feature of the format, and
// helpers to inspect and patch its bytes.
#pragma once

#include "../../model/src/io/crc32c.h"

#include <finbook/model/finbook_file.h>

#include <QFile>
#include <QtEndian>
#include <QtTest>

#include <cmath>

namespace file_test {
using namespace finbook::model;

inline float onGrid(int q)
{
    return float(q) / 65535.0f;
}

inline StrokeDataPtr makeStroke(int n, QRgb color, float width, float x0, float y0)
{
    auto data = std::make_shared<StrokeData>();
    data->color = color;
    data->width = width;
    for (int i = 0; i < n; ++i)
        data->points.push_back(
            {x0 + float(i) * 1.5f, y0 + std::sin(float(i)) * 3.0f, onGrid((i * 7919) % 65536)});
    return data;
}

inline DeformedStrokesPtr shiftedPose(const StrokeGroup &g, float dx)
{
    auto pose = std::make_shared<DeformedStrokes>();
    for (const Stroke &s : g.strokes) {
        auto points = s.data->points;
        for (StrokePoint &p : points)
            p.x += dx;
        pose->strokes.push_back(std::move(points));
    }
    return pose;
}

// Three frames: the second duplicates the first (shared stroke data and pose, new ids), the
// third has an empty object, a one-point stroke and an empty stroke.
inline void buildSample(Document &doc)
{
    std::vector<Frame> frames(3);
    Id next = 1;
    auto id = [&] { return next++; };
    Frame &a = frames[0];
    a.id = id();
    a.hold = 2;
    StrokeGroup body;
    body.id = id();
    body.name = QStringLiteral("body");
    body.strokes = {{id(), makeStroke(40, 0xff102030, 3.0f, 10, 10)},
                    {id(), makeStroke(25, 0x80ff0000, 5.5f, 50, 80)}};
    body.rig.pins = {{id(), QPointF(10.25, 11), QPointF(12, 13.5)},
                     {id(), QPointF(60, 80), QPointF(61.125, 79)}};
    body.deformed = shiftedPose(body, 2.0f);
    StrokeGroup arm;
    arm.id = id();
    arm.name = QStringLiteral("Ärm ✋");
    arm.visible = false;
    arm.locked = true;
    arm.meshDensity = 2.5;
    arm.strokes = {{id(), makeStroke(12, 0xff00ff00, 1.0f, 200, 100)}};
    a.groups = {body, arm};

    Frame &b = frames[1];
    b.id = id();
    b.groups = a.groups;
    for (StrokeGroup &g : b.groups) {
        g.id = id();
        for (Stroke &s : g.strokes)
            s.id = id();
        for (Pin &p : g.rig.pins)
            p.id = id();
    }

    Frame &c = frames[2];
    c.id = id();
    c.hold = 1000;
    StrokeGroup empty;
    empty.id = id();
    StrokeGroup odd;
    odd.id = id();
    odd.name = QStringLiteral("odd");
    odd.strokes = {{id(), makeStroke(1, 0xff000000, 7.0f, 5, 5)},
                   {id(), makeStroke(0, 0xff000000, 0.5f, 0, 0)}};
    c.groups = {empty, odd};

    DocumentSettings settings;
    settings.canvasSize = QSize(640, 360);
    settings.background = 0xfff0e0d0;
    settings.fps = 24;
    settings.loop = false;
    settings.playStart = 1;
    settings.playEnd = 2;
    doc.reset(std::move(frames), settings, next + 5);
}

inline void compareFrames(const std::vector<Frame> &actual, const std::vector<Frame> &expected)
{
    QCOMPARE(actual.size(), expected.size());
    for (std::size_t f = 0; f < actual.size(); ++f) {
        QCOMPARE(actual[f].id, expected[f].id);
        QCOMPARE(actual[f].hold, expected[f].hold);
        QCOMPARE(actual[f].groups.size(), expected[f].groups.size());
        for (std::size_t g = 0; g < actual[f].groups.size(); ++g) {
            const StrokeGroup &x = actual[f].groups[g], &y = expected[f].groups[g];
            QCOMPARE(x.id, y.id);
            QCOMPARE(x.name, y.name);
            QCOMPARE(x.visible, y.visible);
            QCOMPARE(x.locked, y.locked);
            QCOMPARE(x.meshDensity, y.meshDensity);
            QVERIFY(x.strokes == y.strokes);
            QVERIFY(x.rig.pins == y.rig.pins);
            QCOMPARE(bool(x.deformed), bool(y.deformed));
            if (x.deformed)
                QVERIFY(*x.deformed == *y.deformed);
        }
    }
}

inline QByteArray validBytes()
{
    Document doc;
    buildSample(doc);
    return serializeFinbook(doc);
}

// Bytes after each section's payload: its checksum from format 2 on.
inline qsizetype sectionTrailer(const QByteArray &bytes)
{
    return qFromLittleEndian<quint32>(bytes.constData() + 8) >= 2 ? 4 : 0;
}

// Offset of a section's payload, walking the section list as the format describes it.
inline qsizetype sectionPayload(const QByteArray &bytes, const char *name)
{
    qsizetype at = 12;
    while (at + 12 <= bytes.size()) {
        const quint64 length = qFromLittleEndian<quint64>(bytes.constData() + at + 4);
        if (bytes.mid(at, 4) == name)
            return at + 12;
        at += 12 + qsizetype(length) + sectionTrailer(bytes);
    }
    return -1;
}

// Puts right every section checksum after a test patched the bytes on purpose, so the reader
// reports the patched value rather than the damage. Sections must still chain up.
inline void refreshChecksums(QByteArray &bytes)
{
    if (sectionTrailer(bytes) == 0)
        return;
    qsizetype at = 12;
    while (at + 12 <= bytes.size()) {
        const quint64 length = qFromLittleEndian<quint64>(bytes.constData() + at + 4);
        const qsizetype end = at + 12 + qsizetype(length);
        if (length > quint64(bytes.size()) || end + 4 > bytes.size())
            return;
        qToLittleEndian<quint32>(
            finbook::model::io::crc32c(0, bytes.constData() + at, std::size_t(end - at)),
            bytes.data() + end);
        at = end + 4;
    }
}

// A whole section (header, payload, checksum) with `tag` and `payload`, for inserting.
inline QByteArray sectionBytes(const char *tag, const QByteArray &payload, bool withChecksum = true)
{
    QByteArray section(tag, 4);
    char length[8];
    qToLittleEndian<quint64>(quint64(payload.size()), length);
    section.append(length, 8).append(payload);
    if (withChecksum) {
        char crc[4];
        qToLittleEndian<quint32>(
            finbook::model::io::crc32c(0, section.constData(), std::size_t(section.size())), crc);
        section.append(crc, 4);
    }
    return section;
}

inline void putU32(QByteArray &bytes, qsizetype at, quint32 v)
{
    qToLittleEndian(v, bytes.data() + at);
}

inline FileErrorCode errorOf(const QByteArray &bytes, QString *message = nullptr)
{
    auto loaded = readFinbook(bytes);
    if (loaded)
        return FileErrorCode(-1);
    if (message)
        *message = loaded.error().message;
    return loaded.error().code;
}

inline QByteArray fileBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace file_test
