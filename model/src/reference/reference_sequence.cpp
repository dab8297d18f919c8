// Image sequences as a reference: finding the numbered run a picture belongs to, and reading
// several pictures into one Sequence reference, refusing before anything in the document changes.
#include "reference_files.h"

#include <finbook/model/reference/reference_media.h>

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <map>

namespace finbook::model {

namespace {

// "shot_0012.png" → {"shot_", "0012", ".png"}; false when the base name ends in no digits.
bool splitNumbered(const QString &fileName, QString *prefix, QString *digits, QString *suffix)
{
    static const QRegularExpression numbered(QStringLiteral("^(.*?)(\\d+)(\\.[^.]*)?$"));
    const auto match = numbered.match(fileName);
    if (!match.hasMatch())
        return false;
    *prefix = match.captured(1);
    *digits = match.captured(2);
    *suffix = match.captured(3);
    return true;
}

} // namespace

QStringList numberedSequence(const QString &path)
{
    const QFileInfo info(path);
    QString prefix, digits, suffix;
    if (!splitNumbered(info.fileName(), &prefix, &digits, &suffix))
        return {path};
    // Zero-padded numbers keep their width (shot_0009, shot_0010); unpadded ones may grow.
    const bool padded = digits.size() > 1 && digits.startsWith(QLatin1Char('0'));
    std::map<qulonglong, QString> run;
    const QDir dir = info.dir();
    for (const QString &name : dir.entryList(QDir::Files)) {
        QString p, d, s;
        if (!splitNumbered(name, &p, &d, &s) || p != prefix || s != suffix)
            continue;
        if (padded ? d.size() != digits.size() : (d.size() > 1 && d.startsWith(QLatin1Char('0'))))
            continue;
        bool ok = false;
        const qulonglong n = d.toULongLong(&ok);
        if (ok)
            run.emplace(n, dir.filePath(name));
    }
    // Only the unbroken run of numbers through the picked file.
    const qulonglong picked = digits.toULongLong();
    if (!run.count(picked))
        return {path};
    qulonglong first = picked, last = picked;
    while (first > 0 && run.count(first - 1))
        --first;
    while (run.count(last + 1))
        ++last;
    QStringList paths;
    for (qulonglong n = first; n <= last; ++n)
        paths << run.at(n);
    return paths.size() > 1 ? paths : QStringList{path};
}

Expected<Reference, QString> importReferenceSequence(const QStringList &paths, QSizeF canvas)
{
    if (paths.size() == 1)
        return importReferenceFile(paths.front(), canvas);
    if (paths.isEmpty())
        return unexpected(QCoreApplication::translate("Reference", "No picture was chosen."));
    if (paths.size() > kMaxReferencePictures)
        return unexpected(
            QCoreApplication::translate("Reference",
                                        "A sequence of more than %1 pictures cannot be used as a "
                                        "reference.")
                .arg(kMaxReferencePictures));
    Reference reference;
    reference.kind = ReferenceKind::Sequence;
    reference.name = QFileInfo(paths.front()).fileName();
    qint64 total = 0;
    const QString tooLarge =
        QCoreApplication::translate("Reference", "The pictures together are larger than %1 MB.")
            .arg(kMaxReferenceBytes >> 20);
    for (const QString &path : paths) {
        const auto read =
            reference_detail::readReferenceFile(path, kMaxReferenceBytes - total, tooLarge);
        if (!read)
            return unexpected(read.error());
        const QByteArray &bytes = *read;
        total += bytes.size();
        // Each picture is decoded once now (and dropped): one that would not decode later
        // is refused before the document changes, not shown as a gap.
        const auto media = ReferenceMedia::open(ReferenceKind::Image, bytes);
        if (!media)
            return unexpected(reference_detail::referenceRefusal(path, media.error()));
        if (reference.pictures.isEmpty())
            reference.mediaSize = QSizeF((*media)->size());
        reference.pictures << bytes;
    }
    reference.bytes = reference.pictures.front();
    const int more = int(paths.size()) - 1;
    //: %1 is the first file's name, %n how many pictures follow it
    reference.name = QCoreApplication::translate("Reference", "%1 and %n more", nullptr, more)
                         .arg(reference.name);
    fitReferenceToCanvas(reference, canvas);
    return reference;
}

} // namespace finbook::model
