// renderSvg: a look through the XML first (how many elements it paints, <use> counted as the
// copies it makes), then Qt's renderer band by band with the CPU time checked between bands.
#include "reference_svg.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QHash>
#include <QPainter>
#include <QSvgRenderer>
#include <QXmlStreamReader>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <optional>
#include <vector>
#include <zlib.h>

namespace finbook::model::reference_detail {

namespace {
double threadSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

bool isGzip(const QByteArray &bytes)
{
    return bytes.size() >= 2 && uchar(bytes[0]) == 0x1f && uchar(bytes[1]) == 0x8b;
}

// At most `limit` bytes of a gzip stream; `whole` says whether the stream ended there.
// Null when it is damaged.
std::optional<QByteArray> gunzip(const QByteArray &bytes, qint64 limit, bool *whole)
{
    z_stream z{};
    if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK)
        return std::nullopt;
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(bytes.constData()));
    z.avail_in = uInt(bytes.size());
    QByteArray out;
    char buffer[1 << 16];
    int rc = Z_OK;
    *whole = false;
    while (out.size() <= limit) {
        z.next_out = reinterpret_cast<Bytef *>(buffer);
        z.avail_out = sizeof(buffer);
        rc = inflate(&z, Z_NO_FLUSH);
        if (rc != Z_OK && rc != Z_STREAM_END)
            break;
        out.append(buffer, qsizetype(sizeof(buffer) - z.avail_out));
        if (rc == Z_STREAM_END) {
            *whole = true;
            break;
        }
        if (z.avail_in == 0 && z.avail_out != 0)
            break; // cut off
    }
    inflateEnd(&z);
    if (rc != Z_OK && rc != Z_STREAM_END)
        return std::nullopt;
    return out;
}

struct Node {
    qint64 own = 1;
    QString useOf; // the id a <use> refers to
    std::vector<int> children;
};

// The elements the document paints, each <use> counted as a copy of what it refers to, at
// most kMaxSvgElements + 1; -1 with `error` set when it is not XML, declares entities, or a
// <use> refers to itself through others.
qint64 paintedElements(const QByteArray &xml, QString *error)
{
    QXmlStreamReader reader(xml);
    std::vector<Node> nodes;
    std::vector<int> open;
    QHash<QString, int> ids;
    while (!reader.atEnd()) {
        const auto token = reader.readNext();
        if (token == QXmlStreamReader::DTD && !reader.entityDeclarations().isEmpty()) {
            *error = QCoreApplication::translate(
                "Reference", "Its SVG declares entities, which Finbook does not expand.");
            return -1;
        }
        if (token == QXmlStreamReader::EndElement && !open.empty())
            open.pop_back();
        if (token != QXmlStreamReader::StartElement)
            continue;
        if (qint64(nodes.size()) > kMaxSvgElements)
            return kMaxSvgElements + 1;
        Node node;
        const QXmlStreamAttributes attributes = reader.attributes();
        for (const QXmlStreamAttribute &a : attributes) {
            // Long paths cost as several elements: 16 characters of data a point, roughly.
            if (a.name() == u"d" || a.name() == u"points")
                node.own += a.value().size() / 16;
            if (a.name() == u"href" && reader.name() == u"use" && a.value().startsWith(u'#'))
                node.useOf = a.value().mid(1).toString();
        }
        const int index = int(nodes.size());
        if (const QStringView id = attributes.value(QStringLiteral("id")); !id.isEmpty())
            ids.insert(id.toString(), index);
        if (!open.empty())
            nodes[std::size_t(open.back())].children.push_back(index);
        nodes.push_back(std::move(node));
        open.push_back(index);
    }
    if (reader.hasError() || nodes.empty()) {
        *error = QCoreApplication::translate("Reference", "It is not a valid SVG picture.");
        return -1;
    }
    // Post-order without recursion (a file may nest elements 100,000 deep).
    std::vector<qint64> weight(nodes.size(), 0);
    std::vector<char> state(nodes.size(), 0); // 0 new, 1 on the way, 2 done
    struct Step {
        int node;
        std::size_t next;
    };
    std::vector<Step> stack{{0, 0}};
    state[0] = 1;
    const auto dependency = [&](int i, std::size_t k) -> int {
        const Node &n = nodes[std::size_t(i)];
        if (k < n.children.size())
            return n.children[k];
        if (k == n.children.size() && !n.useOf.isEmpty())
            return ids.value(n.useOf, -1);
        return -2; // none left
    };
    while (!stack.empty()) {
        Step &step = stack.back();
        const int next = dependency(step.node, step.next);
        if (next == -2) {
            const Node &n = nodes[std::size_t(step.node)];
            qint64 sum = n.own;
            for (int c : n.children)
                sum = std::min(sum + weight[std::size_t(c)], kMaxSvgElements + 1);
            if (const int target = ids.value(n.useOf, -1); !n.useOf.isEmpty() && target >= 0)
                sum = std::min(sum + weight[std::size_t(target)], kMaxSvgElements + 1);
            weight[std::size_t(step.node)] = sum;
            state[std::size_t(step.node)] = 2;
            stack.pop_back();
            continue;
        }
        ++step.next;
        if (next < 0 || state[std::size_t(next)] == 2)
            continue;
        if (state[std::size_t(next)] == 1) {
            *error = QCoreApplication::translate(
                "Reference", "Its SVG uses an element inside itself (a loop of <use>).");
            return -1;
        }
        state[std::size_t(next)] = 1;
        stack.push_back({next, 0});
    }
    return weight[0];
}
} // namespace

