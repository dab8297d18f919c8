// The inflated shape as a closed solid and its OBJ text (inflate/inflated_solid.h): the file is
// read back by an independent little parser and checked for its vertex count, a closed
// consistently oriented surface, outward normals and the enclosed volume.
#include "closed_surface.h"
#include "geometry_test_support.h"
#include "inflate_test_support.h"

#include <finbook/geometry/inflate/inflated_solid.h>

#include <QtTest>

#include <Eigen/Geometry>

#include <array>
#include <clocale>
#include <locale>
#include <map>
#include <sstream>

using namespace finbook::geometry;
using namespace finbook::test;

namespace {

struct ParsedObj {
    std::vector<Eigen::Vector3d> v, vn;
    std::vector<std::array<int, 3>> f, fn; // 0-based
    std::vector<std::string> objects;
    std::string problem; // the first line that does not parse, if any
};

ParsedObj parseObj(const std::string &text)
{
    ParsedObj obj;
    std::istringstream lines(text);
    lines.imbue(std::locale::classic());
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream in(line);
        in.imbue(std::locale::classic());
        std::string tag;
        in >> tag;
        if (tag.empty() || tag[0] == '#')
            continue;
        if (tag == "o") {
            obj.objects.push_back(line.substr(2));
        } else if (tag == "v" || tag == "vn") {
            Eigen::Vector3d p;
            if (!(in >> p.x() >> p.y() >> p.z()))
                obj.problem = line;
            (tag == "v" ? obj.v : obj.vn).push_back(p);
        } else if (tag == "f") {
            std::array<int, 3> f{}, fn{};
            for (int c = 0; c < 3; ++c) {
                std::string corner;
                in >> corner;
                const auto slashes = corner.find("//");
                if (slashes == std::string::npos) {
                    obj.problem = line;
                    break;
                }
                f[std::size_t(c)] = std::stoi(corner.substr(0, slashes)) - 1;
                fn[std::size_t(c)] = std::stoi(corner.substr(slashes + 2)) - 1;
            }
            std::string extra;
            if (in >> extra)
                obj.problem = line; // only triangles are written
            obj.f.push_back(f);
            obj.fn.push_back(fn);
        } else {
            obj.problem = line;
        }
    }
    return obj;
}

std::string objText(const std::vector<ObjObject> &objects)
{
    std::ostringstream out;
    if (!writeObj(out, objects))
        qFatal("writeObj failed");
    return out.str();
}

Inflation inflated(const Region &region)
{
    auto result = inflateRegion(region);
    if (!result)
        qFatal("inflateRegion failed: %s", result.error().message.c_str());
    return std::move(*result);
}

long eulerCharacteristic(const ParsedObj &obj)
{
    std::map<std::pair<int, int>, int> edges;
    for (const auto &f : obj.f)
        for (int c = 0; c < 3; ++c) {
            const int a = f[std::size_t(c)], b = f[std::size_t((c + 1) % 3)];
            edges[{std::min(a, b), std::max(a, b)}] = 1;
        }
    return long(obj.v.size()) - long(edges.size()) + long(obj.f.size());
}

} // namespace

class TestInflateObj : public QObject {
    Q_OBJECT
private slots:
    void solidIsClosedAndOutward_data();
    void solidIsClosedAndOutward();
    void chordsAreSplit();
    void severalObjectsShareOneFile();
    void numbersIgnoreTheLocale();
};

void TestInflateObj::solidIsClosedAndOutward_data()
{
    QTest::addColumn<int>("shape");
    QTest::addColumn<long>("euler"); // 2 for a sphere, 0 for a torus
    QTest::newRow("disc") << 0 << 2L;
    QTest::newRow("capsule") << 1 << 2L;
    QTest::newRow("annulus") << 2 << 0L;
}

void TestInflateObj::solidIsClosedAndOutward()
{
    QFETCH(int, shape);
    QFETCH(long, euler);
    const Eigen::MatrixX2d hole = circle(48, 40.0).colwise().reverse();
    const Region region = shape == 0   ? Region{Polygon{circle(96, 100.0), {}}}
                          : shape == 1 ? Region{Polygon{capsuleRing(150.0, 40.0, 24), {}}}
                                       : Region{Polygon{circle(96, 100.0), {hole}}};
    const Inflation inflation = inflated(region);
    const InflatedSolid solid = inflatedSolid(inflation);
    const ParsedObj obj = parseObj(objText({{"shape", solid}}));
    QVERIFY2(obj.problem.empty(), obj.problem.c_str());
    QCOMPARE(obj.objects.size(), std::size_t(1));

    // Vertex count: every inflation vertex on top, the ones off the outline once more below.
    const long outline = inflation.outline.sum();
    QCOMPARE(long(obj.v.size()), 2 * long(inflation.V.rows()) - outline);
    QCOMPARE(obj.vn.size(), obj.v.size());
    QCOMPARE(long(obj.f.size()), 2 * long(inflation.F.rows()));
    for (std::size_t i = 0; i < obj.f.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            QVERIFY(obj.f[i][std::size_t(c)] >= 0 && obj.f[i][std::size_t(c)] < int(obj.v.size()));
            QCOMPARE(obj.fn[i][std::size_t(c)], obj.f[i][std::size_t(c)]);
        }

    QVERIFY(closedAndOriented(obj.f));
    QCOMPARE(eulerCharacteristic(obj), euler);

    // Outward: positive enclosed volume, twice the height field's, and the written normals on
    // the side their triangles face.
    double volume = 0.0;
    long agreeing = 0;
    for (std::size_t i = 0; i < obj.f.size(); ++i) {
        const Eigen::Vector3d &a = obj.v[std::size_t(obj.f[i][0])],
                              &b = obj.v[std::size_t(obj.f[i][1])],
                              &c = obj.v[std::size_t(obj.f[i][2])];
        volume += a.dot(b.cross(c)) / 6.0;
        const Eigen::Vector3d normal = obj.vn[std::size_t(obj.fn[i][0])] +
                                       obj.vn[std::size_t(obj.fn[i][1])] +
                                       obj.vn[std::size_t(obj.fn[i][2])];
        agreeing += (b - a).cross(c - a).dot(normal) > 0.0 ? 1 : 0;
    }
    for (const Eigen::Vector3d &n : obj.vn)
        QVERIFY(std::abs(n.norm() - 1.0) <= 1e-9);
    qInfo("%zu vertices, %zu triangles, volume %.0f (height field %.0f), normals agree with "
          "%.2f%% of the triangles",
          obj.v.size(), obj.f.size(), volume, inflatedVolume(inflation),
          100.0 * double(agreeing) / double(obj.f.size()));
    QVERIFY(volume > 0.0);
    QVERIFY(std::abs(volume - 2.0 * inflatedVolume(inflation)) <= 1e-9 * volume);
    QVERIFY(std::abs(signedVolume(solid) - volume) <= 1e-9 * volume);
    QCOMPARE(agreeing, long(obj.f.size()));
}

