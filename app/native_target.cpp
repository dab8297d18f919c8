#include "native_target.h"

#include <finbook/model/io/atomic_file.h>

#include <QFile>

#include <algorithm>
#include <cerrno>

#ifdef Q_OS_LINUX
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace finbook::app {

bool isValidFileName(const QByteArray &bytes)
{
    return QFile::encodeName(QFile::decodeName(bytes)) == bytes;
}

NativeTarget::~NativeTarget()
{
#ifdef Q_OS_LINUX
    for (const int fd : m_descriptors)
        ::close(fd);
    // Only empty folders go, deepest first: what a failed export made and left empty.
    for (auto it = m_created.rbegin(); it != m_created.rend(); ++it)
        if (::rmdir(it->constData()) != 0)
            break;
#endif
}

QString NativeTarget::openFolder(const QByteArray &bytes, QString *reason)
{
#ifdef Q_OS_LINUX
    // Made like mkdir -p, by bytes; what stands in the way is left for the export to report.
    for (qsizetype end = 1; end <= bytes.size(); ++end) {
        if (end < bytes.size() && bytes[end] != '/')
            continue;
        const QByteArray folder = bytes.left(end);
        struct stat status {};
        if (::lstat(folder.constData(), &status) == 0 || errno != ENOENT)
            continue;
        if (::mkdir(folder.constData(), 0777) != 0) {
            *reason = model::describeWriteFailure(model::writeFailureFromErrno(errno), QString());
            return {};
        }
        m_created.push_back(folder);
    }
    // O_PATH: a file where the folder should be opens too, and the export says so.
    const int fd = ::open(bytes.constData(), O_PATH | O_CLOEXEC);
    if (fd < 0) {
        *reason = model::describeWriteFailure(model::writeFailureFromErrno(errno), QString());
        return {};
    }
    m_descriptors.push_back(fd);
    // By process id rather than /proc/self: ffmpeg, a child, writes there too.
    const QString path = QStringLiteral("/proc/%1/fd/%2").arg(::getpid()).arg(fd);
    m_aliases.push_back({path, bytes});
    // Longest first, so that /proc/P/fd/12 is never read as /proc/P/fd/1 followed by "2".
    std::sort(m_aliases.begin(), m_aliases.end(),
              [](const Alias &a, const Alias &b) { return a.path.size() > b.path.size(); });
    return path;
#else
    *reason = model::describeWriteFailure(model::writeFailureFromErrno(EILSEQ), QString());
    Q_UNUSED(bytes);
    return {};
#endif
}

bool NativeTarget::prepare(const QByteArray &given, bool folder, model::ExportOptions &options,
                           QString *reason)
{
    QByteArray bytes = given;
    while (bytes.size() > 1 && bytes.endsWith('/'))
        bytes.chop(1);
    if (isValidFileName(bytes))
        return true;
    const qsizetype slash = bytes.lastIndexOf('/');
    const QByteArray parent = slash < 0 ? QByteArray() : bytes.left(std::max<qsizetype>(slash, 1));
    const QByteArray name = bytes.mid(slash + 1);
    QString parentPath;
    if (!parent.isEmpty()) {
        parentPath =
            isValidFileName(parent) ? QFile::decodeName(parent) : openFolder(parent, reason);
        if (parentPath.isEmpty())
            return false;
    }
    const QString nameText = QFile::decodeName(name);
    const QString joined = parentPath.isEmpty() ? nameText
                           : parentPath.endsWith(QLatin1Char('/'))
                               ? parentPath + nameText
                               : parentPath + QLatin1Char('/') + nameText;
    if (isValidFileName(name)) {
        options.target = joined;
    } else if (folder) {
        options.target = openFolder(bytes, reason);
        if (options.target.isEmpty())
            return false;
    } else {
        options.target = joined;
        options.nativeName = name;
        m_file = joined;
        m_fileBytes = bytes;
    }
    return true;
}

QString NativeTarget::shown(const QString &text) const
{
    QString result = text;
    for (const Alias &alias : m_aliases)
        result.replace(alias.path, QFile::decodeName(alias.bytes));
    return result;
}

QByteArray NativeTarget::bytes(const QString &path) const
{
    if (!m_file.isEmpty() && path == m_file)
        return m_fileBytes;
    for (const Alias &alias : m_aliases)
        if (path == alias.path || path.startsWith(alias.path + QLatin1Char('/')))
            return alias.bytes + QFile::encodeName(path.mid(alias.path.size()));
    return QFile::encodeName(path);
}

} // namespace finbook::app
