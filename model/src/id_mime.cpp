#include "id_mime.h"

#include <QDataStream>
#include <QIODevice>

namespace finbook::model {

QMimeData *idsToMime(const char *mimeType, const std::vector<Id> &ids)
{
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    for (Id id : ids)
        out << quint64(id);
    auto *mime = new QMimeData;
    mime->setData(QString::fromLatin1(mimeType), bytes);
    return mime;
}

std::vector<Id> idsFromMime(const QMimeData *data, const char *mimeType)
{
    std::vector<Id> ids;
    if (!data)
        return ids;
    QDataStream in(data->data(QString::fromLatin1(mimeType)));
    while (!in.atEnd()) {
        quint64 id = 0;
        in >> id;
        if (in.status() != QDataStream::Ok)
            break;
        ids.push_back(Id(id));
    }
    return ids;
}

} // namespace finbook::model
