#include <finbook/geometry/embedding.h>
#include <finbook/geometry/triangle_locator.h>

namespace finbook::geometry {

Embedding embed(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F,
                const Eigen::MatrixX2d &points)
{
    const TriangleLocator locator(V, F);
    Embedding embedding;
    embedding.I.resize(points.rows());
    embedding.B.resize(points.rows(), 3);
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
        const Eigen::Vector2d p = points.row(i).transpose();
        const Location location = locator.locate(p);
        embedding.I(i) = location.triangle;
        embedding.B.row(i) = location.weights.transpose();
        if (!p.allFinite())
            ++embedding.unlocated;
        else if (!location.inside)
            ++embedding.snapped;
    }
    return embedding;
}

Embedding embed(const ObjectMesh &mesh, const Eigen::MatrixX2d &points)
{
    return embed(mesh.V, mesh.F, points);
}

Eigen::MatrixX2d applyEmbedding(const Embedding &embedding, const Eigen::MatrixX2d &Vdeformed,
                                const Eigen::MatrixX3i &F)
{
    Eigen::MatrixX2d out = Eigen::MatrixX2d::Zero(embedding.I.rows(), 2);
    for (Eigen::Index i = 0; i < embedding.I.rows(); ++i) {
        const int t = embedding.I(i);
        if (t < 0 || t >= F.rows())
            continue;
        for (int k = 0; k < 3; ++k)
            out.row(i) += embedding.B(i, k) * Vdeformed.row(F(t, k));
    }
    return out;
}

} // namespace finbook::geometry