bool looksLikeSvg(const QByteArray &bytes)
{
    QByteArray head = bytes.left(64 * 1024);
    if (isGzip(bytes)) {
        bool whole = false;
        head = gunzip(bytes, 64 * 1024, &whole).value_or(QByteArray()).left(64 * 1024);
    }
    const qsizetype at = head.indexOf('<');
    if (at < 0 || head.left(at).trimmed().size() > 3) // a BOM at most before the XML
        return false;
    return head.contains("<svg") || head.contains(":svg");
}

QImage renderSvg(const QByteArray &bytes, QString *error, double *budget)
{
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return QImage();
    };
    const double limit = budget ? std::min(kMaxSvgRenderSeconds, *budget) : kMaxSvgRenderSeconds;
    if (limit <= 0.0)
        return fail(QCoreApplication::translate("Reference",
                                                "The reference's SVG pictures took all the "
                                                "time Finbook spends drawing them."));
    QByteArray xml = bytes;
    if (isGzip(bytes)) {
        bool whole = false;
        const auto unpacked = gunzip(bytes, kMaxSvgBytes, &whole);
        if (!unpacked || !whole)
            return fail(QCoreApplication::translate(
                "Reference", "Its compressed SVG is damaged or larger than 16 MB."));
        xml = *unpacked;
    } else if (xml.size() > kMaxSvgBytes) {
        return fail(QCoreApplication::translate("Reference", "Its SVG is larger than 16 MB."));
    }
    QString why;
    const qint64 elements = paintedElements(xml, &why);
    if (elements < 0)
        return fail(why);
    if (elements > kMaxSvgElements)
        return fail(QCoreApplication::translate(
            "Reference", "Its SVG paints more than 100,000 elements (counting what <use> "
                         "repeats), more than Finbook draws for a reference."));
    // Checked after the look through the XML, which needs no fonts (the fuzzers, on a
    // QCoreApplication, reach it), and before Qt's renderer, which does.
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance()))
        return fail(QCoreApplication::translate(
            "Reference", "SVG pictures are drawn only where Finbook runs with its "
                         "graphical application (their text needs its fonts)."));
    QSvgRenderer renderer;
    if (!renderer.load(xml) || !renderer.isValid())
        return fail(QCoreApplication::translate("Reference", "It is not a valid SVG picture."));
    QSizeF size = renderer.defaultSize();
    if (size.isEmpty())
        size = renderer.viewBoxF().size();
    if (!(size.width() > 0.0 && size.height() > 0.0 && std::isfinite(size.width()) &&
          std::isfinite(size.height())))
        return fail(QCoreApplication::translate("Reference", "Its SVG has no size."));
    const double scale = std::min(1.0, kMaxSvgSide / std::max(size.width(), size.height()));
    const QSize pixels(std::clamp(int(std::lround(size.width() * scale)), 1, kMaxSvgSide),
                       std::clamp(int(std::lround(size.height() * scale)), 1, kMaxSvgSide));
    QImage image(pixels, QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return fail(
            QCoreApplication::translate("Reference", "There is not enough memory to read it."));
    image.fill(Qt::transparent);
    // Band by band: each band paints the whole picture clipped to its rows (the pixels are
    // those of one whole painting), and the time spent is checked between bands.
    const double start = threadSeconds();
    struct Charge { // the time spent, taken from the budget on every way out
        double *budget;
        double start;
        ~Charge()
        {
            if (budget)
                *budget -= threadSeconds() - start;
        }
    } charge{budget, start};
    int top = 0;
    int rows = 8;
    while (top < pixels.height()) {
        const int n = std::min(rows, pixels.height() - top);
        {
            QPainter painter(&image);
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setClipRect(QRect(0, top, pixels.width(), n));
            renderer.render(&painter, QRectF(QPointF(0, 0), QSizeF(pixels)));
        }
        top += n;
        const double spent = threadSeconds() - start;
        const double projected = spent * pixels.height() / top;
        if (top < pixels.height() &&
            (spent > kMaxSvgRenderSeconds || projected > 2 * kMaxSvgRenderSeconds))
            return fail(QCoreApplication::translate(
                            "Reference",
                            "Its SVG takes too long to draw (more than %1 s), more than "
                            "Finbook spends on a reference.")
                            .arg(kMaxSvgRenderSeconds));
        // About 50 ms a band from here on.
        rows = std::clamp(int(top * 0.05 / std::max(spent, 1e-4)), 8, pixels.height());
    }
    return image;
}

} // namespace finbook::model::reference_detail
