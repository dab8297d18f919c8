// finbook-bench deep-open: opens generated files of deep and wide structures (join chains and
// trees, long bone chains, many parts on one huge skeleton) and reports the time and peak
// memory of each open. With --write FOLDER it also leaves the files there, to time the real
// `finbook info` on them (/usr/bin/time -v).
#include "../model/deep_structures.h"
#include "bench.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

namespace {
using deep_build::Shape;

struct Case {
    const char *name;
    deep_build::Params params;
};

int deepOpen(const QStringList &args)
{
    QString folder;
    if (args.size() == 2 && args[0] == QLatin1String("--write"))
        folder = args[1];
    else if (!args.isEmpty())
        return 2;
    const std::vector<Case> cases{
        {"join_chain_80000", {Shape::JoinChain, 80000, 0, 1, true, false}},
        {"join_chain_reversed_80000", {Shape::JoinChain, 80000, 0, 2, true, true}},
        {"join_tree_80000", {Shape::JoinTree, 80000, 0, 3, true, false}},
        {"joint_chain_100000", {Shape::JointChain, 100000, 0, 4, true, false}},
        {"joints_20000_parts_1000", {Shape::JoinStar, 20000, 1000, 5, true, false}},
        {"joints_100000_parts_10000", {Shape::JoinStar, 100000, 10000, 6, true, false}},
    };
    for (const Case &c : cases) {
        const QByteArray bytes = deep_build::file(c.params);
        if (!folder.isEmpty()) {
            QFile out(
                QDir(folder).filePath(QString::fromLatin1(c.name) + QStringLiteral(".finbook")));
            if (!out.open(QIODevice::WriteOnly) || out.write(bytes) != bytes.size())
                return 1;
        }
        QElapsedTimer clock;
        clock.start();
        const auto loaded = finbook::model::readFinbook(bytes);
        const double seconds = double(clock.nsecsElapsed()) / 1e9;
        const QJsonObject line{
            {QStringLiteral("bench"), QStringLiteral("deep-open")},
            {QStringLiteral("case"), QString::fromLatin1(c.name)},
            {QStringLiteral("bytes"), double(bytes.size())},
            {QStringLiteral("opened"), bool(loaded)},
            {QStringLiteral("seconds"), seconds},
            {QStringLiteral("peak_rss_mib"), double(finbook::bench::peakResidentBytes() >> 20)}};
        std::printf("%s\n", QJsonDocument(line).toJson(QJsonDocument::Compact).constData());
        std::fflush(stdout);
    }
    return 0;
}
} // namespace

FINBOOK_BENCH("deep-open", "[--write FOLDER]: open generated deep and wide structures", deepOpen);
