#include "native_names.h"

#include <QFile>
#include <QHash>

#ifdef Q_OS_LINUX
#include <fcntl.h>
#endif

namespace finbook::app {

namespace {
QHash<QString, QByteArray> &rawArguments()
{
    static QHash<QString, QByteArray> raw;
    return raw;
}
} // namespace

void rememberRawArguments(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray bytes(argv[i]);
        const QString text = QFile::decodeName(bytes);
        if (QFile::encodeName(text) != bytes && !rawArguments().contains(text))
            rawArguments().insert(text, bytes);
    }
}

QByteArray argumentBytes(const QString &argument)
{
    return rawArguments().value(argument, QFile::encodeName(argument));
}

QString openablePath(const QString &argument)
{
    const auto raw = rawArguments().constFind(argument);
    if (raw == rawArguments().constEnd())
        return argument;
#ifdef Q_OS_LINUX
    // Left open for the life of the process: the path below names this descriptor.
    const int fd = ::open(raw->constData(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0)
        return QStringLiteral("/proc/self/fd/%1").arg(fd);
#endif
    return argument; // opening it fails as it would have, and says so
}

} // namespace finbook::app