void TestInflateObj::chordsAreSplit()
{
    // A square of two triangles: the diagonal joins two outline vertices. Unsplit, the solid
    // would pinch to a line there with four triangles on it.
    const Eigen::MatrixX2d V = rows({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
    Eigen::MatrixX3i F(2, 3);
    F << 0, 1, 2, 0, 2, 3;
    const auto inflation = inflateMesh(V, F);
    QVERIFY(inflation.hasValue());
    QCOMPARE(inflation->V.rows(), Eigen::Index(5));
    QCOMPARE(Eigen::MatrixX2d(inflation->V.topRows(4)), V);
    QCOMPARE(inflation->V.row(4), Eigen::RowVector2d(5, 5));
    QCOMPARE(inflation->outline.sum(), 4);
    QVERIFY(inflation->height(4) > 4.0); // the square's inscribed circle has radius 5
    QVERIFY(std::abs(inflation->normal(4, 2) - 1.0) <= 1e-9);
    QCOMPARE(inflation->F.rows(), Eigen::Index(4));
    const ParsedObj obj = parseObj(objText({{"square", inflatedSolid(*inflation)}}));
    QCOMPARE(obj.v.size(), std::size_t(6));
    QVERIFY(closedAndOriented(obj.f));
    QCOMPARE(eulerCharacteristic(obj), 2L);
}

void TestInflateObj::severalObjectsShareOneFile()
{
    const InflatedSolid a = inflatedSolid(inflated(Region{Polygon{circle(64, 50.0), {}}}));
    const InflatedSolid b =
        inflatedSolid(inflated(Region{Polygon{capsuleRing(80.0, 20.0, 16), {}}}));
    const ParsedObj obj = parseObj(objText({{"head", a}, {"arm\nleft", b}}));
    QVERIFY2(obj.problem.empty(), obj.problem.c_str());
    QCOMPARE(obj.objects, (std::vector<std::string>{"head", "arm_left"}));
    QCOMPARE(long(obj.v.size()), long(a.V.rows() + b.V.rows()));
    // The second object's faces index past the first object's vertices.
    const auto firstOfB = obj.f.begin() + a.F.rows();
    QVERIFY(std::all_of(obj.f.begin(), firstOfB, [&](const auto &f) {
        return *std::max_element(f.begin(), f.end()) < int(a.V.rows());
    }));
    QVERIFY(std::all_of(firstOfB, obj.f.end(), [&](const auto &f) {
        return *std::min_element(f.begin(), f.end()) >= int(a.V.rows());
    }));
    QVERIFY(closedAndOriented(obj.f));
}

void TestInflateObj::numbersIgnoreTheLocale()
{
    // A stream imbued with a locale that groups digits and uses a decimal comma still gets
    // plain numbers.
    struct Grouping : std::numpunct<char> {
        char do_decimal_point() const override { return ','; }
        char do_thousands_sep() const override { return '.'; }
        std::string do_grouping() const override { return "\3"; }
    };
    const InflatedSolid solid = inflatedSolid(inflated(Region{Polygon{circle(64, 1500.5), {}}}));
    std::ostringstream out;
    out.imbue(std::locale(std::locale::classic(), new Grouping));
    QVERIFY(writeObj(out, {{"big", solid}}));
    const ParsedObj obj = parseObj(out.str());
    QVERIFY2(obj.problem.empty(), obj.problem.c_str());
    QCOMPARE(long(obj.v.size()), long(solid.V.rows()));
    QVERIFY(solid.V.rows() > 1000);
    for (std::size_t i = 0; i < obj.v.size(); ++i)
        QCOMPARE(obj.v[i], Eigen::Vector3d(solid.V.row(Eigen::Index(i)).transpose()));
    QCOMPARE(long(obj.f.size()), long(solid.F.rows()));
    for (std::size_t i = 0; i < obj.f.size(); ++i)
        for (int c = 0; c < 3; ++c)
            QCOMPARE(obj.f[i][std::size_t(c)], solid.F(Eigen::Index(i), c));
}

QTEST_APPLESS_MAIN(TestInflateObj)
#include "tst_inflate_obj.moc"
