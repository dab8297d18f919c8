// Build-time tool: renders an SVG icon to PNGs of the hicolor theme's sizes, so the PNGs are
// made from the one SVG at build time rather than committed.
//
//   finbook-icon-render IN.svg OUT_PATTERN SIZE...
//
// OUT_PATTERN holds "@SIZE@" where each size goes ("hicolor/@SIZE@x@SIZE@/apps/x.png"); missing
// folders are made. Exits 1 with one line on stderr when the SVG does not render or a PNG
// cannot be written.
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QSaveFile>
#include <QSvgRenderer>
#include <QTextStream>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    QTextStream err(stderr);
    if (args.size() < 4) {
        err << "usage: finbook-icon-render IN.svg OUT_PATTERN SIZE..." << Qt::endl;
        return 1;
    }
    QSvgRenderer svg(args[1]);
    if (!svg.isValid()) {
        err << "cannot render " << args[1] << Qt::endl;
        return 1;
    }
    for (qsizetype i = 3; i < args.size(); ++i) {
        bool ok = false;
        const int size = args[i].toInt(&ok);
        if (!ok || size < 1 || size > 4096) {
            err << "bad size " << args[i] << Qt::endl;
            return 1;
        }
        QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::transparent);
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        svg.render(&painter, QRectF(0, 0, size, size));
        painter.end();
        const QString out = QString(args[2]).replace(QLatin1String("@SIZE@"), args[i]);
        QDir().mkpath(QFileInfo(out).path());
        QSaveFile file(out);
        if (!file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit()) {
            err << "cannot write " << out << Qt::endl;
            return 1;
        }
    }
    return 0;
}
